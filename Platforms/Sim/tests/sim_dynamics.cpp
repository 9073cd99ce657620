// sim_dynamics: ODE's response against the rigid-body model (Modules/dynamics, Pinocchio) on every
// body, TAP: gravity torques (hung on a gantry, holding a pose) and the mass matrix's base rows
// (floating free, waving the joints), each within 2%.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "dynamics/dynamics.h"
#include "stance.h"
#include "world.h"
#include "tap.h"

using sim::Mat3;
using sim::Vec3;

namespace {

// One body's numbers and description, for the caller to change before it builds the world.
struct BodyConfig {
  std::vector<sim::Params> ps;
  std::vector<sim::Body> bs;
  explicit BodyConfig(const std::string &robot) { sim::load_bodies({robot}, &ps, &bs); }
};

// Every joint turned a little from the zero pose (seeded), the legs spread 0.15 rad (the hip rolls)
// and the arms 0.5 rad forward (the shoulder pitches), clear of each other and off the stops.
std::vector<double> seeded_pose(const sim::Model &m, const sim::Params &p, unsigned seed) {
  const int nj = (int)p.joints.size();
  std::vector<double> q(nj, 0.0);
  std::vector<Vec3> zpos;
  std::vector<Mat3> zrot;
  m.zero_pose(&zpos, &zrot);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  for (int j = 0; j < nj; j++) {
    const int li = m.joint_link(p.joints[j]);
    const sim::Link &l = m.links[li];
    const std::string &n = p.joints[j];
    const Vec3 ax = zrot[li] * l.axis;
    if (sim::leg_role(n, p.lleg, p.rleg) == 1) {
      q[j] = (ax.x() > 0 ? 1 : -1) * (zpos[li].y() > 0 ? 1 : -1) * 0.15;
    } else {
      q[j] = u(rng);
      if (n == "l_sho_pitch" || n == "r_sho_pitch" || n == "LSP" || n == "RSP")   // arms forward
        q[j] += ax.y() > 0 ? -0.5 : 0.5;
    }
    q[j] = std::min(std::max(q[j], l.lower + 0.05), l.upper - 0.05);   // off the stops, which hold torque too
  }
  return q;
}

// The model of the body in the sim's joint order (NULL after a failed check).
dyn_model *model_of(const sim::Params &p, const std::string &robot) {
  std::vector<const char *> names;
  for (const std::string &n : p.joints) names.push_back(n.c_str());
  char err[512];
  dyn_model *d = nullptr;
  if (dyn_model_load(p.urdf.c_str(), (int)names.size(), names.data(), &d, err, sizeof err) != 0)
    tap_ok(0, (robot + ": the rigid-body model loads").c_str(), err);
  return d;
}

// The torso's world pose as the model's base (position, quaternion x y z w).
std::vector<double> base_of(const sim::World &w, Mat3 *rot = nullptr) {
  Vec3 pos;
  Mat3 R;
  w.link_pose(0, 0, &pos, &R);
  if (rot) *rot = R;
  Eigen::Quaterniond r(R);
  return {pos.x(), pos.y(), pos.z(), r.x(), r.y(), r.z(), r.w()};
}

// Hung on a gantry, servos holding the seeded pose: ODE's torques against the model's gravity.
void gravity_test(const std::string &robot, unsigned seed) {
  BodyConfig c(robot);
  const sim::Params &p = c.ps[0];
  sim::World w(p, c.bs, 7);
  const int nj = (int)p.joints.size();
  std::vector<double> q = seeded_pose(c.bs[0].model, p, seed);
  w.place_robot(0, 0, 0, 0, q.data());
  w.hang_robot(0, 0.3);
  std::vector<double> hard(nj, 1.0);
  std::vector<int> enable(nj, 1);
  w.set_command(0, q.data(), hard.data(), enable.data());
  // still after 1 s; the torques are the mean of the next second's ticks
  const int ticks = (int)std::lround(1.0 / p.period);
  for (int k = 0; k < ticks; k++) w.step();
  sim::Sensors s;
  std::vector<double> load(nj, 0.0);
  for (int k = 0; k < ticks; k++) {
    w.step();
    w.sense(0, &s);
    for (int j = 0; j < nj; j++) load[j] += s.load[j] / ticks;
  }
  dyn_model *d = model_of(p, robot);
  if (!d) return;
  std::vector<double> g(6 + nj), qa = w.joint_positions(0), base = base_of(w);
  dyn_set_state(d, base.data(), qa.data(), nullptr);
  dyn_gravity(d, g.data());
  double gmax = 0, emax = 0;
  std::string worst;
  for (int j = 0; j < nj; j++) gmax = std::max(gmax, std::fabs(g[6 + j]));
  for (int j = 0; j < nj; j++) {
    double e = std::fabs(load[j] - g[6 + j]);
    printf("# %-12s ODE %9.4f N m   model %9.4f N m\n", p.joints[j].c_str(), load[j], g[6 + j]);
    if (e > emax) emax = e, worst = p.joints[j];
  }
  char detail[160];
  snprintf(detail, sizeof detail, "largest torque %.3f N m, largest difference %.4f N m (%.2f%%, %s)", gmax, emax,
           100 * emax / gmax, worst.c_str());
  tap_ok(gmax > 0 && emax <= 0.02 * gmax,
         (robot + ": ODE's holding torques = the model's gravity torques").c_str(), detail);
  dyn_model_destroy(d);
}

// Floating free without gravity (and without the sim's rotor inertia, which the URDF lacks), the
// servos waving every joint 0.1 rad at 0.5 Hz: the momentum stays zero, so the base moves as the
// mass matrix's base rows say, M_bb v_base + M_bj qdot = 0. The base twist ODE produces against the
// one the model predicts from the joint rates (both central differences over a tick), every tick of
// the second second: relative RMS differences within 2%.
void momentum_test(const std::string &robot, unsigned seed) {
  BodyConfig c(robot);
  c.ps[0].gravity = 0;
  c.ps[0].rotor_inertia = 0;
  c.ps[0].iterations = 400;   // the constraints solved: at the real-time 20 the chain stretches (3-19% off)
  const sim::Params &p = c.ps[0];
  sim::World w(p, c.bs, 7);
  const int nj = (int)p.joints.size(), nv = 6 + nj;
  std::vector<double> q0 = seeded_pose(c.bs[0].model, p, seed), q = q0;
  w.place_robot(0, 0, 0, 0, q0.data());
  w.hang_robot(0, 2.0);   // 2 m up, then let go: nothing touches it
  w.release_robot(0);
  std::vector<double> hard(nj, 1.0), phase(nj);
  std::vector<int> enable(nj, 1);
  std::mt19937 rng(seed);
  for (double &ph : phase) ph = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
  dyn_model *d = model_of(p, robot);
  if (!d) return;
  std::vector<std::vector<double>> qs, bases;
  std::vector<Mat3> rots;
  const int ticks = (int)std::lround(1.0 / p.period);
  for (int k = 0; k < 2 * ticks; k++) {
    for (int j = 0; j < nj; j++) q[j] = q0[j] + 0.1 * std::sin(2 * M_PI * 0.5 * k * p.period + phase[j]);
    w.set_command(0, q.data(), hard.data(), enable.data());
    w.step();
    if (k >= ticks) {
      Mat3 R;
      bases.push_back(base_of(w, &R));
      rots.push_back(R);
      qs.push_back(w.joint_positions(0));
    }
  }
  // relative RMS differences over every tick of the second second
  std::vector<double> M(nv * nv);
  double elin = 0, eang = 0, vlin = 0, vang = 0;
  for (size_t k = 1; k + 1 < qs.size(); k++) {
    const double h = 2 * p.period;
    Eigen::VectorXd qd(nj);
    for (int j = 0; j < nj; j++) qd[j] = (qs[k + 1][j] - qs[k - 1][j]) / h;
    Vec3 v = rots[k].transpose() * Vec3(bases[k + 1][0] - bases[k - 1][0], bases[k + 1][1] - bases[k - 1][1],
                                        bases[k + 1][2] - bases[k - 1][2]) / h;
    Eigen::AngleAxisd turn(Mat3(rots[k + 1] * rots[k - 1].transpose()));
    Vec3 om = rots[k].transpose() * turn.axis() * turn.angle() / h;
    dyn_set_state(d, bases[k].data(), qs[k].data(), nullptr);
    dyn_mass_matrix(d, M.data());
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> Mm(M.data(), nv, nv);
    Eigen::Matrix<double, 6, 1> pred = -Mm.topLeftCorner(6, 6).ldlt().solve(Mm.topRightCorner(6, nj) * qd);
    elin += (pred.head<3>() - v).squaredNorm();
    eang += (pred.tail<3>() - om).squaredNorm();
    vlin += v.squaredNorm();
    vang += om.squaredNorm();
  }
  elin = std::sqrt(elin / vlin);
  eang = std::sqrt(eang / vang);
  vlin = std::sqrt(vlin / (qs.size() - 2));
  vang = std::sqrt(vang / (qs.size() - 2));
  char detail[200];
  snprintf(detail, sizeof detail, "base speed RMS %.3f m/s, %.3f rad/s; RMS differences %.2f%%, %.2f%%", vlin, vang,
           100 * elin, 100 * eang);
  tap_ok(vlin > 0 && elin <= 0.02 && eang <= 0.02,
         (robot + ": free-floating base moves as the mass matrix says (zero momentum)").c_str(), detail);
  dyn_model_destroy(d);
}

}  // namespace

int main() {
  const char *bodies[] = {"op3", "darwin", "hubo2plus", "waistbot"};
  for (unsigned b = 0; b < 4; b++) gravity_test(bodies[b], b + 1);
  for (unsigned b = 0; b < 4; b++) momentum_test(bodies[b], b + 1);
  return tap_done();
}
