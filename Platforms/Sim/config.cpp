// config: the simulator's face over the DCM library's config reader (see config.h).
#include "config.h"

#include <stdexcept>

namespace sim {

Config::Config(const std::string &concern, const std::string &robot) {
  char err[1024];
  dcm_config *c = nullptr;
  if (dcm_config_load(concern.c_str(), robot.empty() ? nullptr : robot.c_str(), "Sim", &c, err, sizeof err) < 0)
    throw std::runtime_error(err);
  c_.reset(c, dcm_config_free);
}

double Config::num(const std::string &k) const {
  char err[1024];
  double v = 0;
  if (dcm_config_num(c_.get(), k.c_str(), &v, err, sizeof err) < 0) throw std::runtime_error(err);
  return v;
}

double Config::num(const std::string &k, double dflt) const {
  char err[1024];
  double v = 0;
  if (dcm_config_num_or(c_.get(), k.c_str(), dflt, &v, err, sizeof err) < 0) throw std::runtime_error(err);
  return v;
}

bool Config::flag(const std::string &k) const {
  char err[1024];
  int v = 0;
  if (dcm_config_bool(c_.get(), k.c_str(), &v, err, sizeof err) < 0) throw std::runtime_error(err);
  return v != 0;
}

std::string Config::str(const std::string &k) const {
  char err[1024], v[1024];
  if (dcm_config_str(c_.get(), k.c_str(), v, sizeof v, err, sizeof err) < 0) throw std::runtime_error(err);
  return v;
}

std::vector<std::string> Config::strs(const std::string &k) const {
  char err[1024];
  const int n = dcm_config_len(c_.get(), k.c_str(), err, sizeof err);
  if (n < 0) throw std::runtime_error(err);
  if (n == 0) throw std::runtime_error(file() + ": key '" + k + "' is an empty list");
  std::vector<std::string> v;
  for (int i = 1; i <= n; i++) v.push_back(str(k + "." + std::to_string(i)));
  return v;
}

std::vector<double> Config::nums(const std::string &k) const {
  char err[1024];
  const int n = dcm_config_len(c_.get(), k.c_str(), err, sizeof err);
  if (n < 0) throw std::runtime_error(err);
  if (n == 0) throw std::runtime_error(file() + ": key '" + k + "' is an empty list");
  std::vector<double> v;
  for (int i = 1; i <= n; i++) v.push_back(num(k + "." + std::to_string(i)));
  return v;
}

}  // namespace sim
