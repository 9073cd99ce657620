// sim_ft: the 6-axis force/torque sensors of the simulated bodies (robot.lua `ft`), TAP.
//   Standing in the stance pose: the feet's fz carry the weight above the sensors; each foot's centre
//   of pressure from (fx, fy, mx, my) lies on its sole; the sensors' moments balance the weight
//   above them about its centre of mass (statics of the robot minus its feet). A sideways push on
//   the torso moves load and pressure toward the push. A body without sensors reads 0.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "stance.h"
#include "world.h"
#include "tap.h"

using sim::Mat3;
using sim::Vec3;

namespace {

// links of the subtree under (and including) link li
std::vector<char> subtree(const sim::Model &m, int li) {
  std::vector<char> in(m.links.size(), 0);
  in[li] = 1;
  for (size_t i = 0; i < m.links.size(); i++)   // parents come first
    if (m.links[i].parent >= 0 && in[m.links[i].parent]) in[i] = 1;
  return in;
}

// the sole's footprint in link li's frame: the rectangle around its sole boxes (min x, max x, min y,
// max y) and the height of the sensor (the link frame) above the sole's bottom
struct Sole { double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9, d = 0; };
bool sole_of(const sim::Model &m, int li, Sole *so) {
  bool any = false;
  for (const sim::Box &b : m.links[li].boxes) {
    if (!b.sole) continue;
    any = true;
    so->x0 = std::min(so->x0, b.pos.x() - b.size.x() / 2);
    so->x1 = std::max(so->x1, b.pos.x() + b.size.x() / 2);
    so->y0 = std::min(so->y0, b.pos.y() - b.size.y() / 2);
    so->y1 = std::max(so->y1, b.pos.y() + b.size.y() / 2);
    so->d = -(b.pos.z() - b.size.z() / 2);
  }
  return any;
}

// centre of pressure (x, y at the sole's plane, link frame) from one sensor's wrench
void foot_cop(const Sole &so, const double *ft, double *px, double *py) {
  *px = -(ft[4] + ft[0] * so.d) / ft[2];
  *py = (ft[3] - ft[1] * so.d) / ft[2];
}

// the feet's common centre of pressure, field frame (y)
double cop_y(sim::World &w, const int *link, const Sole *so, const double *ft) {
  double num = 0, den = 0;
  for (int k = 0; k < 2; k++) {
    double px, py;
    foot_cop(so[k], ft + 6 * k, &px, &py);
    Vec3 a;
    Mat3 R;
    w.link_pose(0, link[k], &a, &R);
    num += ft[6 * k + 2] * (a + R * Vec3(px, py, -so[k].d)).y();
    den += ft[6 * k + 2];
  }
  return num / den;
}

void stand(sim::World &w, double seconds) {
  for (int k = 0; k < (int)std::lround(seconds / w.params().period); k++) w.step();
}

void body_test(const std::string &robot) {
  std::vector<sim::Params> ps;
  std::vector<sim::Body> bs;
  sim::load_bodies({robot}, &ps, &bs);
  const sim::Params &p = ps[0];
  const sim::Model &m = bs[0].model;
  sim::World w(p, bs, 7);
  std::vector<double> q = sim::stance_pose(m, p);
  // hands with a sensor held clear of the body: the shoulder's roll joint (the roll joint nearest
  // the torso on the hand's chain) turned 0.4 rad outward
  std::vector<Vec3> zp;
  std::vector<Mat3> zr;
  m.zero_pose(&zp, &zr);
  for (int k = 2; k < 4; k++) {
    if (p.ft[k].empty()) continue;
    int roll = -1;
    for (int li = m.joint_link(p.ft[k]); li > 0; li = m.links[li].parent)
      if (std::fabs((zr[li] * m.links[li].axis).x()) > 0.9) roll = li;
    if (roll < 0) continue;
    const double sx = (zr[roll] * m.links[roll].axis).x() > 0 ? 1 : -1, side = zp[roll].y() > 0 ? 1 : -1;
    const size_t j = std::find(p.joints.begin(), p.joints.end(), m.links[roll].joint) - p.joints.begin();
    q[j] = std::min(std::max(q[j] + sx * side * 0.4, m.links[roll].lower), m.links[roll].upper);
  }
  w.set_command(0, q.data(), nullptr, nullptr);
  w.place_robot(0, -2, 1, 0);
  stand(w, 2);
  sim::Sensors s;
  w.sense(0, &s);
  const char *tag = robot.c_str();
  if (p.ft[0].empty() || p.ft[1].empty()) {
    double sum = 0;
    for (double v : s.ft) sum += std::fabs(v);
    check(sum == 0, robot + ": no ft table, every ft slot reads 0");
    return;
  }
  const int lf = m.joint_link(p.ft[0]), rf = m.joint_link(p.ft[1]);
  std::vector<char> feet = subtree(m, lf), rfeet = subtree(m, rf);
  for (size_t i = 0; i < feet.size(); i++) feet[i] |= rfeet[i];
  // weight above the sensors and its centre of mass, from the link poses
  double mass = 0;
  Vec3 com = Vec3::Zero();
  for (size_t i = 0; i < m.links.size(); i++) {
    if (feet[i]) continue;
    Vec3 pos;
    Mat3 R;
    w.link_pose(0, (int)i, &pos, &R);
    mass += m.links[i].mass;
    com += m.links[i].mass * (pos + R * m.links[i].com);
  }
  com /= mass;
  const double above = mass * p.gravity, weight = m.total_mass() * p.gravity;
  const double fz = s.ft[2] + s.ft[8];
  printf("# %s standing: fz left %.2f right %.2f, sum %.2f N; weight above the sensors %.2f N, whole robot %.2f N\n",
         tag, s.ft[2], s.ft[8], fz, above, weight);
  check(std::fabs(fz - above) < 0.03 * above, robot + ": standing, the feet's fz sum to the weight above the sensors (3%)");
  // statics of everything above the sensors: the sensors' moments about the origin balance the weight
  Vec3 mom = Vec3::Zero(), force = Vec3::Zero();
  for (int k = 0; k < 2; k++) {
    Vec3 a;
    Mat3 R;
    w.link_pose(0, k ? rf : lf, &a, &R);
    const Vec3 f = R * Vec3(s.ft[6 * k], s.ft[6 * k + 1], s.ft[6 * k + 2]);
    const Vec3 t = R * Vec3(s.ft[6 * k + 3], s.ft[6 * k + 4], s.ft[6 * k + 5]);
    mom += a.cross(f) + t;
    force += f;
  }
  const double cx = -mom.y() / force.z(), cy = mom.x() / force.z();
  const double err = std::hypot(cx - com.x(), cy - com.y());
  printf("# %s: centre of mass above the sensors from their moments (%.4f, %.4f), from the link poses (%.4f, %.4f) m: %.2f mm\n",
         tag, cx, cy, com.x(), com.y(), err * 1e3);
  // a hand's sensor carries the hand (what hangs below it): in the world, straight down
  for (int k = 2; k < 4; k++) {
    if (p.ft[k].empty()) continue;
    const int hl = m.joint_link(p.ft[k]);
    const std::vector<char> hand = subtree(m, hl);
    double hm = 0;
    for (size_t i = 0; i < hand.size(); i++) hm += hand[i] ? m.links[i].mass : 0;
    Vec3 a;
    Mat3 R;
    sim::Sensors sh;
    // the mean over 1 s: a 0.3 kg hand on the Hubo's stiff drives rings (a reading is one step's)
    Vec3 f = Vec3::Zero();
    const int n = (int)std::lround(1.0 / p.period);
    sim::World wh(p, bs, 7);
    wh.set_command(0, q.data(), nullptr, nullptr);
    wh.place_robot(0, -2, 1, 0);
    stand(wh, 2);
    for (int i = 0; i < n; i++) {
      wh.step();
      wh.sense(0, &sh);
      wh.link_pose(0, hl, &a, &R);
      f += R * Vec3(sh.ft[6 * k], sh.ft[6 * k + 1], sh.ft[6 * k + 2]) / n;
    }
    printf("# %s %s hand: force (%.3f, %.3f, %.3f) N in the field frame; the hand's weight %.3f N\n", tag,
           k == 2 ? "left" : "right", f.x(), f.y(), f.z(), hm * p.gravity);
    // vertical within 5%; sideways within 30%: the mean of one step per tick aliases the ringing
    check(std::fabs(f.z() + hm * p.gravity) < 0.05 * hm * p.gravity && std::hypot(f.x(), f.y()) < 0.3 * hm * p.gravity,
          robot + (k == 2 ? ": left" : ": right") + " hand's sensor carries the hand's weight (5%, 30% sideways)");
  }
  const int link[2] = {lf, rf};
  Sole so[2];
  if (!sole_of(m, lf, &so[0]) || !sole_of(m, rf, &so[1])) throw std::runtime_error(robot + ": the ft links carry no sole");
  const double tol = 0.03 * (so[0].x1 - so[0].x0);
  check(err < tol, robot + ": the sensors' torques balance the weight above them about its centre of mass (3% of the foot)");
  for (int k = 0; k < 2; k++) {
    double px, py;
    foot_cop(so[k], s.ft + 6 * k, &px, &py);
    printf("# %s %s foot: centre of pressure (%.4f, %.4f) m in its frame; sole x %.4f..%.4f, y %.4f..%.4f\n", tag,
           k ? "right" : "left", px, py, so[k].x0, so[k].x1, so[k].y0, so[k].y1);
    check(px > so[k].x0 && px < so[k].x1 && py > so[k].y0 && py < so[k].y1,
          robot + (k ? ": right" : ": left") + " foot's centre of pressure lies on its sole");
  }
  // push the torso toward +y (the robot's left) with 4% of its weight: load and pressure move left;
  // statics alone (the centre of mass held) move the pressure by push x its height / weight
  const double push = 0.04 * weight, y0 = cop_y(w, link, so, s.ft);
  w.push(0, 0, push, 2.0);
  stand(w, 1.5);
  sim::Sensors s2;
  w.sense(0, &s2);
  const double y1 = cop_y(w, link, so, s2.ft);
  const double lever = push * (com.z() + so[0].d) / weight;
  printf("# %s pushed left with %.2f N: fz left %.2f right %.2f N; feet's centre of pressure y %.4f -> %.4f m "
         "(statics alone: +%.4f); fy sum %.2f N\n", tag, push, s2.ft[2], s2.ft[8], y0, y1, lever, s2.ft[1] + s2.ft[7]);
  check(!w.truth(0).fallen, robot + ": stands the push");
  check(s2.ft[2] - s.ft[2] > 0.1 * s.ft[2] && s.ft[8] - s2.ft[8] > 0.1 * s.ft[8],
        robot + ": pushed left, the left foot's fz rises and the right's falls (by > 10%)");
  check(y1 - y0 > 0.5 * lever, robot + ": pushed left, the feet's centre of pressure moves left (> half the statics)");
  check(std::fabs(s2.ft[1] + s2.ft[7] + push) < 0.25 * push, robot + ": the feet's fy take up the push (25%)");
}

}  // namespace

int main() {
  try {
    for (const char *robot : {"op3", "hubo2plus", "waistbot"}) body_test(robot);
  } catch (const std::exception &e) {
    check(false, e.what());
  }
  return tap_done();
}
