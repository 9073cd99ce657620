// Tests of Modules/dynamics on every body's URDF (TAP), at random floating-base configurations:
// every frame's Jacobian and the COM Jacobian against central differences of the forward
// kinematics, the mass matrix (symmetric, positive definite, m*I in its base block, agreeing with
// RNEA), gravity torques against the derivative of the potential energy, the total mass against a
// plain reading of the URDF's <mass> elements, a joint order other than the URDF's, and the refusals.
#include "dynamics/dynamics.h"
#include "tap.h"

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using Eigen::VectorXd;
using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

const char *BODIES[] = {"op3", "darwin", "hubo2plus", "waistbot"};
const double EPS = 1e-5;      // central-difference step
const double TOL = 1e-6;      // Jacobians and gravity against the differences

void ok(bool cond, const std::string &name, const std::string &detail = "") {
  tap_ok(cond, name.c_str(), detail.c_str());
}

std::string fmt(const char *f, double x) {
  char b[64];
  snprintf(b, sizeof b, f, x);
  return b;
}

std::string root() {
  const char *env = getenv("HRP_ROOT");
  return env && *env ? env : HRP_ROOT_DEFAULT;
}

std::string urdf_of(const std::string &body) { return root() + "/Config/robots/" + body + "/" + body + ".urdf"; }

// Sum of the URDF's <mass value="..."/>, read as text (not through any URDF parser).
double urdf_mass(const std::string &path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  std::string s = ss.str();
  const std::string tag = "<mass value=\"";
  double sum = 0;
  for (size_t at = s.find(tag); at != std::string::npos; at = s.find(tag, at + 1))
    sum += std::stod(s.substr(at + tag.size()));
  return sum;
}

// A state: base position and orientation, joint angles (the model's order).
struct State {
  Vector3d p;
  Quaterniond r;
  VectorXd q;
  // The state moved by t along velocity coordinate k (the base twist in the base frame, then joints),
  // as Pinocchio's free-flyer integration does it.
  State moved(int k, double t) const {
    State s = *this;
    if (k < 3) s.p += r.toRotationMatrix().col(k) * t;
    else if (k < 6) s.r = r * Quaterniond(Eigen::AngleAxisd(t, Vector3d::Unit(k - 3)));
    else s.q[k - 6] += t;
    return s;
  }
};

void set(dyn_model *m, const State &s, const double *v = nullptr) {
  double base[7] = {s.p.x(), s.p.y(), s.p.z(), s.r.x(), s.r.y(), s.r.z(), s.r.w()};
  if (dyn_set_state(m, base, s.q.data(), v) != 0) fprintf(stderr, "set_state: %s\n", dyn_error(m));
}

State random_state(std::mt19937 &rng, int n) {
  std::uniform_real_distribution<double> u(-1, 1);
  State s;
  s.p = Vector3d(u(rng), u(rng), u(rng)) * 0.5;
  s.r = Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng))).normalized();
  s.q = VectorXd(n);
  for (int j = 0; j < n; j++) s.q[j] = u(rng);
  return s;
}

struct Pose {
  Vector3d p;
  Matrix3d R;
};

Pose frame_pose(dyn_model *m, int f) {
  double p[3], R[9];
  dyn_frame_pose(m, f, p, R);
  Pose out;
  out.p = Vector3d(p[0], p[1], p[2]);
  out.R = Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(R);
  return out;
}

Vector3d com_of(dyn_model *m) {
  double c[3];
  dyn_com(m, c, nullptr);
  return Vector3d(c[0], c[1], c[2]);
}

// Rotation vector of Ra * Rb^T (world axes).
Vector3d rot_diff(const Matrix3d &Ra, const Matrix3d &Rb) {
  Eigen::AngleAxisd aa(Matrix3d(Ra * Rb.transpose()));
  return aa.axis() * aa.angle();
}

// Frame and COM Jacobians against central differences; returns the largest error seen.
struct JacErrors {
  double frame = 0, local = 0, com = 0, gravity = 0;
};

