// description: URDF -> desc::Model through liburdfdom, with errors that name the file and the element.
#include "description/description.h"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>

namespace desc {

int Model::link_index(const std::string &n) const {
  for (size_t i = 0; i < links.size(); i++) if (links[i].name == n) return (int)i;
  return -1;
}
int Model::frame_index(const std::string &n) const {
  for (size_t i = 0; i < frames.size(); i++) if (frames[i].name == n) return (int)i;
  return -1;
}
int Model::joint_link(const std::string &j) const {
  for (size_t i = 0; i < links.size(); i++) if (!j.empty() && links[i].joint == j) return (int)i;
  return -1;
}
double Model::total_mass() const {
  double m = 0;
  for (const Link &l : links) m += l.mass;
  return m;
}
void Model::zero_pose(std::vector<Vec3> *pos, std::vector<Mat3> *rot) const {
  pos->assign(links.size(), Vec3::Zero());
  rot->assign(links.size(), Mat3::Identity());
  for (size_t i = 0; i < links.size(); i++) {
    const Link &l = links[i];
    if (l.parent < 0) continue;
    (*pos)[i] = (*pos)[l.parent] + (*rot)[l.parent] * l.origin;
    (*rot)[i] = (*rot)[l.parent] * l.origin_rot;
  }
}

namespace {

// Collects urdfdom's console messages so that they end up in our error string.
struct Capture : console_bridge::OutputHandler {
  std::string text;
  void log(const std::string &msg, console_bridge::LogLevel level, const char *, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN) text += (text.empty() ? "" : "; ") + msg;
  }
};

Mat3 to_mat(const urdf::Rotation &r) {
  Eigen::Quaterniond q(r.w, r.x, r.y, r.z);
  return q.normalized().toRotationMatrix();
}
Vec3 to_vec(const urdf::Vector3 &v) { return Vec3(v.x, v.y, v.z); }

bool finite(const Vec3 &v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

}  // namespace

int load(const std::string &path, Model *out, std::string *err) {
  std::ifstream in(path);
  if (!in) { *err = path + ": cannot open the robot file"; return -1; }
  std::stringstream ss;
  ss << in.rdbuf();
  Capture cap;
  console_bridge::useOutputHandler(&cap);
  urdf::ModelInterfaceSharedPtr u = urdf::parseURDF(ss.str());
  console_bridge::restorePreviousOutputHandler();
  if (!u) {
    *err = path + ": invalid URDF: " + (cap.text.empty() ? "parse failed" : cap.text);
    return -1;
  }
  Model m;
  m.file = path;
  m.name = u->getName();
  urdf::LinkConstSharedPtr root = u->getRoot();
  if (!root) { *err = path + ": no root link"; return -1; }

  // A link that is the child of two joints makes a cycle that urdfdom does not report (it keeps
  // the last parent): refuse it here, naming the link and both joints.
  std::map<std::string, std::string> parent_joint;
  for (const auto &kv : u->joints_) {
    const std::string &child = kv.second->child_link_name;
    auto it = parent_joint.find(child);
    if (it != parent_joint.end()) {
      *err = path + ": link '" + child + "' is the child of two joints ('" + it->second + "' and '" + kv.first +
             "'): the joints form a cycle";
      return -1;
    }
    parent_joint[child] = kv.first;
  }
  std::string e;
  std::set<std::string> seen;
  // Depth-first from the root so parents come first.
  std::function<void(const urdf::LinkConstSharedPtr &, int)> visit =
      [&](const urdf::LinkConstSharedPtr &ul, int parent) {
    if (!e.empty()) return;
    const std::string where = path + ": link '" + ul->name + "'";
    if (!seen.insert(ul->name).second) { e = where + ": reached twice, the joints form a cycle"; return; }
    urdf::JointConstSharedPtr uj = ul->parent_joint;
    if (uj && uj->type == urdf::Joint::FIXED && !ul->inertial) {
      // massless fixed link: a frame on the parent
      const urdf::Pose &p = uj->parent_to_joint_origin_transform;
      Frame f;
      f.name = ul->name;
      f.link = parent;
      f.pos = to_vec(p.position);
      f.rot = to_mat(p.rotation);
      if (!ul->collision_array.empty()) { e = where + ": a massless link cannot have <collision>"; return; }
      if (!ul->child_links.empty()) { e = where + ": a massless link cannot have children"; return; }
      m.frames.push_back(f);
      return;
    }
    Link l;
    l.name = ul->name;
    l.parent = parent;
    if (!ul->inertial) { e = where + ": missing <inertial>"; return; }
    l.mass = ul->inertial->mass;
    if (!(l.mass > 0) || !std::isfinite(l.mass)) { e = where + ": <inertial><mass> must be positive"; return; }
    const urdf::Inertial &in_ = *ul->inertial;
    Mat3 I;
    I << in_.ixx, in_.ixy, in_.ixz, in_.ixy, in_.iyy, in_.iyz, in_.ixz, in_.iyz, in_.izz;
    Mat3 R = to_mat(in_.origin.rotation);
    l.inertia = R * I * R.transpose();
    l.com = to_vec(in_.origin.position);
    Eigen::SelfAdjointEigenSolver<Mat3> eig(l.inertia);
    if (!l.inertia.allFinite() || eig.eigenvalues().minCoeff() <= 0) {
      e = where + ": <inertial><inertia> is not positive definite";
      return;
    }
    for (const urdf::CollisionSharedPtr &c : ul->collision_array) {
      if (!c->geometry || c->geometry->type != urdf::Geometry::BOX) {
        e = where + ": <collision " + c->name + ">: only <box> geometry is supported";
        return;
      }
      const urdf::Box &b = static_cast<const urdf::Box &>(*c->geometry);
      Box box;
      box.name = c->name;
      box.pos = to_vec(c->origin.position);
      box.rot = to_mat(c->origin.rotation);
      box.size = to_vec(b.dim);
      box.sole = c->name.compare(0, 4, "sole") == 0;
      if (!finite(box.size) || box.size.minCoeff() <= 0 || !finite(box.pos)) {
        e = where + ": <collision " + c->name + ">: box size must be positive";
        return;
      }
      l.boxes.push_back(box);
    }
    if (uj) {
      const std::string jw = path + ": joint '" + uj->name + "'";
      l.joint = uj->name;
      l.origin = to_vec(uj->parent_to_joint_origin_transform.position);
      l.origin_rot = to_mat(uj->parent_to_joint_origin_transform.rotation);
      if (uj->type != urdf::Joint::REVOLUTE) {
        e = jw + ": only revolute joints (and massless fixed frames) are supported";
        return;
      }
      l.axis = to_vec(uj->axis);
      if (!finite(l.axis) || l.axis.norm() < 1e-9) { e = jw + ": <axis> is zero"; return; }
      l.axis.normalize();
      if (!uj->limits) { e = jw + ": missing <limit>"; return; }
      l.lower = uj->limits->lower;
      l.upper = uj->limits->upper;
      l.effort = uj->limits->effort;
      l.velocity = uj->limits->velocity;
      if (!(l.lower < l.upper)) { e = jw + ": <limit> lower must be below upper"; return; }
      if (!(l.effort > 0) || !(l.velocity > 0)) { e = jw + ": <limit> effort and velocity must be positive"; return; }
      if (uj->dynamics) {
        l.damping = uj->dynamics->damping;
        l.friction = uj->dynamics->friction;
      }
    }
    int self = (int)m.links.size();
    m.links.push_back(l);
    for (const urdf::LinkSharedPtr &c : ul->child_links) visit(c, self);
  };
  visit(root, -1);
  if (!e.empty()) { *err = e; return -1; }
  for (const auto &kv : u->links_) {
    if (!seen.count(kv.first)) {
      *err = path + ": link '" + kv.first + "' is not connected to the root link '" + root->name + "'";
      return -1;
    }
  }
  *out = std::move(m);
  return 0;
}

}  // namespace desc
