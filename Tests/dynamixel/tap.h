/* Minimal TAP helpers for the Dynamixel C tests. */
#ifndef DXL_TEST_TAP_H
#define DXL_TEST_TAP_H
#include <stdio.h>
#include <string.h>

static int tap_n, tap_failed;

static void tap_ok(int cond, const char *name) {
  tap_n++;
  if (!cond) tap_failed++;
  printf("%s %d - %s\n", cond ? "ok" : "not ok", tap_n, name);
  fflush(stdout);
}

static void tap_hex(const char *label, const unsigned char *b, size_t n) {
  printf("# %s:", label);
  for (size_t i = 0; i < n; i++) printf(" %02X", b[i]);
  printf("\n");
}

/* Compares n bytes and prints both on mismatch. */
static void tap_bytes(const unsigned char *got, int gotlen, const unsigned char *want, int wantlen,
                      const char *name) {
  int same = gotlen == wantlen && memcmp(got, want, (size_t)wantlen) == 0;
  if (!same) {
    tap_hex("got ", got, gotlen > 0 ? (size_t)gotlen : 0);
    tap_hex("want", want, (size_t)wantlen);
  }
  tap_ok(same, name);
}

static int tap_done(void) {
  printf("1..%d\n", tap_n);
  return tap_failed ? 1 : 0;
}
#endif
