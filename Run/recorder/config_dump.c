/* config_dump: the configuration in force, one JSON document per concern, through an embedded LuaJIT
 * running Run/config_dump.lua (Config.export, the same reader as every process). */
#include "record.h"
#include "dcm/dcm.h"

#include <errno.h>
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *LOADER =
    "local concerns = ...\n"
    "return require('Run.config_dump')(concerns)\n";

int rec_config_docs(const rec_opts *o, rec_doc *docs, int max, char *err, size_t errlen) {
  lua_State *L = luaL_newstate();
  if (!L) {
    snprintf(err, errlen, "recorder: out of memory for Lua");
    return -ENOMEM;
  }
  luaL_openlibs(L);
  lua_getglobal(L, "package");
  lua_pushfstring(L, "%s/Lib/?.lua;%s/?.lua;", dcm_root(), dcm_root());
  lua_setfield(L, -2, "path");
  lua_pop(L, 1);
  int n = 0;
  if (luaL_loadbuffer(L, LOADER, strlen(LOADER), "=recorder") != 0) goto fail;
  lua_createtable(L, o->nconcerns, 0);
  for (int i = 0; i < o->nconcerns; i++) {
    lua_pushstring(L, o->concerns[i]);
    lua_rawseti(L, -2, i + 1);
  }
  if (lua_pcall(L, 1, 1, 0) != 0) goto fail;
  for (int i = 1; n < max; i++) {
    lua_rawgeti(L, -1, i);
    if (lua_isnil(L, -1)) break;
    lua_getfield(L, -1, "name");
    lua_getfield(L, -2, "json");
    lua_getfield(L, -3, "files");
    snprintf(docs[n].name, sizeof docs[n].name, "%s", lua_tostring(L, -3));
    snprintf(docs[n].files, sizeof docs[n].files, "%s", lua_tostring(L, -1));
    docs[n].json = strdup(lua_tostring(L, -2));
    if (!docs[n].json) {
      lua_close(L);
      rec_config_free(docs, n);
      snprintf(err, errlen, "recorder: out of memory");
      return -ENOMEM;
    }
    n++;
    lua_pop(L, 4);
  }
  lua_close(L);
  return n;
fail:
  snprintf(err, errlen, "recorder: configuration: %s", lua_tostring(L, -1) ? lua_tostring(L, -1) : "Lua error");
  lua_close(L);
  return -EINVAL;
}

void rec_config_free(rec_doc *docs, int n) {
  for (int i = 0; i < n; i++) {
    free(docs[i].json);
    docs[i].json = NULL;
  }
}
