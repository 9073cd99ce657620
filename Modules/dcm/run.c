/* run: the lifecycle every DCM goes through -- configure, blocks, open, enable, then cycles of
 * wait (deadline or lockstep), commands through the guard, write, read, publish, statistics. */
#include "dcm.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* The one piece of process state: what SIGINT / SIGTERM set. */
static volatile sig_atomic_t g_stop;
static void on_signal(int s) { (void)s; g_stop = 1; }

void dcm_stop(dcm *d) {
  if (d->stop) *d->stop = 1;
}

void dcm_log(const dcm *d, const char *fmt, ...) {
  if (d->quiet) return;
  va_list ap;
  va_start(ap, fmt);
  fprintf(stderr, "%s: ", d->name ? d->name : "dcm");
  vfprintf(stderr, fmt, ap);
  fprintf(stderr, "\n");
  va_end(ap);
}

static int open_blocks(dcm *d, char *err, size_t errlen) {
  int rc = shm_schema_load(NULL, &d->schema, err, errlen);
  if (rc < 0) return rc;
  for (int r = 0; r < d->nrobots; r++) {
    dcm_robot *R = &d->robot[r];
    if ((rc = dcm_blocks_open(d->schema, R->id, DCM_BLK_dcm_sensor(&R->sensor), err, errlen)) < 0 ||
        (rc = dcm_blocks_open(d->schema, R->id, DCM_BLK_dcm_actuator(&R->actuator), err, errlen)) < 0 ||
        (rc = dcm_blocks_open(d->schema, R->id, DCM_BLK_dcm_stats(&R->stats), err, errlen)) < 0 ||
        (rc = dcm_blocks_open(d->schema, R->id, DCM_BLK_sync(&R->sync), err, errlen)) < 0)
      return rc;
    /* one DCM per robot: a second one would fight the first over the bus and the blocks */
    const int other = *R->sensor.dcm_pid;
    if (other != 0 && other != (int)getpid() && shm_pid_alive(other)) {
      snprintf(err, errlen, "robot '%s' (id %d): another DCM (pid %d) is running on its blocks; stop it first",
               R->name, R->id, other);
      return -EBUSY;
    }
    /* every joint array must hold the robot's joints */
    const int have[] = { R->sensor.n.position, R->sensor.n.velocity, R->sensor.n.load, R->sensor.n.temperature,
                         R->actuator.n.command, R->actuator.n.hardness, R->actuator.n.torque_enable,
                         R->actuator.n.mode, R->actuator.n.torque };
    for (size_t k = 0; k < sizeof have / sizeof have[0]; k++) {
      if (have[k] < R->nj) {
        snprintf(err, errlen, "robot '%s' (id %d) has %d joints, the shm schema's joint arrays hold %d (const njoint)",
                 R->name, R->id, R->nj, have[k]);
        return -EINVAL;
      }
    }
    d->sync.sync[r] = &R->sync;
  }
  d->sync.n = d->nrobots;
  return 0;
}

static void close_blocks(dcm *d) {
  for (int r = 0; r < d->nrobots; r++) {
    dcm_robot *R = &d->robot[r];
    shm_block *bs[] = { R->sensor.blk, R->actuator.blk, R->stats.blk, R->sync.blk };
    for (size_t k = 0; k < sizeof bs / sizeof bs[0]; k++)
      if (bs[k]) shm_block_close(bs[k]);
  }
  if (d->schema) shm_schema_free(d->schema);
  d->schema = NULL;
}

static void publish(dcm *d, const dcm_driver *drv, void *hw) {
  const int pid = (int)getpid();
  for (int r = 0; r < d->nrobots; r++) {
    const dcm_blk_dcm_sensor *s = &d->robot[r].sensor;
    shm_write_begin(s->blk);
    *s->time = d->time;
    *s->tick = d->tick;
    *s->period = d->period;
    *s->dcm_pid = pid;
    drv->publish(hw, d, r, s);
    shm_write_end(s->blk);
  }
}

static void write_stats(dcm *d, const dcm_driver *drv, void *hw) {
  for (int r = 0; r < d->nrobots; r++) {
    const dcm_blk_dcm_stats *s = &d->robot[r].stats;
    const dcm_guard *g = &d->robot[r].guard;
    shm_write_begin(s->blk);
    *s->rate = d->pacer.rate;
    *s->jitter_p50 = d->pacer.jitter_p50;
    *s->jitter_p99 = d->pacer.jitter_p99;
    *s->jitter_max = d->pacer.jitter_max;
    *s->cycles = d->pacer.cycles;
    *s->missed_cycles = d->pacer.missed;
    *s->nan_commands = g->refused;
    *s->torque_refused = g->torque_refused;
    *s->torque_clamped = g->torque_clamped;
    *s->watchdog_trips = g->trips;
    *s->watchdog_lag = g->trip_lag;
    if (drv->stats) drv->stats(hw, d, r, s);
    shm_write_end(s->blk);
  }
}

