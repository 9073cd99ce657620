/* config: the one strict config reader of every DCM. An embedded LuaJIT state runs the project's
 * own Lib/Config.lua -- Config.export(concern, { robot =, platform = }), a plain copy of the merged
 * layers -- so C reads exactly what the Lua processes read; typed getters by dotted key name the
 * layer files and the key in every error. */
#include "dcm.h"

#include <ctype.h>
#include <errno.h>
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct dcm_config {
  lua_State *L;
  int ref;                       /* the exported table in the registry */
  char files[1024];
  char robot[DCM_NAME_MAX], platform[DCM_NAME_MAX];
};

const char *dcm_root(void) {
  const char *r = getenv("HRP_ROOT");
  return r && *r ? r : HRP_ROOT_DEFAULT;
}

/* Runs in the embedded state: (concern, robot|nil, platform|nil) -> table, files, robot, platform. */
static const char *LOADER =
    "local concern, robot, platform = ...\n"
    "local Config = require('Config')\n"
    "robot = robot or Config.robot()\n"
    "platform = platform or Config.platform()\n"
    "local t, files = Config.export(concern, { robot = robot, platform = platform })\n"
    "return t, files, robot, platform\n";

int dcm_config_load(const char *concern, const char *robot, const char *platform, dcm_config **out, char *err,
                    size_t errlen) {
  dcm_config *c = calloc(1, sizeof *c);
  if (!c) {
    snprintf(err, errlen, "config: out of memory");
    return -ENOMEM;
  }
  c->L = luaL_newstate();
  if (!c->L) {
    free(c);
    snprintf(err, errlen, "config: out of memory for Lua");
    return -ENOMEM;
  }
  lua_State *L = c->L;
  luaL_openlibs(L);
  /* package.path: the project's Lib first */
  lua_getglobal(L, "package");
  lua_pushfstring(L, "%s/Lib/?.lua;", dcm_root());
  lua_getfield(L, -2, "path");
  lua_concat(L, 2);
  lua_setfield(L, -2, "path");
  lua_pop(L, 1);
  if (luaL_loadbuffer(L, LOADER, strlen(LOADER), "=dcm_config") != 0) goto lua_fail;
  lua_pushstring(L, concern);
  if (robot && *robot) lua_pushstring(L, robot); else lua_pushnil(L);
  if (platform && *platform) lua_pushstring(L, platform); else lua_pushnil(L);
  if (lua_pcall(L, 3, 4, 0) != 0) goto lua_fail;
  if (!lua_istable(L, -4)) {
    snprintf(err, errlen, "config '%s': Config.export returned no table", concern);
    dcm_config_free(c);
    return -EINVAL;
  }
  snprintf(c->files, sizeof c->files, "%s", lua_tostring(L, -3));
  snprintf(c->robot, sizeof c->robot, "%s", lua_tostring(L, -2));
  snprintf(c->platform, sizeof c->platform, "%s", lua_tostring(L, -1));
  lua_pop(L, 3);
  c->ref = luaL_ref(L, LUA_REGISTRYINDEX);
  *out = c;
  return 0;
lua_fail: {
  const char *msg = lua_tostring(L, -1) ? lua_tostring(L, -1) : "config: Lua error";
  /* Config.lua's errors for its caller carry our loader's position: not the user's business */
  if (!strncmp(msg, "dcm_config:", 11) && strstr(msg, ": ")) msg = strstr(msg, ": ") + 2;
  snprintf(err, errlen, "%s", msg);
}
  dcm_config_free(c);
  return -EINVAL;
}

void dcm_config_free(dcm_config *c) {
  if (!c) return;
  if (c->L) lua_close(c->L);
  free(c);
}

const char *dcm_config_files(const dcm_config *c) { return c->files; }
const char *dcm_config_robot(const dcm_config *c) { return c->robot; }
const char *dcm_config_platform(const dcm_config *c) { return c->platform; }

int dcm_config_fail(const dcm_config *c, char *err, size_t errlen, const char *fmt, ...) {
  int n = snprintf(err, errlen, "%s: ", c->files);
  if (n >= 0 && (size_t)n < errlen) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err + n, errlen - (size_t)n, fmt, ap);
    va_end(ap);
  }
  return -EINVAL;
}