void check_jacobians(dyn_model *m, const State &s, JacErrors &e) {
  int nv = dyn_nv(m), nf = dyn_nframe(m);
  double mass = dyn_total_mass(m);
  std::vector<RowMat> J(nf, RowMat(6, nv)), Jl(nf, RowMat(6, nv));
  std::vector<Pose> P(nf);
  RowMat Jc(3, nv);
  VectorXd g(nv);
  set(m, s);
  for (int f = 0; f < nf; f++) {
    dyn_frame_jacobian(m, f, DYN_WORLD_ALIGNED, J[f].data());
    dyn_frame_jacobian(m, f, DYN_LOCAL, Jl[f].data());
    P[f] = frame_pose(m, f);
  }
  double c[3];
  dyn_com(m, c, Jc.data());
  dyn_gravity(m, g.data());
  for (int f = 0; f < nf; f++) {   // LOCAL = the world-aligned Jacobian in the frame's axes
    MatrixXd lin = P[f].R.transpose() * J[f].topRows(3), ang = P[f].R.transpose() * J[f].bottomRows(3);
    e.local = std::max(e.local, std::max((lin - Jl[f].topRows(3)).cwiseAbs().maxCoeff(),
                                         (ang - Jl[f].bottomRows(3)).cwiseAbs().maxCoeff()));
  }
  for (int k = 0; k < nv; k++) {
    State sp = s.moved(k, EPS), sm = s.moved(k, -EPS);
    std::vector<Pose> Pp(nf), Pm(nf);
    set(m, sp);
    for (int f = 0; f < nf; f++) Pp[f] = frame_pose(m, f);
    Vector3d cp = com_of(m);
    set(m, sm);
    for (int f = 0; f < nf; f++) Pm[f] = frame_pose(m, f);
    Vector3d cm = com_of(m);
    for (int f = 0; f < nf; f++) {
      Vector3d dp = (Pp[f].p - Pm[f].p) / (2 * EPS), dw = rot_diff(Pp[f].R, Pm[f].R) / (2 * EPS);
      e.frame = std::max(e.frame, (dp - J[f].block(0, k, 3, 1)).cwiseAbs().maxCoeff());
      e.frame = std::max(e.frame, (dw - J[f].block(3, k, 3, 1)).cwiseAbs().maxCoeff());
    }
    Vector3d dc = (cp - cm) / (2 * EPS);
    e.com = std::max(e.com, (dc - Jc.col(k)).cwiseAbs().maxCoeff());
    // potential energy V = m g z_com: its derivative is the gravity torque
    double dV = mass * 9.81 * (cp.z() - cm.z()) / (2 * EPS);
    e.gravity = std::max(e.gravity, std::fabs(dV - g[k]) / std::max(1.0, g.cwiseAbs().maxCoeff()));
  }
}

