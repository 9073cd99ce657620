/* guard: what stands between the actuator block and the servos -- NaN / inf refused, hardness
 * clamped, torques clamped to each joint's limit, and the watchdog with its safe pose. */
#include "dcm.h"

#include <errno.h>
#include <math.h>
#include <poll.h>
#include <string.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

int dcm_proc_probe(int pid, dcm_proc *out) {
  memset(out, 0, sizeof *out);
  char path[40], buf[512];
  snprintf(path, sizeof path, "/proc/%d/stat", pid);
  FILE *f = pid > 0 ? fopen(path, "r") : NULL;
  if (!f) return -ESRCH;
  const size_t n = fread(buf, 1, sizeof buf - 1, f);
  fclose(f);
  buf[n] = 0;
  /* "pid (comm) S ppid ...": comm may hold spaces and parentheses, so fields count from the last ')' */
  const char *p = strrchr(buf, ')');
  if (!p || p[1] != ' ' || !p[2]) return -ESRCH;
  out->state = (unsigned char)p[2];
  p += 2;
  for (int field = 3; field < 22 && p; field++) {   /* to field 22, starttime */
    p = strchr(p, ' ');
    if (p) p++;
  }
  if (p) out->start = strtoull(p, NULL, 10);
  /* the CPU clock, not utime + stime: those count in clock ticks (10 ms), too coarse for a few ms */
  clockid_t clk;
  struct timespec ts;
  if (clock_getcpuclockid(pid, &clk) == 0 && clock_gettime(clk, &ts) == 0)
    out->cpu = (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
  return 0;
}

double dcm_proc_cpu(int pid) {
  clockid_t clk;
  struct timespec ts;
  if (pid <= 0 || clock_getcpuclockid(pid, &clk) != 0 || clock_gettime(clk, &ts) != 0) return -1;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int dcm_writer_verdict(const dcm_proc *registered, double cpu_at_ack, const dcm_proc *now, double cpu_limit) {
  const int st = now->state;
  if (st == 0 || st == 'Z' || st == 'X' || st == 'x') return DCM_WRITER_GONE;
  if (registered->state && registered->start != now->start) return DCM_WRITER_GONE;   /* the pid was reused */
  if (st == 'T' || st == 't') return DCM_WRITER_STOPPED;
  /* a starved writer burns nothing while it waits for a CPU; one that works without acknowledging
   * for longer than any tick's work takes is looping */
  if (cpu_limit > 0 && cpu_at_ack >= 0 && now->cpu - cpu_at_ack > cpu_limit) return DCM_WRITER_BUSY;
  return DCM_WRITER_RUNS;
}

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
  g->probe = dcm_proc_probe;
  g->cpu = dcm_proc_cpu;
  g->cpu_at_ack = -1;
  dcm_guard_set_safe_pose(g, NULL);
  for (int j = 0; j < nj; j++) {
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
    memcpy(out->mode, a->mode, ni);
    memcpy(out->torque, a->torque, nd);
    out->tick_ack = *(volatile uint32_t *)a->tick_ack;
    out->writer_pid = *(volatile uint32_t *)a->writer_pid;
  } while (shm_read_retry(a->blk, seq));
}

void dcm_guard_set_safe_pose(dcm_guard *g, const dcm_safe_pose *pose) {
  for (int j = 0; j < DCM_NJ_MAX; j++) g->pose.q[j] = pose && j < g->nj ? pose->q[j] : NAN;
  g->pose.ramp = pose && pose->ramp > 0 ? pose->ramp : 0;
  const double h = pose ? pose->hardness : NAN;
  g->pose.hardness = isfinite(h) ? (h < 0 ? 0 : h > 1 ? 1 : h) : NAN;
}

void dcm_guard_set_torque_limits(dcm_guard *g, const double *limit) {
  for (int j = 0; j < DCM_NJ_MAX; j++) {
    const double l = limit && j < g->nj ? limit[j] : 0;
    g->torque_limit[j] = isfinite(l) && l > 0 ? l : 0;
  }
}

void dcm_actuator_position_mode(const dcm_blk_dcm_actuator *a, int nj, const double *hold) {
  shm_write_begin(a->blk);
  for (int j = 0; j < nj; j++) {
    if (a->mode[j] == DCM_MODE_POSITION) continue;
    a->mode[j] = DCM_MODE_POSITION;
    a->command[j] = hold[j];
    a->torque[j] = 0;
  }
  shm_write_end(a->blk);
}

void dcm_guard_set_stall(dcm_guard *g, int cycles, double cpu) {
  g->stall_cycles = cycles > 0 ? cycles : 0;
  g->stall_cpu = cpu > 0 ? cpu : 0;
}

/* A new writer: its pidfd, and what it is (its start time tells its pid reused later). */
static void watch(dcm_guard *g, int pid) {
  if (pid == g->watch_pid) return;
  if (g->watch_fd >= 0) close(g->watch_fd);
  g->watch_pid = pid;
  g->watch_fd = (int)syscall(SYS_pidfd_open, pid, 0);
  if (g->watch_fd < 0 && errno == ESRCH) g->watch_fd = -2;   /* gone already */
  if (g->stall_cycles > 0) g->probe(pid, &g->registered);
}

/* Whether the writer `pid` has ended. A pidfd, kept while the pid stays the writer, says so as
 * soon as the process exits; kill(pid, 0) still finds it until its parent reaps it (run_main took
 * 90 ms to on a loaded machine: Tests/fault/dxl_faults_test.sh). Without pidfds: kill(pid, 0). */
static int writer_dead(dcm_guard *g, int pid) {
  watch(g, pid);
  if (g->watch_fd == -2) return 1;
  if (g->watch_fd < 0) return !shm_pid_alive(pid);
  struct pollfd p = { g->watch_fd, POLLIN, 0 };
  return poll(&p, 1, 0) > 0;
}

/* Joint j's torque-mode command: clamped to its limit, or refused -- then the joint is in position
 * mode holding the pose it had at the refusal, until a valid command (torque or position) comes. */
static void check_torque(dcm_guard *g, int j, const double *present, dcm_command *c) {
  const int32_t mode = c->mode[j];
  if (mode == DCM_MODE_POSITION) {
    g->held[j] = 0;
    return;
  }
  const double lim = g->torque_limit[j];
  if (mode == DCM_MODE_TORQUE && lim > 0 && isfinite(c->torque[j])) {
    g->held[j] = 0;
    if (c->torque[j] > lim || c->torque[j] < -lim) {
      g->torque_clamped++;
      c->torque[j] = c->torque[j] > 0 ? lim : -lim;
    }
    return;
  }
  g->torque_refused++;
  if (!g->held[j]) g->torque_hold[j] = present[j];
  g->held[j] = 1;
  c->mode[j] = DCM_MODE_POSITION;
  c->position[j] = g->torque_hold[j];
  c->torque[j] = 0;
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
    check_torque(g, j, present, c);
    g->last_pos[j] = c->position[j];
    g->last_hard[j] = c->hardness[j];
  }
  const int pid = (int)c->writer_pid;
  if (c->tick_ack != g->last_ack) {
    g->last_ack = c->tick_ack;
    g->ack_time = now;
    if (c->tick_ack) g->armed = 1;
    g->safe = 0;   /* motion answers (again): its commands go through */
    g->still = 0;
    if (g->stall_cycles > 0 && pid) {
      watch(g, pid);
      g->cpu_at_ack = g->cpu(pid);
    }
  } else if (g->still < 0x7fffffff) {
    g->still++;
  }
  if ((g->timeout > 0 || g->stall_cycles > 0) && g->armed && !g->safe) {
    /* a writer that died is seen on the next cycle; one stopped or looping after stall_cycles; one
     * that does not run (a loaded machine: it may yet answer) after the timeout */
    int cause = -1;
    if (pid && writer_dead(g, pid)) {
      cause = DCM_WRITER_GONE;
    } else if (pid && g->stall_cycles > 0 && g->still >= g->stall_cycles) {
      dcm_proc p;
      g->probe(pid, &p);
      const int v = dcm_writer_verdict(&g->registered, g->cpu_at_ack, &p, g->stall_cpu);
      if (v != DCM_WRITER_RUNS) cause = v;
    }
    if (cause < 0 && g->timeout > 0 && now - g->ack_time > g->timeout) cause = DCM_WRITER_RUNS;
    if (cause >= 0) {
      g->safe = 1;
      g->trips++;
      g->trip_lag = (uint32_t)g->still;
      g->cause = cause;
      g->dead_writer = cause == DCM_WRITER_GONE ? pid : 0;
      memcpy(g->hold, present, sizeof(double) * (size_t)g->nj);
      g->trip_time = now;
    }
  }
  if (g->safe) {
    /* from the pose of the trip into the safe pose: a smooth step over `ramp` s */
    double s = g->pose.ramp > 0 ? (now - g->trip_time) / g->pose.ramp : 1;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    s = s * s * (3 - 2 * s);
    const double posed_hardness = isfinite(g->pose.hardness) ? g->pose.hardness : g->safe_hardness;
    for (int j = 0; j < g->nj; j++) {
      const double to = g->pose.q[j];
      c->position[j] = isfinite(to) ? g->hold[j] + (to - g->hold[j]) * s : g->hold[j];
      c->mode[j] = DCM_MODE_POSITION;
      c->torque[j] = 0;
      const double cap = isfinite(to) ? posed_hardness : g->safe_hardness;
      if (c->hardness[j] > cap) c->hardness[j] = cap;
    }
  }
  return g->safe;
}
