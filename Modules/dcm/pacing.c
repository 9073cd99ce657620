/* pacing: cycles at absolute deadlines, missed cycles, jitter p50 / p99 / max and rate per window. */
#include "dcm.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double wall_now(void *ctx) {
  (void)ctx;
  return shm_now();
}

static void wall_sleep_until(void *ctx, double t) {
  volatile sig_atomic_t *stop = (volatile sig_atomic_t *)ctx;
  struct timespec ts;
  ts.tv_sec = (time_t)t;
  ts.tv_nsec = (long)((t - (double)ts.tv_sec) * 1e9);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL) == EINTR && !(stop && *stop)) {}
}

dcm_clock dcm_clock_wall(volatile sig_atomic_t *stop) {
  dcm_clock c = { wall_now, wall_sleep_until, (void *)stop };
  return c;
}

void dcm_pacer_init(dcm_pacer *p, double period, dcm_clock clock) {
  memset(p, 0, sizeof *p);
  p->clock = clock;
  p->period = period;
  p->window = 1.0;
  p->deadline = clock.now(clock.ctx);
  p->win_start = p->deadline;
}

static int cmp_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

/* Counts the cycle; closes the window after `window` s (or when the jitter store is full). */
static void count(dcm_pacer *p, double now) {
  p->cycles++;
  p->win_cycles++;
  p->closed = 0;
  if (now - p->win_start < p->window && p->njit < DCM_JITTER_MAX) return;
  p->rate = now > p->win_start ? p->win_cycles / (now - p->win_start) : 0;
  if (p->njit > 0) {
    qsort(p->jit, (size_t)p->njit, sizeof p->jit[0], cmp_double);
    p->jitter_p50 = p->jit[(int)(0.50 * (p->njit - 1))];
    p->jitter_p99 = p->jit[(int)(0.99 * (p->njit - 1))];
    p->jitter_max = p->jit[p->njit - 1];
  }
  p->closed = 1;
  p->window_cycles = p->win_cycles;
  p->win_start = now;
  p->win_cycles = 0;
  p->njit = 0;
}

double dcm_pacer_wait(dcm_pacer *p) {
  p->deadline += p->period;
  double now = p->clock.now(p->clock.ctx);
  if (now < p->deadline) {
    p->clock.sleep_until(p->clock.ctx, p->deadline);
    now = p->clock.now(p->clock.ctx);
  }
  double late = now - p->deadline;
  if (late > p->period) {
    /* an overrun (a stall, an overloaded machine): the lost cycles are counted, not raced */
    p->missed += (uint32_t)floor(late / p->period);
    p->deadline = now;
  }
  if (p->njit < DCM_JITTER_MAX) p->jit[p->njit++] = fabs(late);
  count(p, now);
  return now;
}

double dcm_pacer_count(dcm_pacer *p) {
  double now = p->clock.now(p->clock.ctx);
  p->deadline = now;
  count(p, now);
  return now;
}
