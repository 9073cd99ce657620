// kinematics: forward kinematics (product of exponentials of the zero-pose joint axes) over a
// joint tree in any order, analytic 6-joint leg IK, damped least squares arm IK of any length,
// head look-at, centre of mass. See kinematics.h; kin_load.cpp reads a URDF into a kin_desc.
#include "kinematics/kinematics.h"
#include "errmsg.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <new>
#include <string>
#include <vector>

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

const double kAxisTol = 1e-9;  // structure checks: parallel axes, meeting axes (m or unit)

struct Joint {
  int parent;
  Vector3d axis, anchor, com;
  double mass, qmin, qmax;
};

// A pose as a rigid displacement from the zero pose: a reference-frame point x0 goes to R x0 + p.
struct Pose {
  Matrix3d R;
  Vector3d p;
};

// A chain and its tip frame (zero pose, reference frame).
struct Chain {
  bool present = false;
  std::vector<int> idx;
  int base = -1;            // parent joint of the first joint (-1: the torso)
  int tip_joint = -1;       // joint whose link carries the tip: the last one, or one below it
  Vector3d tip = Vector3d::Zero();
  Matrix3d tip_rot = Matrix3d::Identity();
};

// Per leg: what the analytic solver needs, in the reference frame.
struct Leg {
  double sign[6];    // joint angle = sign * canonical angle (about +z, +x, +y, +y, +y, +x)
  Vector3d yaw_pt;   // a point on the hip yaw axis (z of no importance)
  Vector3d hip0;     // hip centre: hip roll and pitch axes meet here
  Vector3d ankle0;   // ankle centre: ankle pitch and roll axes meet here
  double tx, tz;     // hip -> knee axis, xz plane
  double sx, sz;     // knee axis -> ankle, xz plane
  double lt2, ls2, lts, phi;  // |t|^2, |s|^2, |t||s|, knee angle of the straight leg
  double dy;         // ankle centre minus hip centre along the pitch axes (a CAD offset, or 0)
  bool yaw_offset;   // hip yaw axis misses the hip centre
};

}  // namespace

struct kin_model {
  std::vector<Joint> joints;
  std::vector<int> order;    // joints with parents first
  double torso_mass, total_mass;
  Vector3d torso_com, origin;
  Chain leg[2], arm[2], head;
  Leg legs[2];
  double head_sign[2];
  bool head_tilts;   // head of two tilt axes (no pan): look-at solved numerically
};

