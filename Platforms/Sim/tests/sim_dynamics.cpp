// sim_dynamics: ODE's joint torques against the rigid-body model (Modules/dynamics, Pinocchio), TAP.
//   Each body hangs on a gantry (torso held, feet off the carpet), its servos holding a seeded pose
//   near the stance, until it is still. Every joint then carries only gravity: ODE's torque about its
//   axis (`load`, the mean over a second) must equal the model's gravity torque at the measured torso
//   pose and joint angles, within 2% of the largest of them.
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

void body_test(const std::string &robot, unsigned seed) {
  std::vector<sim::Params> ps;
  std::vector<sim::Body> bs;
  sim::load_bodies({robot}, &ps, &bs);
  const sim::Params &p = ps[0];
  const sim::Model &m = bs[0].model;
  sim::World w(p, bs, 7);
  const int nj = (int)p.joints.size();
  // the zero pose with every joint turned a little (seeded), the legs spread 0.15 rad (the hip rolls)
  // and the arms 0.5 rad forward (the shoulder pitches), clear of each other, hung 0.3 m up
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
  std::vector<double> qa = w.joint_positions(0);
  Vec3 pos;
  Mat3 R;
  w.link_pose(0, 0, &pos, &R);
  Eigen::Quaterniond r(R);
  double base[7] = {pos.x(), pos.y(), pos.z(), r.x(), r.y(), r.z(), r.w()};

  std::vector<const char *> names;
  for (const std::string &n : p.joints) names.push_back(n.c_str());
  char err[512];
  dyn_model *d = nullptr;
  if (dyn_model_load(p.urdf.c_str(), nj, names.data(), &d, err, sizeof err) != 0) {
    tap_ok(0, (robot + ": the rigid-body model loads").c_str(), err);
    return;
  }
  std::vector<double> g(6 + nj);
  dyn_set_state(d, base, qa.data(), nullptr);
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

}  // namespace

int main() {
  body_test("op3", 1);
  body_test("darwin", 2);
  body_test("hubo2plus", 3);
  body_test("waistbot", 4);
  return tap_done();
}
