/* dcm/args: the DCMs' command line from a table of options (args.h). */
#include "args.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define OPTS_MAX 64   /* rows of one table: enough for any DCM, and the size of the "given" marks */

static int fail(char *err, size_t errlen, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int fail(char *err, size_t errlen, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(err, errlen, fmt, ap);
  va_end(ap);
  return -EINVAL;
}

/* A range's end as a long: the table keeps ranges as doubles, and LONG_MAX is not one exactly. */
static long to_long(double v) {
  if (v >= (double)LONG_MAX) return LONG_MAX;
  if (v <= (double)LONG_MIN) return LONG_MIN;
  return (long)v;
}

int dcm_args_long(const char *s, long min, long max, long *out, char *err, size_t errlen) {
  /* strtol alone would take " 12", "12abc" (as 12) and "" (as 0) */
  if (!*s || !(*s == '-' || *s == '+' || (*s >= '0' && *s <= '9'))) return fail(err, errlen, "'%s' is not an integer", s);
  char *end = NULL;
  errno = 0;
  const long v = strtol(s, &end, 10);
  if (*end) return fail(err, errlen, "'%s' is not an integer", s);
  if (errno == ERANGE || v < min || v > max) {
    if (max == LONG_MAX || (max == INT_MAX && min >= INT_MIN))
      return fail(err, errlen, "%s is out of range (>= %ld)", s, min);
    return fail(err, errlen, "%s is out of range (%ld..%ld)", s, min, max);
  }
  *out = v;
  return 0;
}

int dcm_args_double(const char *s, double min, double max, double *out, char *err, size_t errlen) {
  /* decimal only: strtod would also read "nan", "inf", "0x1p3" and skip leading blanks */
  if (!*s || strspn(s, "0123456789+-.eE") != strlen(s)) return fail(err, errlen, "'%s' is not a number", s);
  char *end = NULL;
  errno = 0;
  const double v = strtod(s, &end);
  if (end == s || *end) return fail(err, errlen, "'%s' is not a number", s);
  if (errno == ERANGE || !isfinite(v) || v < min || v > max) {
    if (max >= 1e300) return fail(err, errlen, "%s is out of range (>= %g)", s, min);
    return fail(err, errlen, "%s is out of range (%g..%g)", s, min, max);
  }
  *out = v;
  return 0;
}

/* Converts one value into the option's output; err without the option's name. */
static int convert(const dcm_opt *o, const char *v, char *err, size_t errlen) {
  long l;
  double d;
  int rc;
  switch (o->kind) {
    case DCM_OPT_INT:
      rc = dcm_args_long(v, to_long(fmax(o->min, INT_MIN)), to_long(fmin(o->max, INT_MAX)), &l, err, errlen);
      if (rc == 0) *(int *)o->out = (int)l;
      return rc;
    case DCM_OPT_LONG:
      rc = dcm_args_long(v, to_long(o->min), to_long(o->max), &l, err, errlen);
      if (rc == 0) *(long *)o->out = l;
      return rc;
    case DCM_OPT_DOUBLE:
      rc = dcm_args_double(v, o->min, o->max, &d, err, errlen);
      if (rc == 0) *(double *)o->out = d;
      return rc;
    case DCM_OPT_STRING:
      if (!*v) return fail(err, errlen, "an empty value");
      *(const char **)o->out = v;
      return 0;
    case DCM_OPT_FUNC:
      return o->parse(v, o->out, err, errlen);
    case DCM_OPT_FLAG:
      break;
  }
  return fail(err, errlen, "takes no value");
}

int dcm_args_parse(const dcm_opt *opts, int argc, char *const *argv, char *err, size_t errlen) {
  int n = 0;
  while (opts[n].name) n++;
  if (n > OPTS_MAX) return fail(err, errlen, "%d options in the table, at most %d", n, OPTS_MAX);
  unsigned char given[OPTS_MAX] = { 0 };
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i];
    if (!strcmp(a, "-h") || !strcmp(a, "--help")) return DCM_ARGS_HELP;
    int k = 0;
    while (k < n && strcmp(opts[k].name, a)) k++;
    if (k == n) return fail(err, errlen, "unknown argument '%s'", a);
    const dcm_opt *o = &opts[k];
    given[k] = 1;
    if (o->kind == DCM_OPT_FLAG) {
      *(int *)o->out = 1;
      continue;
    }
    if (i + 1 >= argc) return fail(err, errlen, "%s needs a value (%s)", a, o->value ? o->value : "one");
    char why[256] = "";
    if (convert(o, argv[++i], why, sizeof why) < 0) return fail(err, errlen, "%s: %s", a, why);
  }
  for (int k = 0; k < n; k++)
    if (opts[k].required && !given[k])
      return fail(err, errlen, "%s %s is required", opts[k].name, opts[k].value ? opts[k].value : "");
  return 0;
}

