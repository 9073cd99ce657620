// kin_load: a kinematic model from the robot's URDF (Modules/description, the parser the sim uses
// too) plus the robot config's joint order and chains. Fills a kin_desc in the URDF's root-link
// frame at the zero pose and hands it to kin_model_create.
#include "description/description.h"
#include "kinematics/kinematics.h"
#include "kinematics/kin_arrays.hpp"

#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

int fail(char *err, size_t errlen, const std::string &msg) {
  if (err && errlen) snprintf(err, errlen, "%s", msg.c_str());
  return KIN_EMODEL;
}

}  // namespace

extern "C" int kin_model_load(const kin_spec *s, kin_model **out, char *err, size_t errlen) {
  if (!s || !out || !s->urdf || !s->joints || s->njoint < 1 || (s->nchain > 0 && !s->chains)) {
    fail(err, errlen, "kin_model_load: NULL argument or no joints");
    return KIN_EINVAL;
  }
  *out = nullptr;
  const std::string file = s->urdf, config = s->config ? s->config : "the robot config";
  desc::Model md;
  std::string e;
  if (desc::load(file, &md, &e) < 0) return fail(err, errlen, e);
  if (s->njoint > KIN_MAXJ) return fail(err, errlen, config + ": more than " + std::to_string(KIN_MAXJ) + " joints");

  // robot joint order <-> URDF joints, both ways
  const int n = s->njoint;
  std::map<std::string, int> index;
  std::vector<int> link_of(n);
  for (int j = 0; j < n; j++) {
    const std::string name = s->joints[j] ? s->joints[j] : "";
    if (index.count(name)) return fail(err, errlen, config + ": joint '" + name + "' listed twice in joints");
    index[name] = j;
    link_of[j] = md.joint_link(name);
    if (link_of[j] < 0) {
      return fail(err, errlen, file + ": no joint '" + name + "' (listed in joints of " + config + ")");
    }
  }
  for (const desc::Link &l : md.links) {
    if (!l.joint.empty() && !index.count(l.joint)) {
      return fail(err, errlen, file + ": joint '" + l.joint + "' is not in joints of " + config);
    }
  }

  // zero pose of every link in the root frame = the torso frame (origin 0)
  std::vector<desc::Vec3> pos;
  std::vector<desc::Mat3> rot;
  md.zero_pose(&pos, &rot);
  KinArrays arr(n);
  for (int j = 0; j < n; j++) {
    const int li = link_of[j];
    const desc::Link &l = md.links[li];
    const int pl = l.parent;
    arr.parent[j] = pl <= 0 ? -1 : index.at(md.links[pl].joint);
    desc::Vec3 a = rot[li] * l.axis, c = pos[li] + rot[li] * l.com;
    for (int k = 0; k < 3; k++) {
      arr.axis[3 * j + k] = a[k];
      arr.anchor[3 * j + k] = pos[li][k];
      arr.com[3 * j + k] = c[k];
    }
    arr.mass[j] = l.mass;
    arr.qmin[j] = l.lower;
    arr.qmax[j] = l.upper;
  }
  kin_desc d{};
  arr.describe(d);
  d.names = s->joints;
  const desc::Link &torso = md.links[0];
  d.torso_mass = torso.mass;
  for (int k = 0; k < 3; k++) d.torso_com[k] = torso.com[k];

  // chains: joint names to indices, the tip to a zero-pose frame on the chain's last link
  std::vector<kin_chain> chains(s->nchain);
  std::vector<std::vector<int>> idx(s->nchain);
  for (int i = 0; i < s->nchain; i++) {
    const kin_chain_spec &cs = s->chains[i];
    const std::string what = config + ": chains." + (cs.name ? cs.name : "?");
    if (cs.n < 1 || !cs.joints) return fail(err, errlen, what + ": no joints");
    for (int k = 0; k < cs.n; k++) {
      auto it = index.find(cs.joints[k] ? cs.joints[k] : "");
      if (it == index.end()) {
        return fail(err, errlen, what + ": unknown joint '" + (cs.joints[k] ? cs.joints[k] : "") + "'");
      }
      idx[i].push_back(it->second);
    }
    const std::string tip = cs.tip ? cs.tip : "";
    const int fi = md.frame_index(tip), li = md.link_index(tip);
    int on;
    desc::Vec3 tp;
    desc::Mat3 tr;
    if (fi >= 0) {
      const desc::Frame &f = md.frames[fi];
      on = f.link;
      tp = pos[on] + rot[on] * f.pos;
      tr = rot[on] * f.rot;
    } else if (li >= 0) {
      on = li;
      tp = pos[li];
      tr = rot[li];
    } else {
      return fail(err, errlen, what + ": tip '" + tip + "' is no frame or link of " + file);
    }
    // on the last joint's link, or on a link below it (its joint then named to the model)
    const int last = link_of[idx[i].back()];
    int up = on;
    while (up > 0 && up != last) up = md.links[up].parent;
    if (up != last) {
      return fail(err, errlen, what + ": tip '" + tip + "' is on link '" + md.links[on].name +
                                   "', not on or below the last joint's link '" + md.links[last].name + "' (" +
                                   file + ")");
    }
    kin_chain &c = chains[i];
    c.name = cs.name;
    c.kind = cs.kind;
    c.side = cs.side;
    c.n = cs.n;
    c.joints = idx[i].data();
    c.tip_below = on == last ? 0 : 1 + index.at(md.links[on].joint);
    for (int k = 0; k < 3; k++) {
      c.tip[k] = tp[k];
      for (int m = 0; m < 3; m++) c.tip_rot[3 * k + m] = tr(k, m);
    }
  }
  d.nchain = s->nchain;
  d.chains = chains.data();
  char buf[384] = "";
  int rc = kin_model_create(&d, out, buf, sizeof buf);
  if (rc < 0) fail(err, errlen, config + " with " + file + ": " + buf);
  return rc;
}
