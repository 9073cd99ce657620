// world_internal: what the files of sim::World share that its interface (world.h) does not show --
// the kinds of geometry, the collision bits and the small helpers of more than one file. The world
// by concern:
//   world.cpp          construction: the ODE world, the field's static parts, the ball, each robot
//   world_params.cpp   a body's configs (sim, robot, camera, actuators) into Params
//   world_load.cpp     the bodies of a world (Params and model) and the project's paths
//   world_place.cpp    teleports of robots and ball, reset, pushes
//   world_step.cpp     commands, servos, contacts and goals: the physics steps of a tick
//   world_sense.cpp    sensors, truth, link and camera poses
//   world_ft.cpp       the 6-axis force/torque sensors
//   world_solids.cpp   what the camera sees: the solids of goals, objects and robots
#ifndef HRP_SIM_WORLD_INTERNAL_H
#define HRP_SIM_WORLD_INTERNAL_H

#include "world.h"

namespace sim {
namespace world_internal {

const int kGround = 0, kBall = 1, kRobot = 2;   // GeomInfo::kind
const double kWorldCfm = 1e-5;
const double kWorldErp = 0.2;   // dWorldSetERP: the share of a joint's error corrected each step
// collision category bits: 0..47 the links of a robot, 48..62 robots, 63 static parts
const int kLinkBits = 48;
const unsigned long kStatic = 1ul << 63;

inline Mat3 rot_z(double a) { return Eigen::AngleAxisd(a, Vec3::UnitZ()).toRotationMatrix(); }

// A rotation as ODE keeps it: rows of four, the fourth unused.
inline void ode_rotation(const Mat3 &M, dMatrix3 R) {
  for (int a = 0; a < 3; a++) {
    for (int k = 0; k < 3; k++) R[a * 4 + k] = M(a, k);
    R[a * 4 + 3] = 0;
  }
}

// A body's pose: its centre of mass at c (field frame), its frame's rotation rot.
inline void set_body_pose(dBodyID b, const Vec3 &c, const Mat3 &rot) {
  dBodySetPosition(b, c.x(), c.y(), c.z());
  dMatrix3 R;
  ode_rotation(rot, R);
  dBodySetRotation(b, R);
}

// Solids for the camera (world_solids.cpp): a box of the given size centred at c, rotated by R.
void box_solid(const Vec3 &c, const Mat3 &R, const Vec3 &size, Solid *s);
// A cylinder of radius r and length len along R's z axis as an n-sided prism.
void cylinder_solid(const Vec3 &c, const Mat3 &R, double r, double len, int n, Solid *s);
void set_yuv(Solid *s, int y, int u, int v);

}  // namespace world_internal
}  // namespace sim
#endif
