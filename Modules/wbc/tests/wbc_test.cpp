// Unit tests of the kinematic whole-body controller (Modules/wbc/wbc.h) on the Hubo2+'s and the
// OP3's models (TAP), without a simulator: hand and centre-of-mass targets reached in the model,
// the soles held, a posture below a hand moving the hand by nothing, joint limits kept, bad input
// refused by name. The simulated robot's figures are the scenario tests' (Tests/wbc).
#include "wbc/wbc.h"
#include "tap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct Ctl {
  wbc *w = nullptr;
  int nj = 0;
  std::vector<double> q, lo, hi;
  ~Ctl() { wbc_free(w); }
  int joint(const char *name) const {
    for (int j = 0; j < nj; j++)
      if (!strcmp(wbc_joint_name(w, j), name)) return j;
    return -1;
  }
};

std::string urdf_of(const char *body) { return std::string(HRP_ROOT_DEFAULT) + "/Config/robots/" + body + "/" + body + ".urdf"; }

bool make(Ctl *c, const char *body, double dt, const std::vector<std::pair<const char *, double>> &pose,
          const char *lsole, const char *rsole) {
  char err[512];
  if (wbc_new(urdf_of(body).c_str(), 0, nullptr, dt, &c->w, err, sizeof err) < 0) {
    tap_ok(0, (std::string(body) + ": controller built").c_str(), err);
    return false;
  }
  c->nj = wbc_njoint(c->w);
  c->q.assign(c->nj, 0.0);
  for (auto &p : pose) c->q[c->joint(p.first)] = p.second;
  // limits: +-2.5 rad, knees bent only, 3 rad/s (the test's, not a body's)
  c->lo.assign(c->nj, -2.5);
  c->hi.assign(c->nj, 2.5);
  std::vector<double> speed(c->nj, 3.0);
  wbc_set_limits(c->w, c->lo.data(), c->hi.data(), speed.data());
  const char *soles[2] = { lsole, rsole };
  wbc_set_contacts(c->w, 2, soles);
  return wbc_reset(c->w, c->q.data()) == 0;
}

