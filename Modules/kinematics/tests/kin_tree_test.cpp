// Unit tests of Modules/kinematics on joint trees beyond the OP3's shape (TAP): joints in any
// order, a waist carrying the arms and the head, arms of 4 joints, a leg hanging from a moving
// link, a camera pitched down at the zero pose, and descriptions the model must refuse.
#include "kinematics/kinematics.h"
#include "kinematics/kin_arrays.hpp"
#include "tap.h"

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

void ok(bool cond, const std::string &name, const std::string &detail = "") {
  tap_ok(cond, name.c_str(), detail.c_str());
}

// A description built joint by joint (std::vector storage; desc() points a kin_desc into it).
struct Body : KinArrays {
  std::vector<std::vector<int>> chain_joints;
  std::vector<kin_chain> chains;
  kin_desc d{};

  int add(int par, Vector3d a, Vector3d p, double m) {
    parent.push_back(par);
    for (int k = 0; k < 3; k++) {
      axis.push_back(a[k]);
      anchor.push_back(p[k]);
      com.push_back(p[k] + 0.01 * (k + 1));
    }
    mass.push_back(m);
    qmin.push_back(-2.8);
    qmax.push_back(2.8);
    return (int)parent.size() - 1;
  }
  void chain(int kind, int side, std::vector<int> joints, Vector3d tip, Matrix3d rot = Matrix3d::Identity()) {
    chain_joints.push_back(joints);
    kin_chain c{};
    c.kind = kind;
    c.side = side;
    c.n = (int)joints.size();
    for (int k = 0; k < 3; k++) {
      c.tip[k] = tip[k];
      for (int m = 0; m < 3; m++) c.tip_rot[3 * k + m] = rot(k, m);
    }
    chains.push_back(c);
  }
  const kin_desc *desc() {
    describe(d);
    d.torso_mass = 1.2;
    d.torso_com[0] = -0.01;
    d.torso_com[2] = 0.05;
    for (size_t i = 0; i < chains.size(); i++) chains[i].joints = chain_joints[i].data();
    d.nchain = (int)chains.size();
    d.chains = chains.data();
    return &d;
  }
  // The same body with its joints renumbered: new index = perm[old index].
  Body permuted(const std::vector<int> &perm) const {
    Body b = *this;
    const int n = (int)parent.size();
    for (int j = 0; j < n; j++) {
      const int t = perm[j];
      b.parent[t] = parent[j] < 0 ? -1 : perm[parent[j]];
      b.mass[t] = mass[j];
      b.qmin[t] = qmin[j];
      b.qmax[t] = qmax[j];
      for (int k = 0; k < 3; k++) {
        b.axis[3 * t + k] = axis[3 * j + k];
        b.anchor[3 * t + k] = anchor[3 * j + k];
        b.com[3 * t + k] = com[3 * j + k];
      }
    }
    for (auto &cj : b.chain_joints)
      for (int &j : cj) j = perm[j];
    return b;
  }
};

