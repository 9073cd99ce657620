// world_place: teleports -- a robot placed upright on the carpet in a given pose or hung on a gantry,
// the ball placed rolling -- the reset to the start, and pushes on a torso.
#include <algorithm>
#include <cmath>

#include "world_internal.h"

namespace sim {

using namespace world_internal;

// Link poses for joint angles ql with the root at the origin turned by R0; the lowest point of any
// box into *zmin, and the link carrying the lowest sole box into *sole (-1: none).
static void place_links(const Model &m, const std::vector<double> &ql, const Mat3 &R0, std::vector<Vec3> *pos,
                        std::vector<Mat3> *rot, double *zmin, int *sole, Mat3 *sole_rot) {
  const int nl = (int)m.links.size();
  double sole_min = 1e9;
  *zmin = 1e9;
  *sole = -1;
  for (int i = 0; i < nl; i++) {
    const Link &l = m.links[i];
    if (l.parent < 0) {
      (*pos)[i] = Vec3::Zero();
      (*rot)[i] = R0;
    } else {
      (*pos)[i] = (*pos)[l.parent] + (*rot)[l.parent] * l.origin;
      (*rot)[i] = (*rot)[l.parent] * l.origin_rot * Eigen::AngleAxisd(ql[i], l.axis).toRotationMatrix();
    }
    for (const Box &b : l.boxes) {
      for (int c = 0; c < 8; c++) {
        Vec3 h((c & 1 ? 0.5 : -0.5) * b.size.x(), (c & 2 ? 0.5 : -0.5) * b.size.y(),
               (c & 4 ? 0.5 : -0.5) * b.size.z());
        const double z = ((*pos)[i] + (*rot)[i] * (b.pos + b.rot * h)).z();
        *zmin = std::min(*zmin, z);
        if (b.sole && z < sole_min) {
          sole_min = z;
          *sole = i;
          *sole_rot = (*rot)[i] * b.rot;
        }
      }
    }
  }
}

// The robot stands on its lower sole laid flat: a pose with the torso leaning over flat feet (a
// walk's stance) is placed as it stands, not with the torso upright and the feet tipped onto their
// heels; a body without soles is placed with its torso upright.
void World::place_robot(int r, double x, double y, double yaw, const double *q) {
  Robot &rb = robots_[r];
  const Model &m = *rb.m;
  const int nl = (int)m.links.size();
  std::vector<double> ql(nl, 0.0);
  for (size_t j = 0; j < rb.jlink.size(); j++) {
    const Link &l = m.links[rb.jlink[j]];
    double v = q ? q[j] : rb.cmd[j];
    ql[rb.jlink[j]] = std::min(std::max(v, l.lower), l.upper);
  }
  std::vector<Vec3> pos(nl);
  std::vector<Mat3> rot(nl);
  double zmin;
  int sole;
  Mat3 sole_rot = Mat3::Identity();
  place_links(m, ql, Mat3::Identity(), &pos, &rot, &zmin, &sole, &sole_rot);
  Mat3 level = Mat3::Identity();
  if (sole >= 0) {
    // the shortest turn taking the sole's normal up
    const Vec3 up = sole_rot.col(2), axis = up.cross(Vec3::UnitZ());
    const double s = axis.norm();
    if (s > 1e-12) level = Eigen::AngleAxisd(std::atan2(s, up.z()), axis / s).toRotationMatrix();
  }
  place_links(m, ql, rot_z(yaw) * level, &pos, &rot, &zmin, &sole, &sole_rot);
  const Vec3 shift(x, y, -zmin + 0.0002);
  for (int i = 0; i < nl; i++) {
    dBodyID b = rb.body[i];
    set_body_pose(b, pos[i] + shift + rot[i] * m.links[i].com, rot[i]);
    dBodySetLinearVel(b, 0, 0, 0);
    dBodySetAngularVel(b, 0, 0, 0);
  }
  rb.vel_start = Vec3::Zero();
  rb.push_left = 0;
  rb.push_at_left = 0;
}

void World::hang_robot(int r, double height) {
  Robot &rb = robots_[r];
  release_robot(r);
  for (dBodyID b : rb.body) {
    const dReal *p = dBodyGetPosition(b);
    dBodySetPosition(b, p[0], p[1], p[2] + height);
  }
  rb.gantry = dJointCreateFixed(world_, nullptr);
  dJointAttach(rb.gantry, rb.body[0], nullptr);
  dJointSetFixed(rb.gantry);
}

void World::release_robot(int r) {
  Robot &rb = robots_[r];
  if (rb.gantry) dJointDestroy(rb.gantry);
  rb.gantry = nullptr;
}

void World::place_ball(double x, double y, double vx, double vy) {
  const double r = p_.ball_diameter / 2;
  dBodySetPosition(ball_, x, y, r);
  dBodySetLinearVel(ball_, vx, vy, 0);
  dBodySetAngularVel(ball_, -vy / r, vx / r, 0);   // rolling without slipping
  const dQuaternion q0 = {1, 0, 0, 0};
  dBodySetQuaternion(ball_, q0);
  in_goal_ = 0;
  ball_touch_ = -1;
}

void World::reset() {
  const int nstart = (int)p_.start.size() / 3;
  for (int r = 0; r < nrobots(); r++) {
    const double *s = &p_.start[3 * (r % nstart)];
    place_robot(r, s[0], s[1], s[2]);
  }
  place_ball(p_.ball_start[0], p_.ball_start[1]);
  score_[0] = score_[1] = 0;
  // a reset world evolves the same whenever the reset happens: restart every random sequence
  dRandSetSeed((unsigned long)(seed_ & 0xffffffffu));
  rng_.seed(seed_);
  normal_.reset();
}

void World::push(int r, double fx, double fy, double duration) {
  Robot &rb = robots_[r];
  rb.push_force = Vec3(fx, fy, 0);
  rb.push_left = duration;
}

bool World::push_link(int r, const std::string &name, double fx, double fy, double fz, double duration) {
  Robot &rb = robots_[r];
  const Model &m = *rb.m;
  int li = m.link_index(name);
  Vec3 off = Vec3::Zero();
  if (li < 0) {
    const int fi = m.frame_index(name);
    if (fi < 0) return false;
    li = m.frames[fi].link;
    off = m.frames[fi].pos;
  }
  rb.push_at = li;
  rb.push_at_offset = off;
  rb.push_at_force = Vec3(fx, fy, fz);
  rb.push_at_left = duration;
  return true;
}

}  // namespace sim
