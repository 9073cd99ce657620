/* TAP output shared by the C and C++ test programs (Tests/run_all.sh counts these lines):
 * check() prints one result, tap_done() prints the plan and gives the exit status. */
#ifndef HRP_TAP_H
#define HRP_TAP_H
#include <stddef.h>
#include <stdio.h>
#include <string.h>

static int tap_count, tap_failures;

/* One result line; detail (may be NULL or empty) goes after a '#'. */
static inline void tap_ok(int cond, const char *name, const char *detail) {
  tap_count++;
  if (!cond) tap_failures++;
  printf("%s %d - %s%s%s\n", cond ? "ok" : "not ok", tap_count, name, detail && detail[0] ? " # " : "",
         detail ? detail : "");
  fflush(stdout);
}

static inline void check(int cond, const char *name) { tap_ok(cond, name, NULL); }

#ifdef __cplusplus
#include <string>
static inline void check(int cond, const std::string &name) { tap_ok(cond, name.c_str(), nullptr); }
#endif

static inline void tap_hex(const char *label, const unsigned char *b, size_t n) {
  printf("# %s:", label);
  for (size_t i = 0; i < n; i++) printf(" %02X", b[i]);
  printf("\n");
}

/* Compares two byte strings and prints both on a mismatch. */
static inline void check_bytes(const unsigned char *got, int gotlen, const unsigned char *want, int wantlen,
                               const char *name) {
  int same = gotlen == wantlen && memcmp(got, want, (size_t)wantlen) == 0;
  if (!same) {
    tap_hex("got ", got, gotlen > 0 ? (size_t)gotlen : 0);
    tap_hex("want", want, (size_t)wantlen);
  }
  check(same, name);
}

/* Prints the plan; returns the exit status (1 if any check failed). */
static inline int tap_done(void) {
  printf("1..%d\n", tap_count);
  fflush(stdout);
  return tap_failures ? 1 : 0;
}
#endif
