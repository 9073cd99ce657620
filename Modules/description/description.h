// description: a robot description (URDF) read into plain structs through liburdfdom, with errors
// that name the file and the element. One parser for everyone who needs the body: the sim
// (Platforms/Sim builds its ODE bodies from it) and the kinematics (Modules/kinematics).
//
// Conventions: SI units. Every link keeps its URDF frame; inertia is about the COM in the link frame.
// Links are ordered so that a parent comes before its children; link 0 is the root (the torso, a
// floating base). Massless links attached by fixed joints (camera, soles, hands) become frames on
// their parent. Only revolute joints move; a fixed joint to a link with mass is refused.
#ifndef HRP_DESCRIPTION_H
#define HRP_DESCRIPTION_H

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace desc {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

struct Box {
  Vec3 pos;            // centre in the link frame
  Mat3 rot;            // box axes in the link frame
  Vec3 size;           // full edge lengths
  std::string name;    // collision element name
  bool sole;           // a sole box (name starts with "sole"): its contacts are summed as foot force
};

struct Link {
  std::string name;
  int parent = -1;               // index of the parent link, -1 for the root
  std::string joint;             // name of the joint to the parent ("" for the root)
  Vec3 origin = Vec3::Zero();    // joint frame (= link frame) in the parent link frame
  Mat3 origin_rot = Mat3::Identity();
  Vec3 axis = Vec3::UnitZ();     // hinge axis in the link frame (unit)
  double lower = 0, upper = 0;   // rad
  double effort = 0, velocity = 0, damping = 0, friction = 0;   // N*m, rad/s, N*m*s/rad, N*m
  double mass = 0;               // kg
  Vec3 com = Vec3::Zero();       // in the link frame
  Mat3 inertia = Mat3::Zero();   // about the COM, link frame axes
  std::vector<Box> boxes;
};

struct Frame {                   // a massless frame fixed to a link (camera, sole, hand)
  std::string name;
  int link = -1;
  Vec3 pos = Vec3::Zero();       // in the link frame
  Mat3 rot = Mat3::Identity();
};

struct Model {
  std::string file;
  std::string name;
  std::vector<Link> links;       // parents first
  std::vector<Frame> frames;
  // Index of a link or frame by name, -1 if absent.
  int link_index(const std::string &name) const;
  int frame_index(const std::string &name) const;
  // Link index of the joint with this name, -1 if absent.
  int joint_link(const std::string &joint) const;
  double total_mass() const;
  // Every link frame in the root link's frame with all joints at 0: pos[i], rot[i].
  void zero_pose(std::vector<Vec3> *pos, std::vector<Mat3> *rot) const;
};

// Reads a URDF file. Returns 0, or -1 with a message naming the file and the element in err.
int load(const std::string &path, Model *out, std::string *err);

}  // namespace desc
#endif
