// config: Lib/Config.lua (run in LuaJIT) merges a concern's layers; the table is flattened into "a.b.c" keys.
#include "config.h"

#include <lua.hpp>

#include <cstdlib>
#include <stdexcept>

namespace sim {

static void flatten(lua_State *L, const std::string &prefix, int depth,
                    std::map<std::string, double> *nums, std::map<std::string, std::string> *strs) {
  if (depth > 8) return;
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    std::string key;
    if (lua_type(L, -2) == LUA_TNUMBER) {
      key = std::to_string((long long)lua_tonumber(L, -2));
    } else if (lua_type(L, -2) == LUA_TSTRING) {
      key = lua_tostring(L, -2);
    }
    if (!key.empty()) {
      std::string full = prefix.empty() ? key : prefix + "." + key;
      int t = lua_type(L, -1);
      if (t == LUA_TNUMBER) (*nums)[full] = lua_tonumber(L, -1);
      else if (t == LUA_TBOOLEAN) (*nums)[full] = lua_toboolean(L, -1) ? 1 : 0;
      else if (t == LUA_TSTRING) (*strs)[full] = lua_tostring(L, -1);
      else if (t == LUA_TTABLE) flatten(L, full, depth + 1, nums, strs);
    }
    lua_pop(L, 1);
  }
}

Config::Config(const std::string &concern, const std::string &robot) {
  lua_State *L = luaL_newstate();
  if (!L) throw std::runtime_error(concern + ": out of memory");
  luaL_openlibs(L);
  // The one config reader (Lib/Config.lua): the same layers and errors as the Lua processes.
  const char *script =
      "local root, concern, robot = ...\n"
      "package.path = root .. '/Lib/?.lua;' .. package.path\n"
      "local Config = require('Config')\n"
      "return Config.export(concern, { robot = robot ~= '' and robot or nil })\n";
  const char *r = getenv("HRP_ROOT");
  const std::string root = r && *r ? r : HRP_ROOT_DEFAULT;
  if (luaL_loadstring(L, script) != 0) {
    std::string msg = lua_tostring(L, -1);
    lua_close(L);
    throw std::runtime_error(msg);
  }
  lua_pushstring(L, root.c_str());
  lua_pushstring(L, concern.c_str());
  lua_pushstring(L, robot.c_str());
  if (lua_pcall(L, 3, 2, 0) != 0) {
    std::string msg = lua_tostring(L, -1) ? lua_tostring(L, -1) : "error";
    lua_close(L);
    throw std::runtime_error(msg);
  }
  file_ = lua_tostring(L, -1) ? lua_tostring(L, -1) : concern;
  lua_pop(L, 1);
  flatten(L, "", 0, &num_, &str_);
  lua_close(L);
}

bool Config::has(const std::string &k) const { return num_.count(k) || str_.count(k); }

double Config::num(const std::string &k) const {
  auto it = num_.find(k);
  if (it == num_.end()) {
    throw std::runtime_error(file_ + ": " + (str_.count(k) ? "key '" + k + "' must be a number"
                                                            : "missing number '" + k + "'"));
  }
  return it->second;
}

double Config::num(const std::string &k, double dflt) const {
  if (!has(k)) return dflt;
  return num(k);
}

std::string Config::str(const std::string &k) const {
  auto it = str_.find(k);
  if (it == str_.end()) {
    throw std::runtime_error(file_ + ": " + (num_.count(k) ? "key '" + k + "' must be a string"
                                                            : "missing string '" + k + "'"));
  }
  return it->second;
}

std::vector<std::string> Config::strs(const std::string &k) const {
  std::vector<std::string> v;
  for (int i = 1;; i++) {
    std::string key = k + "." + std::to_string(i);
    if (!has(key)) break;
    v.push_back(str(key));
  }
  if (v.empty()) throw std::runtime_error(file_ + ": missing list '" + k + "'");
  return v;
}

std::vector<double> Config::nums(const std::string &k) const {
  std::vector<double> v;
  for (int i = 1;; i++) {
    std::string key = k + "." + std::to_string(i);
    if (!has(key)) break;
    v.push_back(num(key));
  }
  if (v.empty()) throw std::runtime_error(file_ + ": missing list '" + k + "'");
  return v;
}

}  // namespace sim
