// model: the robot description the sim builds its bodies from. The parser is shared with the
// kinematics (Modules/description); the sim uses its structs under its own names.
#ifndef HRP_SIM_MODEL_H
#define HRP_SIM_MODEL_H

#include "description/description.h"

namespace sim {

using desc::Box;
using desc::Frame;
using desc::Link;
using desc::Mat3;
using desc::Model;
using desc::Vec3;

// Reads a URDF file. Returns 0, or -1 with a message naming the file and the element in err.
inline int model_load(const std::string &path, Model *out, std::string *err) { return desc::load(path, out, err); }

}  // namespace sim
#endif