namespace {

inline bool finite3(const Vector3d &v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

inline Matrix3d rot_axis(const Vector3d &w, double q) { return Eigen::AngleAxisd(q, w).toRotationMatrix(); }

inline Matrix3d rz(double a) { return rot_axis(Vector3d::UnitZ(), a); }
inline Matrix3d ry(double a) { return rot_axis(Vector3d::UnitY(), a); }
inline Matrix3d rx(double a) { return rot_axis(Vector3d::UnitX(), a); }

Matrix3d rpy_to_rot(double roll, double pitch, double yaw) { return rz(yaw) * ry(pitch) * rx(roll); }

void rot_to_rpy(const Matrix3d &R, double *rpy) {
  // R = Rz(yaw) Ry(pitch) Rx(roll)
  rpy[1] = std::atan2(-R(2, 0), std::sqrt(R(0, 0) * R(0, 0) + R(1, 0) * R(1, 0)));
  rpy[0] = std::atan2(R(2, 1), R(2, 2));
  rpy[2] = std::atan2(R(1, 0), R(0, 0));
}

void put_rot(const Matrix3d &R, double *out) {
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) out[3 * i + j] = R(i, j);
}

// Replaces a non-finite angle by 0 (the zero pose) and notes it.
inline double clean(double v, int *flags) {
  if (std::isfinite(v)) return v;
  *flags |= KIN_BAD_INPUT;
  return 0.0;
}

inline double clamp(double v, double lo, double hi) { return v < lo ? lo : (v > hi ? hi : v); }

const Pose kIdentity{Matrix3d::Identity(), Vector3d::Zero()};

// Displacement of joint `last`'s link for all angles qfull, walking parents up to the torso:
// T_j = T_parent * exp(xi_j q_j). last = -1: the torso (identity).
Pose chain_pose(const kin_model *m, int last, const double *qfull, int *flags) {
  int path[KIN_MAXJ];
  int n = 0;
  for (int j = last; j >= 0 && n < KIN_MAXJ; j = m->joints[j].parent) path[n++] = j;
  Pose T = kIdentity;
  for (int k = n - 1; k >= 0; k--) {
    const Joint &J = m->joints[path[k]];
    Matrix3d E = rot_axis(J.axis, clean(qfull[path[k]], flags));
    Vector3d e = J.anchor - E * J.anchor;
    T.p = T.R * e + T.p;
    T.R = T.R * E;
  }
  return T;
}

// Every joint's link displacement for all angles q, parents first.
std::vector<Pose> all_poses(const kin_model *m, const double *q, int *flags) {
  std::vector<Pose> T(m->joints.size());
  for (int j : m->order) {
    const Joint &J = m->joints[j];
    Matrix3d E = rot_axis(J.axis, clean(q[j], flags));
    Vector3d e = J.anchor - E * J.anchor;
    const Pose &P = J.parent < 0 ? kIdentity : T[J.parent];
    T[j].p = P.R * e + P.p;
    T[j].R = P.R * E;
  }
  return T;
}

// Whole-body angles from qbase (NULL: zeros) with the chain's own angles put in.
void fill_full(const kin_model *m, const Chain &c, const double *qc, const double *qbase, double *qfull) {
  const int n = (int)m->joints.size();
  for (int j = 0; j < n; j++) qfull[j] = qbase ? qbase[j] : 0.0;
  if (qc)
    for (size_t k = 0; k < c.idx.size(); k++) qfull[c.idx[k]] = qc[k];
}

// The tip frame of a chain for the whole-body angles qfull: R (axes) and p (origin), torso frame.
Pose tip_pose(const kin_model *m, const Chain &c, const double *qfull, int *flags) {
  Pose T = chain_pose(m, c.tip_joint, qfull, flags);
  return Pose{T.R * c.tip_rot, T.R * c.tip + T.p - m->origin};
}

// The tip frame carried onto the chain's last link for the angles qbase gives the joints between
// them (a neck roll below the tilt): zero-pose coordinates, as Chain::tip and tip_rot.
void tip_on_last(const kin_model *m, const Chain &c, const double *qbase, Vector3d *tip, Matrix3d *rot) {
  *tip = c.tip;
  *rot = c.tip_rot;
  const int last = c.idx.back();
  if (c.tip_joint == last || !qbase) return;
  double q[KIN_MAXJ] = {0};
  for (int j = c.tip_joint; j != last; j = m->joints[j].parent) q[j] = qbase[j];
  int flags = 0;
  const Pose T = chain_pose(m, c.tip_joint, q, &flags);
  *tip = T.R * c.tip + T.p;
  *rot = T.R * c.tip_rot;
}

bool is_axis(const Vector3d &a, int k, double *sign) {
  for (int i = 0; i < 3; i++)
    if (i != k && std::fabs(a[i]) > kAxisTol) return false;
  *sign = a[k] > 0 ? 1.0 : -1.0;
  return std::fabs(std::fabs(a[k]) - 1.0) < kAxisTol;
}

const char *kind_name(int kind) { return kind == KIN_LEG ? "leg" : kind == KIN_ARM ? "arm" : "head"; }

std::string chain_label(const kin_chain &c) {
  std::string s = c.name ? std::string("chain '") + c.name + "'" : std::string("chain");
  s += std::string(" (") + (c.kind == KIN_HEAD ? "" : c.side == KIN_LEFT ? "left " : "right ") + kind_name(c.kind) + ")";
  return s;
}

std::string joint_label(const kin_desc *d, int j) {
  if (d->names && d->names[j]) return std::string("'") + d->names[j] + "'";
  return "#" + std::to_string(j);
}

// The joints of a chain must follow each other down the tree.
bool setup_chain(kin_model *m, const kin_desc *d, const kin_chain &c, Chain *out, char *err, size_t errlen) {
  const std::string what = chain_label(c);
  const int want = c.kind == KIN_LEG ? 6 : c.kind == KIN_HEAD ? 2 : -1;
  if (!c.joints || c.n < 1 || (want > 0 && c.n != want) || (c.kind == KIN_ARM && c.n > KIN_MAXARM)) {
    if (want > 0) hrp_err(err, errlen, "%s: needs %d joints, has %d", what.c_str(), want, c.n);
    else hrp_err(err, errlen, "%s: needs 1..%d joints, has %d", what.c_str(), KIN_MAXARM, c.n);
    return false;
  }
  out->idx.assign(c.joints, c.joints + c.n);
  for (int k = 0; k < c.n; k++) {
    const int j = c.joints[k];
    if (j < 0 || j >= d->njoint) {
      hrp_err(err, errlen, "%s: joint %d: index %d out of range", what.c_str(), k + 1, j);
      return false;
    }
    if (k > 0 && m->joints[j].parent != c.joints[k - 1]) {
      hrp_err(err, errlen, "%s: joint %s does not hang from the chain's previous joint %s", what.c_str(),
              joint_label(d, j).c_str(), joint_label(d, c.joints[k - 1]).c_str());
      return false;
    }
  }
  out->base = m->joints[c.joints[0]].parent;
  out->tip_joint = c.joints[c.n - 1];
  if (c.tip_below != 0) {
    // the tip's link hangs below the last joint: walk up from it to the last joint
    const int t = c.tip_below - 1;
    int j = t;
    while (j >= 0 && j < d->njoint && j != out->tip_joint) j = m->joints[j].parent;
    if (c.kind == KIN_LEG || t < 0 || t >= d->njoint || j != out->tip_joint) {
      hrp_err(err, errlen, "%s: the tip must be on the last joint's link%s", what.c_str(),
              c.kind == KIN_LEG ? " (a leg's analytic IK)" : " or below it");
      return false;
    }
    out->tip_joint = t;
  }
  out->tip = Vector3d(c.tip[0], c.tip[1], c.tip[2]);
  for (int i = 0; i < 3; i++)
    for (int k = 0; k < 3; k++) out->tip_rot(i, k) = c.tip_rot[3 * i + k];
  if (!finite3(out->tip) || !out->tip_rot.allFinite() ||
      (out->tip_rot.transpose() * out->tip_rot - Matrix3d::Identity()).norm() > 1e-6 || out->tip_rot.determinant() < 0) {
    hrp_err(err, errlen, "%s: the tip frame is not a finite point with a rotation", what.c_str());
    return false;
  }
  out->present = true;
  return true;
}

bool setup_leg(kin_model *m, const kin_desc *d, const kin_chain &c, char *err, size_t errlen) {
  const std::string what = chain_label(c);
  Leg &L = m->legs[c.side];
  const Chain &C = m->leg[c.side];
  static const int canon[6] = {2, 0, 1, 1, 1, 0};
  static const char *names[6] = {"hip yaw", "hip roll", "hip pitch", "knee", "ankle pitch", "ankle roll"};
  for (int k = 0; k < 6; k++) {
    if (!is_axis(m->joints[C.idx[k]].axis, canon[k], &L.sign[k])) {
      hrp_err(err, errlen, "%s: %s joint %s: axis must be along %c for the analytic leg IK", what.c_str(), names[k],
              joint_label(d, C.idx[k]).c_str(), "xyz"[canon[k]]);
      return false;
    }
  }
  const Vector3d &ry_ = m->joints[C.idx[0]].anchor, &rr = m->joints[C.idx[1]].anchor,
                 &rp = m->joints[C.idx[2]].anchor, &rk = m->joints[C.idx[3]].anchor,
                 &rap = m->joints[C.idx[4]].anchor, &rar = m->joints[C.idx[5]].anchor;
  if (std::fabs(rr.z() - rp.z()) > kAxisTol) {
    hrp_err(err, errlen, "%s: hip roll and hip pitch axes do not meet (z %g vs %g)", what.c_str(), rr.z(), rp.z());
    return false;
  }
  if (std::fabs(rap.z() - rar.z()) > kAxisTol) {
    hrp_err(err, errlen, "%s: ankle pitch and roll axes do not meet (z %g vs %g)", what.c_str(), rap.z(), rar.z());
    return false;
  }
  L.yaw_pt = ry_;
  L.hip0 = Vector3d(rp.x(), rr.y(), rr.z());
  L.ankle0 = Vector3d(rap.x(), rar.y(), rap.z());
  // the shank may sit off the hip centre along the pitch axes (the Hubo's CAD: 0.8 mm)
  L.dy = L.ankle0.y() - L.hip0.y();
  L.tx = rk.x() - L.hip0.x();
  L.tz = rk.z() - L.hip0.z();
  L.sx = L.ankle0.x() - rk.x();
  L.sz = L.ankle0.z() - rk.z();
  L.lt2 = L.tx * L.tx + L.tz * L.tz;
  L.ls2 = L.sx * L.sx + L.sz * L.sz;
  L.lts = std::sqrt(L.lt2 * L.ls2);
  if (L.lts < 1e-6) {
    hrp_err(err, errlen, "%s: thigh or tibia has no length", what.c_str());
    return false;
  }
  // t . Ry(d) s = P cos d + Q sin d = |t||s| cos(d - phi)
  L.phi = std::atan2(L.tx * L.sz - L.tz * L.sx, L.tx * L.sx + L.tz * L.sz);
  L.yaw_offset = std::hypot(L.hip0.x() - ry_.x(), L.hip0.y() - ry_.y()) > 1e-12;
  return true;
}

// A head is either pan (z) then tilt (y), solved in closed form, or two tilt axes (both in the
// horizontal plane, not parallel, like the Hubo's NK1/NK2 at +-45 deg), solved numerically.
bool setup_head(kin_model *m, const kin_desc *d, const kin_chain &c, char *err, size_t errlen) {
  const std::string what = chain_label(c);
  const Chain &H = m->head;
  const Vector3d &a0 = m->joints[H.idx[0]].axis, &a1 = m->joints[H.idx[1]].axis;
  m->head_tilts = std::fabs(a0.z()) < kAxisTol && std::fabs(a1.z()) < kAxisTol && a0.cross(a1).norm() > 0.1;
  if (m->head_tilts) {
    // the optical axis must not lie along either axis: each tilt must move it
    Vector3d opt = H.tip_rot.col(0);
    if (opt.cross(a0).norm() < 0.1 || opt.cross(a1).norm() < 0.1) {
      hrp_err(err, errlen, "%s: the camera's optical axis (the tip frame's x) lies along a tilt axis", what.c_str());
      return false;
    }
    return true;
  }
  if (!is_axis(a0, 2, &m->head_sign[0])) {
    hrp_err(err, errlen, "%s: pan joint %s: axis must be along z for look-at (or two horizontal tilt axes)",
            what.c_str(), joint_label(d, H.idx[0]).c_str());
    return false;
  }
  if (!is_axis(a1, 1, &m->head_sign[1])) {
    hrp_err(err, errlen, "%s: tilt joint %s: axis must be along y for look-at", what.c_str(),
            joint_label(d, H.idx[1]).c_str());
    return false;
  }
  if (std::fabs(H.tip_rot(1, 0)) > 1e-9) {
    hrp_err(err, errlen, "%s: the camera's optical axis (the tip frame's x) must be perpendicular to the tilt axis",
            what.c_str());
    return false;
  }
  return true;
}

// One pass of the analytic solution for a given hip yaw (canonical) `a` used to place the hip
// centre when the yaw axis misses it. R: orientation of the last link, A: ankle centre (both
// reference frame, the leg's base at its zero pose). Writes canonical angles c[6]; returns flags.
int leg_solve(const Leg &L, const Matrix3d &R, const Vector3d &A, double a, double *c) {
  int flags = 0;
  Vector3d H = L.hip0;
  if (L.yaw_offset) {
    Vector3d off(L.hip0.x() - L.yaw_pt.x(), L.hip0.y() - L.yaw_pt.y(), 0.0);
    H = Vector3d(L.yaw_pt.x(), L.yaw_pt.y(), L.hip0.z()) + rz(a) * off;
  }
  Vector3d u = R.transpose() * (A - H);  // hip -> ankle, foot frame
  double r = u.norm();
  const double dy2 = L.dy * L.dy;
  double rmax2 = L.lt2 + L.ls2 + 2.0 * L.lts + dy2, rmin2 = L.lt2 + L.ls2 - 2.0 * L.lts + dy2;
  double r2 = r * r;
  if (r2 > rmax2 || r2 < rmin2) {
    // a straight leg's own pose may land a rounding error beyond the reach: not a miss
    if (r2 > rmax2 * (1 + 1e-12) || r2 < rmin2 * (1 - 1e-12)) flags |= KIN_UNREACHABLE;
    double rc = std::sqrt(clamp(r2, rmin2, rmax2));
    if (r > 1e-12) {
      u *= rc / r;
    } else {
      u = Vector3d(0, 0, -rc);
    }
    r2 = rc * rc;
  }
  double cosk = clamp((r2 - dy2 - L.lt2 - L.ls2) / (2.0 * L.lts), -1.0, 1.0);
  double d = L.phi + std::acos(cosk);  // the knee bends with the ankle going back
  // w = t + Ry(d) s, xz plane
  double sd = std::sin(d), cd = std::cos(d);
  double wx = L.tx + L.sx * cd + L.sz * sd;
  double wz = L.tz - L.sx * sd + L.sz * cd;
  // u = Rx(-f) Ry(-g) w with Ry(-g) w = (u.x, dy, w'z): Rx(-f) turns (dy, w'z) into (u.y, u.z).
  // Take the ankle roll branch with w'z of the sign of u.z (usually negative: hip above ankle).
  double yz = std::sqrt(u.y() * u.y() + u.z() * u.z());
  double pz = std::sqrt(std::max(yz * yz - dy2, 0.0));
  double wpz = u.z() > 0 ? pz : -pz;
  double f = 0.0;
  if (yz >= 1e-12) {
    // (the plain form without an offset keeps the small bodies' numbers bit for bit)
    f = L.dy == 0.0 ? std::atan2(u.y() / wpz, u.z() / wpz)
                    : std::remainder(std::atan2(wpz, L.dy) - std::atan2(u.z(), u.y()), 2.0 * M_PI);
  }
  double g = std::atan2(wx, wz) - std::atan2(u.x(), wpz);  // Ry adds its angle to atan2(x, z)
  g = std::remainder(g, 2.0 * M_PI);
  double e = g - d;
  // Rz(a) Rx(b) Ry(c) = R Rx(-f) Ry(-g)
  Matrix3d Rh = R * rx(-f) * ry(-g);
  c[0] = std::atan2(-Rh(0, 1), Rh(1, 1));
  c[1] = std::atan2(Rh(2, 1), std::sqrt(Rh(0, 1) * Rh(0, 1) + Rh(1, 1) * Rh(1, 1)));
  c[2] = std::atan2(-Rh(2, 0), Rh(2, 2));
  c[3] = d;
  c[4] = e;
  c[5] = f;
  return flags;
}

bool finite_all(const double *v, int n) {
  for (int i = 0; i < n; i++)
    if (!std::isfinite(v[i])) return false;
  return true;
}

// Parents-first order of the joints; false (with the joint named) if the parents form a cycle.
bool sort_joints(kin_model *m, const kin_desc *d, char *err, size_t errlen) {
  const int n = (int)m->joints.size();
  std::vector<int> depth(n, 0);
  for (int j = 0; j < n; j++) {
    int k = 0;
    for (int p = m->joints[j].parent; p >= 0; p = m->joints[p].parent) {
      if (++k > n) {
        hrp_err(err, errlen, "joint %s: its parents form a cycle", joint_label(d, j).c_str());
        return false;
      }
    }
    depth[j] = k;
  }
  m->order.resize(n);
  for (int j = 0; j < n; j++) m->order[j] = j;
  std::stable_sort(m->order.begin(), m->order.end(), [&](int a, int b) { return depth[a] < depth[b]; });
  return true;
}

const Chain *find_chain(const kin_model *m, int kind, int side) {
  if (side != KIN_LEFT && side != KIN_RIGHT) return nullptr;
  const Chain *c = kind == KIN_LEG ? &m->leg[side] : kind == KIN_ARM ? &m->arm[side] : kind == KIN_HEAD ? &m->head : nullptr;
  return c && c->present ? c : nullptr;
}

}  // namespace