// The waist robot: torso at the origin (reference frame = torso frame); legs from the torso;
// a waist yaw joint carrying a 4-joint arm on each side and the pan/tilt head; the camera is
// pitched 45 deg down at the zero pose. Joint order: legs, arms, head, waist (children first).
Body waist_robot(bool pelvis) {
  Body b;
  const double ptch = M_PI / 4;
  Matrix3d cam = Eigen::AngleAxisd(ptch, Vector3d::UnitY()).toRotationMatrix();
  int pel = -1;
  if (pelvis) pel = b.add(-1, Vector3d(0, 1, 0), Vector3d(0, 0, -0.01), 0.05);  // legs hang from it
  std::vector<int> leg[2];
  for (int s = 0; s < 2; s++) {
    const double sy = s == 0 ? 1 : -1;
    const Vector3d ax[6] = {{0, 0, -1}, {-1, 0, 0}, {0, sy, 0}, {0, sy, 0}, {0, -sy, 0}, {1, 0, 0}};
    const Vector3d an[6] = {{0, sy * 0.035, 0},       {-0.02, sy * 0.035, -0.03}, {0, sy * 0.05, -0.03},
                            {0.002, sy * 0.05, -0.14}, {0, sy * 0.05, -0.25},      {-0.02, sy * 0.035, -0.25}};
    int p = pel;
    for (int k = 0; k < 6; k++) leg[s].push_back(p = b.add(p, ax[k], an[k], 0.1));
  }
  // placeholder for the waist: index fixed after the children, so children come first
  std::vector<int> arm[2];
  const int W = 12 + (pelvis ? 1 : 0) + 8 + 2;  // the waist's index once every other joint is in
  for (int s = 0; s < 2; s++) {
    const double sy = s == 0 ? 1 : -1;
    int p = W;
    p = b.add(p, Vector3d(0, sy, 0), Vector3d(0, sy * 0.06, 0.11), 0.02);
    arm[s].push_back(p);
    p = b.add(p, Vector3d(-1, 0, 0), Vector3d(0.015, sy * 0.09, 0.10), 0.15);
    arm[s].push_back(p);
    p = b.add(p, Vector3d(1, 0, 0), Vector3d(0.015, sy * 0.18, 0.10), 0.05);
    arm[s].push_back(p);
    p = b.add(p, Vector3d(0, 0, 1), Vector3d(0, sy * 0.30, 0.10), 0.1);  // wrist
    arm[s].push_back(p);
  }
  int pan = b.add(W, Vector3d(0, 0, 1), Vector3d(0, 0, 0.14), 0.01);
  int tilt = b.add(pan, Vector3d(0, -1, 0), Vector3d(0.01, 0.0, 0.165), 0.14);
  int w = b.add(-1, Vector3d(0, 0, 1), Vector3d(0.005, 0, 0.07), 0.1);
  if (w != W) std::abort();
  for (int s = 0; s < 2; s++) {
    const double sy = s == 0 ? 1 : -1;
    b.chain(KIN_LEG, s, leg[s], Vector3d(0, sy * 0.035, -0.28));
    b.chain(KIN_ARM, s, arm[s], Vector3d(0, sy * 0.35, 0.10));
  }
  b.chain(KIN_HEAD, 0, {pan, tilt}, Vector3d(0.045, 0, 0.19), cam);
  return b;
}

double dist(const double *a, const double *b, int n) {
  double s = 0;
  for (int k = 0; k < n; k++) s += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(s);
}

kin_model *make(const kin_desc *d, const std::string &name) {
  kin_model *m = nullptr;
  char err[384] = "";
  int rc = kin_model_create(d, &m, err, sizeof err);
  ok(rc == 0 && m, name + ": model created", err);
  return m;
}

// Angle between the optical axis (column 0 of R) and the direction from the camera to t.
double look_error(const double *t, const double *c, const double *R) {
  Vector3d d(t[0] - c[0], t[1] - c[1], t[2] - c[2]), x(R[0], R[3], R[6]);
  return std::atan2(d.cross(x).norm(), d.dot(x));   // exact near 0, unlike acos
}

std::string refused(Body b, const std::string &want) {
  kin_model *m = nullptr;
  char err[384] = "";
  int rc = kin_model_create(b.desc(), &m, err, sizeof err);
  kin_model_destroy(m);
  return rc == KIN_EMODEL && m == nullptr && std::strstr(err, want.c_str()) ? std::string(err) : std::string();
}

}  // namespace

