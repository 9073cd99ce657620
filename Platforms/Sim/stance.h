// stance: a bent-knee standing pose for the sim's own tests and benchmarks (the walk's stance lives
// in the motion config). The pose is stated about the torso's axes (thigh forward 0.3 rad, knee bent
// 0.6, foot flat; upper arms 1.25 rad down from sideways, elbows 0.5, head tilt -0.3) and turned
// into joint angles through each joint's URDF axis, so mirrored or reversed axes (OP3, DARwIn-OP)
// get the same posture; angles are clamped to the joint limits. The leg joints are found by their
// place in the groups lleg/rleg (hip yaw, roll, pitch, knee, ankle pitch, roll: robot.lua), the
// arms and head by the OP-class names (a body with other names keeps its zero pose there: the
// Hubo's arms hang at zero).
#ifndef HRP_SIM_STANCE_H
#define HRP_SIM_STANCE_H

#include <algorithm>
#include <string>
#include <vector>

#include "model.h"
#include "world.h"

namespace sim {

// role of a joint in a leg group: 2 hip pitch, 3 knee, 4 ankle pitch (0-based), -1 otherwise
inline int leg_role(const std::string &n, const std::vector<std::string> &l, const std::vector<std::string> &r) {
  for (const std::vector<std::string> *g : {&l, &r})
    for (size_t k = 0; k < g->size() && k < 6; k++)
      if ((*g)[k] == n) return (int)k;
  return -1;
}

inline std::vector<double> stance_pose(const Model &m, const Params &p, double knee = 0.6) {
  const std::vector<std::string> &joints = p.joints;
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
    const int role = leg_role(n, p.lleg, p.rleg);
    if (role == 2) q[j] = sy * -a;
    else if (role == 3) q[j] = sy * knee;
    else if (role == 4) q[j] = sy * -a;
    else if (n == "l_sho_roll" || n == "r_sho_roll") q[j] = sx * -side * 1.25;
    else if (n == "l_el" || n == "r_el") q[j] = side * 0.5;
    else if (n == "head_tilt") q[j] = sy * 0.3;          // looks down
    q[j] = std::min(std::max(q[j], l.lower), l.upper);
  }
  return q;
}

}  // namespace sim
#endif
