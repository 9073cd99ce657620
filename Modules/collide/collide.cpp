// Self-collision behind collide.h: Pinocchio's geometry model of the URDF's <collision> shapes, its
// pairs filtered once, checked by coal at each configuration asked.
#include "collide/collide.h"

#include <pinocchio/multibody.hpp>
#include <pinocchio/geometry.hpp>
#include <pinocchio/algorithm/geometry.hpp>
#include <pinocchio/algorithm/joint-configuration.hpp>
#include <pinocchio/algorithm/kinematics.hpp>
#include <pinocchio/collision/collision.hpp>
#include <pinocchio/parsers/urdf.hpp>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <exception>
#include <memory>
#include <set>
#include <string>
#include <vector>

struct collide {
  pinocchio::Model model;
  std::unique_ptr<pinocchio::Data> data;
  pinocchio::GeometryModel geom;
  std::unique_ptr<pinocchio::GeometryData> gdata;
  std::vector<int> qidx;              // caller's joint j -> index in Pinocchio's q
  std::vector<std::string> names;     // caller's joint order
  Eigen::VectorXd q;
  double margin = 0;
  double check_us = 0;
  std::string err;
};

namespace {

int fail(collide *c, const std::string &msg) {
  c->err = msg;
  return -1;
}

double thread_cpu_us() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e6 + ts.tv_nsec * 1e-3;
}

int set_q(collide *c, const double *q) {
  if (!q) return fail(c, "no joint angles");
  for (size_t j = 0; j < c->qidx.size(); j++) {
    if (!std::isfinite(q[j])) return fail(c, "joint '" + c->names[j] + "': angle is not finite");
    c->q[c->qidx[j]] = q[j];
  }
  pinocchio::updateGeometryPlacements(c->model, *c->data, c->geom, *c->gdata, c->q);
  return 0;
}

// The pair's objects are closer than the margin (coal's security margin: a positive one counts
// shapes that far apart as touching).
bool in_collision(collide *c, size_t k) {
  return pinocchio::computeCollision(c->geom, *c->gdata, k);
}

void apply_margin(collide *c) {
  for (auto &req : c->gdata->collisionRequests) req.security_margin = c->margin;
}

}  // namespace