int main() {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  Body body = waist_robot(false);
  kin_model *m = make(body.desc(), "waist robot (children before parents)");
  if (!m) return tap_done();
  const int n = kin_njoint(m);
  const int W = n - 1;
  int larm[KIN_MAXARM], head[2];
  ok(kin_chain_joints(m, KIN_ARM, KIN_LEFT, larm) == 4 && kin_chain_joints(m, KIN_HEAD, 0, head) == 2,
     "chain lengths: arm 4, head 2");

  // 1. The same body in another joint order gives the same link poses and COM.
  std::vector<int> perm(n);
  for (int j = 0; j < n; j++) perm[j] = (j * 7 + 3) % n;  // 7 is prime to n = 23
  Body other = body.permuted(perm);
  kin_model *m2 = make(other.desc(), "the same body, joints renumbered");
  double worst = 0;
  for (int trial = 0; trial < 20; trial++) {
    std::vector<double> q(n), q2(n), P1(12 * n), P2(12 * n);
    for (int j = 0; j < n; j++) q2[perm[j]] = q[j] = 0.8 * U(rng);
    kin_link_poses(m, q.data(), P1.data());
    kin_link_poses(m2, q2.data(), P2.data());
    for (int j = 0; j < n; j++) worst = std::max(worst, dist(&P1[12 * j], &P2[12 * perm[j]], 12));
    double c1[3], c2[3];
    kin_com(m, q.data(), c1);
    kin_com(m2, q2.data(), c2);
    worst = std::max(worst, dist(c1, c2, 3));
  }
  char det[200];
  snprintf(det, sizeof det, "worst difference %.3g", worst);
  ok(worst < 1e-12, "link poses and COM do not depend on the joint order", det);
  kin_model_destroy(m2);

  // 2. The waist turns the arms and the head about its axis.
  std::vector<double> qb(n, 0.0);
  qb[W] = 0.5;
  const double qa[4] = {0.3, -0.4, 0.6, 0.2};
  double h0[3], h1[3];
  kin_arm_fk(m, KIN_LEFT, qa, nullptr, h0, nullptr);
  kin_arm_fk(m, KIN_LEFT, qa, qb.data(), h1, nullptr);
  Vector3d wa(0.005, 0, 0.07);
  Vector3d want = Eigen::AngleAxisd(0.5, Vector3d::UnitZ()) * (Vector3d(h0[0], h0[1], h0[2]) - wa) + wa;
  ok(dist(h1, want.data(), 3) < 1e-12, "arm FK with the waist at 0.5 rad: the hand turned about the waist axis");
  double c0[3], R0[9], c1[3], R1[9];
  const double qh[2] = {0.2, -0.3};
  kin_head_fk(m, qh, nullptr, c0, R0);
  kin_head_fk(m, qh, qb.data(), c1, R1);
  want = Eigen::AngleAxisd(0.5, Vector3d::UnitZ()) * (Vector3d(c0[0], c0[1], c0[2]) - wa) + wa;
  ok(dist(c1, want.data(), 3) < 1e-12 && std::fabs(std::atan2(R1[3], R1[0]) - std::atan2(R0[3], R0[0]) - 0.5) < 1e-12,
     "head FK with the waist turned: camera turned with it");

  // 3. Arms of 4 joints: IK reaches FK-made targets, with and without the waist.
  double worst_arm = 0;
  int arm_flags = 0;
  for (int i = 0; i < 200; i++) {
    double q[4], qs[4] = {0, 0, 0, 0}, h[3], h2[3];
    for (int k = 0; k < 4; k++) q[k] = 1.2 * U(rng);
    const double *base = i % 2 ? qb.data() : nullptr;
    kin_arm_fk(m, i % 4 < 2 ? KIN_LEFT : KIN_RIGHT, q, base, h, nullptr);
    arm_flags |= kin_arm_ik(m, i % 4 < 2 ? KIN_LEFT : KIN_RIGHT, h, base, qs);
    kin_arm_fk(m, i % 4 < 2 ? KIN_LEFT : KIN_RIGHT, qs, base, h2, nullptr);
    worst_arm = std::max(worst_arm, dist(h, h2, 3));
  }
  snprintf(det, sizeof det, "worst %.3g m, flags %d", worst_arm, arm_flags);
  ok(worst_arm < 1e-4 && arm_flags == 0, "4-joint arm IK (damped least squares) reaches 200 FK-made hand points", det);

  // 4. The camera pitched 45 deg down at the zero pose: head FK and look-at.
  kin_head_fk(m, (const double[2]){0, 0}, nullptr, c0, R0);
  ok(std::fabs(R0[0] - M_SQRT1_2) < 1e-12 && std::fabs(R0[6] + M_SQRT1_2) < 1e-12 && std::fabs(R0[8] - M_SQRT1_2) < 1e-12,
     "tilted camera at the zero pose: optical axis 45 deg down, image up 45 deg forward");
  double worst_look = 0;
  int look_flags = 0;
  for (int i = 0; i < 300; i++) {
    double t[3] = {0.3 + 2.0 * (U(rng) + 1), 1.5 * U(rng), -0.2 - 0.1 * (U(rng) + 1)};
    if (i % 3 == 0) t[2] = 0.3 + 0.5 * (U(rng) + 1);  // above the head: the tilt must lift the camera
    double q2[2], c[3], R[9];
    const double *base = i % 2 ? qb.data() : nullptr;
    look_flags |= kin_head_look_at(m, t, base, q2);
    kin_head_fk(m, q2, base, c, R);
    worst_look = std::max(worst_look, look_error(t, c, R));
  }
  snprintf(det, sizeof det, "worst angle %.3g rad, flags %d", worst_look, look_flags);
  ok(worst_look < 1e-9 && look_flags == 0, "look_at with the tilted camera (and the waist turned): on target", det);

  // 5. Camera pose in the level frame: height above the lower sole.
  std::vector<double> qz(n, 0.0);
  double pos[3], rot[9], height;
  kin_camera_pose(m, qz.data(), (const double[3]){0, 0, 0}, pos, rot, &height);
  ok(std::fabs(height - 0.47) < 1e-12 && std::fabs(rot[0] - M_SQRT1_2) < 1e-12, "camera height 0.19 + 0.28 m at zero");
  kin_model_destroy(m);

  // 6. A leg hanging from a moving link (a pelvis joint): IK with the base's angle.
  Body pb = waist_robot(true);
  m = make(pb.desc(), "legs under a pelvis joint");
  if (m) {
    std::vector<double> qp(kin_njoint(m), 0.0);
    qp[0] = 0.2;  // the pelvis joint pitches both legs
    double worst_leg = 0;
    int leg_flags = 0;
    for (int i = 0; i < 500; i++) {
      double q[6] = {0.3 * U(rng), 0.3 * U(rng), 0.5 * U(rng), 0.2 + 0.6 * (U(rng) + 1), 0.4 * U(rng), 0.3 * U(rng)};
      const int side = i % 2;
      if (side == KIN_RIGHT) q[2] = -q[2], q[3] = -q[3], q[4] = -q[4];
      double p[6], Rf[9], qs[6], p2[6], Rf2[9];
      kin_leg_fk(m, side, q, qp.data(), p, Rf);
      leg_flags |= kin_leg_ik(m, side, p, qp.data(), qs);
      kin_leg_fk(m, side, qs, qp.data(), p2, Rf2);
      worst_leg = std::max(worst_leg, dist(p, p2, 3) + dist(Rf, Rf2, 9));
    }
    snprintf(det, sizeof det, "worst %.3g, flags %d", worst_leg, leg_flags);
    ok(worst_leg < 1e-9 && leg_flags == 0, "leg IK under a pitched pelvis: FK(IK(x)) = x", det);
    kin_model_destroy(m);
  }

  // 7. Descriptions the model must refuse, with the element named.
  std::string e;
  Body cyc = waist_robot(false);
  cyc.parent[0] = 5;  // left hip yaw under the left ankle roll: a cycle
  e = refused(cyc, "cycle");
  ok(!e.empty(), "a cycle in the joint tree: refused", e);
  Body skip = waist_robot(false);
  std::swap(skip.chain_joints[1][1], skip.chain_joints[1][2]);  // left arm listed out of order
  e = refused(skip, "does not hang from");
  ok(!e.empty(), "a chain that is not a path down the tree: refused", e);
  Body squint = waist_robot(false);
  Matrix3d rz = Eigen::AngleAxisd(0.3, Vector3d::UnitZ()).toRotationMatrix();
  for (int k = 0; k < 9; k++) squint.chains[4].tip_rot[k] = rz(k / 3, k % 3);
  e = refused(squint, "perpendicular");
  ok(!e.empty(), "a camera squinting sideways (optical axis not across the tilt axis): refused", e);
  Body shortleg = waist_robot(false);
  shortleg.chain_joints[0].pop_back();
  shortleg.chains[0].n = 5;
  e = refused(shortleg, "needs 6 joints");
  ok(!e.empty(), "a leg of 5 joints: refused", e);
  Body twice = waist_robot(false);
  twice.chain(KIN_HEAD, 0, {20, 21}, Vector3d(0, 0, 0.2));
  e = refused(twice, "second chain");
  ok(!e.empty(), "two heads: refused", e);

  // 8. A model without a chain answers KIN_ENOCHAIN for it.
  Body nohead = waist_robot(false);
  nohead.chains.pop_back();
  nohead.chain_joints.pop_back();
  m = make(nohead.desc(), "no head chain");
  double q2[2];
  ok(m && kin_head_look_at(m, (const double[3]){1, 0, 0}, nullptr, q2) == KIN_ENOCHAIN &&
         kin_head_fk(m, (const double[2]){0, 0}, nullptr, c0, R0) == KIN_ENOCHAIN,
     "no head chain: head functions answer KIN_ENOCHAIN");
  kin_model_destroy(m);
  return tap_done();
}
