// config: one concern of the robot's configuration for the simulator, a thin C++ face over the DCM
// library's reader (Modules/dcm: Lib/Config.lua's layers common, robot, platform Sim, site). Keys
// are dotted paths ("physics.timestep", "start.2.1"); errors (std::runtime_error) name the files
// and the key.
#ifndef HRP_SIM_CONFIG_H
#define HRP_SIM_CONFIG_H

#include <memory>
#include <string>
#include <vector>

#include "dcm/dcm.h"

namespace sim {

class Config {
 public:
  // Config.export(concern, { robot = robot, platform = 'Sim' }) ("" robot: $ROBOT).
  explicit Config(const std::string &concern, const std::string &robot = "");
  // The layer files, for messages.
  std::string file() const { return dcm_config_files(c_.get()); }
  bool has(const std::string &key) const { return dcm_config_has(c_.get(), key.c_str()); }
  double num(const std::string &key) const;                 // required number
  double num(const std::string &key, double dflt) const;    // optional number
  std::string str(const std::string &key) const;            // required string
  bool flag(const std::string &key) const;                  // required boolean
  // Lists of strings / numbers at key; required, non-empty.
  std::vector<std::string> strs(const std::string &key) const;
  std::vector<double> nums(const std::string &key) const;

 private:
  std::shared_ptr<dcm_config> c_;
};

}  // namespace sim
#endif