/* "devices.3.model" -> "devices[3].model" (as the key is written in Lua). */
static const char *lua_key(const char *key, char *buf, size_t len) {
  size_t o = 0;
  const char *p = key;
  while (*p && o + 8 < len) {
    const char *e = strchr(p, '.');
    size_t n = e ? (size_t)(e - p) : strlen(p);
    int num = n > 0;
    for (size_t k = 0; k < n; k++) num = num && isdigit((unsigned char)p[k]);
    if (num) o += (size_t)snprintf(buf + o, len - o, "[%.*s]", (int)n, p);
    else o += (size_t)snprintf(buf + o, len - o, "%s%.*s", o ? "." : "", (int)n, p);
    if (o >= len) { o = len - 1; break; }
    if (!e) break;
    p = e + 1;
  }
  buf[o < len ? o : len - 1] = '\0';
  return buf;
}

/* Pushes the value at key (nil when absent). -1 with a message if a step is not a table. */
static int push(const dcm_config *c, const char *key, char *err, size_t errlen) {
  lua_State *L = c->L;
  lua_rawgeti(L, LUA_REGISTRYINDEX, c->ref);
  const char *p = key;
  char part[DCM_NAME_MAX];
  while (p) {
    const char *e = strchr(p, '.');
    size_t n = e ? (size_t)(e - p) : strlen(p);
    if (n == 0 || n >= sizeof part) {
      lua_pop(L, 1);
      char kb[256];
      return dcm_config_fail(c, err, errlen, "bad key '%s'", lua_key(key, kb, sizeof kb));
    }
    memcpy(part, p, n);
    part[n] = '\0';
    if (!lua_istable(L, -1)) {
      char kb[256], pb[256];
      snprintf(pb, sizeof pb, "%.*s", (int)(p - key - 1), key);
      int t = lua_type(L, -1);
      lua_pop(L, 1);
      return dcm_config_fail(c, err, errlen, "key '%s' must be a table, got %s", lua_key(pb, kb, sizeof kb),
                             lua_typename(L, t));
    }
    char *end;
    long idx = strtol(part, &end, 10);
    if (*end == '\0' && isdigit((unsigned char)part[0])) lua_rawgeti(L, -1, (int)idx);
    else {
      lua_pushstring(L, part);
      lua_rawget(L, -2);
    }
    lua_remove(L, -2);
    p = e ? e + 1 : NULL;
  }
  return 0;
}

/* Pushes the value at key and checks its Lua type; absent or another type -> error. */
static int need(const dcm_config *c, const char *key, int type, const char *what, char *err, size_t errlen) {
  if (push(c, key, err, errlen) < 0) return -EINVAL;
  int t = lua_type(c->L, -1);
  if (t == type) return 0;
  lua_pop(c->L, 1);
  char kb[256];
  if (t == LUA_TNIL) return dcm_config_fail(c, err, errlen, "missing key '%s' (%s)", lua_key(key, kb, sizeof kb), what);
  return dcm_config_fail(c, err, errlen, "key '%s' must be %s, got %s", lua_key(key, kb, sizeof kb), what,
                         lua_typename(c->L, t));
}

int dcm_config_has(const dcm_config *c, const char *key) {
  char err[8];
  if (push(c, key, err, sizeof err) < 0) return 0;
  int has = !lua_isnil(c->L, -1);
  lua_pop(c->L, 1);
  return has;
}

int dcm_config_num(const dcm_config *c, const char *key, double *out, char *err, size_t errlen) {
  if (need(c, key, LUA_TNUMBER, "a number", err, errlen) < 0) return -EINVAL;
  *out = lua_tonumber(c->L, -1);
  lua_pop(c->L, 1);
  return 0;
}

int dcm_config_int(const dcm_config *c, const char *key, int *out, char *err, size_t errlen) {
  double v;
  if (dcm_config_num(c, key, &v, err, errlen) < 0) return -EINVAL;
  if (v != floor(v) || fabs(v) > 2147483647.0) {
    char kb[256];
    return dcm_config_fail(c, err, errlen, "key '%s' must be an integer, got %g", lua_key(key, kb, sizeof kb), v);
  }
  *out = (int)v;
  return 0;
}

