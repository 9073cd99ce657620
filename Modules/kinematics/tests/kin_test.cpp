// Unit tests of Modules/kinematics on synthetic geometries (the real OP3 / DARwIn-OP configs are
// tested from Lua in kinematics_spec.lua). Prints TAP; exits non-zero on a failure.
//
// A random geometry generator makes legs with the structure the analytic solver accepts but
// with every offset it must handle (hip yaw axis off the hip centre, knee off the hip-ankle line,
// sole off the ankle, mirrored axis signs), and FK(IK(x)) = x is checked over sampled poses.
#include "kinematics/kinematics.h"
#include "tap.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

namespace {

void ok(bool cond, const char *name, const char *detail = "") { tap_ok(cond, name, detail); }

struct Geometry {
  // joint order: 0 head_pan 1 head_tilt | 2..4 left arm | 5..10 left leg | 11..16 right leg | 17..19 right arm
  int parent[20];
  double axis[60], anchor[60], mass[20], com[60], qmin[20], qmax[20];
  int leg[2][6], arm[2][3], head[2];
  kin_chain chains[5];   // left leg, right leg, left arm, right arm, head
  kin_desc d;
};

void identity(double *R) {
  for (int k = 0; k < 9; k++) R[k] = k % 4 == 0 ? 1.0 : 0.0;
}

void set3(double *a, int j, double x, double y, double z) {
  a[3 * j] = x;
  a[3 * j + 1] = y;
  a[3 * j + 2] = z;
}

// Points the description at the geometry's own arrays (needed after every copy).
const kin_desc *bind(Geometry &g) {
  g.d.parent = g.parent;
  g.d.axis = g.axis;
  g.d.anchor = g.anchor;
  g.d.mass = g.mass;
  g.d.com = g.com;
  g.d.qmin = g.qmin;
  g.d.qmax = g.qmax;
  for (int s = 0; s < 2; s++) {
    g.chains[s].joints = g.leg[s];
    g.chains[2 + s].joints = g.arm[s];
  }
  g.chains[4].joints = g.head;
  g.d.chains = g.chains;
  return &g.d;
}

// A leg-and-arm robot. thigh/tibia lengths, hip yaw axis offset (dx, dy) from the hip centre,
// knee x offset, sole offset (sx, sy) from the ankle, foot height fh, and axis sign flips.
Geometry make_geometry(double thigh, double tibia, double yaw_dx, double yaw_dy, double knee_x, double sole_x,
                       double sole_y, double fh, const int *flip, bool limits) {
  Geometry g;
  std::memset(&g, 0, sizeof g);
  const double hip_z = fh + tibia + thigh;
  // head
  g.parent[0] = -1;
  set3(g.axis, 0, 0, 0, 1);
  set3(g.anchor, 0, 0, 0, hip_z + 0.15);
  g.parent[1] = 0;
  set3(g.axis, 1, 0, 1, 0);
  set3(g.anchor, 1, 0.01, 0.02, hip_z + 0.18);
  for (int s = 0; s < 2; s++) {
    double sy = s == 0 ? 1.0 : -1.0;
    int a0 = s == 0 ? 2 : 17;
    // arm: pitch (y) at the shoulder, roll (x), elbow (x) 0.08 further out, hand 0.1 further
    g.parent[a0] = -1;
    set3(g.axis, a0, 0, sy, 0);
    set3(g.anchor, a0, 0, sy * 0.06, hip_z + 0.12);
    g.parent[a0 + 1] = a0;
    set3(g.axis, a0 + 1, -1, 0, 0);
    set3(g.anchor, a0 + 1, 0.01, sy * 0.08, hip_z + 0.11);
    g.parent[a0 + 2] = a0 + 1;
    set3(g.axis, a0 + 2, 1, 0, 0);
    set3(g.anchor, a0 + 2, 0.01, sy * 0.16, hip_z + 0.11);
    // leg
    int l0 = s == 0 ? 5 : 11;
    double hy = sy * 0.04;
    const double ax[6][3] = {{0, 0, -1}, {-1, 0, 0}, {0, sy, 0}, {0, sy, 0}, {0, -sy, 0}, {1, 0, 0}};
    for (int k = 0; k < 6; k++) {
      g.parent[l0 + k] = k == 0 ? -1 : l0 + k - 1;
      double f = flip[k] ? -1.0 : 1.0;
      set3(g.axis, l0 + k, f * ax[k][0], f * ax[k][1], f * ax[k][2]);
    }
    set3(g.anchor, l0 + 0, yaw_dx, hy - sy * yaw_dy, hip_z + 0.03);
    set3(g.anchor, l0 + 1, -0.02, hy, hip_z);
    set3(g.anchor, l0 + 2, 0.0, hy + sy * 0.02, hip_z);
    set3(g.anchor, l0 + 3, knee_x, hy + sy * 0.02, fh + tibia);
    set3(g.anchor, l0 + 4, 0.0, hy + sy * 0.02, fh);
    set3(g.anchor, l0 + 5, -0.02, hy, fh);
    kin_chain &L = g.chains[s], &A = g.chains[2 + s];
    L.kind = KIN_LEG;
    A.kind = KIN_ARM;
    L.side = A.side = s;
    L.n = 6;
    A.n = 3;
    set3(L.tip, 0, sole_x, hy + sy * sole_y, 0.0);
    set3(A.tip, 0, 0.0, sy * 0.26, hip_z + 0.11);
    identity(L.tip_rot);
    identity(A.tip_rot);
    for (int k = 0; k < 6; k++) g.leg[s][k] = l0 + k;
    for (int k = 0; k < 3; k++) g.arm[s][k] = a0 + k;
  }
  for (int j = 0; j < 20; j++) {
    g.mass[j] = 0.05 + 0.01 * j;
    for (int k = 0; k < 3; k++) g.com[3 * j + k] = g.anchor[3 * j + k] + 0.001 * (k + 1);
    g.qmin[j] = limits ? -2.5 : -INFINITY;
    g.qmax[j] = limits ? 2.5 : INFINITY;
  }
  g.d.njoint = 20;
  bind(g);
  g.d.torso_mass = 1.0;
  set3(g.d.torso_com, 0, -0.01, 0.0, hip_z + 0.08);
  set3(g.d.origin, 0, 0.0, 0.0, hip_z);
  g.head[0] = 0;
  g.head[1] = 1;
  kin_chain &H = g.chains[4];
  H.kind = KIN_HEAD;
  H.side = 0;
  H.n = 2;
  set3(H.tip, 0, 0.04, 0.0, hip_z + 0.22);
  identity(H.tip_rot);
  g.d.nchain = 5;
  return g;
}

double rot_angle_between(const double *R1, const double *R2) {
  // angle of R1^T R2
  double tr = 0;
  for (int i = 0; i < 3; i++)
    for (int k = 0; k < 3; k++) tr += R1[3 * k + i] * R2[3 * k + i];
  double c = (tr - 1.0) / 2.0;
  if (c > 1) c = 1;
  if (c < -1) c = -1;
  // acos loses precision near 0: use the norm of the skew part instead
  double sx = 0, v[3];
  v[0] = 0;
  for (int i = 0; i < 3; i++) {
    int a = (i + 1) % 3, b = (i + 2) % 3;
    double mab = 0, mba = 0;
    for (int k = 0; k < 3; k++) {
      mab += R1[3 * k + a] * R2[3 * k + b];
      mba += R1[3 * k + b] * R2[3 * k + a];
    }
    v[i] = 0.5 * (mab - mba);
    sx += v[i] * v[i];
  }
  return std::atan2(std::sqrt(sx), c);
}

bool all_finite(const double *v, int n) {
  for (int i = 0; i < n; i++)
    if (!std::isfinite(v[i])) return false;
  return true;
}

// FK(IK(x)) = x over poses made by FK of random joint angles in a walking range.
void test_roundtrip(const char *name, Geometry &g, std::mt19937 &rng, int samples) {
  kin_model *m = nullptr;
  char err[256] = "";
  int rc = kin_model_create(bind(g), &m, err, sizeof err);
  char msg[320];
  std::snprintf(msg, sizeof msg, "%s: model created", name);
  ok(rc == 0 && m, msg, err);
  if (!m) return;
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  double worst_p = 0, worst_r = 0;
  int bad_flags = 0;
  for (int side = 0; side < 2; side++) {
    for (int i = 0; i < samples; i++) {
      // a random reachable pose: FK of random angles (knee bent the solver's way)
      double q[6], pose[6], R[9], qs[6], pose2[6], R2[9];
      const Geometry *gg = &g;
      for (int k = 0; k < 6; k++) q[k] = 0.6 * U(rng);
      double knee_sign = gg->axis[3 * gg->leg[side][3] + 1] > 0 ? 1.0 : -1.0;  // canonical +y bend
      q[3] = knee_sign * (0.05 + 1.6 * (0.5 + 0.5 * U(rng)));
      kin_leg_fk(m, side, q, nullptr, pose, R);
      int f = kin_leg_ik(m, side, pose, nullptr, qs);
      if (f != 0) bad_flags++;
      kin_leg_fk(m, side, qs, nullptr, pose2, R2);
      double dp = std::sqrt((pose[0] - pose2[0]) * (pose[0] - pose2[0]) + (pose[1] - pose2[1]) * (pose[1] - pose2[1]) +
                            (pose[2] - pose2[2]) * (pose[2] - pose2[2]));
      double dr = rot_angle_between(R, R2);
      if (dp > worst_p) worst_p = dp;
      if (dr > worst_r) worst_r = dr;
    }
  }
  std::snprintf(msg, sizeof msg, "%s: FK(IK(x)) = x over %d poses per leg", name, samples);
  char det[128];
  std::snprintf(det, sizeof det, "worst position %.3g m, orientation %.3g rad, flagged %d", worst_p, worst_r,
                bad_flags);
  ok(worst_p < 1e-6 && worst_r < 1e-6 && bad_flags == 0, msg, det);
  kin_model_destroy(m);
}

}  // namespace