void check_dynamics(dyn_model *m, const State &s, std::mt19937 &rng, const std::string &body) {
  int nv = dyn_nv(m);
  std::uniform_real_distribution<double> u(-1, 1);
  VectorXd v(nv), a(nv);
  for (int k = 0; k < nv; k++) v[k] = u(rng), a[k] = u(rng);
  set(m, s, v.data());
  RowMat M(nv, nv);
  VectorXd g(nv), h(nv), tau(nv), h2(nv);
  dyn_mass_matrix(m, M.data());
  dyn_gravity(m, g.data());
  dyn_nonlinear(m, h.data());
  dyn_inverse_dynamics(m, a.data(), tau.data());
  double scale = M.cwiseAbs().maxCoeff();
  ok((M - M.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale, body + ": mass matrix symmetric");
  Eigen::SelfAdjointEigenSolver<MatrixXd> es(M);
  double lmin = es.eigenvalues().minCoeff();
  ok(lmin > 0, body + ": mass matrix positive definite", "smallest eigenvalue " + fmt("%.3g", lmin));
  double mass = dyn_total_mass(m);
  ok((M.topLeftCorner(3, 3) - mass * Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-9,
     body + ": base block of the mass matrix is m I");
  double e = (tau - (M * a + h)).cwiseAbs().maxCoeff() / std::max(1.0, tau.cwiseAbs().maxCoeff());
  ok(e < 1e-9, body + ": RNEA(q, v, a) = M a + h (CRBA against RNEA)", "relative error " + fmt("%.2g", e));
  // h - g = C(q, v) v is quadratic in v
  VectorXd v2 = 2 * v;
  set(m, s, v2.data());
  dyn_nonlinear(m, h2.data());
  e = ((h2 - g) - 4 * (h - g)).cwiseAbs().maxCoeff() / std::max(1.0, (h2 - g).cwiseAbs().maxCoeff());
  ok(e < 1e-9, body + ": Coriolis terms quadratic in the velocity", "relative error " + fmt("%.2g", e));
  set(m, s);
  dyn_nonlinear(m, h2.data());
  ok((h2 - g).cwiseAbs().maxCoeff() < 1e-9, body + ": nonlinear effects at rest = gravity");
}

void check_body(const std::string &body, std::mt19937 &rng) {
  std::string path = urdf_of(body);
  char err[512];
  dyn_model *m = nullptr;
  int rc = dyn_model_load(path.c_str(), 0, nullptr, &m, err, sizeof err);
  ok(rc == 0, body + ": loads with a floating base", rc ? err : "");
  if (rc) return;
  int n = dyn_njoint(m);
  ok(dyn_nv(m) == 6 + n && dyn_nq(m) == 7 + n, body + ": nq = 7 + njoint, nv = 6 + njoint",
     std::to_string(n) + " joints, " + std::to_string(dyn_nframe(m)) + " frames");
  double want = urdf_mass(path), got = dyn_total_mass(m);
  ok(std::fabs(got - want) < 1e-9, body + ": total mass = the URDF's masses", fmt("%.6f kg", got));
  JacErrors e;
  for (int i = 0; i < 3; i++) check_jacobians(m, random_state(rng, n), e);
  ok(e.frame < TOL, body + ": every frame Jacobian = differences of its pose", "max error " + fmt("%.2g", e.frame));
  ok(e.local < 1e-12, body + ": LOCAL Jacobian = WORLD_ALIGNED one in the frame's axes", fmt("%.2g", e.local));
  ok(e.com < TOL, body + ": COM Jacobian = differences of the COM", "max error " + fmt("%.2g", e.com));
  ok(e.gravity < TOL, body + ": gravity torques = derivative of the potential energy",
     "max relative error " + fmt("%.2g", e.gravity));
  check_dynamics(m, random_state(rng, n), rng, body);
  dyn_model_destroy(m);
}

// The same body with its joints in reverse order: every column and torque moves with its joint.
void check_order(std::mt19937 &rng) {
  std::string path = urdf_of("hubo2plus");
  char err[512];
  dyn_model *a = nullptr, *b = nullptr;
  dyn_model_load(path.c_str(), 0, nullptr, &a, err, sizeof err);
  int n = dyn_njoint(a), nv = dyn_nv(a);
  std::vector<const char *> rev;
  for (int j = n - 1; j >= 0; j--) rev.push_back(dyn_joint_name(a, j));
  int rc = dyn_model_load(path.c_str(), n, rev.data(), &b, err, sizeof err);
  ok(rc == 0, "hubo2plus: loads in a joint order of the caller's", rc ? err : "");
  if (rc) return;
  State s = random_state(rng, n), sr = s;
  for (int j = 0; j < n; j++) sr.q[j] = s.q[n - 1 - j];
  set(a, s);
  set(b, sr);
  int fa = dyn_frame_id(a, "r_palm"), fb = dyn_frame_id(b, "r_palm");
  RowMat Ja(6, nv), Jb(6, nv), Ma(nv, nv), Mb(nv, nv);
  VectorXd ga(nv), gb(nv);
  dyn_frame_jacobian(a, fa, DYN_WORLD_ALIGNED, Ja.data());
  dyn_frame_jacobian(b, fb, DYN_WORLD_ALIGNED, Jb.data());
  dyn_mass_matrix(a, Ma.data());
  dyn_mass_matrix(b, Mb.data());
  dyn_gravity(a, ga.data());
  dyn_gravity(b, gb.data());
  auto r = [&](int c) { return c < 6 ? c : 6 + (n - 1 - (c - 6)); };   // column c of a in b
  double e = 0;
  for (int c = 0; c < nv; c++) {
    e = std::max(e, (Ja.col(c) - Jb.col(r(c))).cwiseAbs().maxCoeff());
    e = std::max(e, std::fabs(ga[c] - gb[r(c)]));
    for (int d = 0; d < nv; d++) e = std::max(e, std::fabs(Ma(c, d) - Mb(r(c), r(d))));
  }
  ok(e < 1e-12, "hubo2plus: Jacobian, mass matrix and gravity follow the joint order", fmt("%.2g", e));
  ok(std::string(dyn_joint_name(b, 0)) == rev[0], "joint names come back in the caller's order");
  dyn_model_destroy(a);
  dyn_model_destroy(b);
}

bool has(const char *msg, const std::string &part) { return std::string(msg).find(part) != std::string::npos; }

void check_refusals() {
  std::string path = urdf_of("op3");
  char err[512] = "";
  dyn_model *m = nullptr;
  int rc = dyn_model_load("/nonexistent/x.urdf", 0, nullptr, &m, err, sizeof err);
  ok(rc == DYN_EMODEL && !m && has(err, "/nonexistent/x.urdf"), "a missing URDF is refused, naming it", err);
  std::string bad = std::string(getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp") + "/dyn_test_bad.urdf";
  std::ofstream(bad) << "<robot name=\"x\"><link name=\"a\"/><joint name=\"j\" type=\"revolute\">";
  rc = dyn_model_load(bad.c_str(), 0, nullptr, &m, err, sizeof err);
  ok(rc == DYN_EMODEL && !m && has(err, bad), "a broken URDF is refused, naming the file", err);
  remove(bad.c_str());
  const char *unknown[] = {"l_knee", "no_such_joint"};
  rc = dyn_model_load(path.c_str(), 2, unknown, &m, err, sizeof err);
  ok(rc == DYN_EMODEL && has(err, "no_such_joint"), "an unknown joint in the order is refused, naming it", err);
  dyn_model_load(path.c_str(), 0, nullptr, &m, err, sizeof err);
  int n = dyn_njoint(m);
  std::vector<const char *> order;
  for (int j = 0; j < n; j++) order.push_back(dyn_joint_name(m, j));
  dyn_model *m2 = nullptr;
  std::string dropped = order.back();
  rc = dyn_model_load(path.c_str(), n - 1, order.data(), &m2, err, sizeof err);
  ok(rc == DYN_EMODEL && has(err, dropped), "a URDF joint missing from the order is refused, naming it", err);
  order.back() = order.front();
  rc = dyn_model_load(path.c_str(), n, order.data(), &m2, err, sizeof err);
  ok(rc == DYN_EMODEL && has(err, order.front()), "a joint named twice is refused, naming it", err);

  rc = dyn_frame_id(m, "r_palm_typo");
  ok(rc == DYN_ENOFRAME && has(dyn_error(m), "r_palm_typo"), "an unknown frame is refused, naming it", dyn_error(m));
  ok(dyn_frame_id(m, "l_sole") >= 0 && dyn_frame_id(m, "l_knee") >= 0, "links and joints are frames");
  VectorXd q = VectorXd::Constant(n, 0.1);
  dyn_set_state(m, nullptr, q.data(), nullptr);
  int f = dyn_frame_id(m, "l_sole");
  double p0[3], p1[3], J[6 * 64];
  dyn_frame_pose(m, f, p0, nullptr);
  VectorXd qn = q;
  qn[3] = NAN;
  rc = dyn_set_state(m, nullptr, qn.data(), nullptr);
  ok(rc == DYN_EBADINPUT && has(dyn_error(m), dyn_joint_name(m, 3)), "a NaN angle is refused, naming the joint",
     dyn_error(m));
  dyn_frame_pose(m, f, p1, nullptr);
  ok(p0[0] == p1[0] && p0[1] == p1[1] && p0[2] == p1[2], "a refused state leaves the previous one");
  double base[7] = {0, 0, INFINITY, 0, 0, 0, 1};
  rc = dyn_set_state(m, base, q.data(), nullptr);
  ok(rc == DYN_EBADINPUT && has(dyn_error(m), "base z"), "an infinite base position is refused", dyn_error(m));
  double zero[7] = {0, 0, 0, 0, 0, 0, 0};
  rc = dyn_set_state(m, zero, q.data(), nullptr);
  ok(rc == DYN_EBADINPUT && has(dyn_error(m), "quaternion"), "a zero quaternion is refused", dyn_error(m));
  VectorXd v = VectorXd::Zero(dyn_nv(m));
  v[7] = NAN;
  rc = dyn_set_state(m, nullptr, q.data(), v.data());
  ok(rc == DYN_EBADINPUT && has(dyn_error(m), dyn_joint_name(m, 1)), "a NaN joint rate is refused, naming the joint",
     dyn_error(m));
  rc = dyn_frame_jacobian(m, 9999, DYN_WORLD_ALIGNED, J);
  ok(rc == DYN_EINVAL && has(dyn_error(m), "9999"), "a frame id out of range is refused", dyn_error(m));
  rc = dyn_frame_jacobian(m, f, 7, J);
  ok(rc == DYN_EINVAL && has(dyn_error(m), "reference frame"), "an unknown reference frame is refused", dyn_error(m));
  ok(dyn_frame_pose(nullptr, f, p0, nullptr) == DYN_EINVAL && dyn_set_state(m, nullptr, nullptr, nullptr) == DYN_EINVAL,
     "NULL arguments are refused");
  dyn_model_destroy(m);
  dyn_model_destroy(nullptr);
}

}  // namespace

int main() {
  std::mt19937 rng(31);
  for (const char *body : BODIES) check_body(body, rng);
  check_order(rng);
  check_refusals();
  return tap_done();
}
