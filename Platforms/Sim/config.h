// config: one concern of the robot's configuration (Lib/Config.lua's layers: common, robot,
// platform, site) as flat "a.b.c" keys. Errors (std::runtime_error) name the files and the key.
#ifndef HRP_SIM_CONFIG_H
#define HRP_SIM_CONFIG_H

#include <map>
#include <string>
#include <vector>

namespace sim {

class Config {
 public:
  // Config.export(concern, { robot = robot }) through LuaJIT ("" robot: $ROBOT); throws
  // std::runtime_error naming the files on failure.
  explicit Config(const std::string &concern, const std::string &robot = "");
  const std::string &file() const { return file_; }
  bool has(const std::string &key) const;
  double num(const std::string &key) const;                 // required number
  double num(const std::string &key, double dflt) const;    // optional number
  std::string str(const std::string &key) const;            // required string
  // Array of strings / numbers at key (key.1, key.2, ...); required, non-empty.
  std::vector<std::string> strs(const std::string &key) const;
  std::vector<double> nums(const std::string &key) const;

 private:
  std::string file_;
  std::map<std::string, double> num_;
  std::map<std::string, std::string> str_;
};

}  // namespace sim
#endif