int main() {
  std::mt19937 rng(12345);
  const int none[6] = {0, 0, 0, 0, 0, 0};
  const int flips[6] = {1, 0, 1, 1, 0, 1};

  // 1. Round trips on several geometries.
  Geometry plain = make_geometry(0.1, 0.1, 0, 0, 0, 0, 0, 0.03, none, false);
  test_roundtrip("plain legs", plain, rng, 2000);
  Geometry offs = make_geometry(0.11015, 0.11, 0.004, 0.003, 0.012, 0.02, 0.013, 0.0305, none, false);
  test_roundtrip("offset yaw axis, knee, sole", offs, rng, 2000);
  Geometry flipped = make_geometry(0.093, 0.093, 0.0001, 0, -0.01, -0.01, 0.0, 0.0335, flips, false);
  test_roundtrip("flipped axis signs", flipped, rng, 2000);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int i = 0; i < 5; i++) {
    Geometry r = make_geometry(0.08 + 0.05 * (U(rng) + 1), 0.08 + 0.05 * (U(rng) + 1), 0.005 * U(rng),
                               0.005 * U(rng), 0.02 * U(rng), 0.03 * U(rng), 0.02 * U(rng), 0.02 + 0.02 * (U(rng) + 1),
                               none, false);
    char name[64];
    std::snprintf(name, sizeof name, "random geometry %d", i + 1);
    test_roundtrip(name, r, rng, 500);
  }

  // 2. Known poses on the plain geometry (thigh = tibia = 0.1, foot height 0.03, hip y 0.04).
  kin_model *m = nullptr;
  char err[256] = "";
  kin_model_create(bind(plain), &m, err, sizeof err);
  double q0[6] = {0, 0, 0, 0, 0, 0}, pose[6], q[6];
  kin_leg_fk(m, KIN_LEFT, q0, nullptr, pose, nullptr);
  ok(std::fabs(pose[0]) < 1e-12 && std::fabs(pose[1] - 0.04) < 1e-12 && std::fabs(pose[2] + 0.23) < 1e-12 &&
         std::fabs(pose[3]) + std::fabs(pose[4]) + std::fabs(pose[5]) < 1e-12,
     "zero pose: left foot 0.23 m below the torso origin, under the hip");
  // Bent knee by hand: hip pitch -45 deg (thigh forward), knee 90 deg, ankle -45 deg: the ankle
  // comes back under the hip at sqrt(2) * 0.1 below it, the foot flat.
  double qb[6] = {0, 0, -M_PI / 4, M_PI / 2, M_PI / 4, 0};  // left ankle pitch axis is -y
  kin_leg_fk(m, KIN_LEFT, qb, nullptr, pose, nullptr);
  double want_z = -(std::sqrt(2.0) * 0.1 + 0.03);
  char det[160];
  std::snprintf(det, sizeof det, "got %.9f %.9f %.9f pitch %.3g", pose[0], pose[1], pose[2], pose[4]);
  ok(std::fabs(pose[0]) < 1e-12 && std::fabs(pose[1] - 0.04) < 1e-12 && std::fabs(pose[2] - want_z) < 1e-12 &&
         std::fabs(pose[4]) < 1e-12,
     "bent knee: FK matches the hand computation", det);
  int f = kin_leg_ik(m, KIN_LEFT, pose, nullptr, q);
  std::snprintf(det, sizeof det, "got %.6f %.6f %.6f %.6f %.6f %.6f flags %d", q[0], q[1], q[2], q[3], q[4], q[5], f);
  ok(f == 0 && std::fabs(q[2] + M_PI / 4) < 1e-9 && std::fabs(q[3] - M_PI / 2) < 1e-9 &&
         std::fabs(q[4] - M_PI / 4) < 1e-9 && std::fabs(q[0]) + std::fabs(q[1]) + std::fabs(q[5]) < 1e-9,
     "bent knee: IK gives back the hand-made angles", det);
  // Right leg mirrored: hip pitch axis -y, so the same motion has opposite signs.
  double pr[6] = {pose[0], -pose[1], pose[2], 0, 0, 0};
  f = kin_leg_ik(m, KIN_RIGHT, pr, nullptr, q);
  ok(f == 0 && std::fabs(q[2] - M_PI / 4) < 1e-9 && std::fabs(q[3] + M_PI / 2) < 1e-9 && std::fabs(q[4] + M_PI / 4) < 1e-9,
     "bent knee, right leg: mirrored signs");
  // Hip yaw alone turns the foot about the hip yaw axis (-z): yaw +0.3 turns the foot by -0.3.
  double qy[6] = {0.3, 0, 0, 0, 0, 0};
  kin_leg_fk(m, KIN_LEFT, qy, nullptr, pose, nullptr);
  ok(std::fabs(pose[5] + 0.3) < 1e-12, "hip yaw axis -z: foot yaw = -q");

  // 3. Unreachable targets: nearest reachable solution, flagged, never NaN.
  double far[6] = {0.0, 0.04, -0.5, 0, 0, 0};
  f = kin_leg_ik(m, KIN_LEFT, far, nullptr, q);
  kin_leg_fk(m, KIN_LEFT, q, nullptr, pose, nullptr);
  std::snprintf(det, sizeof det, "flags %d, foot z %.6f", f, pose[2]);
  ok((f & KIN_UNREACHABLE) && all_finite(q, 6) && std::fabs(pose[2] + 0.23) < 1e-6 && std::fabs(pose[1] - 0.04) < 1e-9,
     "too far below: straight leg toward the target, flagged", det);
  double far2[6] = {0.3, 0.2, -0.2, 0, 0.2, 0};
  f = kin_leg_ik(m, KIN_LEFT, far2, nullptr, q);
  kin_leg_fk(m, KIN_LEFT, q, nullptr, pose, nullptr);
  // nearest point: on the line from the hip centre to the requested ankle, at full leg length
  double hip[3] = {0, 0.04, 0};
  double sp = std::sin(0.2), cp = std::cos(0.2);
  double ankle_t[3] = {0.3 + 0.03 * sp, 0.2, -0.2 + 0.03 * cp};  // ankle = sole + R (0,0,0.03)
  double ankle_g[3] = {pose[0] + 0.03 * std::sin(pose[4]), pose[1], pose[2] + 0.03 * std::cos(pose[4])};
  double v1[3], v2[3], n1 = 0, n2 = 0, dot = 0;
  for (int k = 0; k < 3; k++) {
    v1[k] = ankle_t[k] - hip[k];
    v2[k] = ankle_g[k] - hip[k];
    n1 += v1[k] * v1[k];
    n2 += v2[k] * v2[k];
    dot += v1[k] * v2[k];
  }
  double cosang = dot / std::sqrt(n1 * n2);
  std::snprintf(det, sizeof det, "flags %d, reach %.6f, direction cos %.12f, pitch %.6f", f, std::sqrt(n2), cosang,
                pose[4]);
  ok((f & KIN_UNREACHABLE) && std::fabs(std::sqrt(n2) - 0.2) < 1e-6 && cosang > 1 - 1e-9 &&
         std::fabs(pose[4] - 0.2) < 1e-9,
     "too far sideways: orientation kept, ankle at full reach toward the target", det);
  double close[6] = {0.0, 0.04, -0.035, 0, 0, 0};  // thigh = tibia: fully folded is reachable
  f = kin_leg_ik(m, KIN_LEFT, close, nullptr, q);
  ok(all_finite(q, 6), "target at the hip: finite answer");
  const double nan = NAN, inf = INFINITY;
  double bad[][6] = {{nan, 0.04, -0.2, 0, 0, 0}, {0, inf, -0.2, 0, 0, 0}, {0, 0.04, -inf, 0, 0, 0},
                     {0, 0.04, -0.2, nan, nan, nan}, {nan, nan, nan, nan, nan, nan}, {1e300, -1e300, 1e300, 1e300, 0, 0}};
  bool all_ok = true;
  for (auto &b : bad) {
    f = kin_leg_ik(m, KIN_LEFT, b, nullptr, q);
    bool fin = all_finite(q, 6);
    bool flagged = (f & (KIN_BAD_INPUT | KIN_UNREACHABLE)) != 0;
    all_ok = all_ok && fin && flagged;
  }
  ok(all_ok, "NaN / inf / huge targets: finite angles and a flag");
  f = kin_leg_ik(m, KIN_LEFT, bad[0], nullptr, q);
  kin_leg_fk(m, KIN_LEFT, q, nullptr, pose, nullptr);
  ok((f & KIN_BAD_INPUT) && std::fabs(pose[2] + 0.2) < 1e-9 && std::fabs(pose[0]) < 1e-9,
     "NaN x: replaced by the zero-pose x, the rest honoured");
  double qnan[6] = {nan, 0, 0, 0, 0, 0};
  f = kin_leg_fk(m, KIN_LEFT, qnan, nullptr, pose, nullptr);
  ok((f & KIN_BAD_INPUT) && all_finite(pose, 6), "FK with a NaN angle: finite and flagged");
  ok(kin_leg_ik(m, 2, far, nullptr, q) == KIN_EINVAL && kin_leg_ik(nullptr, 0, far, nullptr, q) == KIN_EINVAL, "bad side / NULL model");
  kin_model_destroy(m);

  // 4. Joint limits: a pose beyond them is clamped and flagged.
  Geometry lim = make_geometry(0.1, 0.1, 0, 0, 0, 0, 0, 0.03, none, true);
  kin_model_create(bind(lim), &m, err, sizeof err);
  double twist[6] = {0, 0.04, -0.2, 0, 0, 2.9};
  f = kin_leg_ik(m, KIN_LEFT, twist, nullptr, q);
  ok((f & KIN_JOINT_LIMIT) && std::fabs(q[0]) <= 2.5, "beyond the hip yaw limit: clamped, flagged");

  // 5. Centre of mass by hand: torso 1 kg + links 0.05 + 0.01 j kg at anchor + (0.001, 0.002, 0.003).
  double qz[20] = {0}, com[3];
  kin_com(m, qz, com);
  double M = 1.0, sum[3] = {-0.01 * 1.0, 0.0, (0.03 + 0.2 + 0.08) * 1.0};
  for (int j = 0; j < 20; j++) {
    M += lim.mass[j];
    for (int k = 0; k < 3; k++) sum[k] += lim.mass[j] * lim.com[3 * j + k];
  }
  ok(std::fabs(com[0] - sum[0] / M) < 1e-12 && std::fabs(com[1] - sum[1] / M) < 1e-12 &&
         std::fabs(com[2] - (sum[2] / M - 0.23)) < 1e-12 && std::fabs(kin_total_mass(m) - M) < 1e-12,
     "COM at the zero pose = mass-weighted mean of the link COMs");
  // Bending one knee 90 deg moves that shank's COM: check against a hand computation.
  qz[8] = M_PI / 2;  // left knee (axis +y): shank swings back
  double com2[3];
  kin_com(m, qz, com2);
  double ankle_mass_shift[3] = {0, 0, 0};
  // links below the knee (8, 9, 10) all rotate about the knee axis
  for (int j = 8; j <= 10; j++) {
    double r[3];
    for (int k = 0; k < 3; k++) r[k] = lim.com[3 * j + k] - lim.anchor[3 * 8 + k];
    double rr[3] = {r[2], r[1], -r[0]};
    for (int k = 0; k < 3; k++) ankle_mass_shift[k] += lim.mass[j] * (rr[k] - r[k]);
  }
  bool com_ok = true;
  for (int k = 0; k < 3; k++) com_ok = com_ok && std::fabs(com2[k] - (com[k] + ankle_mass_shift[k] / M)) < 1e-12;
  ok(com_ok, "COM with a bent knee matches the hand computation");

  // 6. Arm FK/IK and head look-at.
  double qa[3] = {0.3, -0.5, 0.7}, hand[3], qi[3] = {0, 0, 0};
  kin_arm_fk(m, KIN_LEFT, qa, nullptr, hand, nullptr);
  f = kin_arm_ik(m, KIN_LEFT, hand, nullptr, qi);
  double hand2[3];
  kin_arm_fk(m, KIN_LEFT, qi, nullptr, hand2, nullptr);
  double dh = std::sqrt((hand[0] - hand2[0]) * (hand[0] - hand2[0]) + (hand[1] - hand2[1]) * (hand[1] - hand2[1]) +
                        (hand[2] - hand2[2]) * (hand[2] - hand2[2]));
  std::snprintf(det, sizeof det, "error %.3g m, flags %d", dh, f);
  ok(f == 0 && dh < 1e-8, "arm IK reaches a hand position made by FK", det);
  double hfar[3] = {1.0, 1.0, 1.0};
  qi[0] = qi[1] = qi[2] = 0;
  f = kin_arm_ik(m, KIN_LEFT, hfar, nullptr, qi);
  ok((f & KIN_UNREACHABLE) && all_finite(qi, 3), "arm IK out of reach: flagged, finite");
  bool look_ok = true;
  double worst_look = 0;
  for (int i = 0; i < 200; i++) {
    double t[3] = {0.3 + 2.0 * (U(rng) + 1), 1.5 * U(rng), -0.2 - 0.5 * (U(rng) + 1)};
    double qh[2], cpos[3], crot[9];
    f = kin_head_look_at(m, t, nullptr, qh);
    kin_head_fk(m, qh, nullptr, cpos, crot);
    // the optical axis is the camera frame's x: column 0 of R
    double d[3] = {t[0] - cpos[0], t[1] - cpos[1], t[2] - cpos[2]};
    double nd = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double c = (d[0] * crot[0] + d[1] * crot[3] + d[2] * crot[6]) / nd;
    double ang = std::acos(c > 1 ? 1 : c);
    if (ang > worst_look) worst_look = ang;
    look_ok = look_ok && f == 0;
  }
  std::snprintf(det, sizeof det, "worst angle %.3g rad", worst_look);
  ok(look_ok && worst_look < 1e-6, "look_at: the optical axis passes through the target", det);
  kin_model_destroy(m);

  // 7. Descriptions the analytic solver cannot take are refused with a message.
  Geometry badg = make_geometry(0.1, 0.1, 0, 0, 0, 0, 0, 0.03, none, false);
  badg.anchor[3 * 7 + 2] += 0.01;  // left hip pitch axis no longer meets the roll axis
  int rc = kin_model_create(bind(badg), &m, err, sizeof err);
  ok(rc == KIN_EMODEL && m == nullptr && std::strstr(err, "left leg"), "hip axes that do not meet: refused", err);
  badg = make_geometry(0.1, 0.1, 0, 0, 0, 0, 0, 0.03, none, false);
  badg.axis[3 * 5 + 0] = 0.3;  // hip yaw axis tilted
  rc = kin_model_create(bind(badg), &m, err, sizeof err);
  ok(rc == KIN_EMODEL && std::strstr(err, "hip yaw"), "tilted hip yaw axis: refused", err);
  badg = make_geometry(0.1, 0.1, 0, 0, 0, 0, 0, 0.03, none, false);
  badg.mass[3] = NAN;
  rc = kin_model_create(bind(badg), &m, err, sizeof err);
  ok(rc == KIN_EMODEL && std::strstr(err, "mass"), "NaN mass: refused", err);

  return tap_done();
}
