// world_sense: what the robots sense (quantised joints, IMU with its noise, foot forces) and the
// truth the tests and the referee read: poses of links, torsos, the camera and the ball.
#include <algorithm>
#include <cmath>

#include "pressure.h"
#include "world_internal.h"

namespace sim {

Vec3 World::body_pos(dBodyID b) const {
  const dReal *p = dBodyGetPosition(b);
  return Vec3(p[0], p[1], p[2]);
}

Mat3 World::body_rot(dBodyID b) const {
  const dReal *R = dBodyGetRotation(b);
  Mat3 M;
  M << R[0], R[1], R[2], R[4], R[5], R[6], R[8], R[9], R[10];
  return M;
}

std::vector<double> World::joint_positions(int r) const {
  const Robot &rb = robots_[r];
  std::vector<double> q(rb.jlink.size());
  for (size_t j = 0; j < q.size(); j++) q[j] = dJointGetHingeAngle(rb.hinge[rb.jlink[j]]);
  return q;
}

void World::sense(int r, Sensors *s) {
  Robot &rb = robots_[r];
  const size_t nj = rb.jlink.size();
  s->position.resize(nj);
  s->velocity.resize(nj);
  s->load.resize(nj);
  for (size_t j = 0; j < nj; j++) {
    const Servo &sv = (*rb.servo)[j];
    const double qstep = 2 * M_PI / sv.resolution, vstep = sv.speed_unit;
    const int li = rb.jlink[j];
    dJointID h = rb.hinge[li];
    s->position[j] = std::round(dJointGetHingeAngle(h) / qstep) * qstep;
    s->velocity[j] = std::round(dJointGetHingeAngleRate(h) / vstep) * vstep;
    // ODE gives the joint's torque on the link about the link's centre of mass (its body origin);
    // about the hinge axis, through the anchor, the joint force's moment adds to it
    dVector3 ax, an;
    dJointGetHingeAxis(h, ax);
    dJointGetHingeAnchor(h, an);
    const dJointFeedback &f = rb.fb[li];
    const Vec3 arm = body_pos(rb.body[li]) - Vec3(an[0], an[1], an[2]);
    const Vec3 t = Vec3(f.t1[0], f.t1[1], f.t1[2]) + arm.cross(Vec3(f.f1[0], f.f1[1], f.f1[2]));
    // in torque mode the drive's torque is no constraint of ODE's: it is added
    s->load[j] = t.dot(Vec3(ax[0], ax[1], ax[2])) + rb.applied[j];
  }
  const Mat3 R = body_rot(rb.body[0]);
  const dReal *w = dBodyGetAngularVel(rb.body[0]);
  Vec3 g = R.transpose() * Vec3(w[0], w[1], w[2]);
  for (int k = 0; k < 3; k++) {
    s->gyro[k] = g[k] + p_.gyro_noise * normal_(rng_);
    s->accel[k] = rb.accel[k] + p_.accel_noise * normal_(rng_);
  }
  s->angle[0] = std::atan2(R(2, 1), R(2, 2));
  s->angle[1] = std::asin(std::min(1.0, std::max(-1.0, -R(2, 0))));
  s->angle[2] = std::atan2(R(1, 0), R(0, 0));
  s->foot_force[0] = rb.foot_acc[0];
  s->foot_force[1] = rb.foot_acc[1];
  sense_ft(rb, s->ft);
  // pressure sensors: the ground's wrench on the foot in its sole frame gives the sole's normal force
  // and centre of pressure, which the sensors share (pressure.h)
  s->pressure.clear();
  for (int k = 0; k < 2 && rb.press_frame[k] >= 0; k++) {
    const Frame &fr = rb.m->frames[rb.press_frame[k]];
    Vec3 lp;
    Mat3 lR;
    link_pose(r, fr.link, &lp, &lR);
    const Vec3 o = lp + lR * fr.pos;
    const Mat3 Rs = lR * fr.rot;
    const Vec3 f = Rs.transpose() * rb.press_f[k], m = Rs.transpose() * (rb.press_m[k] - o.cross(rb.press_f[k]));
    const std::vector<double> &xy = (*rb.pressure)[k].xy;
    const double fz = f.z();
    const std::vector<double> share = fz > 0 ? pressure_distribute(xy, fz, -m.y() / fz, m.x() / fz)
                                             : std::vector<double>(xy.size() / 2, 0.0);
    s->pressure.insert(s->pressure.end(), share.begin(), share.end());
  }
}

void World::link_pose(int r, int link, Vec3 *pos, Mat3 *rot) const {
  dBodyID b = robots_[r].body[link];
  *rot = body_rot(b);
  *pos = body_pos(b) - *rot * robots_[r].m->links[link].com;
}

Truth World::truth(int r) const {
  Truth t;
  Vec3 p;
  Mat3 R;
  link_pose(r, 0, &p, &R);
  t.x = p.x();
  t.y = p.y();
  t.z = p.z();
  t.yaw = std::atan2(R(1, 0), R(0, 0));
  t.pitch = std::asin(std::min(1.0, std::max(-1.0, -R(2, 0))));
  t.roll = std::atan2(R(2, 1), R(2, 2));
  t.fallen = std::acos(std::min(1.0, std::max(-1.0, R(2, 2)))) > p_.fall_angle;
  const dReal *bp = dBodyGetPosition(ball_), *bv = dBodyGetLinearVel(ball_);
  t.ball[0] = bp[0];
  t.ball[1] = bp[1];
  t.ball[2] = bp[2];
  t.ball[3] = bv[0];
  t.ball[4] = bv[1];
  const Robot &rb = robots_[r];
  const bool on = rb.ground_f.z() > 0;
  t.cop[0] = on ? -rb.ground_m.y() / rb.ground_f.z() : 0;
  t.cop[1] = on ? rb.ground_m.x() / rb.ground_f.z() : 0;
  t.cop[2] = on ? rb.ground_f.z() : 0;
  return t;
}

Vec3 World::ball_position() const { return body_pos(ball_); }

Mat3 World::ball_rotation() const { return body_rot(ball_); }

bool World::frame_pose(int r, const std::string &name, Vec3 *pos, Mat3 *rot) const {
  const Model &m = *robots_[r].m;
  const int li = m.link_index(name);
  if (li >= 0) {
    link_pose(r, li, pos, rot);
    return true;
  }
  const int fi = m.frame_index(name);
  if (fi < 0) return false;
  const Frame &f = m.frames[fi];
  Vec3 lp;
  Mat3 lR;
  link_pose(r, f.link, &lp, &lR);
  *pos = lp + lR * f.pos;
  *rot = lR * f.rot;
  return true;
}

void World::camera_pose(int r, Vec3 *pos, Mat3 *rot) const { frame_pose(r, p_.camera_frame, pos, rot); }

}  // namespace sim