extern "C" {

int kin_model_create(const kin_desc *d, kin_model **out, char *err, size_t errlen) {
  if (!d || !out) {
    hrp_err(err, errlen, "kin_model_create: NULL argument");
    return KIN_EINVAL;
  }
  *out = nullptr;
  if (d->njoint <= 0 || d->njoint > KIN_MAXJ || !d->parent || !d->axis || !d->anchor || !d->mass || !d->com ||
      d->nchain < 0 || (d->nchain > 0 && !d->chains)) {
    hrp_err(err, errlen, "kin_model_create: need 1..%d joints with parent, axis, anchor, mass, com", KIN_MAXJ);
    return KIN_EINVAL;
  }
  kin_model *m = new (std::nothrow) kin_model();
  if (!m) {
    hrp_err(err, errlen, "kin_model_create: out of memory");
    return KIN_EMODEL;
  }
  auto fail = [&]() {
    delete m;
    return KIN_EMODEL;
  };
  m->joints.resize(d->njoint);
  m->total_mass = d->torso_mass;
  for (int j = 0; j < d->njoint; j++) {
    Joint &J = m->joints[j];
    J.parent = d->parent[j];
    J.axis = Vector3d(d->axis[3 * j], d->axis[3 * j + 1], d->axis[3 * j + 2]);
    J.anchor = Vector3d(d->anchor[3 * j], d->anchor[3 * j + 1], d->anchor[3 * j + 2]);
    J.com = Vector3d(d->com[3 * j], d->com[3 * j + 1], d->com[3 * j + 2]);
    J.mass = d->mass[j];
    J.qmin = d->qmin ? d->qmin[j] : -INFINITY;
    J.qmax = d->qmax ? d->qmax[j] : INFINITY;
    const char *bad = nullptr;
    if (J.parent < -1 || J.parent >= d->njoint || J.parent == j) bad = "parent must be -1 (torso) or another joint";
    else if (!finite3(J.axis) || J.axis.norm() < 1e-9) bad = "axis is not a finite non-zero vector";
    else if (!finite3(J.anchor) || !finite3(J.com)) bad = "anchor or com not finite";
    else if (!std::isfinite(J.mass) || J.mass < 0) bad = "mass must be finite and >= 0";
    else if (std::isnan(J.qmin) || std::isnan(J.qmax) || J.qmin > J.qmax) bad = "limits: need min <= max";
    if (bad) {
      hrp_err(err, errlen, "joint %s: %s", joint_label(d, j).c_str(), bad);
      return fail();
    }
    J.axis.normalize();
    m->total_mass += J.mass;
  }
  if (!sort_joints(m, d, err, errlen)) return fail();
  m->torso_mass = d->torso_mass;
  m->torso_com = Vector3d(d->torso_com[0], d->torso_com[1], d->torso_com[2]);
  m->origin = Vector3d(d->origin[0], d->origin[1], d->origin[2]);
  if (!std::isfinite(d->torso_mass) || d->torso_mass < 0 || !finite3(m->torso_com) || !finite3(m->origin) ||
      !(m->total_mass > 0)) {
    hrp_err(err, errlen, "torso mass/com or origin not finite, or total mass not positive");
    return fail();
  }
  for (int i = 0; i < d->nchain; i++) {
    const kin_chain &c = d->chains[i];
    const bool sided = c.kind == KIN_LEG || c.kind == KIN_ARM;
    if ((!sided && c.kind != KIN_HEAD) || (sided && c.side != KIN_LEFT && c.side != KIN_RIGHT)) {
      hrp_err(err, errlen, "%s: unknown kind %d or side %d", chain_label(c).c_str(), c.kind, c.side);
      return fail();
    }
    Chain *C = c.kind == KIN_LEG ? &m->leg[c.side] : c.kind == KIN_ARM ? &m->arm[c.side] : &m->head;
    if (C->present) {
      hrp_err(err, errlen, "%s: a second chain of this kind", chain_label(c).c_str());
      return fail();
    }
    if (!setup_chain(m, d, c, C, err, errlen)) return fail();
    if (c.kind == KIN_LEG && !setup_leg(m, d, c, err, errlen)) return fail();
    if (c.kind == KIN_HEAD && !setup_head(m, d, c, err, errlen)) return fail();
  }
  *out = m;
  return 0;
}

void kin_model_destroy(kin_model *m) { delete m; }

int kin_njoint(const kin_model *m) { return m ? (int)m->joints.size() : KIN_EINVAL; }

double kin_total_mass(const kin_model *m) { return m ? m->total_mass : 0.0; }

int kin_joint_info(const kin_model *m, int j, double *axis, double *qmin, double *qmax) {
  if (!m || !axis || j < 0 || j >= (int)m->joints.size()) return KIN_EINVAL;
  const Joint &J = m->joints[j];
  for (int k = 0; k < 3; k++) axis[k] = J.axis[k];
  if (qmin) *qmin = J.qmin;
  if (qmax) *qmax = J.qmax;
  return 0;
}

int kin_chain_joints(const kin_model *m, int kind, int side, int *idx) {
  if (!m) return KIN_EINVAL;
  const Chain *c = find_chain(m, kind, kind == KIN_HEAD ? 0 : side);
  if (!c) return KIN_ENOCHAIN;
  if (idx)
    for (size_t k = 0; k < c->idx.size(); k++) idx[k] = c->idx[k];
  return (int)c->idx.size();
}

int kin_link_poses(const kin_model *m, const double *q, double *out) {
  if (!m || !q || !out) return KIN_EINVAL;
  int flags = 0;
  const int n = (int)m->joints.size();
  const std::vector<Pose> T = all_poses(m, q, &flags);
  for (int j = 0; j < n; j++) {
    put_rot(T[j].R, out + 12 * j);
    Vector3d o = T[j].R * m->origin + T[j].p - m->origin;  // link frame origin, torso frame
    for (int k = 0; k < 3; k++) out[12 * j + 9 + k] = o[k];
  }
  return flags;
}

// Forward kinematics of chain (kind, side) from the chain's own angles q (and qbase above it): the
// tip's position into pos (3), its rotation into rot (9, if not NULL) and *tip (if not NULL). A flag
// set, or KIN_ENOCHAIN (a side the body lacks) / KIN_EINVAL (a side that is not 0 or 1).
static int chain_fk(const kin_model *m, int kind, int side, const double *q, const double *qbase, double *pos,
                    double *rot, Pose *tip) {
  const Chain *c = find_chain(m, kind, side);
  if (!c) return side == 0 || side == 1 ? KIN_ENOCHAIN : KIN_EINVAL;
  int flags = 0;
  double qfull[KIN_MAXJ];
  fill_full(m, *c, q, qbase, qfull);
  Pose T = tip_pose(m, *c, qfull, &flags);
  for (int k = 0; k < 3; k++) pos[k] = T.p[k];
  if (rot) put_rot(T.R, rot);
  if (tip) *tip = T;
  return flags;
}

int kin_leg_fk(const kin_model *m, int side, const double *q6, const double *qbase, double *pose, double *rot) {
  if (!m || !q6 || !pose) return KIN_EINVAL;
  Pose F;
  int flags = chain_fk(m, KIN_LEG, side, q6, qbase, pose, rot, &F);
  if (flags >= 0) rot_to_rpy(F.R, pose + 3);
  return flags;
}

int kin_arm_fk(const kin_model *m, int side, const double *qn, const double *qbase, double *pos, double *rot) {
  if (!m || !qn || !pos) return KIN_EINVAL;
  return chain_fk(m, KIN_ARM, side, qn, qbase, pos, rot, nullptr);
}

int kin_head_fk(const kin_model *m, const double *q2, const double *qbase, double *pos, double *rot) {
  if (!m || !q2 || !pos) return KIN_EINVAL;
  return chain_fk(m, KIN_HEAD, 0, q2, qbase, pos, rot, nullptr);
}

int kin_camera_pose(const kin_model *m, const double *q, const double *rpy, double *pos, double *rot,
                    double *height) {
  if (!m || !q || !rpy || !pos || !rot) return KIN_EINVAL;
  const Chain *c = find_chain(m, KIN_HEAD, 0);
  if (!c) return KIN_ENOCHAIN;
  int flags = 0;
  double roll = clean(rpy[0], &flags), pitch = clean(rpy[1], &flags);
  Matrix3d Rl = ry(pitch) * rx(roll);
  Pose C = tip_pose(m, *c, q, &flags);
  Vector3d p = Rl * C.p;
  for (int k = 0; k < 3; k++) pos[k] = p[k];
  put_rot(Rl * C.R, rot);
  if (height) {
    double low = INFINITY;
    for (int s = 0; s < 2; s++) {
      if (!m->leg[s].present) continue;
      double z = (Rl * tip_pose(m, m->leg[s], q, &flags).p).z();
      if (z < low) low = z;
    }
    *height = std::isfinite(low) ? p.z() - low : p.z();
  }
  return flags;
}

int kin_com(const kin_model *m, const double *q, double *com) {
  if (!m || !q || !com) return KIN_EINVAL;
  int flags = 0;
  const int n = (int)m->joints.size();
  const std::vector<Pose> T = all_poses(m, q, &flags);
  Vector3d sum = m->torso_mass * m->torso_com;
  for (int j = 0; j < n; j++) sum += m->joints[j].mass * (T[j].R * m->joints[j].com + T[j].p);
  Vector3d c = sum / m->total_mass - m->origin;
  for (int k = 0; k < 3; k++) com[k] = c[k];
  return flags;
}

int kin_leg_ik(const kin_model *m, int side, const double *pose, const double *qbase, double *q6) {
  if (!m || !pose || !q6) return KIN_EINVAL;
  const Chain *ch = find_chain(m, KIN_LEG, side);
  if (!ch) return side == 0 || side == 1 ? KIN_ENOCHAIN : KIN_EINVAL;
  const Leg &L = m->legs[side];
  int flags = 0;
  // The leg's base (a waist may move it), from qbase.
  Pose B = kIdentity;
  if (ch->base >= 0 && qbase) B = chain_pose(m, ch->base, qbase, &flags);
  // Non-finite components fall back to the zero-pose foot pose.
  double p[6];
  const Vector3d zero = B.R * ch->tip + B.p - m->origin;
  double zrpy[3];
  rot_to_rpy(B.R * ch->tip_rot, zrpy);
  for (int k = 0; k < 6; k++) {
    double z0 = k < 3 ? zero[k] : zrpy[k - 3];
    p[k] = std::isfinite(pose[k]) ? pose[k] : (flags |= KIN_BAD_INPUT, z0);
  }
  // The last link's displacement relative to the base: R, and the sole point F on it.
  Matrix3d R = B.R.transpose() * rpy_to_rot(p[3], p[4], p[5]) * ch->tip_rot.transpose();
  Vector3d F = B.R.transpose() * (Vector3d(p[0], p[1], p[2]) + m->origin - B.p);
  Vector3d A = F - R * (ch->tip - L.ankle0);
  double c[6];
  int f = leg_solve(L, R, A, 0.0, c);
  if (L.yaw_offset) {
    // The hip centre moves with the yaw: a fixed point, contracting by |offset| / leg length.
    for (int it = 0; it < 20; it++) {
      double prev = c[0];
      f = leg_solve(L, R, A, c[0], c);
      if (std::fabs(c[0] - prev) < 1e-15) break;
    }
  }
  flags |= f;
  for (int k = 0; k < 6; k++) {
    const Joint &J = m->joints[ch->idx[k]];
    double q = L.sign[k] * std::remainder(c[k], 2.0 * M_PI);
    if (!std::isfinite(q)) {
      q = 0.0;
      flags |= KIN_BAD_INPUT;
    }
    if (q < J.qmin || q > J.qmax) {
      q = clamp(q, J.qmin, J.qmax);
      flags |= KIN_JOINT_LIMIT;
    }
    q6[k] = q;
  }
  return flags;
}

int kin_arm_ik(const kin_model *m, int side, const double *pos, const double *qbase, double *qn) {
  if (!m || !pos || !qn) return KIN_EINVAL;
  const Chain *ch = find_chain(m, KIN_ARM, side);
  if (!ch) return side == 0 || side == 1 ? KIN_ENOCHAIN : KIN_EINVAL;
  int flags = 0;
  const int n = (int)ch->idx.size();
  double q[KIN_MAXARM];
  for (int k = 0; k < n; k++) q[k] = clean(qn[k], &flags);
  Pose B = kIdentity;
  if (ch->base >= 0 && qbase) B = chain_pose(m, ch->base, qbase, &flags);
  // target in the base's zero-pose frame (reference coordinates)
  Vector3d target, tip;
  Matrix3d tip_rot;
  tip_on_last(m, *ch, qbase, &tip, &tip_rot);
  const Vector3d h0 = B.R * tip + B.p - m->origin;  // hand at the arm's zero pose
  for (int k = 0; k < 3; k++) target[k] = std::isfinite(pos[k]) ? pos[k] : (flags |= KIN_BAD_INPUT, h0[k]);
  target = B.R.transpose() * (target + m->origin - B.p);
  const double lambda = 1e-4;
  double err_norm = INFINITY;
  Eigen::MatrixXd Jac(3, n), A(n, n);
  Eigen::VectorXd dq(n);
  for (int it = 0; it < 100; it++) {
    // Current pose of each arm joint: its axis and anchor, and the hand.
    Pose T = kIdentity;
    Vector3d w[KIN_MAXARM], r[KIN_MAXARM];
    for (int k = 0; k < n; k++) {
      const Joint &J = m->joints[ch->idx[k]];
      w[k] = T.R * J.axis;
      r[k] = T.R * J.anchor + T.p;
      Matrix3d E = rot_axis(J.axis, q[k]);
      T.p = T.R * (J.anchor - E * J.anchor) + T.p;
      T.R = T.R * E;
    }
    Vector3d h = T.R * tip + T.p;
    for (int k = 0; k < n; k++) Jac.col(k) = w[k].cross(h - r[k]);
    Vector3d e = target - h;
    err_norm = e.norm();
    if (err_norm < 1e-10) break;
    A = Jac.transpose() * Jac + lambda * Eigen::MatrixXd::Identity(n, n);
    dq = A.ldlt().solve(Jac.transpose() * e);
    if (!dq.allFinite()) break;
    double step = dq.norm();
    if (step > 0.3) dq *= 0.3 / step;
    for (int k = 0; k < n; k++) {
      const Joint &J = m->joints[ch->idx[k]];
      q[k] = clamp(std::remainder(q[k] + dq[k], 2.0 * M_PI), J.qmin, J.qmax);
    }
    if (step < 1e-13) break;
  }
  if (err_norm > 1e-4) flags |= KIN_UNREACHABLE;
  for (int k = 0; k < n; k++) qn[k] = std::isfinite(q[k]) ? q[k] : 0.0;
  return flags;
}

}  // extern "C"

