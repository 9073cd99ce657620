// kinematics: forward kinematics (product of exponentials of the zero-pose joint axes),
// analytic 6-joint leg IK, arm and head IK, centre of mass. See kinematics.h.
#include "kinematics/kinematics.h"

#include <Eigen/Dense>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <new>
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

// Per leg: what the analytic solver needs, in the reference frame.
struct Leg {
  int idx[6];
  double sign[6];    // joint angle = sign * canonical angle (about +z, +x, +y, +y, +y, +x)
  Vector3d yaw_pt;   // a point on the hip yaw axis (z of no importance)
  Vector3d hip0;     // hip centre: hip roll and pitch axes meet here
  Vector3d ankle0;   // ankle centre: ankle pitch and roll axes meet here
  Vector3d sole0;    // foot-frame origin
  double tx, tz;     // hip -> knee axis, xz plane
  double sx, sz;     // knee axis -> ankle, xz plane
  double lt2, ls2, lts, phi;  // |t|^2, |s|^2, |t||s|, knee angle of the straight leg
  bool yaw_offset;   // hip yaw axis misses the hip centre
};

struct Pose {
  Matrix3d R;
  Vector3d p;
};

}  // namespace

struct kin_model {
  std::vector<Joint> joints;
  double torso_mass, total_mass;
  Vector3d torso_com, origin;
  Leg leg[2];
  int arm[2][3];
  Vector3d hand[2];
  int head[2];
  double head_sign[2];
  bool head_ok;
  Vector3d camera;
};

