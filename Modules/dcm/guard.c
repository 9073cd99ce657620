/* guard: what stands between the actuator block and the servos -- NaN / inf refused, hardness
 * clamped, and the watchdog with its safe pose. */
#include "dcm.h"

#include <errno.h>
#include <math.h>
#include <poll.h>
#include <string.h>
#include <sys/syscall.h>
#include <unistd.h>

void dcm_guard_init(dcm_guard *g, int nj, double timeout, double safe_hardness, const double *present,
                    uint32_t tick_ack) {
  memset(g, 0, sizeof *g);
  g->nj = nj;
  g->timeout = timeout;
  g->safe_hardness = safe_hardness < 0 ? 0 : safe_hardness > 1 ? 1 : safe_hardness;
  /* an acknowledgement left from before this DCM started does not arm the watchdog: the next
   * new one does */
  g->last_ack = tick_ack;
  g->watch_fd = -1;
  for (int j = 0; j < nj; j++) {
    g->safe_pose[j] = NAN;
    g->last_pos[j] = present[j];
    g->last_hard[j] = 0;
  }
}

void dcm_command_read(const dcm_blk_dcm_actuator *a, int nj, dcm_command *out) {
  const size_t nd = sizeof(double) * (size_t)nj, ni = sizeof(int32_t) * (size_t)nj;
  uint32_t seq;
  do {
    seq = shm_read_begin(a->blk);
    memcpy(out->position, a->command, nd);
    memcpy(out->hardness, a->hardness, nd);
    memcpy(out->enable, a->torque_enable, ni);
    out->tick_ack = *(volatile uint32_t *)a->tick_ack;
    out->writer_pid = *(volatile uint32_t *)a->writer_pid;
  } while (shm_read_retry(a->blk, seq));
}

void dcm_guard_set_safe_pose(dcm_guard *g, const double *pose, double ramp) {
  for (int j = 0; j < g->nj; j++) g->safe_pose[j] = pose ? pose[j] : NAN;
  g->ramp = ramp > 0 ? ramp : 0;
}

/* Whether the writer `pid` has ended. A pidfd, kept while the pid stays the writer, says so as
 * soon as the process exits; kill(pid, 0) still finds it until its parent reaps it (run_main took
 * 90 ms to on a loaded machine: Tests/fault/dxl_faults_test.sh). Without pidfds: kill(pid, 0). */
static int writer_dead(dcm_guard *g, int pid) {
  if (pid != g->watch_pid) {
    if (g->watch_fd >= 0) close(g->watch_fd);
    g->watch_pid = pid;
    g->watch_fd = (int)syscall(SYS_pidfd_open, pid, 0);
    if (g->watch_fd < 0 && errno == ESRCH) return 1;
  }
  if (g->watch_fd < 0) return !shm_pid_alive(pid);
  struct pollfd p = { g->watch_fd, POLLIN, 0 };
  return poll(&p, 1, 0) > 0;
}

int dcm_guard_apply(dcm_guard *g, double now, const double *present, dcm_command *c) {
  for (int j = 0; j < g->nj; j++) {
    if (!isfinite(c->position[j])) {
      g->refused++;
      c->position[j] = g->last_pos[j];
    }
    if (!isfinite(c->hardness[j])) {
      g->refused++;
      c->hardness[j] = g->last_hard[j];
    }
    c->hardness[j] = c->hardness[j] < 0 ? 0 : c->hardness[j] > 1 ? 1 : c->hardness[j];
    c->enable[j] = c->enable[j] ? 1 : 0;
    g->last_pos[j] = c->position[j];
    g->last_hard[j] = c->hardness[j];
  }
  if (c->tick_ack != g->last_ack) {
    g->last_ack = c->tick_ack;
    g->ack_time = now;
    if (c->tick_ack) g->armed = 1;
    g->safe = 0;   /* motion answers (again): its commands go through */
  }
  if (g->timeout > 0 && g->armed && !g->safe) {
    /* a writer that died is seen on the next cycle; one that hangs after the timeout */
    const int dead = c->writer_pid && writer_dead(g, (int)c->writer_pid);
    if (dead || now - g->ack_time > g->timeout) {
      g->safe = 1;
      g->trips++;
      g->dead_writer = dead ? (int)c->writer_pid : 0;
      memcpy(g->hold, present, sizeof(double) * (size_t)g->nj);
      g->trip_time = now;
    }
  }
  if (g->safe) {
    /* from the pose of the trip into the safe pose: a smooth step over `ramp` s */
    double s = g->ramp > 0 ? (now - g->trip_time) / g->ramp : 1;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    s = s * s * (3 - 2 * s);
    for (int j = 0; j < g->nj; j++) {
      const double to = g->safe_pose[j];
      c->position[j] = isfinite(to) ? g->hold[j] + (to - g->hold[j]) * s : g->hold[j];
      if (c->hardness[j] > g->safe_hardness) c->hardness[j] = g->safe_hardness;
    }
  }
  return g->safe;
}