/* The DCM owns the start state: on every start, whatever the actuator block held (a REPL command
 * written before any DCM ran, a previous run's last pose or hardness 0, torque mode), every joint is
 * commanded in position mode to its present position at start_hardness with its torque on, so
 * nothing moves when the DCM starts and nothing is limp. The robot's processes take over with their next commands. */
static void seed_actuators(dcm *d) {
  for (int r = 0; r < d->nrobots; r++) {
    dcm_robot *R = &d->robot[r];
    const dcm_blk_dcm_actuator *a = &R->actuator;
    shm_write_begin(a->blk);
    for (int j = 0; j < R->nj; j++) {
      a->command[j] = R->sensor.position[j];
      a->hardness[j] = d->start_hardness;
      a->torque_enable[j] = 1;
      a->mode[j] = DCM_MODE_POSITION;
      a->torque[j] = 0;
    }
    shm_write_end(a->blk);
  }
}

/* The robot clock and the tick continue across DCM restarts: participants keep counting ticks. */
static void start_clock(dcm *d) {
  uint32_t tick = 0;
  double time0 = 0;
  for (int r = 0; r < d->nrobots; r++) {
    const dcm_robot *R = &d->robot[r];
    if (*R->sensor.tick > tick) tick = *R->sensor.tick;
    if (*R->sync.tick > tick) tick = *R->sync.tick;
    if (*R->sensor.time > time0) time0 = *R->sensor.time;
  }
  if (tick < 1) tick = 1;   /* tick 0 never appears: a participant joining at 0 holds tick 0 - 1 */
  d->tick = tick;
  d->time0 = d->simulated ? 0 : time0;
  d->t0 = d->pacer.clock.now(d->pacer.clock.ctx);
  d->time = d->simulated ? tick * d->period : d->time0;
}

/* The driver's idle hook behind dcm_lockstep_wait's callback. */
struct idle_ctx {
  const dcm_driver *drv;
  void *hw;
  dcm *d;
};
static void idle(void *ctx, int alone) {
  struct idle_ctx *c = (struct idle_ctx *)ctx;
  c->drv->idle(c->hw, c->d, alone);
}

/* each robot's safe pose (robot.lua safe_pose), read with the configuration, before any I/O */
static struct { dcm_safe_pose pose; int has; } g_safe[DCM_ROBOTS_MAX];

/* what the safe state does, for the log: "into the safe pose at hardness 1.00, the rest held at 0.30" */
static void safe_state_words(char *out, size_t len, const dcm_safe_pose *pose, int has, double safe_hardness) {
  if (!has)
    snprintf(out, len, "holding the pose at hardness %.2f", safe_hardness);
  else if (isfinite(pose->hardness))
    snprintf(out, len, "into the safe pose at hardness %.2f, the rest held at %.2f", pose->hardness, safe_hardness);
  else
    snprintf(out, len, "into the safe pose at hardness %.2f", safe_hardness);
}

static int setup(dcm *d, const dcm_driver *drv, void *hw, char *err, size_t errlen) {
  int rc = drv->configure(hw, d, err, errlen);
  if (rc < 0) return rc;
  if (d->nrobots < 1 || d->nrobots > DCM_ROBOTS_MAX || !(d->period > 0)) {
    snprintf(err, errlen, "%s: configure gave %d robots, period %g s", d->name, d->nrobots, d->period);
    return -EINVAL;
  }
  for (int r = 0; r < d->nrobots; r++) {
    if (d->robot[r].nj < 1 || d->robot[r].nj > DCM_NJ_MAX) {
      snprintf(err, errlen, "robot '%s': %d joints (1 to %d)", d->robot[r].name, d->robot[r].nj, DCM_NJ_MAX);
      return -EINVAL;
    }
    if ((rc = dcm_safe_pose_load(d->robot[r].name, d->robot[r].nj, &g_safe[r].pose, err, errlen)) < 0) return rc;
    g_safe[r].has = rc > 0;
  }
  if ((rc = open_blocks(d, err, errlen)) < 0) return rc;
  /* open: a missing bus is waited for (the adapter is plugged in later) */
  int reported = 0;
  while ((rc = drv->open(hw, d, err, errlen)) == -EAGAIN && !*d->stop) {
    if (!reported) dcm_log(d, "%s (retrying)", err);
    reported = 1;
    d->pacer.clock.sleep_until(d->pacer.clock.ctx, d->pacer.clock.now(d->pacer.clock.ctx) + 0.5);
  }
  if (rc < 0) return *d->stop ? 0 : rc;
  return drv->enable(hw, d, err, errlen);
}