namespace {

void set_err(char *err, size_t errlen, const char *fmt, ...) {
  if (!err || errlen == 0) return;
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(err, errlen, fmt, ap);
  va_end(ap);
}

inline bool finite3(const Vector3d &v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

inline Matrix3d rot_axis(const Vector3d &w, double q) {
  return Eigen::AngleAxisd(q, w).toRotationMatrix();
}

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

// Pose of a chain of joints given as indices ending at `last`, walking parents up to the torso.
// T_j = T_parent * exp(xi_j q_j); a point x0 of link j at the zero pose goes to R x0 + p.
Pose chain_pose(const kin_model *m, int last, const double *qfull, int *flags) {
  int path[64];
  int n = 0;
  for (int j = last; j >= 0 && n < 64; j = m->joints[j].parent) path[n++] = j;
  Pose T{Matrix3d::Identity(), Vector3d::Zero()};
  for (int k = n - 1; k >= 0; k--) {
    const Joint &J = m->joints[path[k]];
    Matrix3d E = rot_axis(J.axis, clean(qfull[path[k]], flags));
    Vector3d e = J.anchor - E * J.anchor;
    T.p = T.R * e + T.p;
    T.R = T.R * E;
  }
  return T;
}

// Every joint's link pose (rotation and the displacement of reference points) for all angles q;
// parents come before their children in the joint list.
std::vector<Pose> all_poses(const kin_model *m, const double *q, int *flags) {
  const int n = (int)m->joints.size();
  std::vector<Pose> T(n);
  for (int j = 0; j < n; j++) {
    const Joint &J = m->joints[j];
    Matrix3d E = rot_axis(J.axis, clean(q[j], flags));
    Vector3d e = J.anchor - E * J.anchor;
    Pose P = J.parent < 0 ? Pose{Matrix3d::Identity(), Vector3d::Zero()} : T[J.parent];
    T[j].p = P.R * e + P.p;
    T[j].R = P.R * E;
  }
  return T;
}

// Same as chain_pose for a limb given by its own angles (limb order) instead of all joints.
Pose limb_pose(const kin_model *m, const int *idx, int n, const double *qlimb, int *flags) {
  double qfull[64] = {0};
  for (int k = 0; k < n; k++) qfull[idx[k]] = qlimb[k];
  return chain_pose(m, idx[n - 1], qfull, flags);
}

bool is_axis(const Vector3d &a, int k, double *sign) {
  for (int i = 0; i < 3; i++)
    if (i != k && std::fabs(a[i]) > kAxisTol) return false;
  *sign = a[k] > 0 ? 1.0 : -1.0;
  return std::fabs(std::fabs(a[k]) - 1.0) < kAxisTol;
}

bool check_chain(const kin_desc *d, const int *idx, int n, char *err, size_t errlen, const char *what) {
  for (int k = 0; k < n; k++) {
    if (idx[k] < 0 || idx[k] >= d->njoint) {
      set_err(err, errlen, "%s joint %d: index %d out of range", what, k + 1, idx[k]);
      return false;
    }
    int want = k == 0 ? -1 : idx[k - 1];
    if (d->parent[idx[k]] != want) {
      set_err(err, errlen, "%s joint %d (index %d): parent must be %d (%s)", what, k + 1, idx[k], want,
              k == 0 ? "the torso" : "the previous joint");
      return false;
    }
  }
  return true;
}

bool setup_leg(kin_model *m, const kin_desc *d, int side, char *err, size_t errlen) {
  Leg &L = m->leg[side];
  const char *what = side == KIN_LEFT ? "left leg" : "right leg";
  if (!check_chain(d, d->leg[side], 6, err, errlen, what)) return false;
  static const int canon[6] = {2, 0, 1, 1, 1, 0};
  static const char *names[6] = {"hip yaw", "hip roll", "hip pitch", "knee", "ankle pitch", "ankle roll"};
  for (int k = 0; k < 6; k++) {
    L.idx[k] = d->leg[side][k];
    if (!is_axis(m->joints[L.idx[k]].axis, canon[k], &L.sign[k])) {
      set_err(err, errlen, "%s: %s axis must be along %c", what, names[k], "xyz"[canon[k]]);
      return false;
    }
  }
  const Vector3d &ry_ = m->joints[L.idx[0]].anchor, &rr = m->joints[L.idx[1]].anchor,
                 &rp = m->joints[L.idx[2]].anchor, &rk = m->joints[L.idx[3]].anchor,
                 &rap = m->joints[L.idx[4]].anchor, &rar = m->joints[L.idx[5]].anchor;
  if (std::fabs(rr.z() - rp.z()) > kAxisTol) {
    set_err(err, errlen, "%s: hip roll and hip pitch axes do not meet (z %g vs %g)", what, rr.z(), rp.z());
    return false;
  }
  if (std::fabs(rap.z() - rar.z()) > kAxisTol) {
    set_err(err, errlen, "%s: ankle pitch and roll axes do not meet (z %g vs %g)", what, rap.z(), rar.z());
    return false;
  }
  L.yaw_pt = ry_;
  L.hip0 = Vector3d(rp.x(), rr.y(), rr.z());
  L.ankle0 = Vector3d(rap.x(), rar.y(), rap.z());
  if (std::fabs(L.hip0.y() - L.ankle0.y()) > kAxisTol) {
    set_err(err, errlen, "%s: ankle centre (y %g) not below the hip centre (y %g)", what, L.ankle0.y(),
            L.hip0.y());
    return false;
  }
  L.sole0 = Vector3d(d->sole[side][0], d->sole[side][1], d->sole[side][2]);
  L.tx = rk.x() - L.hip0.x();
  L.tz = rk.z() - L.hip0.z();
  L.sx = L.ankle0.x() - rk.x();
  L.sz = L.ankle0.z() - rk.z();
  L.lt2 = L.tx * L.tx + L.tz * L.tz;
  L.ls2 = L.sx * L.sx + L.sz * L.sz;
  L.lts = std::sqrt(L.lt2 * L.ls2);
  if (L.lts < 1e-6) {
    set_err(err, errlen, "%s: thigh or tibia has no length", what);
    return false;
  }
  // t . Ry(d) s = P cos d + Q sin d = |t||s| cos(d - phi)
  L.phi = std::atan2(L.tx * L.sz - L.tz * L.sx, L.tx * L.sx + L.tz * L.sz);
  L.yaw_offset = std::hypot(L.hip0.x() - ry_.x(), L.hip0.y() - ry_.y()) > 1e-12;
  return true;
}

// One pass of the analytic solution for a given hip yaw (canonical) `a` used to place the hip
// centre when the yaw axis misses it. Writes canonical angles c[6]; returns flags.
int leg_solve(const Leg &L, const Matrix3d &R, const Vector3d &F, double a, double *c) {
  int flags = 0;
  Vector3d A = F - R * (L.sole0 - L.ankle0);
  Vector3d H = L.hip0;
  if (L.yaw_offset) {
    Vector3d off(L.hip0.x() - L.yaw_pt.x(), L.hip0.y() - L.yaw_pt.y(), 0.0);
    H = Vector3d(L.yaw_pt.x(), L.yaw_pt.y(), L.hip0.z()) + rz(a) * off;
  }
  Vector3d u = R.transpose() * (A - H);  // hip -> ankle, foot frame
  double r = u.norm();
  double rmax2 = L.lt2 + L.ls2 + 2.0 * L.lts, rmin2 = L.lt2 + L.ls2 - 2.0 * L.lts;
  double r2 = r * r;
  if (r2 > rmax2 || r2 < rmin2) {
    flags |= KIN_UNREACHABLE;
    double rc = std::sqrt(clamp(r2, rmin2, rmax2));
    if (r > 1e-12) {
      u *= rc / r;
    } else {
      u = Vector3d(0, 0, -rc);
    }
    r2 = rc * rc;
  }
  double cosk = clamp((r2 - L.lt2 - L.ls2) / (2.0 * L.lts), -1.0, 1.0);
  double d = L.phi + std::acos(cosk);  // the knee bends with the ankle going back
  // w = t + Ry(d) s, xz plane
  double sd = std::sin(d), cd = std::cos(d);
  double wx = L.tx + L.sx * cd + L.sz * sd;
  double wz = L.tz - L.sx * sd + L.sz * cd;
  // u = Rx(-f) Ry(-g) w with Ry(-g) w = (u.x, 0, w'z): u.y = w'z sin f, u.z = w'z cos f. Take the
  // ankle roll branch |f| <= pi/2 (w'z of the sign of u.z; usually negative: hip above ankle).
  double yz = std::sqrt(u.y() * u.y() + u.z() * u.z());
  double wpz = u.z() > 0 ? yz : -yz;
  double f = yz < 1e-12 ? 0.0 : std::atan2(u.y() / wpz, u.z() / wpz);
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

}  // namespace

extern "C" {

int kin_model_create(const kin_desc *d, kin_model **out, char *err, size_t errlen) {
  if (!d || !out) {
    set_err(err, errlen, "kin_model_create: NULL argument");
    return KIN_EINVAL;
  }
  *out = nullptr;
  if (d->njoint <= 0 || d->njoint > 64 || !d->parent || !d->axis || !d->anchor || !d->mass || !d->com) {
    set_err(err, errlen, "kin_model_create: need 1..64 joints with parent, axis, anchor, mass, com");
    return KIN_EINVAL;
  }
  kin_model *m = new (std::nothrow) kin_model();
  if (!m) {
    set_err(err, errlen, "kin_model_create: out of memory");
    return KIN_EMODEL;
  }
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
    if (J.parent < -1 || J.parent >= j) bad = "parent must be -1 (torso) or an earlier joint";
    else if (!finite3(J.axis) || J.axis.norm() < 1e-9) bad = "axis is not a finite non-zero vector";
    else if (!finite3(J.anchor) || !finite3(J.com)) bad = "anchor or com not finite";
    else if (!std::isfinite(J.mass) || J.mass < 0) bad = "mass must be finite and >= 0";
    else if (std::isnan(J.qmin) || std::isnan(J.qmax) || J.qmin > J.qmax) bad = "limits: need min <= max";
    if (bad) {
      set_err(err, errlen, "joint %d: %s", j, bad);
      delete m;
      return KIN_EMODEL;
    }
    J.axis.normalize();
    m->total_mass += J.mass;
  }
  m->torso_mass = d->torso_mass;
  m->torso_com = Vector3d(d->torso_com[0], d->torso_com[1], d->torso_com[2]);
  m->origin = Vector3d(d->origin[0], d->origin[1], d->origin[2]);
  m->camera = Vector3d(d->camera[0], d->camera[1], d->camera[2]);
  if (!std::isfinite(d->torso_mass) || d->torso_mass < 0 || !finite3(m->torso_com) || !finite3(m->origin) ||
      !finite3(m->camera) || !(m->total_mass > 0)) {
    set_err(err, errlen, "torso mass/com, origin or camera not finite, or total mass not positive");
    delete m;
    return KIN_EMODEL;
  }
  for (int s = 0; s < 2; s++) {
    if (!setup_leg(m, d, s, err, errlen) ||
        !check_chain(d, d->arm[s], 3, err, errlen, s == 0 ? "left arm" : "right arm")) {
      delete m;
      return KIN_EMODEL;
    }
    for (int k = 0; k < 3; k++) m->arm[s][k] = d->arm[s][k];
    m->hand[s] = Vector3d(d->hand[s][0], d->hand[s][1], d->hand[s][2]);
  }
  if (!check_chain(d, d->head, 2, err, errlen, "head")) {
    delete m;
    return KIN_EMODEL;
  }
  m->head[0] = d->head[0];
  m->head[1] = d->head[1];
  m->head_ok = is_axis(m->joints[d->head[0]].axis, 2, &m->head_sign[0]) &&
               is_axis(m->joints[d->head[1]].axis, 1, &m->head_sign[1]);
  *out = m;
  return 0;
}

void kin_model_destroy(kin_model *m) { delete m; }

int kin_njoint(const kin_model *m) { return m ? (int)m->joints.size() : KIN_EINVAL; }

double kin_total_mass(const kin_model *m) { return m ? m->total_mass : 0.0; }

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

int kin_leg_fk(const kin_model *m, int side, const double *q6, double *pose, double *rot) {
  if (!m || !q6 || !pose || (side != 0 && side != 1)) return KIN_EINVAL;
  int flags = 0;
  const Leg &L = m->leg[side];
  Pose T = limb_pose(m, L.idx, 6, q6, &flags);
  Vector3d F = T.R * L.sole0 + T.p - m->origin;
  for (int k = 0; k < 3; k++) pose[k] = F[k];
  rot_to_rpy(T.R, pose + 3);
  if (rot) put_rot(T.R, rot);
  return flags;
}

int kin_arm_fk(const kin_model *m, int side, const double *q3, double *pos, double *rot) {
  if (!m || !q3 || !pos || (side != 0 && side != 1)) return KIN_EINVAL;
  int flags = 0;
  Pose T = limb_pose(m, m->arm[side], 3, q3, &flags);
  Vector3d h = T.R * m->hand[side] + T.p - m->origin;
  for (int k = 0; k < 3; k++) pos[k] = h[k];
  if (rot) put_rot(T.R, rot);
  return flags;
}

int kin_head_fk(const kin_model *m, const double *q2, double *pos, double *rot) {
  if (!m || !q2 || !pos) return KIN_EINVAL;
  int flags = 0;
  Pose T = limb_pose(m, m->head, 2, q2, &flags);
  Vector3d c = T.R * m->camera + T.p - m->origin;
  for (int k = 0; k < 3; k++) pos[k] = c[k];
  if (rot) put_rot(T.R, rot);
  return flags;
}

int kin_camera_pose(const kin_model *m, const double *q, const double *rpy, double *pos, double *rot,
                    double *height) {
  if (!m || !q || !rpy || !pos || !rot) return KIN_EINVAL;
  int flags = 0;
  double roll = clean(rpy[0], &flags), pitch = clean(rpy[1], &flags);
  Matrix3d Rl = ry(pitch) * rx(roll);
  Pose T = chain_pose(m, m->head[1], q, &flags);
  Vector3d c = Rl * (T.R * m->camera + T.p - m->origin);
  for (int k = 0; k < 3; k++) pos[k] = c[k];
  put_rot(Rl * T.R, rot);
  if (height) {
    double low = INFINITY;
    for (int s = 0; s < 2; s++) {
      const Leg &L = m->leg[s];
      Pose F = chain_pose(m, L.idx[5], q, &flags);
      double z = (Rl * (F.R * L.sole0 + F.p - m->origin)).z();
      if (z < low) low = z;
    }
    *height = c.z() - low;
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

int kin_leg_ik(const kin_model *m, int side, const double *pose, double *q6) {
  if (!m || !pose || !q6 || (side != 0 && side != 1)) return KIN_EINVAL;
  const Leg &L = m->leg[side];
  int flags = 0;
  // Non-finite components fall back to the zero-pose foot pose.
  double p[6];
  Vector3d zero = L.sole0 - m->origin;
  for (int k = 0; k < 6; k++) {
    double z0 = k < 3 ? zero[k] : 0.0;
    p[k] = std::isfinite(pose[k]) ? pose[k] : (flags |= KIN_BAD_INPUT, z0);
  }
  Matrix3d R = rpy_to_rot(p[3], p[4], p[5]);
  Vector3d F = Vector3d(p[0], p[1], p[2]) + m->origin;
  double c[6];
  int f = leg_solve(L, R, F, 0.0, c);
  if (L.yaw_offset) {
    // The hip centre moves with the yaw: a fixed point, contracting by |offset| / leg length.
    for (int it = 0; it < 20; it++) {
      double prev = c[0];
      f = leg_solve(L, R, F, c[0], c);
      if (std::fabs(c[0] - prev) < 1e-15) break;
    }
  }
  flags |= f;
  for (int k = 0; k < 6; k++) {
    const Joint &J = m->joints[L.idx[k]];
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

int kin_arm_ik(const kin_model *m, int side, const double *pos, double *q3) {
  if (!m || !pos || !q3 || (side != 0 && side != 1)) return KIN_EINVAL;
  int flags = 0;
  const int *idx = m->arm[side];
  double q[3];
  for (int k = 0; k < 3; k++) q[k] = clean(q3[k], &flags);
  Vector3d target;
  double zero[3] = {0, 0, 0}, h0[3];
  kin_arm_fk(m, side, zero, h0, nullptr);
  for (int k = 0; k < 3; k++) target[k] = std::isfinite(pos[k]) ? pos[k] : (flags |= KIN_BAD_INPUT, h0[k]);
  target += m->origin;
  double lambda = 1e-4;
  double err_norm = INFINITY;
  for (int it = 0; it < 100; it++) {
    // Current pose of each arm joint: its axis and anchor in the torso frame, and the hand.
    Pose T{Matrix3d::Identity(), Vector3d::Zero()};
    Eigen::Matrix3d Jac;
    Vector3d w[3], r[3];
    for (int k = 0; k < 3; k++) {
      const Joint &J = m->joints[idx[k]];
      w[k] = T.R * J.axis;
      r[k] = T.R * J.anchor + T.p;
      Matrix3d E = rot_axis(J.axis, q[k]);
      T.p = T.R * (J.anchor - E * J.anchor) + T.p;
      T.R = T.R * E;
    }
    Vector3d h = T.R * m->hand[side] + T.p;  // the arm hangs from the torso (checked at create)
    for (int k = 0; k < 3; k++) Jac.col(k) = w[k].cross(h - r[k]);
    Vector3d e = target - h;
    err_norm = e.norm();
    if (err_norm < 1e-10) break;
    Matrix3d A = Jac.transpose() * Jac + lambda * Matrix3d::Identity();
    Vector3d dq = A.ldlt().solve(Jac.transpose() * e);
    if (!finite3(dq)) break;
    double step = dq.norm();
    if (step > 0.3) dq *= 0.3 / step;
    for (int k = 0; k < 3; k++) {
      const Joint &J = m->joints[idx[k]];
      q[k] = clamp(std::remainder(q[k] + dq[k], 2.0 * M_PI), J.qmin, J.qmax);
    }
    if (step < 1e-13) break;
  }
  if (err_norm > 1e-4) flags |= KIN_UNREACHABLE;
  for (int k = 0; k < 3; k++) q3[k] = std::isfinite(q[k]) ? q[k] : 0.0;
  return flags;
}

int kin_head_look_at(const kin_model *m, const double *target, double *q2) {
  if (!m || !target || !q2) return KIN_EINVAL;
  if (!m->head_ok) return KIN_EMODEL;
  int flags = 0;
  if (!finite_all(target, 3)) {
    q2[0] = q2[1] = 0.0;
    return KIN_BAD_INPUT;
  }
  const Joint &P = m->joints[m->head[0]], &Tl = m->joints[m->head[1]];
  Vector3d p = Vector3d(target[0], target[1], target[2]) + m->origin;
  // Pan: the optical axis (lateral offset e from the pan axis) must pass over the target.
  double dx = p.x() - P.anchor.x(), dy = p.y() - P.anchor.y();
  double rho = std::hypot(dx, dy);
  double e = m->camera.y() - P.anchor.y();
  double ratio = rho > 1e-12 ? e / rho : 0.0;
  if (std::fabs(ratio) > 1.0) flags |= KIN_UNREACHABLE;
  double a = std::atan2(dy, dx) - std::asin(clamp(ratio, -1.0, 1.0));
  // Tilt: in the panned frame, the target relative to the tilt axis must sit on the optical axis.
  Vector3d pl = rz(-a) * (p - Vector3d(P.anchor.x(), P.anchor.y(), 0)) + Vector3d(P.anchor.x(), P.anchor.y(), 0);
  double X = pl.x() - Tl.anchor.x(), Z = pl.z() - Tl.anchor.z();
  double cz = m->camera.z() - Tl.anchor.z();
  double R = std::hypot(X, Z);
  double cr = R > 1e-12 ? cz / R : 2.0;
  if (std::fabs(cr) > 1.0) flags |= KIN_UNREACHABLE;
  double th = std::atan2(X, Z) - std::acos(clamp(cr, -1.0, 1.0));
  double q[2] = {m->head_sign[0] * std::remainder(a, 2 * M_PI), m->head_sign[1] * std::remainder(th, 2 * M_PI)};
  const Joint *J[2] = {&P, &Tl};
  for (int k = 0; k < 2; k++) {
    if (q[k] < J[k]->qmin || q[k] > J[k]->qmax) {
      q[k] = clamp(q[k], J[k]->qmin, J[k]->qmax);
      flags |= KIN_UNREACHABLE | KIN_JOINT_LIMIT;
    }
    q2[k] = std::isfinite(q[k]) ? q[k] : 0.0;
  }
  return flags;
}

}  // extern "C"