int dcm_config_bool(const dcm_config *c, const char *key, int *out, char *err, size_t errlen) {
  if (need(c, key, LUA_TBOOLEAN, "true or false", err, errlen) < 0) return -EINVAL;
  *out = lua_toboolean(c->L, -1);
  lua_pop(c->L, 1);
  return 0;
}

int dcm_config_str(const dcm_config *c, const char *key, char *out, size_t outlen, char *err, size_t errlen) {
  if (need(c, key, LUA_TSTRING, "a string", err, errlen) < 0) return -EINVAL;
  size_t n = 0;
  const char *s = lua_tolstring(c->L, -1, &n);
  if (n >= outlen) {
    lua_pop(c->L, 1);
    char kb[256];
    return dcm_config_fail(c, err, errlen, "key '%s' is longer than %zu characters", lua_key(key, kb, sizeof kb),
                           outlen - 1);
  }
  memcpy(out, s, n + 1);
  lua_pop(c->L, 1);
  return 0;
}

int dcm_config_num_or(const dcm_config *c, const char *key, double dflt, double *out, char *err, size_t errlen) {
  if (!dcm_config_has(c, key)) {
    *out = dflt;
    return 0;
  }
  return dcm_config_num(c, key, out, err, errlen);
}

int dcm_config_str_or(const dcm_config *c, const char *key, const char *dflt, char *out, size_t outlen, char *err,
                      size_t errlen) {
  if (!dcm_config_has(c, key)) {
    snprintf(out, outlen, "%s", dflt);
    return 0;
  }
  return dcm_config_str(c, key, out, outlen, err, errlen);
}

int dcm_config_len(const dcm_config *c, const char *key, char *err, size_t errlen) {
  if (need(c, key, LUA_TTABLE, "a list", err, errlen) < 0) return -EINVAL;
  int n = (int)lua_objlen(c->L, -1);
  lua_pop(c->L, 1);
  return n;
}

/* Checks the list at key has min..max entries; returns the count. */
static int list(const dcm_config *c, const char *key, int min, int max, const char *what, char *err, size_t errlen) {
  int n = dcm_config_len(c, key, err, errlen);
  if (n < 0) return n;
  if (n < min || n > max) {
    char kb[256];
    if (min == max) return dcm_config_fail(c, err, errlen, "key '%s' must be a list of %d %s, has %d",
                                           lua_key(key, kb, sizeof kb), min, what, n);
    return dcm_config_fail(c, err, errlen, "key '%s' must be a list of %d to %d %s, has %d",
                           lua_key(key, kb, sizeof kb), min, max, what, n);
  }
  return n;
}

int dcm_config_nums(const dcm_config *c, const char *key, double *out, int min, int max, char *err, size_t errlen) {
  int n = list(c, key, min, max, "numbers", err, errlen);
  for (int i = 0; i < n; i++) {
    char k[256];
    snprintf(k, sizeof k, "%s.%d", key, i + 1);
    if (dcm_config_num(c, k, &out[i], err, errlen) < 0) return -EINVAL;
  }
  return n;
}

int dcm_config_strs(const dcm_config *c, const char *key, char (*out)[DCM_NAME_MAX], int min, int max, char *err,
                    size_t errlen) {
  int n = list(c, key, min, max, "strings", err, errlen);
  for (int i = 0; i < n; i++) {
    char k[256];
    snprintf(k, sizeof k, "%s.%d", key, i + 1);
    if (dcm_config_str(c, k, out[i], DCM_NAME_MAX, err, errlen) < 0) return -EINVAL;
  }
  return n;
}

int dcm_config_joints(const dcm_config *c, char (*joint)[DCM_NAME_MAX], double *lo, double *hi, char *err,
                      size_t errlen) {
  int nj = dcm_config_strs(c, "joints", joint, 1, DCM_NJ_MAX, err, errlen);
  for (int j = 0; j < nj; j++) {
    char key[128];
    double lh[2];
    snprintf(key, sizeof key, "limits.%s", joint[j]);
    if (dcm_config_nums(c, key, lh, 2, 2, err, errlen) < 0) return -EINVAL;
    if (!(lh[0] < lh[1]))
      return dcm_config_fail(c, err, errlen, "limits.%s: min %g must be below max %g", joint[j], lh[0], lh[1]);
    lo[j] = lh[0];
    hi[j] = lh[1];
  }
  return nj;
}
