// Unit tests of the self-collision checker (Modules/collide/collide.h) on the Hubo2+'s collision boxes
// (TAP): the zero pose free once the pairs of near links are dropped, the right hand swung across the
// belly against the body with the pair named, a NaN and a bad joint order refused by name.
#include "collide/collide.h"
#include "tap.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

const std::vector<std::string> JOINTS = {
  "WST", "NK1", "NK2", "LSP", "LSR", "LSY", "LEB", "LWY", "LWP", "RSP", "RSR", "RSY", "REB", "RWY", "RWP",
  "LHY", "LHR", "LHP", "LKN", "LAP", "LAR", "RHY", "RHR", "RHP", "RKN", "RAP", "RAR" };

int index_of(const char *name) {
  for (size_t j = 0; j < JOINTS.size(); j++)
    if (JOINTS[j] == name) return (int)j;
  return -1;
}

}  // namespace

int main() {
  const std::string urdf = std::string(HRP_ROOT_DEFAULT) + "/Config/robots/hubo2plus/hubo2plus.urdf";
  std::vector<const char *> names;
  for (auto &j : JOINTS) names.push_back(j.c_str());
  char err[512];
  collide *c = nullptr;
  int rc = collide_new(urdf.c_str(), (int)names.size(), names.data(), &c, err, sizeof err);
  tap_ok(rc == 0, "the Hubo2+'s checker built", rc == 0 ? nullptr : err);
  if (rc != 0) return tap_done();
  const int all = collide_npair(c);
  check(collide_set_margin(c, 0.005) == 0, "a 5 mm margin taken");
  const int near = collide_ignore_near(c, 3);
  std::vector<double> q(JOINTS.size(), 0.0);
  const int touching = collide_ignore_at(c, q.data());
  char detail[160];
  snprintf(detail, sizeof detail, "%d pairs, %d of links up to 3 joints apart and %d touching at zero dropped", all, near,
           touching);
  tap_ok(all > 1000 && near > 0 && collide_npair(c) == all - near - touching, "pairs counted and dropped", detail);
  check(collide_check(c, q.data(), nullptr) == 0, "the zero pose is free");
  // the right forearm bent forward and swung across the belly
  q[index_of("REB")] = -1.6;
  q[index_of("RSP")] = -0.3;
  q[index_of("RSY")] = 1.5;
  int first = -1;
  const int hits = collide_check(c, q.data(), &first);
  const char *a = collide_pair_link(c, first, 0), *b = collide_pair_link(c, first, 1);
  snprintf(detail, sizeof detail, "%d pairs, first %s against %s, %.0f us", hits, a ? a : "?", b ? b : "?",
           collide_check_us(c));
  tap_ok(hits > 0 && a && b && (strstr(a, "r_") || strstr(b, "r_")), "the right arm across the belly collides", detail);
  q[index_of("RSY")] = -1.5;
  check(collide_check(c, q.data(), nullptr) == 0, "the same forearm swung outwards is free");
  q[0] = NAN;
  rc = collide_check(c, q.data(), nullptr);
  tap_ok(rc < 0 && strstr(collide_error(c), "WST"), "a NaN angle refused by joint", collide_error(c));
  check(collide_pair_link(c, -1, 0) == nullptr && collide_pair_link(c, 0, 2) == nullptr, "a pair out of range: NULL");
  check(collide_set_margin(c, -1) < 0, "a negative margin refused");
  collide_free(c);
  names[3] = "XYZ";
  collide *bad = nullptr;
  rc = collide_new(urdf.c_str(), (int)names.size(), names.data(), &bad, err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "XYZ") && !bad, "a joint order naming no joint refused by name", err);
  return tap_done();
}