int dcm_main(dcm *d, const dcm_driver *drv, void *hw, char *err, size_t errlen) {
  if (!d->stop) {
    g_stop = 0;
    d->stop = &g_stop;
    signal(SIGINT, on_signal);
    signal(SIGTERM, on_signal);
    signal(SIGPIPE, SIG_IGN);
  }
  if (!d->pacer.clock.now) d->pacer.clock = dcm_clock_wall(d->stop);
  d->sync.spin = d->sync.spin > 0 ? d->sync.spin : 100e-6;
  d->sync.drop_after = d->sync.drop_after > 0 ? d->sync.drop_after : 0.2;
  int rc = setup(d, drv, hw, err, errlen);
  if (rc < 0 || *d->stop) {
    if (drv->close) drv->close(hw, d);
    close_blocks(d);
    return rc;
  }
  dcm_pacer_init(&d->pacer, d->period, d->pacer.clock);
  start_clock(d);
  publish(d, drv, hw);
  seed_actuators(d);
  for (int r = 0; r < d->nrobots; r++) {
    dcm_robot *R = &d->robot[r];
    dcm_guard_init(&R->guard, R->nj, d->lockstep ? 0 : d->watchdog, d->safe_hardness, R->sensor.position,
                   *R->actuator.tick_ack);
    dcm_guard_set_safe_pose(&R->guard, &g_safe[r].pose);
    dcm_guard_set_stall(&R->guard, d->stall_cycles, d->stall_cpu);
    dcm_guard_set_torque_limits(&R->guard, R->torque_limit);
  }
  /* lockstep waits for a stalled participant no longer than the guard would in real time */
  d->sync.stall_after = d->stall_cycles > 0 ? d->stall_cycles * d->period : 0;
  write_stats(d, drv, hw);
  if (d->lockstep) dcm_lockstep_start(&d->sync, d->tick);
  else dcm_lockstep_end(&d->sync);

  while (!*d->stop && (d->max_cycles < 0 || (long)d->pacer.cycles < d->max_cycles)) {
    /* ---- wait: the participants of the published tick, or the next deadline */
    if (d->lockstep) {
      struct idle_ctx ic = { drv, hw, d };
      if (dcm_lockstep_hold(&d->sync, d->tick, drv->idle ? idle : NULL, &ic, d->stop)) break;
      dcm_lockstep_publish(&d->sync, d->tick);
      if (drv->published) drv->published(hw, d);
      if (dcm_lockstep_wait(&d->sync, d->tick, drv->idle ? idle : NULL, &ic, d->stop)) break;
      d->now = dcm_pacer_count(&d->pacer);
    } else {
      if (drv->published) drv->published(hw, d);
      d->now = dcm_pacer_wait(&d->pacer);
    }
    if (*d->stop) break;
    /* ---- commands, checked */
    for (int r = 0; r < d->nrobots; r++) {
      dcm_robot *R = &d->robot[r];
      dcm_command_read(&R->actuator, R->nj, &R->cmd);
      const int was_safe = R->guard.safe;
      dcm_guard_apply(&R->guard, d->time, R->sensor.position, &R->cmd);
      if (R->guard.safe && !was_safe) dcm_actuator_position_mode(&R->actuator, R->nj, R->guard.hold);
      char into[96];
      safe_state_words(into, sizeof into, &g_safe[r].pose, g_safe[r].has, d->safe_hardness);
      if (R->guard.safe && !was_safe && R->guard.dead_writer)
        dcm_log(d, "robot %d: watchdog: the writer (pid %d) died: %s", R->id, R->guard.dead_writer, into);
      else if (R->guard.safe && !was_safe && R->guard.cause == DCM_WRITER_STOPPED)
        dcm_log(d, "robot %d: watchdog: the writer (pid %u) is stopped (no new tick_ack for %d cycles): %s",
                R->id, R->cmd.writer_pid, R->guard.still, into);
      else if (R->guard.safe && !was_safe && R->guard.cause == DCM_WRITER_BUSY)
        dcm_log(d, "robot %d: watchdog: the writer (pid %u) runs without a new tick_ack (%d cycles, over %.1f ms of CPU): "
                "%s", R->id, R->cmd.writer_pid, R->guard.still, d->stall_cpu * 1e3, into);
      else if (R->guard.safe && !was_safe)
        dcm_log(d, "robot %d: watchdog: no new tick_ack for %.2f s: %s", R->id, d->watchdog, into);
      else if (was_safe && !R->guard.safe)
        dcm_log(d, "robot %d: motion answers again: commands resume", R->id);
    }
    /* ---- the hardware */
    drv->write(hw, d);
    drv->read(hw, d);
    /* a driver that stopped in read (the Replay's log ended) has no new tick: publishing the last one
     * again under a new tick number would give the processes a step the recording never had */
    if (*d->stop) break;
    /* ---- sensors and statistics */
    d->tick++;
    d->time = d->simulated ? d->tick * d->period : d->time0 + (d->now - d->t0);
    publish(d, drv, hw);
    write_stats(d, drv, hw);
  }
  if (d->lockstep) dcm_lockstep_end(&d->sync);
  if (drv->close) drv->close(hw, d);
  close_blocks(d);
  return 0;
}

int dcm_run(dcm *d, const dcm_driver *drv, void *hw) {
  char err[1024];
  const int rc = dcm_main(d, drv, hw, err, sizeof err);
  if (rc == 0) return 0;
  fprintf(stderr, "%s: %s\n", d->name ? d->name : "dcm", err);
  return rc == -EINVAL ? 2 : 1;
}
