// A deliberate leak, to show that the soak's check catches one (Tests/soak/soak.sh with
// HRP_SOAK_LEAK_BYTES_PER_S=N builds this and preloads it into run_main's processes). It wraps ODE's
// dWorldQuickStep, which only the sim DCM calls, and keeps N bytes per simulated second (the steps' sizes
// summed) in 1 kB pieces: allocated, written (so they are resident) and never freed.
#define _GNU_SOURCE
#include <dlfcn.h>
#include <ode/ode.h>
#include <stdlib.h>
#include <string.h>

static void *volatile kept;   // the newest piece; each piece holds the one before it

int dWorldQuickStep(dWorldID w, dReal stepsize) {
  static int (*next)(dWorldID, dReal);
  static double rate = -1, owed = 0;
  if (!next) *(void **)&next = dlsym(RTLD_NEXT, "dWorldQuickStep");
  if (rate < 0) {
    const char *s = getenv("HRP_SOAK_LEAK_BYTES_PER_S");
    rate = s ? atof(s) : 0;
  }
  owed += rate * stepsize;
  while (owed >= 1024) {
    void **p = malloc(1024);
    if (!p) break;
    memset(p, 0xa5, 1024);
    p[0] = kept;
    kept = p;
    owed -= 1024;
  }
  return next ? next(w, stepsize) : 0;
}
