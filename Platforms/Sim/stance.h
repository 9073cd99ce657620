// stance: a bent-knee standing pose of the OP3-class robot for the sim's own tests and benchmarks
// (the walk's stance lives in the motion config). Signs follow the URDF axes: left and right legs
// are mirrored.
#ifndef HRP_SIM_STANCE_H
#define HRP_SIM_STANCE_H

#include <string>
#include <vector>

namespace sim {

inline std::vector<double> stance_pose(const std::vector<std::string> &joints, double knee = 0.6) {
  std::vector<double> q(joints.size(), 0.0);
  const double a = knee / 2;
  for (size_t j = 0; j < joints.size(); j++) {
    const std::string &n = joints[j];
    const double s = n[0] == 'l' ? 1 : -1;
    if (n == "l_hip_pitch" || n == "r_hip_pitch") q[j] = -s * a;
    else if (n == "l_knee" || n == "r_knee") q[j] = s * knee;
    else if (n == "l_ank_pitch" || n == "r_ank_pitch") q[j] = s * a;
    else if (n == "l_sho_roll" || n == "r_sho_roll") q[j] = s * 1.25;
    else if (n == "l_el" || n == "r_el") q[j] = s * 0.5;
    else if (n == "head_tilt") q[j] = -0.3;   // positive tilt looks up
  }
  return q;
}

}  // namespace sim
#endif