namespace {

// Two tilt axes: Gauss-Newton on the unit direction to the target against the optical axis (both
// in the torso frame), damped, within the joint limits. Each tilt turns the optical axis about its
// own axis, so the Jacobian column is axis x d. Unreachable: the nearest direction in the limits.
int head_look_tilts(const kin_model *m, const Chain &ch, const Vector3d &t, const double *qbase, double *q2) {
  int flags = 0;
  double q[2] = {0.0, 0.0}, qfull[KIN_MAXJ];
  double err_norm = INFINITY;
  for (int it = 0; it < 50; it++) {
    fill_full(m, ch, q, qbase, qfull);
    Pose C = tip_pose(m, ch, qfull, &flags);
    Vector3d u = t - C.p;
    if (u.norm() < 1e-9) break;
    u.normalize();
    Vector3d d = C.R.col(0);
    Vector3d e = u - d;
    err_norm = e.norm();
    if (err_norm < 1e-10) break;
    Eigen::Matrix<double, 3, 2> J;
    for (int k = 0; k < 2; k++) {
      Pose L = chain_pose(m, ch.idx[k], qfull, &flags);
      J.col(k) = (L.R * m->joints[ch.idx[k]].axis).cross(d);
    }
    Eigen::Matrix2d A = J.transpose() * J + 1e-6 * Eigen::Matrix2d::Identity();
    Eigen::Vector2d dq = A.ldlt().solve(J.transpose() * e);
    // a joint at its limit and pushed beyond stays there; the other one alone takes the step
    for (int k = 0; k < 2; k++) {
      const Joint &Jk = m->joints[ch.idx[k]];
      if ((q[k] >= Jk.qmax && dq[k] > 0) || (q[k] <= Jk.qmin && dq[k] < 0)) {
        const int o = 1 - k;
        dq[k] = 0.0;
        dq[o] = J.col(o).dot(e) / (J.col(o).squaredNorm() + 1e-6);
        break;
      }
    }
    for (int k = 0; k < 2; k++) {
      const Joint &Jk = m->joints[ch.idx[k]];
      q[k] = clamp(q[k] + clamp(dq[k], -0.3, 0.3), Jk.qmin, Jk.qmax);
    }
  }
  if (err_norm > 1e-4) flags |= KIN_UNREACHABLE;
  for (int k = 0; k < 2; k++) q2[k] = std::isfinite(q[k]) ? q[k] : 0.0;
  return flags;
}

}  // namespace

