// world_ft: the 6-axis force/torque sensors of a robot, from the feedback of the hinge whose child
// link carries the sensor (robot.lua `ft`). ODE fills the hinges' feedback in the last physics step
// of a tick (World::step), so a reading is that step's wrench, not a tick mean.
#include "world.h"

namespace sim {

void World::sense_ft(const Robot &rb, double *ft) const {
  for (int k = 0; k < 4; k++) {
    double *o = ft + 6 * k;
    for (int i = 0; i < 6; i++) o[i] = 0;
    const int li = rb.ft_link[k];
    if (li < 0) continue;
    // f1, t1: what the parent applies to the child (body 1) at the child's centre of mass
    const dJointFeedback &f = rb.fb[li];
    dVector3 anchor;
    dJointGetHingeAnchor(rb.hinge[li], anchor);
    const Vec3 f1(f.f1[0], f.f1[1], f.f1[2]), t1(f.t1[0], f.t1[1], f.t1[2]);
    const Vec3 arm = body_pos(rb.body[li]) - Vec3(anchor[0], anchor[1], anchor[2]);
    // the reaction: what the sensor's link exerts on the parent, about the anchor, link frame
    const Mat3 Rt = body_rot(rb.body[li]).transpose();
    const Vec3 force = Rt * -f1, torque = Rt * -(t1 + arm.cross(f1));
    for (int i = 0; i < 3; i++) {
      o[i] = force[i];
      o[3 + i] = torque[i];
    }
  }
}

}  // namespace sim
