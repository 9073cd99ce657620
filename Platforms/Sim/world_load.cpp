// world_load: the bodies of a world -- each one's Params and robot description, checked against
// each other -- and the project's paths.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "world_internal.h"

namespace sim {

std::string hrp_root() {
  const char *r = getenv("HRP_ROOT");
  return r && *r ? r : HRP_ROOT_DEFAULT;
}

std::string robot_dir(const std::string &robot) { return hrp_root() + "/Config/robots/" + robot; }

// Every joint of a description is driven: each must be in the robot's joint list.
static void check_joints(const Params &p, const Model &m) {
  for (const Link &l : m.links) {
    if (!l.joint.empty() && std::find(p.joints.begin(), p.joints.end(), l.joint) == p.joints.end()) {
      throw std::runtime_error(p.urdf + ": joint '" + l.joint + "' is not in the robot config's joints");
    }
  }
}

void load_all(Params *p, Model *m, const std::string &ball_kind) {
  params_load("", p);
  if (!ball_kind.empty()) p->ball_kind = ball_kind;
  std::string err;
  if (model_load(p->urdf, m, &err) < 0) throw std::runtime_error(err);
  check_joints(*p, *m);
}

void load_bodies(const std::vector<std::string> &robots, std::vector<Params> *params, std::vector<Body> *bodies) {
  params->clear();
  bodies->clear();
  for (size_t r = 0; r < robots.size(); r++) {
    size_t same = 0;   // a body already loaded is copied, not read again
    while (same < r && robots[same] != robots[r]) same++;
    if (same < r) {
      params->push_back((*params)[same]);
      bodies->push_back((*bodies)[same]);
      continue;
    }
    Params p;
    params_load(robots[r], &p);
    Body b;
    std::string err;
    if (model_load(p.urdf, &b.model, &err) < 0) throw std::runtime_error(err);
    check_joints(p, b.model);
    b.joints = p.joints;
    b.servos = p.servos;
    b.ft = p.ft;
    b.pressure = p.pressure;
    // one world steps every robot with one control period
    if (r > 0 && std::fabs(p.period - (*params)[0].period) > 1e-12) {
      throw std::runtime_error("robot '" + robots[r] + "' has a control period of " + std::to_string(p.period) +
                               " s, robot '" + robots[0] + "' one of " + std::to_string((*params)[0].period) +
                               " s: one world steps all robots with one period (robot.lua 'period')");
    }
    params->push_back(p);
    bodies->push_back(std::move(b));
  }
}

}  // namespace sim