extern "C" {

int kin_head_look_at(const kin_model *m, const double *target, const double *qbase, double *q2) {
  if (!m || !target || !q2) return KIN_EINVAL;
  const Chain *ch = find_chain(m, KIN_HEAD, 0);
  if (!ch) return KIN_ENOCHAIN;
  int flags = 0;
  if (!finite_all(target, 3)) {
    q2[0] = q2[1] = 0.0;
    return KIN_BAD_INPUT;
  }
  if (m->head_tilts) return head_look_tilts(m, *ch, Vector3d(target[0], target[1], target[2]), qbase, q2);
  Pose B = kIdentity;
  if (ch->base >= 0 && qbase) B = chain_pose(m, ch->base, qbase, &flags);
  const Joint &P = m->joints[ch->idx[0]], &Tl = m->joints[ch->idx[1]];
  Vector3d tip;
  Matrix3d tip_rot;
  tip_on_last(m, *ch, qbase, &tip, &tip_rot);
  // the target in the head base's zero-pose frame
  Vector3d p = B.R.transpose() * (Vector3d(target[0], target[1], target[2]) + m->origin - B.p);
  // Pan: the optical axis (in a plane at lateral offset e from the pan axis: the tilt turns about
  // y, and the optical axis has no y part) must pass over the target.
  double dx = p.x() - P.anchor.x(), dy = p.y() - P.anchor.y();
  double rho = std::hypot(dx, dy);
  double e = tip.y() - P.anchor.y();
  double ratio = rho > 1e-12 ? e / rho : 0.0;
  if (std::fabs(ratio) > 1.0) flags |= KIN_UNREACHABLE;
  double a = std::atan2(dy, dx) - std::asin(clamp(ratio, -1.0, 1.0));
  // Tilt: in the panned frame, xz plane about the tilt axis, find th with the target on the ray
  // from the camera centre c along d (both turned by Ry(th)): Ry(-th) t - c parallel to d, i.e.
  // A cos th - B sin th = k with A = X dz - Z dx, B = X dx + Z dz, k = cx dz - cz dx.
  Vector3d pa(P.anchor.x(), P.anchor.y(), 0);
  Vector3d pl = rz(-a) * (p - pa) + pa;
  double X = pl.x() - Tl.anchor.x(), Z = pl.z() - Tl.anchor.z();
  double cx = tip.x() - Tl.anchor.x(), cz = tip.z() - Tl.anchor.z();
  double ddx = tip_rot(0, 0), ddz = tip_rot(2, 0);
  const double dn = std::hypot(ddx, ddz);
  ddx /= dn;
  ddz /= dn;
  double Ac = X * ddz - Z * ddx, Bc = X * ddx + Z * ddz, k = cx * ddz - cz * ddx;
  double Rn = std::hypot(Ac, Bc);
  double cr = Rn > 1e-12 ? k / Rn : 2.0;
  if (std::fabs(cr) > 1.0) flags |= KIN_UNREACHABLE;
  double phi = std::atan2(Bc, Ac), ac = std::acos(clamp(cr, -1.0, 1.0));
  double th = 0.0, best = -INFINITY;
  for (double cand : {-phi + ac, -phi - ac}) {
    // distance along the optical axis to the target: (Ry(-th) t - c) . d, the larger one wins
    double ux = X * std::cos(cand) - Z * std::sin(cand) - cx, uz = X * std::sin(cand) + Z * std::cos(cand) - cz;
    double t = ux * ddx + uz * ddz;
    if (t > best) {
      best = t;
      th = cand;
    }
  }
  double q[2] = {m->head_sign[0] * std::remainder(a, 2 * M_PI), m->head_sign[1] * std::remainder(th, 2 * M_PI)};
  const Joint *J[2] = {&P, &Tl};
  for (int i = 0; i < 2; i++) {
    if (q[i] < J[i]->qmin || q[i] > J[i]->qmax) {
      q[i] = clamp(q[i], J[i]->qmin, J[i]->qmax);
      flags |= KIN_UNREACHABLE | KIN_JOINT_LIMIT;
    }
    q2[i] = std::isfinite(q[i]) ? q[i] : 0.0;
  }
  return flags;
}

}  // extern "C"
