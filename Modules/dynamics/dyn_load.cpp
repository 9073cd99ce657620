// dyn_model_load: a body's URDF with a free-flyer base through Pinocchio's parser, and the map from
// the caller's joint order (robot.lua `joints`) to Pinocchio's.
#include "dynamics/dyn_model.hpp"

#include <pinocchio/algorithm/joint-configuration.hpp>
#include <pinocchio/parsers/urdf.hpp>

#include <cstdio>
#include <exception>
#include <memory>
#include <set>

namespace {

int refuse(char *err, size_t errlen, const std::string &msg) {
  if (err && errlen) snprintf(err, errlen, "%s", msg.c_str());
  return DYN_EMODEL;
}

// The caller's joint order against the URDF's movable joints; empty on success, else the message.
std::string map_joints(dyn_model &d, const std::string &urdf, int njoint, const char *const *joints) {
  const pinocchio::Model &pm = d.model;
  if (pm.njoints < 2 || pm.joints[1].shortname() != "JointModelFreeFlyer")
    return urdf + ": no floating base joint in the model";
  if (joints) {
    for (int j = 0; j < njoint; j++) {
      if (!joints[j]) return urdf + ": joint order entry " + std::to_string(j + 1) + " is NULL";
      d.joints.emplace_back(joints[j]);
    }
  } else {
    for (int i = 2; i < (int)pm.njoints; i++) d.joints.push_back(pm.names[i]);
  }
  std::set<std::string> seen;
  d.vcol.assign(6, 0);
  for (int c = 0; c < 6; c++) d.vcol[c] = c;
  for (const std::string &name : d.joints) {
    if (!seen.insert(name).second) return "joint '" + name + "' is named twice in the joint order";
    if (!pm.existJointName(name)) return "joint '" + name + "' of the joint order is not a movable joint of " + urdf;
    auto id = pm.getJointId(name);
    if (pm.nvs[id] != 1 || pm.nqs[id] != 1)
      return urdf + ": joint '" + name + "' has " + std::to_string(pm.nqs[id]) +
             " position coordinates: only revolute and prismatic joints are supported";
    d.vcol.push_back(pm.idx_vs[id]);
    d.qidx.push_back(pm.idx_qs[id]);
  }
  for (int i = 2; i < (int)pm.njoints; i++)
    if (!seen.count(pm.names[i])) return urdf + ": joint '" + pm.names[i] + "' is missing from the joint order";
  return "";
}

// Frame names: a link's body frame wins over a joint's frame of the same name.
void map_frames(dyn_model &d) {
  const pinocchio::Model &pm = d.model;
  for (int pass = 0; pass < 2; pass++)
    for (int f = 0; f < (int)pm.nframes; f++) {
      bool body = pm.frames[f].type == pinocchio::BODY;
      if ((pass == 0) == body) d.frames.emplace(pm.frames[f].name, f);
    }
}

}  // namespace

int dyn_fail(dyn_model *m, int code, const std::string &msg) {
  m->err = msg;
  return code;
}

extern "C" int dyn_model_load(const char *urdf, int njoint, const char *const *joints, dyn_model **out,
                              char *err, size_t errlen) {
  if (!out) return refuse(err, errlen, "dyn_model_load: NULL output pointer");
  *out = nullptr;
  if (!urdf) return refuse(err, errlen, "dyn_model_load: NULL URDF path");
  if (joints && njoint < 0) return refuse(err, errlen, "dyn_model_load: negative joint count");
  std::string path = urdf;
  if (FILE *f = fopen(urdf, "r")) fclose(f);
  else return refuse(err, errlen, path + ": cannot be read");
  pinocchio::Model pm;
  try {
    pinocchio::urdf::buildModel(path, pinocchio::JointModelFreeFlyer(), pm);
  } catch (const std::exception &e) {
    return refuse(err, errlen, path + ": not a usable URDF: " + e.what());
  }
  auto d = std::make_unique<dyn_model>(std::move(pm));
  std::string msg = map_joints(*d, path, njoint, joints);
  if (!msg.empty()) return refuse(err, errlen, msg);
  map_frames(*d);
  d->q = pinocchio::neutral(d->model);
  d->v = Eigen::VectorXd::Zero(d->model.nv);
  d->acc = d->v;
  d->work = Eigen::MatrixXd::Zero(6, d->model.nv);
  *out = d.release();
  return 0;
}

extern "C" void dyn_model_destroy(dyn_model *m) { delete m; }
