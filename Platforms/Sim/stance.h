// stance: a bent-knee standing pose for the sim's own tests and benchmarks (the walk's stance lives
// in the motion config). The pose is stated about the torso's axes (thigh forward 0.3 rad, knee bent
// 0.6, foot flat; upper arms 1.25 rad down from sideways, elbows 0.5, head tilt -0.3) and turned
// into joint angles through each joint's URDF axis, so mirrored or reversed axes (OP3, DARwIn-OP)
// get the same posture; angles are clamped to the joint limits.
#ifndef HRP_SIM_STANCE_H
#define HRP_SIM_STANCE_H

#include <algorithm>
#include <string>
#include <vector>

#include "model.h"

namespace sim {

inline std::vector<double> stance_pose(const Model &m, const std::vector<std::string> &joints, double knee = 0.6) {
  std::vector<Vec3> pos;
  std::vector<Mat3> rot;
  m.zero_pose(&pos, &rot);
  std::vector<double> q(joints.size(), 0.0);
  const double a = knee / 2;
  for (size_t j = 0; j < joints.size(); j++) {
    const std::string &n = joints[j];
    const int li = m.joint_link(n);
    if (li < 0) continue;
    const Link &l = m.links[li];
    const Vec3 ax = rot[li] * l.axis;                  // torso frame, zero pose
    const double sx = ax.x() > 0 ? 1 : -1, sy = ax.y() > 0 ? 1 : -1;
    const double side = pos[li].y() > 0 ? 1 : -1;      // left: +y
    // rotations about +y (pitch) and +x (roll) of the torso frame
    if (n == "l_hip_pitch" || n == "r_hip_pitch") q[j] = sy * -a;
    else if (n == "l_knee" || n == "r_knee") q[j] = sy * knee;
    else if (n == "l_ank_pitch" || n == "r_ank_pitch") q[j] = sy * -a;
    else if (n == "l_sho_roll" || n == "r_sho_roll") q[j] = sx * -side * 1.25;
    else if (n == "l_el" || n == "r_el") q[j] = side * 0.5;
    else if (n == "head_tilt") q[j] = sy * 0.3;          // looks down
    q[j] = std::min(std::max(q[j], l.lower), l.upper);
  }
  return q;
}

}  // namespace sim
#endif