/* Appends to out as snprintf would, counting what did not fit. */
static void put(char *out, size_t outlen, size_t *len, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
static void put(char *out, size_t outlen, size_t *len, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  const int w = vsnprintf(*len < outlen ? out + *len : NULL, *len < outlen ? outlen - *len : 0, fmt, ap);
  va_end(ap);
  if (w > 0) *len += (size_t)w;
}

/* " [1..1000]", " [>= 0]" or "" for the option's range. */
static void range_text(const dcm_opt *o, char *buf, size_t len) {
  buf[0] = 0;
  if (o->kind == DCM_OPT_INT || o->kind == DCM_OPT_LONG) {
    const double top = o->kind == DCM_OPT_INT ? INT_MAX : (double)LONG_MAX;
    if (o->max >= top) snprintf(buf, len, " [>= %ld]", to_long(o->min));
    else snprintf(buf, len, " [%ld..%ld]", to_long(o->min), to_long(o->max));
  } else if (o->kind == DCM_OPT_DOUBLE) {
    if (o->max >= 1e300) snprintf(buf, len, " [>= %g]", o->min);
    else snprintf(buf, len, " [%g..%g]", o->min, o->max);
  }
}

int dcm_args_usage(const char *invocation, const dcm_opt *opts, char *out, size_t outlen) {
  size_t len = 0;
  if (outlen) out[0] = 0;
  put(out, outlen, &len, "usage: %s", invocation);
  for (const dcm_opt *o = opts; o->name; o++)
    if (o->required) put(out, outlen, &len, " %s %s", o->name, o->value ? o->value : "");
  put(out, outlen, &len, " [options]\noptions:\n");
  int width = (int)strlen("-h, --help");
  for (const dcm_opt *o = opts; o->name; o++) {
    const int w = (int)strlen(o->name) + (o->value ? 1 + (int)strlen(o->value) : 0);
    if (w > width) width = w;
  }
  for (const dcm_opt *o = opts; o->name; o++) {
    char range[96];
    range_text(o, range, sizeof range);
    const int w = (int)strlen(o->name) + (o->value ? 1 + (int)strlen(o->value) : 0);
    put(out, outlen, &len, "  %s%s%s%*s  %s%s\n", o->name, o->value ? " " : "", o->value ? o->value : "", width - w, "",
        o->help ? o->help : "", range);
  }
  put(out, outlen, &len, "  %-*s  this text\n", width, "-h, --help");
  return (int)len;
}

void dcm_args(const char *prog, const char *invocation, const dcm_opt *opts, int argc, char *const *argv) {
  char err[512];
  const int rc = dcm_args_parse(opts, argc, argv, err, sizeof err);
  if (rc == 0) return;
  const int need = dcm_args_usage(invocation, opts, NULL, 0);
  char *usage = malloc((size_t)need + 1);
  if (usage) dcm_args_usage(invocation, opts, usage, (size_t)need + 1);
  if (rc == DCM_ARGS_HELP) {
    fputs(usage ? usage : "", stdout);
    free(usage);
    exit(0);
  }
  fprintf(stderr, "%s: %s\n", prog, err);
  fputs(usage ? usage : "", stderr);
  free(usage);
  exit(2);
}
