/* dcm/args: the command line of every DCM, read from a table of its options.
 *
 * A DCM declares its options once, as rows of name, kind, where the value goes, the accepted range,
 * the value's name and one line of help; the table gives both the parsing and the usage text:
 *
 *   const dcm_opt opts[] = {
 *     { "--rate", DCM_OPT_DOUBLE, &o.rate, 1, 1000, "HZ", "control rate (default: the body's)", NULL, 0 },
 *     { "--quiet", DCM_OPT_FLAG, &d.quiet, 0, 0, NULL, "no log lines", NULL, 0 },
 *     DCM_OPT_END,
 *   };
 *   dcm_args("dcm_op", "PLATFORM=OP ./run_dcm", opts, argc, argv);
 *
 * Numbers are converted strictly: the whole argument must be a decimal number of the option's kind
 * inside its range (no silent 0 for garbage, no "12abc" read as 12, no nan / inf); an unknown
 * option, a missing value or a missing required option is an error naming the argument. Options
 * take their value from the next argument ("--rate 125"); given twice, the last one counts (a
 * DCM_OPT_FUNC option sees every occurrence). "-h" and "--help" ask for the usage.
 */
#ifndef HRP_DCM_ARGS_H
#define HRP_DCM_ARGS_H

#include <limits.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum dcm_opt_kind {
  DCM_OPT_FLAG,     /* no value; out: int, set to 1 */
  DCM_OPT_INT,      /* out: int, min..max */
  DCM_OPT_LONG,     /* out: long, min..max */
  DCM_OPT_DOUBLE,   /* out: double, min..max, finite */
  DCM_OPT_STRING,   /* out: const char *, pointing into argv; non-empty */
  DCM_OPT_FUNC,     /* out: whatever parse converts into */
} dcm_opt_kind;

/* One option: a row of a DCM's table, which ends with a row whose name is NULL. */
typedef struct dcm_opt {
  const char *name;    /* "--rate" */
  dcm_opt_kind kind;
  void *out;
  double min, max;     /* INT, LONG, DOUBLE: the accepted range, both ends included */
  const char *value;   /* the value's name in the usage ("HZ"); NULL for a flag */
  const char *help;    /* one line for the usage */
  /* DCM_OPT_FUNC: converts the value into out; returns 0, or -EINVAL with the reason in err
   * (without the option's name: the parser puts it in front). */
  int (*parse)(const char *value, void *out, char *err, size_t errlen);
  int required;        /* 1: the command line must give it */
} dcm_opt;

/* Rows every DCM that has the option declares alike (d: its struct dcm *). --lockstep-wait fills
 * d->sync.start_with; the DCM then sets d->lockstep when it is > 0. */
#define DCM_OPT_LOCKSTEP(d)                                                                                  \
  { "--lockstep", DCM_OPT_FLAG, &(d)->lockstep, 0, 0, NULL,                                                  \
    "each tick waits for every live participant (Lib/lockstep.lua)", NULL, 0 },                              \
  { "--lockstep-wait", DCM_OPT_INT, &(d)->sync.start_with, 1, 1000, "N",                                     \
    "lockstep, and the first tick waits until N participants have joined", NULL, 0 }
#define DCM_OPT_CYCLES(d, help) { "--cycles", DCM_OPT_LONG, &(d)->max_cycles, 0, (double)LONG_MAX, "N", help, NULL, 0 }
#define DCM_OPT_QUIET(d) { "--quiet", DCM_OPT_FLAG, &(d)->quiet, 0, 0, NULL, "no log or status lines", NULL, 0 }

/* The row that ends a table. */
#define DCM_OPT_END { NULL, DCM_OPT_FLAG, NULL, 0, 0, NULL, NULL, NULL, 0 }

#define DCM_ARGS_HELP 1

/* Reads argv[1..argc-1] into the table's outputs. Returns 0; DCM_ARGS_HELP when -h or --help is
 * given (nothing after it is read); or -EINVAL with one line in err naming the argument, e.g.
 * "--rate: 'fast' is not a number". */
int dcm_args_parse(const dcm_opt *opts, int argc, char *const *argv, char *err, size_t errlen);

/* The usage built from the table into out: "usage: <invocation> <required options> [options]" and
 * a line per option with its value, help and range ("[1..1000]", "[>= 0]"). Returns the length it needed (as snprintf). */
int dcm_args_usage(const char *invocation, const dcm_opt *opts, char *out, size_t outlen);

/* For a DCM's main, before anything is opened: parses; on -h / --help prints the usage on stdout
 * and exits 0; on an error prints "<prog>: <error>" and the usage on stderr and exits 2. */
void dcm_args(const char *prog, const char *invocation, const dcm_opt *opts, int argc, char *const *argv);

/* Strict conversions for DCM_OPT_FUNC parsers (e.g. each entry of a list): the whole of s, decimal,
 * inside min..max; 0, or -EINVAL with the reason in err ("'x' is not an integer", "... out of range"). */
int dcm_args_long(const char *s, long min, long max, long *out, char *err, size_t errlen);
int dcm_args_double(const char *s, double min, double max, double *out, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
