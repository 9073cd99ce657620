/* hrp_err: a formatted message into the caller's error buffer (char *err, size_t errlen), the way
 * the native parts report errors; nothing is written when err is NULL or errlen is 0. */
#ifndef HRP_ERRMSG_H
#define HRP_ERRMSG_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

static inline void hrp_err(char *err, size_t errlen, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static inline void hrp_err(char *err, size_t errlen, const char *fmt, ...) {
  if (!err || errlen == 0) return;
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(err, errlen, fmt, ap);
  va_end(ap);
}

#endif
