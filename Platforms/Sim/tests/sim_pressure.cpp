// sim_pressure: the point pressure sensors under the soles (robot.lua `foot_pressure`,
// Platforms/Sim/pressure.h) and the truth's centre of pressure, TAP.
//   The model's maths: the sensors' forces sum to the sole's, never pull, and their centre of
//   pressure is the sole's inside their hull and the hull's nearest point outside it.
//   The HOAP-3 standing in the world: its eight sensors carry its weight, their centre of pressure
//   (field frame, through the sole frames' poses) is the truth's to within 1 mm and lies on the
//   soles; pushed sideways, both move by the statics' amount and still agree. A body without
//   sensors reads none.
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "pressure.h"
#include "stance.h"
#include "tap.h"
#include "world.h"

using sim::Mat3;
using sim::Vec3;

namespace {

// the sensors' sum and centre of pressure
void cop_of(const std::vector<double> &xy, const std::vector<double> &f, double *fz, double *cx, double *cy) {
  *fz = *cx = *cy = 0;
  for (size_t i = 0; i < f.size(); i++) {
    *fz += f[i];
    *cx += f[i] * xy[2 * i];
    *cy += f[i] * xy[2 * i + 1];
  }
  if (*fz > 0) {
    *cx /= *fz;
    *cy /= *fz;
  }
}

bool all_nonnegative(const std::vector<double> &f) {
  for (double v : f)
    if (!(v >= 0)) return false;
  return true;
}

void maths_test() {
  // the HOAP-3's left foot's rectangle: 0.083 x 0.047 m about (0.014, 0.005)
  const std::vector<double> xy = {0.0555, -0.0185, 0.0555, 0.0285, -0.0275, -0.0185, -0.0275, 0.0285};
  double fz, cx, cy;
  std::vector<double> f = sim::pressure_distribute(xy, 80, 0.014, 0.005);
  check(std::fabs(f[0] - 20) < 1e-9 && std::fabs(f[1] - 20) < 1e-9 && std::fabs(f[2] - 20) < 1e-9 &&
            std::fabs(f[3] - 20) < 1e-9,
        "pressure: the load at the rectangle's centre is shared equally");
  // near the front outer sensor: the plate lifts off the rear inner one and rests on three
  f = sim::pressure_distribute(xy, 80, 0.050, 0.025);
  cop_of(xy, f, &fz, &cx, &cy);
  printf("# near the front outer sensor: %.2f %.2f %.2f %.2f N\n", f[0], f[1], f[2], f[3]);
  check(f[2] == 0 && all_nonnegative(f) && std::fabs(fz - 80) < 1e-9 && std::fabs(cx - 0.050) < 1e-9 &&
            std::fabs(cy - 0.025) < 1e-9,
        "pressure: near a corner the opposite sensor reads 0 and the others give the centre of pressure exactly");
  // outside the sensors (between them and the sole's toe): the front row's line
  f = sim::pressure_distribute(xy, 80, 0.065, 0.0);
  cop_of(xy, f, &fz, &cx, &cy);
  check(f[2] == 0 && f[3] == 0 && std::fabs(fz - 80) < 1e-9 && std::fabs(cx - 0.0555) < 1e-9 && std::fabs(cy) < 1e-9,
        "pressure: ahead of the front row the sensors read the front row's nearest point");
  f = sim::pressure_distribute(xy, 80, -0.06, 0.05);
  cop_of(xy, f, &fz, &cx, &cy);
  check(std::fabs(cx + 0.0275) < 1e-9 && std::fabs(cy - 0.0285) < 1e-9 && f[2] == 0 && f[0] == 0 && f[1] == 0,
        "pressure: beyond a corner all the load is on that corner's sensor");
  // no load, or a bad one: nothing
  bool zero = true;
  for (double load : {0.0, -5.0, (double)NAN}) {
    for (double v : sim::pressure_distribute(xy, load, 0.01, 0)) zero = zero && v == 0;
  }
  for (double v : sim::pressure_distribute(xy, 10, NAN, 0)) zero = zero && v == 0;
  check(zero, "pressure: no load, a negative or NaN load or centre: every sensor reads 0");
  // a sweep over the hull, and a layout of five sensors not on a rectangle
  const std::vector<double> five = {0.06, 0.0, 0.02, 0.03, -0.03, 0.025, -0.03, -0.02, 0.03, -0.03};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> ux(-0.0275, 0.0555), uy(-0.0185, 0.0285), u5(-0.03, 0.06);
  double worst = 0;
  bool ok = true;
  for (int k = 0; k < 2000; k++) {
    const bool rect = k < 1000;
    const std::vector<double> &pts = rect ? xy : five;
    const double x = rect ? ux(rng) : u5(rng), y = rect ? uy(rng) : u5(rng);
    // for the five: only the points inside their hull (its edges, counter-clockwise)
    if (!rect) {
      bool inside = true;
      const int order[5] = {0, 1, 2, 3, 4};
      for (int e = 0; e < 5; e++) {
        const int a = order[e], b = order[(e + 1) % 5];
        const double ex = pts[2 * b] - pts[2 * a], ey = pts[2 * b + 1] - pts[2 * a + 1];
        if (ex * (y - pts[2 * a + 1]) - ey * (x - pts[2 * a]) < 0) inside = false;
      }
      if (!inside) continue;
    }
    f = sim::pressure_distribute(pts, 50, x, y);
    cop_of(pts, f, &fz, &cx, &cy);
    ok = ok && all_nonnegative(f) && std::fabs(fz - 50) < 1e-9;
    worst = std::max(worst, std::hypot(cx - x, cy - y));
  }
  printf("# sweep inside the sensors' hulls: worst centre-of-pressure error %.2g m\n", worst);
  check(ok && worst < 1e-9, "pressure: inside the hull (rectangle and five sensors) the sum and centre are the sole's, no sensor pulls");
  check(sim::pressure_layout_ok(xy) && sim::pressure_layout_ok(five), "pressure: a rectangle and five points are a layout");
  check(!sim::pressure_layout_ok({0, 0, 0.05, 0}) && !sim::pressure_layout_ok({0, 0, 0.05, 0, 0.1, 0.0005}) &&
            !sim::pressure_layout_ok({0, 0, 0.05, 0, NAN, 0.03}),
        "pressure: two points, three on a line (within 1 mm), a NaN: no layout");
}

// The sensors' centre of pressure in the field frame, on the carpet's plane, and their sum.
void sensor_cop(sim::World &w, const sim::Params &p, const sim::Sensors &s, double *fz, double *x, double *y) {
  *fz = *x = *y = 0;
  size_t i = 0;
  for (const sim::PressureFoot &foot : p.pressure) {
    Vec3 o;
    Mat3 R;
    if (!w.frame_pose(0, foot.frame, &o, &R)) throw std::runtime_error("no frame " + foot.frame);
    for (size_t k = 0; k + 1 < foot.xy.size(); k += 2, i++) {
      const Vec3 q = o + R * Vec3(foot.xy[k], foot.xy[k + 1], 0);
      *fz += s.pressure[i];
      *x += s.pressure[i] * q.x();
      *y += s.pressure[i] * q.y();
    }
  }
  if (*fz > 0) {
    *x /= *fz;
    *y /= *fz;
  }
}

void stand(sim::World &w, double seconds) {
  for (int k = 0; k < (int)std::lround(seconds / w.params().period); k++) w.step();
}

void hoap3_test() {
  std::vector<sim::Params> ps;
  std::vector<sim::Body> bs;
  sim::load_bodies({"hoap3"}, &ps, &bs);
  const sim::Params &p = ps[0];
  const sim::Model &m = bs[0].model;
  check(p.pressure.size() == 2 && p.pressure[0].xy.size() == 8 && p.pressure[1].xy.size() == 8,
        "hoap3: four pressure sensors under each foot");
  sim::World w(p, bs, 7);
  std::vector<double> q = sim::stance_pose(m, p);
  w.set_command(0, q.data(), nullptr, nullptr);
  w.place_robot(0, -2, 1, 0);
  stand(w, 2);
  sim::Sensors s;
  w.sense(0, &s);
  const sim::Truth t = w.truth(0);
  double fz, x, y;
  sensor_cop(w, p, s, &fz, &x, &y);
  const double weight = m.total_mass() * p.gravity;
  printf("# hoap3 standing: sensors (N) left %.2f %.2f %.2f %.2f right %.2f %.2f %.2f %.2f; sum %.2f N, weight %.2f N\n",
         s.pressure[0], s.pressure[1], s.pressure[2], s.pressure[3], s.pressure[4], s.pressure[5], s.pressure[6],
         s.pressure[7], fz, weight);
  printf("# hoap3 standing: centre of pressure from the sensors (%.4f, %.4f), truth (%.4f, %.4f) m: %.2f mm apart\n", x,
         y, t.cop[0], t.cop[1], 1e3 * std::hypot(x - t.cop[0], y - t.cop[1]));
  check(s.pressure.size() == 8 && std::fabs(fz - weight) < 0.03 * weight && std::fabs(t.cop[2] - weight) < 0.03 * weight,
        "hoap3 standing: the sensors carry the weight (3%), as the truth's normal force");
  check(std::hypot(x - t.cop[0], y - t.cop[1]) < 0.001, "hoap3 standing: the sensors' centre of pressure is the truth's (1 mm)");
  // on the soles: between the feet's sole frames sideways, within the soles' length (toe 0.068, heel
  // 0.040 about the ankles)
  Vec3 lo, ro;
  Mat3 R;
  w.frame_pose(0, "l_sole", &lo, &R);
  w.frame_pose(0, "r_sole", &ro, &R);
  const double mx = 0.5 * (lo.x() + ro.x());
  check(y < lo.y() && y > ro.y() && x > mx - 0.040 && x < mx + 0.068, "hoap3 standing: the centre of pressure under the feet");
  // pushed left with 4% of the weight for 2 s: the pressure moves left by about push * height / weight
  const double push = 0.04 * weight;
  w.push(0, 0, push, 2.0);
  stand(w, 1.5);
  sim::Sensors s2;
  w.sense(0, &s2);
  const sim::Truth t2 = w.truth(0);
  double fz2, x2, y2;
  sensor_cop(w, p, s2, &fz2, &x2, &y2);
  printf("# hoap3 pushed left with %.2f N: sensors' centre of pressure y %.4f -> %.4f m, truth %.4f -> %.4f m (%.2f mm apart)\n",
         push, y, y2, t.cop[1], t2.cop[1], 1e3 * std::hypot(x2 - t2.cop[0], y2 - t2.cop[1]));
  check(!t2.fallen && y2 - y > 0.005 && std::hypot(x2 - t2.cop[0], y2 - t2.cop[1]) < 0.001,
        "hoap3 pushed left: the sensors' centre of pressure moves left (> 5 mm) and stays the truth's (1 mm)");
}

void no_sensors_test() {
  std::vector<sim::Params> ps;
  std::vector<sim::Body> bs;
  sim::load_bodies({"op3"}, &ps, &bs);
  sim::World w(ps[0], bs, 7);
  std::vector<double> q = sim::stance_pose(bs[0].model, ps[0]);
  w.set_command(0, q.data(), nullptr, nullptr);
  w.place_robot(0, -2, 1, 0);   // away from the ball at the centre
  stand(w, 1.5);
  sim::Sensors s;
  w.sense(0, &s);
  const double weight = bs[0].model.total_mass() * ps[0].gravity;
  printf("# op3 standing: %zu pressure sensors; the truth's normal force %.2f N, weight %.2f N\n", s.pressure.size(),
         w.truth(0).cop[2], weight);
  check(s.pressure.empty() && std::fabs(w.truth(0).cop[2] - weight) < 0.03 * weight,
        "op3: no pressure sensors, the truth (the ground's forces on it) carries its weight");
}

}  // namespace

int main() {
  try {
    maths_test();
    hoap3_test();
    no_sensors_test();
  } catch (const std::exception &e) {
    check(false, e.what());
  }
  return tap_done();
}