double dist(const double *a, const double *b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

std::string fmt(const char *f, double a, double b = 0, double c = 0) {
  char s[160];
  snprintf(s, sizeof s, f, a, b, c);
  return s;
}

void hubo_tests() {
  Ctl c;
  // the Hubo2+'s crouch (its safe pose): knees bent, feet flat under the hips
  const std::vector<std::pair<const char *, double>> crouch = {
    { "LHR", 0.016 }, { "LHP", -0.709 }, { "LKN", 1.315 }, { "LAP", -0.605 }, { "LAR", -0.016 },
    { "RHR", -0.016 }, { "RHP", -0.709 }, { "RKN", 1.315 }, { "RAP", -0.605 }, { "RAR", 0.016 },
    { "LEB", -0.5 }, { "REB", -0.5 } };
  if (!make(&c, "hubo2plus", 0.005, crouch, "l_sole", "r_sole")) {
    tap_ok(0, "hubo2plus: reset", wbc_error(c.w));
    return;
  }
  double l0[3], r0[3], p[3], com0[3];
  wbc_frame_pose(c.w, "l_sole", l0, nullptr);
  wbc_frame_pose(c.w, "r_sole", r0, nullptr);
  wbc_frame_pose(c.w, "com", com0, nullptr);
  tap_ok(std::fabs(l0[0] + r0[0]) < 1e-9 && std::fabs(l0[1] + r0[1]) < 1e-9 && std::fabs(l0[2]) < 1e-6 &&
             std::fabs(r0[2]) < 1e-6 && l0[1] > 0,
         "hubo2plus: the stance frame lies midway between the soles, on the ground",
         fmt("l_sole %.3f %.3f %.1e", l0[0], l0[1], l0[2]).c_str());
  const int com = wbc_task_add(c.w, "com", WBC_COM_XY, nullptr, 1, 5, 0.2);
  const int hand = wbc_task_add(c.w, "r_palm", WBC_POSITION, "r_palm", 2, 5, 0.5);
  const int posture = wbc_task_add(c.w, "posture", WBC_POSTURE, nullptr, 3, 1, 1.0);
  const double com_xy[2] = { 0, 0 };
  wbc_task_target(c.w, com, com_xy, 2);
  wbc_task_target(c.w, posture, c.q.data(), c.nj);
  // five hand targets, some ahead of what the arm reaches without the torso
  const double targets[5][3] = { { 0.30, -0.25, 0.80 }, { 0.35, -0.25, 0.90 }, { 0.40, -0.15, 0.85 },
                                 { 0.45, -0.20, 0.75 }, { 0.25, -0.35, 1.00 } };
  double worst_hand = 0, worst_sole = 0, worst_com = 0, worst_limit = 0, tick = 0;
  for (auto &t : targets) {
    wbc_task_target(c.w, hand, t, 3);
    for (int k = 0; k < 600; k++) {   // 3 s at 200 Hz
      wbc_step(c.w, c.q.data());
      tick = std::max(tick, wbc_step_us(c.w));
      for (int j = 0; j < c.nj; j++)
        worst_limit = std::max(worst_limit, std::max(c.q[j] - c.hi[j], c.lo[j] - c.q[j]));
    }
    wbc_frame_pose(c.w, "r_palm", p, nullptr);
    worst_hand = std::max(worst_hand, dist(p, t));
    double l[3], r[3], cm[3];
    wbc_frame_pose(c.w, "l_sole", l, nullptr);
    wbc_frame_pose(c.w, "r_sole", r, nullptr);
    wbc_frame_pose(c.w, "com", cm, nullptr);
    worst_sole = std::max(worst_sole, std::max(dist(l, l0), dist(r, r0)));
    worst_com = std::max(worst_com, std::hypot(cm[0], cm[1]));
  }
  wbc_task_status st;
  wbc_task_status_of(c.w, hand, &st);
  tap_ok(worst_hand < 1e-3, "hubo2plus: five hand targets up to 0.45 m ahead reached in the model within 3 s each",
         fmt("worst %.2e m", worst_hand).c_str());
  tap_ok(worst_sole < 1e-4 && worst_com < 1e-3, "hubo2plus: meanwhile the soles held and the COM over the stance centre",
         fmt("soles moved %.1e m, COM off %.1e m", worst_sole, worst_com).c_str());
  tap_ok(worst_limit <= 1e-12, "hubo2plus: no joint beyond its limits", fmt("worst excess %.1e rad", worst_limit).c_str());
  tap_ok(st.feasible && st.level == 2 && st.error < 1e-3, "hubo2plus: the hand's task reports feasible at its level",
         fmt("level %.0f, sigma_min %.3f", st.level, st.sigma_min).c_str());

  // the posture below the hand: a new posture target or ten times its gain moves the hand by nothing
  double before[3], after[3];
  wbc_frame_pose(c.w, "r_palm", before, nullptr);
  std::vector<double> other = c.q;
  for (int j = 0; j < c.nj; j++) other[j] += 0.3 * std::sin(1.0 + j);
  wbc_task_target(c.w, posture, other.data(), c.nj);
  wbc_task_gain(c.w, posture, 10);
  for (int k = 0; k < 400; k++) wbc_step(c.w, c.q.data());
  wbc_frame_pose(c.w, "r_palm", after, nullptr);
  tap_ok(dist(before, after) < 1e-4, "hubo2plus: the posture task's target changed and its gain x10: the hand stays",
         fmt("hand moved %.1e m", dist(before, after)).c_str());

  // out of reach: flagged, the soles and the balance kept
  const double far[3] = { 1.5, -0.3, 0.9 };
  wbc_task_target(c.w, hand, far, 3);
  for (int k = 0; k < 600; k++) wbc_step(c.w, c.q.data());
  wbc_task_status_of(c.w, hand, &st);
  double l[3], cm[3];
  wbc_frame_pose(c.w, "l_sole", l, nullptr);
  wbc_frame_pose(c.w, "com", cm, nullptr);
  tap_ok(!st.feasible && dist(l, l0) < 1e-4 && std::hypot(cm[0], cm[1]) < 1e-3,
         "hubo2plus: a target 1.5 m ahead: the hand's task infeasible, the soles and the COM held",
         fmt("hand error %.2f m, sigma_min %.2e, COM off %.1e m", st.error, st.sigma_min, std::hypot(cm[0], cm[1])).c_str());
  printf("# hubo2plus: a step (COM, hand, posture over two contacts; 27 joints + base) took at most %.0f us\n", tick);

  // bad input, refused by name; nothing changes
  bool refused = wbc_task_add(c.w, "x", WBC_POSITION, "no_such_frame", 2, 1, 0) < 0;
  tap_ok(refused && strstr(wbc_error(c.w), "no_such_frame"), "an unknown frame is refused by name", wbc_error(c.w));
  const double nan3[3] = { 0.3, NAN, 0.9 };
  refused = wbc_task_target(c.w, hand, nan3, 3) < 0;
  tap_ok(refused && strstr(wbc_error(c.w), "r_palm"), "a NaN target is refused", wbc_error(c.w));
  const double rot[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 2 };
  const int ori = wbc_task_add(c.w, "torso", WBC_ORIENTATION, "torso", 2, 1, 0);
  refused = ori >= 0 && wbc_task_target(c.w, ori, rot, 9) < 0;
  tap_ok(refused && strstr(wbc_error(c.w), "rotation"), "an orientation target that is not a rotation is refused",
         wbc_error(c.w));
  refused = wbc_task_target(c.w, hand, far, 2) < 0;
  tap_ok(refused, "a target of the wrong size is refused", wbc_error(c.w));
  wbc_task_status_of(c.w, hand, &st);
  tap_ok(st.enabled, "after the refusals the hand's task keeps its target", "");
}

void op3_tests() {
  Ctl c;
  // the OP3's crouch (its safe pose)
  const std::vector<std::pair<const char *, double>> crouch = {
    { "l_hip_roll", -0.062 }, { "l_hip_pitch", -0.732 }, { "l_knee", 1.495 }, { "l_ank_pitch", 0.844 },
    { "l_ank_roll", -0.062 }, { "r_hip_roll", 0.062 }, { "r_hip_pitch", 0.732 }, { "r_knee", -1.495 },
    { "r_ank_pitch", -0.844 }, { "r_ank_roll", 0.062 } };
  if (!make(&c, "op3", 0.008, crouch, "l_sole", "r_sole")) {
    tap_ok(0, "op3: reset", wbc_error(c.w));
    return;
  }
  // the COM over the left foot, then the right foot released and lifted 5 cm
  double l0[3], r0[3], rot[9];
  wbc_frame_pose(c.w, "l_sole", l0, nullptr);
  wbc_frame_pose(c.w, "r_sole", r0, rot);
  const int com = wbc_task_add(c.w, "com", WBC_COM_XY, nullptr, 1, 4, 0.1);
  const int posture = wbc_task_add(c.w, "posture", WBC_POSTURE, nullptr, 3, 1, 1.0);
  wbc_task_target(c.w, com, l0, 2);
  wbc_task_target(c.w, posture, c.q.data(), c.nj);
  for (int k = 0; k < 250; k++) wbc_step(c.w, c.q.data());
  const char *left[1] = { "l_sole" };
  const bool released = wbc_set_contacts(c.w, 1, left) == 0;
  tap_ok(released, "op3: the right sole released while running, the left the only contact", wbc_error(c.w));
  double l1[3], r1[3], cm[3];
  wbc_frame_pose(c.w, "l_sole", l1, nullptr);
  wbc_frame_pose(c.w, "r_sole", r1, rot);
  const int foot = wbc_task_add(c.w, "r_sole", WBC_POSE, "r_sole", 2, 4, 0.1);
  double lift[12] = { r1[0], r1[1], r1[2] + 0.05 };
  memcpy(lift + 3, rot, sizeof rot);
  wbc_task_target(c.w, com, l1, 2);
  wbc_task_target(c.w, foot, lift, 12);
  for (int k = 0; k < 250; k++) wbc_step(c.w, c.q.data());
  double r2[3];
  wbc_frame_pose(c.w, "r_sole", r2, nullptr);
  wbc_frame_pose(c.w, "com", cm, nullptr);
  double l2[3];
  wbc_frame_pose(c.w, "l_sole", l2, nullptr);
  tap_ok(std::fabs(r2[2] - r1[2] - 0.05) < 1e-3 && std::hypot(cm[0] - l2[0], cm[1] - l2[1]) < 1e-3 && dist(l0, l2) < 1e-4,
         "op3: the COM over the left sole, the right foot lifted 5 cm in the model",
         fmt("lift %.4f m, COM off the sole %.1e m", r2[2] - r1[2], std::hypot(cm[0] - l2[0], cm[1] - l2[1])).c_str());
}

}  // namespace

int main() {
  hubo_tests();
  op3_tests();
  return tap_done();
}