extern "C" {

int collide_new(const char *urdf, int njoint, const char *const *joints, collide **out, char *err, size_t errlen) {
  if (!out || !urdf || njoint < 1 || !joints) {
    snprintf(err, errlen, "collide: a URDF and its joint order are needed");
    return -1;
  }
  *out = nullptr;
  std::unique_ptr<collide> c(new collide);
  try {
    pinocchio::urdf::buildModel(std::string(urdf), c->model);
    pinocchio::urdf::buildGeom(c->model, std::string(urdf), pinocchio::COLLISION, c->geom);
  } catch (const std::exception &e) {
    snprintf(err, errlen, "%s: %s", urdf, e.what());
    return -1;
  }
  std::set<std::string> seen;
  for (int j = 0; j < njoint; j++) {
    const std::string name = joints[j] ? joints[j] : "";
    if (!c->model.existJointName(name) || !seen.insert(name).second) {
      snprintf(err, errlen, "%s: joint '%s' of the joint order is not a movable joint (or named twice)", urdf,
               name.c_str());
      return -1;
    }
    auto id = c->model.getJointId(name);
    if (c->model.nqs[id] != 1) {
      snprintf(err, errlen, "%s: joint '%s' is not revolute or prismatic", urdf, name.c_str());
      return -1;
    }
    c->qidx.push_back(c->model.idx_qs[id]);
    c->names.push_back(name);
  }
  if ((int)seen.size() != c->model.njoints - 1) {
    snprintf(err, errlen, "%s: the joint order names %d joints, the URDF has %d", urdf, (int)seen.size(),
             (int)c->model.njoints - 1);
    return -1;
  }
  // every pair on different links, less the links one joint apart
  c->geom.addAllCollisionPairs();
  std::vector<pinocchio::CollisionPair> keep;
  for (const auto &p : c->geom.collisionPairs) {
    const auto a = c->geom.geometryObjects[p.first].parentJoint, b = c->geom.geometryObjects[p.second].parentJoint;
    if (a == b || c->model.parents[a] == b || c->model.parents[b] == a) continue;
    keep.push_back(p);
  }
  c->geom.removeAllCollisionPairs();
  for (const auto &p : keep) c->geom.addCollisionPair(p);
  c->data.reset(new pinocchio::Data(c->model));
  c->gdata.reset(new pinocchio::GeometryData(c->geom));
  c->q = pinocchio::neutral(c->model);
  *out = c.release();
  return 0;
}

void collide_free(collide *c) { delete c; }
const char *collide_error(const collide *c) { return c ? c->err.c_str() : "collide: no checker"; }
int collide_npair(const collide *c) { return (int)c->geom.collisionPairs.size(); }

int collide_ignore_at(collide *c, const double *q) {
  if (set_q(c, q) < 0) return -1;
  std::vector<pinocchio::CollisionPair> keep;
  int dropped = 0;
  for (size_t k = 0; k < c->geom.collisionPairs.size(); k++) {
    if (in_collision(c, k)) dropped++;
    else keep.push_back(c->geom.collisionPairs[k]);
  }
  c->geom.removeAllCollisionPairs();
  for (const auto &p : keep) c->geom.addCollisionPair(p);
  c->gdata.reset(new pinocchio::GeometryData(c->geom));
  apply_margin(c);
  return dropped;
}

int collide_ignore_near(collide *c, int joints) {
  if (joints < 0) return fail(c, "collide_ignore_near: a count of joints >= 0");
  const pinocchio::Model &m = c->model;
  auto depth = [&m](pinocchio::JointIndex j) {
    int d = 0;
    while (j != 0) j = m.parents[j], d++;
    return d;
  };
  // joints between the links of joints a and b along the tree (through their common ancestor)
  auto apart = [&m, &depth](pinocchio::JointIndex a, pinocchio::JointIndex b) {
    int da = depth(a), db = depth(b), n = 0;
    while (da > db) a = m.parents[a], da--, n++;
    while (db > da) b = m.parents[b], db--, n++;
    while (a != b) a = m.parents[a], b = m.parents[b], n += 2;
    return n;
  };
  std::vector<pinocchio::CollisionPair> keep;
  int dropped = 0;
  for (const auto &p : c->geom.collisionPairs) {
    if (apart(c->geom.geometryObjects[p.first].parentJoint, c->geom.geometryObjects[p.second].parentJoint) <= joints)
      dropped++;
    else
      keep.push_back(p);
  }
  c->geom.removeAllCollisionPairs();
  for (const auto &p : keep) c->geom.addCollisionPair(p);
  c->gdata.reset(new pinocchio::GeometryData(c->geom));
  apply_margin(c);
  return dropped;
}

int collide_set_margin(collide *c, double margin) {
  if (!std::isfinite(margin) || margin < 0) return fail(c, "collide: the margin must be finite and >= 0");
  c->margin = margin;
  apply_margin(c);
  return 0;
}

int collide_check(collide *c, const double *q, int *first) {
  const double t0 = thread_cpu_us();
  if (set_q(c, q) < 0) return -1;
  int n = 0;
  if (first) *first = -1;
  for (size_t k = 0; k < c->geom.collisionPairs.size(); k++)
    if (in_collision(c, k)) {
      if (n == 0 && first) *first = (int)k;
      n++;
    }
  c->check_us = thread_cpu_us() - t0;
  return n;
}

const char *collide_pair_link(const collide *c, int pair, int side) {
  if (pair < 0 || pair >= (int)c->geom.collisionPairs.size() || side < 0 || side > 1) return nullptr;
  const auto &p = c->geom.collisionPairs[pair];
  const auto &o = c->geom.geometryObjects[side == 0 ? p.first : p.second];
  return c->model.frames[o.parentFrame].name.c_str();
}

double collide_check_us(const collide *c) { return c->check_us; }

}  // extern "C"
