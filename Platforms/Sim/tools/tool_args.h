// tool_args: the options the sim's tools share, as rows of a dcm/args.h table.
#ifndef HRP_SIM_TOOL_ARGS_H
#define HRP_SIM_TOOL_ARGS_H

#include <cerrno>
#include <cstdio>
#include <string>

#include "dcm/args.h"

namespace sim {

// --ball white|orange: the ball the camera sees (out: a std::string; unset: the sim config's).
inline int parse_ball_kind(const char *v, void *out, char *err, size_t n) {
  const std::string kind = v;
  if (kind != "white" && kind != "orange") {
    snprintf(err, n, "'%s' is not 'white' or 'orange'", v);
    return -EINVAL;
  }
  *static_cast<std::string *>(out) = kind;
  return 0;
}

}  // namespace sim
#endif
