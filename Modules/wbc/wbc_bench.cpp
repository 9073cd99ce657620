// Speed of one whole-body controller step (Modules/wbc) on a body: two contacts, the COM over the
// feet, both palms moving (position tasks on their level), a posture; CPU time per step (thread
// clock), median and p99 over N steps. `make bench BENCH=wbc` prints it beside the dynamics
// library's own times (build/bin/dyn_bench).
//   build/bin/wbc_bench [steps] [body]     (default 5000 hubo2plus)
#include "wbc/wbc.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char **argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 5000;
  const std::string body = argc > 2 ? argv[2] : "hubo2plus";
  const std::string urdf = std::string(HRP_ROOT_DEFAULT) + "/Config/robots/" + body + "/" + body + ".urdf";
  char err[512];
  wbc *w = nullptr;
  if (wbc_new(urdf.c_str(), 0, nullptr, 0.005, &w, err, sizeof err) < 0) {
    fprintf(stderr, "wbc_bench: %s\n", err);
    return 1;
  }
  const int nj = wbc_njoint(w);
  // a bent-knee stance: the knees and hips of any body whose joint names say so, bent a little
  std::vector<double> q(nj, 0.0);
  for (int j = 0; j < nj; j++) {
    const std::string n = wbc_joint_name(w, j);
    if (n == "LKN" || n == "RKN") q[j] = 1.0;
    if (n == "LHP" || n == "RHP" || n == "LAP" || n == "RAP") q[j] = -0.5;
    if (n == "LEB" || n == "REB") q[j] = -0.5;
  }
  const char *soles[2] = { "l_sole", "r_sole" };
  if (wbc_set_contacts(w, 2, soles) < 0 || wbc_reset(w, q.data()) < 0) {
    fprintf(stderr, "wbc_bench: %s\n", wbc_error(w));
    return 1;
  }
  const int com = wbc_task_add(w, "com", WBC_COM_XY, nullptr, 1, 4, 0.05);
  const int rh = wbc_task_add(w, "r_palm", WBC_POSITION, "r_palm", 2, 3, 0.15);
  const int lh = wbc_task_add(w, "l_palm", WBC_POSITION, "l_palm", 2, 3, 0.15);
  const int posture = wbc_task_add(w, "posture", WBC_POSTURE, nullptr, 3, 1, 0.5);
  if (com < 0 || rh < 0 || lh < 0 || posture < 0) {
    fprintf(stderr, "wbc_bench: %s\n", wbc_error(w));
    return 1;
  }
  const double c0[2] = { 0, 0 };
  wbc_task_target(w, com, c0, 2);
  wbc_task_target(w, posture, q.data(), nj);
  std::vector<double> us;
  us.reserve(steps);
  for (int k = 0; k < steps; k++) {
    const double t = k * 0.005;
    const double r[3] = { 0.35 + 0.05 * std::sin(t), -0.25, 0.85 + 0.05 * std::cos(t) };
    const double l[3] = { 0.30, 0.25 + 0.05 * std::sin(0.7 * t), 0.85 };
    wbc_task_target(w, rh, r, 3);
    wbc_task_target(w, lh, l, 3);
    wbc_step(w, q.data());
    us.push_back(wbc_step_us(w));
  }
  std::sort(us.begin(), us.end());
  printf("wbc step, %s (%d joints + floating base; 2 contacts, COM, two palms, posture), %d steps:\n", body.c_str(), nj,
         steps);
  printf("  median %.0f us, p99 %.0f us, max %.0f us of CPU\n", us[us.size() / 2], us[(size_t)(us.size() * 0.99)],
         us.back());
  wbc_free(w);
  return 0;
}
