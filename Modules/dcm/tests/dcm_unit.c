/* Tests of the DCM library (TAP): generated shm bindings, pacing statistics on a fake clock, the
 * guard (NaN refusal, hardness clamp, watchdog trip and resume, dead writer; torque mode: the torque
 * clamped to the joint's limit, a NaN torque or a joint without a torque path refused and held, a
 * trip putting every joint in position mode, in the block too; the stall check's
 * verdicts: stopped, busy, starved, pid reused), the lockstep wait (dead participants dropped,
 * stopped ones passed over, live ones waited for), the config reader's errors and the command-line
 * parser (strict numbers, ranges, unknown and missing arguments, the usage, the exit statuses). */
#include "dcm/args.h"
#include "dcm/dcm.h"
#include "tap.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static int g_id;   /* a robot id of this test's own */

static void remove_blocks(void) {
  const char *names[] = { "dcm.sensor", "dcm.actuator", "dcm.stats", "sync" };
  for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) shm_block_unlink(names[k], g_id);
}

/* ---------------------------------------------------------------- blocks */

static void test_blocks(void) {
  char err[512] = "";
  shm_schema *s = NULL;
  check(shm_schema_load(NULL, &s, err, sizeof err) == 0, "the schema loads");
  long nj = shm_schema_const(s, "njoint");
  dcm_blk_dcm_sensor sen;
  memset(&sen, 0, sizeof sen);
  int rc = dcm_blocks_open(s, g_id, DCM_BLK_dcm_sensor(&sen), err, sizeof err);
  check(rc == 0 && sen.blk && sen.position && sen.gyro && sen.dcm_pid, "dcm.sensor binds from the generated struct");
  check(sen.n.position == nj && sen.n.gyro == 3 && sen.n.time == 1, "element counts come from the segment");
  sen.position[nj - 1] = 1.25;
  double *p = (double *)shm_field_ptr(sen.blk, "position", NULL, NULL);
  check(p && p[nj - 1] == 1.25, "the bound pointer is the segment's field");
  dcm_blk_dcm_stats st;
  rc = dcm_blocks_bind(sen.blk, DCM_BLK_dcm_stats(&st), err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "dcm.sensor") && strstr(err, "dcm.stats"), "binding a block as another is refused", err);
  shm_block_close(sen.blk);
  shm_schema_free(s);

  /* a schema whose dcm.stats lacks a field the generated struct has */
  char path[] = "/tmp/dcm_unit_schemaXXXXXX";
  int fd = mkstemp(path);
  FILE *f = fdopen(fd, "w");
  fprintf(f, "const njoint 4\nblock dcm.stats\n  f64 jitter_p99 1\n  u32 cycles 1\n");
  fclose(f);
  shm_block_unlink("dcm.stats", g_id);
  rc = shm_schema_load(path, &s, err, sizeof err);
  rc = rc == 0 ? dcm_blocks_open(s, g_id, DCM_BLK_dcm_stats(&st), err, sizeof err) : rc;
  tap_ok(rc < 0 && strstr(err, "dcm.stats") && strstr(err, "'rate'"), "a field missing from the segment is named", err);
  shm_block_unlink("dcm.stats", g_id);
  if (s) shm_schema_free(s);
  unlink(path);
}

/* ---------------------------------------------------------------- pacing */

typedef struct fake_clock {
  double t;
  int k;              /* sleeps so far */
  double late_every;  /* every n-th sleep ends late_big late, the others late_small */
  double late_small, late_big;
  int overrun_at;     /* this sleep ends 3.5 periods late */
  double period;
} fake_clock;

static double fake_now(void *ctx) { return ((fake_clock *)ctx)->t; }
static void fake_sleep(void *ctx, double t) {
  fake_clock *c = (fake_clock *)ctx;
  c->k++;
  double late = (c->k % (int)c->late_every == 0) ? c->late_big : c->late_small;
  if (c->k == c->overrun_at) late = 3.5 * c->period;
  c->t = t + late;
}

static void test_pacing(void) {
  fake_clock fc = { 100.0, 0, 50, 50e-6, 400e-6, -1, 0.008 };
  dcm_clock clk = { fake_now, fake_sleep, &fc };
  dcm_pacer p;
  dcm_pacer_init(&p, 0.008, clk);
  p.window = 8.0;   /* 1000 cycles in one window */
  int closed_at = -1;
  for (int i = 0; i < 1000; i++) {
    dcm_pacer_wait(&p);
    if (p.closed && closed_at < 0) closed_at = i + 1;
  }
  char d[160];
  snprintf(d, sizeof d, "closed after %d cycles, rate %.4f Hz", closed_at, p.rate);
  tap_ok(closed_at == 1000 && fabs(p.rate - 125.0) < 0.01, "rate over a window of absolute deadlines", d);
  snprintf(d, sizeof d, "p50 %.1f us, p99 %.1f us, max %.1f us", p.jitter_p50 * 1e6, p.jitter_p99 * 1e6,
           p.jitter_max * 1e6);
  /* 20 of 1000 cycles start 400 us late (2%): the 99th percentile is one of them; the median is
   * one of the others, 50 us late */
  tap_ok(fabs(p.jitter_p99 - 400e-6) < 1e-9 && fabs(p.jitter_max - 400e-6) < 1e-9 && fabs(p.jitter_p50 - 50e-6) < 1e-9,
         "jitter p50, p99 and max", d);
  check(p.missed == 0 && p.cycles == 1000, "no cycle missed when every cycle starts within its period");

  /* deadlines are absolute: constant lateness does not accumulate into drift */
  fake_clock f2 = { 0.0, 0, 1000000, 300e-6, 0, -1, 0.008 };
  dcm_clock c2 = { fake_now, fake_sleep, &f2 };
  dcm_pacer_init(&p, 0.008, c2);
  for (int i = 0; i < 500; i++) dcm_pacer_wait(&p);
  snprintf(d, sizeof d, "cycle 500 starts at %.6f s", f2.t);
  tap_ok(fabs(f2.t - (500 * 0.008 + 300e-6)) < 1e-9, "absolute deadlines: no drift from late wake-ups", d);

  /* an overrun of 3.5 periods: 3 cycles missed, the deadlines restart from then */
  fake_clock f3 = { 0.0, 0, 1000000, 0, 0, 10, 0.008 };
  dcm_clock c3 = { fake_now, fake_sleep, &f3 };
  dcm_pacer_init(&p, 0.008, c3);
  for (int i = 0; i < 20; i++) dcm_pacer_wait(&p);
  snprintf(d, sizeof d, "missed %u, time %.4f s", p.missed, f3.t);
  tap_ok(p.missed == 3 && fabs(f3.t - (20 * 0.008 + 3.5 * 0.008)) < 1e-9,
         "an overrun counts the lost cycles and does not race to catch up", d);
}

/* ---------------------------------------------------------------- guard */

static void fill(dcm_command *c, int nj, double pos, double hard, uint32_t ack) {
  for (int j = 0; j < nj; j++) {
    c->position[j] = pos;
    c->hardness[j] = hard;
    c->enable[j] = 1;
    c->mode[j] = DCM_MODE_POSITION;
    c->torque[j] = 0;
  }
  c->tick_ack = ack;
  c->writer_pid = 0;
}

static void test_guard(void) {
  enum { NJ = 4 };
  const double present[NJ] = { 0.1, 0.2, 0.3, 0.4 };
  dcm_guard g;
  dcm_command c;
  dcm_guard_init(&g, NJ, 0.5, 0.3, present, 0);

  fill(&c, NJ, 0.5, 0.8, 0);
  dcm_guard_apply(&g, 0.0, present, &c);
  c.position[2] = NAN;
  c.position[3] = INFINITY;
  c.hardness[1] = NAN;
  c.hardness[0] = 1.7;
  c.hardness[3] = -0.2;
  dcm_guard_apply(&g, 0.01, present, &c);
  check(g.refused == 3 && c.position[2] == 0.5 && c.position[3] == 0.5 && c.hardness[1] == 0.8,
        "NaN / inf commands are refused (the last good value stays) and counted");
  check(c.hardness[0] == 1 && c.hardness[3] == 0, "hardness is clamped to 0..1");

  /* nobody acknowledges yet: no watchdog (a REPL alone may drive the robot) */
  fill(&c, NJ, 0.5, 0.8, 0);
  check(dcm_guard_apply(&g, 5.0, present, &c) == 0 && g.trips == 0, "no trip before motion ever acknowledged");
  /* motion acknowledges, then goes silent */
  fill(&c, NJ, 0.5, 0.8, 7);
  dcm_guard_apply(&g, 5.1, present, &c);
  fill(&c, NJ, 0.6, 0.8, 7);
  check(dcm_guard_apply(&g, 5.5, present, &c) == 0 && c.position[0] == 0.6, "within the timeout commands go through");
  fill(&c, NJ, 0.7, 0.8, 7);
  int safe = dcm_guard_apply(&g, 5.65, present, &c);
  check(safe == 1 && g.trips == 1, "silence longer than the timeout trips the watchdog");
  check(c.position[0] == 0.1 && c.position[3] == 0.4 && c.hardness[0] == 0.3,
        "safe state: the present pose held at the safe hardness");
  const double moved[NJ] = { 9, 9, 9, 9 };
  fill(&c, NJ, -0.5, 0.1, 7);
  dcm_guard_apply(&g, 6.0, moved, &c);
  check(c.position[0] == 0.1 && c.hardness[0] == 0.1 && g.trips == 1,
        "while tripped new commands do not land (the pose of the trip is held, lower hardness kept)");
  fill(&c, NJ, -0.5, 0.8, 8);
  check(dcm_guard_apply(&g, 6.1, present, &c) == 0 && c.position[0] == -0.5 && c.hardness[0] == 0.8,
        "commands resume when acknowledgements return");

  /* the writer died */
  pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, NULL, 0);
  fill(&c, NJ, 0.2, 0.8, 9);
  dcm_guard_apply(&g, 6.2, present, &c);
  fill(&c, NJ, 0.2, 0.8, 9);
  c.writer_pid = (uint32_t)child;
  check(dcm_guard_apply(&g, 6.21, present, &c) == 1 && g.trips == 2 && g.dead_writer == (int)child,
        "a dead writer trips the watchdog at once, naming its pid");

  /* a writer that died and is not reaped yet (its parent is slow): a zombie is dead too */
  pid_t zombie = fork();
  if (zombie == 0) _exit(0);
  fill(&c, NJ, 0.2, 0.8, 10);
  c.writer_pid = (uint32_t)getpid();
  check(dcm_guard_apply(&g, 6.3, present, &c) == 0, "a live writer: commands go through");
  /* until it has exited (left unreaped: WNOWAIT), 5 s at most (a child of an ASan build on a loaded
   * machine took longer than 0.2 s) */
  for (int k = 0; k < 5000; k++) {
    siginfo_t si;
    si.si_pid = 0;
    if (waitid(P_PID, (id_t)zombie, &si, WEXITED | WNOHANG | WNOWAIT) == 0 && si.si_pid == zombie) break;
    usleep(1000);
  }
  fill(&c, NJ, 0.2, 0.8, 10);
  c.writer_pid = (uint32_t)zombie;
  check(kill(zombie, 0) == 0 && dcm_guard_apply(&g, 6.31, present, &c) == 1 && g.dead_writer == (int)zombie,
        "an exited writer its parent has not reaped yet trips the watchdog at once");
  waitpid(zombie, NULL, 0);

  /* a safe pose: from the pose of the trip into it within the ramp, then held; NaN joints held */
  dcm_guard_init(&g, NJ, 0.5, 0.3, present, 0);
  dcm_safe_pose pose = { .q = { 1.1, NAN, 0.3, -0.6 }, .ramp = 0.3, .hardness = NAN };
  dcm_guard_set_safe_pose(&g, &pose);
  fill(&c, NJ, 0.5, 0.8, 1);
  dcm_guard_apply(&g, 1.0, present, &c);
  fill(&c, NJ, 0.5, 0.8, 1);
  dcm_guard_apply(&g, 1.6, present, &c);   /* silent for 0.6 s: trips, at the pose of the trip */
  check(g.safe && c.position[0] == 0.1 && c.position[1] == 0.2 && c.hardness[0] == 0.3,
        "safe pose: the ramp starts at the pose of the trip");
  fill(&c, NJ, 0.5, 0.8, 1);
  dcm_guard_apply(&g, 1.75, present, &c);  /* half way: the smooth step's middle */
  check(fabs(c.position[0] - 0.6) < 1e-9 && c.position[1] == 0.2 && fabs(c.position[3] - (-0.1)) < 1e-9,
        "half the ramp: half way (a joint without a safe angle held)");
  fill(&c, NJ, 0.5, 0.8, 1);
  dcm_guard_apply(&g, 2.5, present, &c);
  check(c.position[0] == 1.1 && c.position[1] == 0.2 && c.position[2] == 0.3 && c.position[3] == -0.6 &&
        c.hardness[3] == 0.3, "after the ramp: the safe pose held at the safe hardness");

  /* a safe pose with its own hardness: its joints held at most at that, the others at the platform's */
  dcm_guard_init(&g, NJ, 0.5, 0.3, present, 0);
  pose.hardness = 0.7;
  dcm_guard_set_safe_pose(&g, &pose);
  fill(&c, NJ, 0.5, 0.8, 1);
  dcm_guard_apply(&g, 1.0, present, &c);
  fill(&c, NJ, 0.5, 0.8, 1);
  dcm_guard_apply(&g, 1.6, present, &c);
  check(g.safe && c.hardness[0] == 0.7 && c.hardness[1] == 0.3 && c.hardness[2] == 0.7 && c.hardness[3] == 0.7,
        "safe pose hardness: the posed joints at the pose's, a held one at the platform's");
  fill(&c, NJ, 0.5, 0.6, 1);
  dcm_guard_apply(&g, 1.7, present, &c);
  check(c.hardness[0] == 0.6 && c.hardness[1] == 0.3, "safe pose hardness caps: a softer command stays softer");

  /* no watchdog (lockstep): silence is not a fault */
  dcm_guard_init(&g, NJ, 0, 0.3, present, 0);
  fill(&c, NJ, 0.5, 0.8, 3);
  dcm_guard_apply(&g, 0, present, &c);
  check(dcm_guard_apply(&g, 100, present, &c) == 0 && g.trips == 0, "timeout 0: no watchdog");
}

/* ---------------------------------------------------------------- stall check */

/* A fake /proc: what the writer's probe and CPU clock say this cycle. */
static dcm_proc g_fake;
static int fake_probe(int pid, dcm_proc *out) {
  (void)pid;
  *out = g_fake;
  return g_fake.state ? 0 : -ESRCH;
}
static double fake_cpu(int pid) {
  (void)pid;
  return g_fake.state ? g_fake.cpu : -1;
}

/* Torque mode: joint 0 and 1 have torque paths (10 and 2 N*m), joint 2 none. */
static void test_torque(void) {
  enum { NJ = 3 };
  const double present[NJ] = { 0.1, 0.2, 0.3 }, limit[NJ] = { 10, 2, 0 };
  double sensed[NJ] = { 0.1, 0.2, 0.3 };
  dcm_guard g;
  dcm_command c;
  dcm_guard_init(&g, NJ, 0.5, 0.3, present, 0);
  fill(&c, NJ, 0.5, 1, 0);
  c.mode[0] = c.mode[1] = c.mode[2] = DCM_MODE_TORQUE;
  c.torque[0] = 4;
  c.torque[1] = -2.5;
  c.torque[2] = 1;
  dcm_guard_apply(&g, 0, sensed, &c);
  check(c.mode[0] == DCM_MODE_POSITION && c.mode[2] == DCM_MODE_POSITION && c.position[2] == 0.3 &&
            g.torque_refused == 3,
        "no torque limits set: no joint leaves position mode, each holds its pose (counted)");
  dcm_guard_set_torque_limits(&g, limit);
  fill(&c, NJ, 0.5, 1, 0);
  c.mode[0] = c.mode[1] = DCM_MODE_TORQUE;
  c.torque[0] = 4;
  c.torque[1] = -2.5;
  dcm_guard_apply(&g, 0.01, sensed, &c);
  check(c.mode[0] == DCM_MODE_TORQUE && c.torque[0] == 4 && c.mode[1] == DCM_MODE_TORQUE && c.torque[1] == -2,
        "a torque within the limit goes through; one beyond it is clamped to the limit");
  check(g.torque_clamped == 1 && c.mode[2] == DCM_MODE_POSITION && c.position[2] == 0.5,
        "the clamp is counted; a position-mode joint keeps its command");
  /* a NaN torque: the joint to position mode, holding the pose it had at the refusal */
  fill(&c, NJ, 0.5, 1, 0);
  c.mode[0] = c.mode[1] = DCM_MODE_TORQUE;
  c.torque[0] = NAN;
  c.torque[1] = INFINITY;
  dcm_guard_apply(&g, 0.02, sensed, &c);
  check(c.mode[0] == DCM_MODE_POSITION && c.position[0] == 0.1 && c.mode[1] == DCM_MODE_POSITION &&
            c.position[1] == 0.2 && g.torque_refused == 5,
        "a NaN / inf torque is refused (counted): position mode holding the pose of the refusal");
  sensed[0] = 0.15;   /* it sagged a little meanwhile: the hold stays where it was taken */
  fill(&c, NJ, 0.5, 1, 0);
  c.mode[0] = DCM_MODE_TORQUE;
  c.torque[0] = NAN;
  dcm_guard_apply(&g, 0.03, sensed, &c);
  check(c.mode[0] == DCM_MODE_POSITION && c.position[0] == 0.1, "while the NaN stays, the same pose is held");
  fill(&c, NJ, 0.5, 1, 0);
  c.mode[0] = 7;
  dcm_guard_apply(&g, 0.04, sensed, &c);
  check(c.mode[0] == DCM_MODE_POSITION && c.position[0] == 0.1 && g.torque_refused == 7,
        "a mode other than position or torque is refused likewise");
  fill(&c, NJ, 0.5, 1, 0);
  c.mode[0] = DCM_MODE_TORQUE;
  c.torque[0] = -3;
  dcm_guard_apply(&g, 0.05, sensed, &c);
  check(c.mode[0] == DCM_MODE_TORQUE && c.torque[0] == -3, "a valid torque again: torque mode resumes");

  /* the watchdog: every joint in position mode holding its pose */
  fill(&c, NJ, 0.5, 1, 9);
  c.mode[0] = c.mode[1] = DCM_MODE_TORQUE;
  c.torque[0] = c.torque[1] = 1;
  dcm_guard_apply(&g, 1.0, sensed, &c);
  check(c.mode[0] == DCM_MODE_TORQUE && c.mode[1] == DCM_MODE_TORQUE, "motion acknowledges: torque mode");
  fill(&c, NJ, 0.5, 1, 9);
  c.mode[0] = c.mode[1] = DCM_MODE_TORQUE;
  c.torque[0] = c.torque[1] = 1;
  const int safe = dcm_guard_apply(&g, 1.6, sensed, &c);
  check(safe == 1 && c.mode[0] == DCM_MODE_POSITION && c.mode[1] == DCM_MODE_POSITION && c.torque[0] == 0 &&
            c.position[0] == 0.15 && c.position[1] == 0.2 && c.hardness[0] == 0.3,
        "a watchdog trip: every joint in position mode holding the pose of the trip at the safe hardness");

  /* the same in the block: the trip's end of torque mode (dcm_actuator_position_mode) */
  char err[512] = "";
  shm_schema *s = NULL;
  dcm_blk_dcm_actuator a;
  memset(&a, 0, sizeof a);
  int rc = shm_schema_load(NULL, &s, err, sizeof err);
  rc = rc == 0 ? dcm_blocks_open(s, g_id, DCM_BLK_dcm_actuator(&a), err, sizeof err) : rc;
  if (rc == 0) {
    for (int j = 0; j < NJ; j++) {
      a.mode[j] = j < 2 ? DCM_MODE_TORQUE : DCM_MODE_POSITION;
      a.command[j] = 0.9;
      a.torque[j] = 5;
    }
    dcm_actuator_position_mode(&a, NJ, g.hold);
    dcm_command_read(&a, NJ, &c);
    check(c.mode[0] == DCM_MODE_POSITION && c.mode[1] == DCM_MODE_POSITION && c.position[0] == 0.15 &&
              c.position[1] == 0.2 && c.torque[0] == 0 && c.position[2] == 0.9 && c.torque[2] == 5,
          "after a trip the block holds position mode at the pose of the trip (a position-mode joint untouched)");
    shm_block_close(a.blk);
  } else {
    tap_ok(0, "dcm.actuator opens", err);
  }
  shm_schema_free(s);
}

static void test_verdict(void) {
  const dcm_proc reg = { 'S', 1000, 0.5 };
  dcm_proc now = { 'R', 1000, 0.501 };
  check(dcm_writer_verdict(&reg, 0.5, &now, 0.005) == DCM_WRITER_RUNS,
        "runnable, 1 ms of CPU since its ack: starved, not stalled (the timeout's case)");
  now.state = 'S';
  check(dcm_writer_verdict(&reg, 0.5, &now, 0.005) == DCM_WRITER_RUNS, "asleep (blocked, waiting): left to the timeout");
  now.state = 'T';
  check(dcm_writer_verdict(&reg, 0.5, &now, 0.005) == DCM_WRITER_STOPPED, "'T' (SIGSTOP): stopped");
  now.state = 't';
  check(dcm_writer_verdict(&reg, 0.5, &now, 0.005) == DCM_WRITER_STOPPED, "'t' (a tracer's stop): stopped");
  now.state = 'R';
  now.cpu = 0.512;
  check(dcm_writer_verdict(&reg, 0.5, &now, 0.005) == DCM_WRITER_BUSY, "12 ms of CPU without an ack: a busy loop");
  check(dcm_writer_verdict(&reg, -1, &now, 0.005) == DCM_WRITER_RUNS, "no CPU time at the ack: no busy verdict");
  check(dcm_writer_verdict(&reg, 0.5, &now, 0) == DCM_WRITER_RUNS, "stall_cpu 0: no busy verdict");
  now.cpu = 0.501;
  now.start = 2000;
  check(dcm_writer_verdict(&reg, 0.5, &now, 0.005) == DCM_WRITER_GONE, "another start time: the pid was reused");
  const dcm_proc unknown = { 0, 0, 0 };
  check(dcm_writer_verdict(&unknown, 0.5, &now, 0.005) == DCM_WRITER_RUNS, "start time unknown at registration: no reuse verdict");
  now.state = 'Z';
  now.start = 1000;
  check(dcm_writer_verdict(&reg, 0.5, &now, 0.005) == DCM_WRITER_GONE, "a zombie: gone");
  now.state = 0;
  check(dcm_writer_verdict(&reg, 0.5, &now, 0.005) == DCM_WRITER_GONE, "no such process: gone");

  /* the real probe, on this process and a stopped child */
  dcm_proc me;
  check(dcm_proc_probe((int)getpid(), &me) == 0 && me.state == 'R' && me.start > 0 && me.cpu > 0,
        "the probe reads this process: running, a start time, CPU time");
  pid_t child = fork();
  if (child == 0) {
    for (;;) pause();
  }
  kill(child, SIGSTOP);
  dcm_proc st = { 0, 0, 0 };
  for (int k = 0; k < 2000 && st.state != 'T'; k++) {   /* the stop lands asynchronously */
    dcm_proc_probe((int)child, &st);
    usleep(1000);
  }
  check(st.state == 'T' && st.start >= me.start, "the probe sees a SIGSTOPped child as 'T'");
  kill(child, SIGKILL);
  waitpid(child, NULL, 0);
  check(dcm_proc_probe((int)child, &st) == -ESRCH && st.state == 0, "the probe of a reaped pid: -ESRCH");
}

static void test_stall(void) {
  enum { NJ = 2 };
  const double present[NJ] = { 0.1, 0.2 };
  dcm_guard g;
  dcm_command c;
  /* the writer must look alive to the pidfd check: this process's pid, its /proc faked */
  const uint32_t me = (uint32_t)getpid();
  dcm_guard_init(&g, NJ, 0.5, 0.3, present, 0);
  g.probe = fake_probe;
  g.cpu = fake_cpu;
  dcm_guard_set_stall(&g, 2, 0.005);
  g_fake = (dcm_proc){ 'S', 1000, 1.0 };
  double t = 0;
  uint32_t ack = 1;
  for (; ack < 5; ack++, t += 0.008) {
    fill(&c, NJ, 0.5, 0.8, ack);
    c.writer_pid = me;
    dcm_guard_apply(&g, t, present, &c);
  }
  /* SIGSTOP: one cycle without an ack is routine, the second looks */
  g_fake.state = 'T';
  fill(&c, NJ, 0.5, 0.8, ack - 1);
  c.writer_pid = me;
  check(dcm_guard_apply(&g, t, present, &c) == 0, "stopped, one cycle without an ack: no trip yet");
  fill(&c, NJ, 0.5, 0.8, ack - 1);
  c.writer_pid = me;
  check(dcm_guard_apply(&g, t + 0.008, present, &c) == 1 && g.cause == DCM_WRITER_STOPPED && g.trips == 1 &&
        c.hardness[0] == 0.3, "stopped, the second cycle: tripped (cause: stopped), at the safe hardness");
  /* SIGCONT: it answers again */
  g_fake.state = 'S';
  fill(&c, NJ, 0.5, 0.8, ack++);
  c.writer_pid = me;
  check(dcm_guard_apply(&g, t + 0.016, present, &c) == 0, "continued: its answers resume the commands");
  t += 0.024;

  /* starved: runnable, no CPU burnt: not before the timeout */
  g_fake = (dcm_proc){ 'R', 1000, 1.0005 };
  int tripped_at = -1;
  for (int k = 1; k <= 100 && tripped_at < 0; k++) {
    fill(&c, NJ, 0.5, 0.8, ack - 1);
    c.writer_pid = me;
    if (dcm_guard_apply(&g, t + 0.008 * k, present, &c)) tripped_at = k;
  }
  char d[96];
  snprintf(d, sizeof d, "tripped after %d cycles (%s)", tripped_at, g.cause == DCM_WRITER_RUNS ? "timeout" : "stall");
  tap_ok(tripped_at > 60 && g.cause == DCM_WRITER_RUNS, "starved (runnable, 0.5 ms of CPU): only the 0.5 s timeout trips",
         d);
  g_fake.state = 'S';
  fill(&c, NJ, 0.5, 0.8, ack++);
  c.writer_pid = me;
  dcm_guard_apply(&g, t + 1, present, &c);
  t += 1.008;

  /* a busy loop: CPU grows, no ack */
  g_fake.cpu = 2.0;
  fill(&c, NJ, 0.5, 0.8, ack++);
  c.writer_pid = me;
  dcm_guard_apply(&g, t, present, &c);   /* the ack: CPU 2.0 s */
  g_fake.state = 'R';
  g_fake.cpu = 2.008;
  fill(&c, NJ, 0.5, 0.8, ack - 1);
  c.writer_pid = me;
  check(dcm_guard_apply(&g, t + 0.008, present, &c) == 0, "busy, one cycle: no trip yet");
  g_fake.cpu = 2.016;
  fill(&c, NJ, 0.5, 0.8, ack - 1);
  c.writer_pid = me;
  check(dcm_guard_apply(&g, t + 0.016, present, &c) == 1 && g.cause == DCM_WRITER_BUSY,
        "busy: 16 ms of CPU in 2 cycles without an ack trips (cause: busy)");
  g_fake = (dcm_proc){ 'S', 1000, 2.02 };
  fill(&c, NJ, 0.5, 0.8, ack++);
  c.writer_pid = me;
  dcm_guard_apply(&g, t + 0.024, present, &c);
  t += 0.032;

  /* the pid now belongs to another process (another start time) */
  g_fake.start = 5000;
  fill(&c, NJ, 0.5, 0.8, ack - 1);
  c.writer_pid = me;
  dcm_guard_apply(&g, t, present, &c);
  fill(&c, NJ, 0.5, 0.8, ack - 1);
  c.writer_pid = me;
  check(dcm_guard_apply(&g, t + 0.008, present, &c) == 1 && g.cause == DCM_WRITER_GONE && g.dead_writer == (int)me,
        "a reused pid (another start time than at registration): gone");

  /* lockstep: no timeout, the stall check still trips a stopped writer */
  dcm_guard_init(&g, NJ, 0, 0.3, present, 0);
  g.probe = fake_probe;
  g.cpu = fake_cpu;
  dcm_guard_set_stall(&g, 2, 0.005);
  g_fake = (dcm_proc){ 'S', 1000, 1.0 };
  fill(&c, NJ, 0.5, 0.8, 3);
  c.writer_pid = me;
  dcm_guard_apply(&g, 0, present, &c);
  g_fake.state = 'T';
  int trips = 0;
  for (int k = 1; k <= 3; k++) {
    fill(&c, NJ, 0.5, 0.8, 3);
    c.writer_pid = me;
    trips += dcm_guard_apply(&g, 0.008 * k, present, &c);
  }
  check(trips == 2 && g.cause == DCM_WRITER_STOPPED, "timeout 0 (lockstep): a stopped writer still trips after 2 cycles");
}

/* ---------------------------------------------------------------- lockstep */

/* idle hook of the start_with test: asks the wait to stop after a few calls */
static void idle_count(void *ctx, int alone) {
  struct idle_ctx { volatile sig_atomic_t *stop; int *n; } *c = ctx;
  (void)alone;
  if (++*c->n >= 5) *c->stop = 1;
}

/* A participant in a child process that reports tick done on slot 0 after `after` s; returns its pid. */
static pid_t finish_later(dcm_blk_sync *y, uint32_t tick, double after) {
  const pid_t pid = fork();
  if (pid == 0) {
    struct timespec ts = { (time_t)after, (long)((after - (time_t)after) * 1e9) };
    nanosleep(&ts, NULL);
    __atomic_store_n(&y->done_tick[0], tick, __ATOMIC_RELEASE);
    shm_fetch_add_u32(y->done_count, 1);
    shm_futex_wake(y->done_count);
    _exit(0);
  }
  return pid;
}

/* A lockstep over one sync block, quick to poll and to drop the dead (tests wait less). */
static void lockstep_of(dcm_lockstep *l, dcm_blk_sync *y) {
  memset(l, 0, sizeof *l);
  l->n = 1;
  l->sync[0] = y;
  l->spin = 50e-6;
  l->drop_after = 0.05;
}

static void test_lockstep(void) {
  char err[512] = "";
  dcm_blk_sync y;
  int rc = dcm_blocks_open(NULL, g_id, DCM_BLK_sync(&y), err, sizeof err);
  tap_ok(rc == 0, "sync binds", err);
  if (rc) return;
  for (int k = 0; k < y.n.pid; k++) {
    y.pid[k] = 0;
    y.wake_tick[k] = 0;
    y.done_tick[k] = 0;
  }
  dcm_lockstep l;
  lockstep_of(&l, &y);
  dcm_lockstep_start(&l, 5);
  check(*y.lockstep == 1, "lockstep on");

  /* one live participant that is done, one dead that never will be */
  pid_t dead = fork();
  if (dead == 0) _exit(0);
  waitpid(dead, NULL, 0);
  y.pid[0] = (int32_t)getpid();
  y.done_tick[0] = 5;
  y.wake_tick[0] = 5;
  y.pid[1] = (int32_t)dead;
  y.done_tick[1] = 2;
  y.wake_tick[1] = 3;
  dcm_lockstep_publish(&l, 5);
  check(*y.tick == 5, "the tick is published");
  double t0 = shm_now();
  rc = dcm_lockstep_wait(&l, 5, NULL, NULL, NULL);
  double dt = shm_now() - t0;
  char d[128];
  snprintf(d, sizeof d, "after %.3f s", dt);
  tap_ok(rc == 0 && y.pid[1] == 0 && l.dropped == 1, "a participant that died is dropped", d);

  /* a live participant that finishes 0.2 s later is waited for */
  y.done_tick[0] = 5;
  y.wake_tick[0] = 6;
  dcm_lockstep_publish(&l, 6);
  const pid_t worker = finish_later(&y, 6, 0.2);
  t0 = shm_now();
  rc = dcm_lockstep_wait(&l, 6, NULL, NULL, NULL);
  dt = shm_now() - t0;
  /* returned only once the worker had finished the tick (no wall-clock bound: the order decides) */
  const uint32_t seen = __atomic_load_n(&y.done_tick[0], __ATOMIC_ACQUIRE);
  waitpid(worker, NULL, 0);
  snprintf(d, sizeof d, "waited %.3f s", dt);
  tap_ok(rc == 0 && seen == 6, "the DCM waits for a live participant's done_tick", d);

  /* a participant that wants a later tick is not waited for */
  y.wake_tick[0] = 100;
  /* a helper finishes tick 7 after 2 s, so a wait that (wrongly) waited for it would end too, later */
  const pid_t late = finish_later(&y, 7, 2);
  rc = dcm_lockstep_wait(&l, 7, NULL, NULL, NULL);
  const uint32_t at_return = __atomic_load_n(&y.done_tick[0], __ATOMIC_ACQUIRE);
  kill(late, SIGKILL);
  waitpid(late, NULL, 0);
  check(rc == 0 && at_return != 7, "wake_tick ahead: not consulted at this tick");

  /* a stop request ends a wait for somebody who never joins */
  y.pid[0] = 0;
  volatile sig_atomic_t stop = 1;
  check(dcm_lockstep_wait(&l, 8, NULL, NULL, &stop) == 1, "nobody joined: the wait holds the clock until stopped");

  /* a stopped participant: passed over after stall_after, waited for again once continued */
  pid_t stopped = fork();
  if (stopped == 0) {
    for (;;) pause();
  }
  kill(stopped, SIGSTOP);
  y.pid[0] = (int32_t)stopped;
  y.done_tick[0] = 8;
  y.wake_tick[0] = 9;
  l.stall_after = 0.02;
  dcm_lockstep_publish(&l, 9);
  t0 = shm_now();
  rc = dcm_lockstep_wait(&l, 9, NULL, NULL, NULL);
  dt = shm_now() - t0;
  snprintf(d, sizeof d, "after %.3f s, passed %u", dt, l.passed);
  tap_ok(rc == 0 && l.passed == 1 && y.pid[0] == (int32_t)stopped, "a stopped participant is passed over (its slot kept)",
         d);
  rc = dcm_lockstep_wait(&l, 10, NULL, NULL, NULL);
  check(rc == 0 && l.passed == 1, "and from then on while it stays stopped, without waiting again");
  kill(stopped, SIGCONT);
  const pid_t answer = finish_later(&y, 11, 0.1);
  for (int k = 0; k < 2000; k++) {   /* the continue lands asynchronously */
    dcm_proc p;
    if (dcm_proc_probe((int)stopped, &p) == 0 && p.state != 'T') break;
    usleep(1000);
  }
  rc = dcm_lockstep_wait(&l, 11, NULL, NULL, NULL);
  const uint32_t done11 = __atomic_load_n(&y.done_tick[0], __ATOMIC_ACQUIRE);
  waitpid(answer, NULL, 0);
  check(rc == 0 && done11 == 11, "continued: it is waited for again");
  kill(stopped, SIGKILL);
  waitpid(stopped, NULL, 0);
  y.pid[0] = 0;
  l.stall_after = 0;

  /* start_with: a fresh clock waits for that many participants; once it ran, one is enough */
  dcm_lockstep f;
  lockstep_of(&f, &y);
  f.start_with = 2;
  y.pid[0] = (int32_t)getpid();
  y.done_tick[0] = 0;
  y.wake_tick[0] = 0;
  volatile sig_atomic_t stop_after = 0;
  int idles = 0;
  struct idle_ctx { volatile sig_atomic_t *stop; int *n; } ic = { &stop_after, &idles };
  rc = dcm_lockstep_wait(&f, 0, idle_count, &ic, &stop_after);
  check(rc == 1 && idles >= 5 && !f.started, "start_with 2: one participant does not start the clock");
  pid_t second = fork();
  if (second == 0) {
    struct timespec ts = { 5, 0 };
    nanosleep(&ts, NULL);
    _exit(0);
  }
  y.pid[1] = (int32_t)second;
  y.done_tick[1] = 0;
  y.wake_tick[1] = 0;
  stop_after = 0;
  idles = 0;
  rc = dcm_lockstep_wait(&f, 0, idle_count, &ic, &stop_after);
  check(rc == 0 && f.started, "start_with 2: the second participant starts it");
  kill(second, SIGKILL);
  waitpid(second, NULL, 0);
  y.pid[1] = 0;
  y.done_tick[0] = 1;
  rc = dcm_lockstep_wait(&f, 1, NULL, NULL, NULL);
  check(rc == 0, "start_with 2: once started, one participant keeps it going");
  y.pid[0] = 0;

  /* a slot being claimed (a negative pid: Lib/lockstep.lua sets its fields) is no participant yet:
   * neither counted nor waited for, and kept while its claimant lives; dropped once it died */
  dcm_lockstep c;
  lockstep_of(&c, &y);
  c.start_with = 2;
  c.drop_after = 0.01;
  y.pid[0] = (int32_t)getpid();
  y.done_tick[0] = 11;
  y.wake_tick[0] = 12;
  y.pid[1] = -(int32_t)getpid();
  y.done_tick[1] = 0;
  y.wake_tick[1] = 0;
  stop_after = 0;
  idles = 0;
  rc = dcm_lockstep_wait(&c, 12, idle_count, &ic, &stop_after);
  check(rc == 1 && !c.started, "a claim in progress does not count towards start_with");
  c.started = 1;
  pid_t answer12 = finish_later(&y, 12, 0.1);   /* the wait lasts past drop_after: the dead are looked for */
  rc = dcm_lockstep_wait(&c, 12, NULL, NULL, NULL);
  waitpid(answer12, NULL, 0);
  check(rc == 0 && y.pid[1] == -(int32_t)getpid() && c.dropped == 0,
        "a live claim in progress is not waited for, nor dropped");
  pid_t gone = fork();
  if (gone == 0) _exit(0);
  waitpid(gone, NULL, 0);
  y.pid[1] = -(int32_t)gone;
  answer12 = finish_later(&y, 13, 0.1);
  rc = dcm_lockstep_wait(&c, 13, NULL, NULL, NULL);
  waitpid(answer12, NULL, 0);
  check(rc == 0 && y.pid[1] == 0 && c.dropped == 1, "the claim of a process that died is dropped");
  y.pid[0] = 0;
  dcm_lockstep_end(&l);
  check(*y.lockstep == 0, "lockstep off");
  shm_block_close(y.blk);
}

/* ---------------------------------------------------------------- config */

static char g_root[256];

static void write_file(const char *rel, const char *text) {
  char path[512];
  snprintf(path, sizeof path, "%s/%s", g_root, rel);
  FILE *f = fopen(path, "w");
  fputs(text, f);
  fclose(f);
}

static void test_config(void) {
  snprintf(g_root, sizeof g_root, "/tmp/dcm_unit_config.XXXXXX");
  if (!mkdtemp(g_root)) return;
  const char *dirs[] = { "Config", "Config/robots", "Config/robots/t", "Config/platforms", "Config/platforms/P" };
  for (size_t k = 0; k < sizeof dirs / sizeof dirs[0]; k++) {
    char p[512];
    snprintf(p, sizeof p, "%s/%s", g_root, dirs[k]);
    mkdir(p, 0700);
  }
  char lib[512], link[512];
  snprintf(lib, sizeof lib, "%s/Lib", dcm_root());
  snprintf(link, sizeof link, "%s/Lib", g_root);
  if (symlink(lib, link) != 0) return;
  setenv("HRP_ROOT", g_root, 1);
  write_file("Config/robots/t/dcm.lua",
             "return { rate = 125, name = 'x', n = 3, frac = 0.5, flag = true, list = { 1, 2 },\n"
             "  nested = { a = { 4, 5, 6 } }, rows = { { x = 1 }, { x = 2, s = 'two' } }, names = { 'p', 'q' } }\n");
  write_file("Config/platforms/P/dcm.lua", "return { rate = 250 }\n");

  char err[512] = "";
  dcm_config *c = NULL;
  int rc = dcm_config_load("dcm", "t", "P", &c, err, sizeof err);
  tap_ok(rc == 0, "a concern loads through Lib/Config.lua", err);
  if (rc) return;
  tap_ok(!strcmp(dcm_config_files(c), "Config/robots/t/dcm.lua + Config/platforms/P/dcm.lua"), "the layer files are named",
         dcm_config_files(c));
  check(!strcmp(dcm_config_robot(c), "t") && !strcmp(dcm_config_platform(c), "P"), "robot and platform as asked");
  double v = 0;
  int i = 0, flag = 0;
  char str[32] = "";
  check(dcm_config_num(c, "rate", &v, err, sizeof err) == 0 && v == 250, "the platform layer overlays the body's");
  check(dcm_config_int(c, "n", &i, err, sizeof err) == 0 && i == 3 && dcm_config_bool(c, "flag", &flag, err, sizeof err) == 0 &&
            flag == 1 && dcm_config_str(c, "name", str, sizeof str, err, sizeof err) == 0 && !strcmp(str, "x"),
        "typed getters: integer, boolean, string");
  check(dcm_config_num(c, "nested.a.3", &v, err, sizeof err) == 0 && v == 6 &&
            dcm_config_str(c, "rows.2.s", str, sizeof str, err, sizeof err) == 0 && !strcmp(str, "two"),
        "dotted keys: a number indexes a list");
  check(dcm_config_len(c, "rows", err, sizeof err) == 2 && dcm_config_has(c, "rows.2.x") && !dcm_config_has(c, "rows.3.x") &&
            !dcm_config_has(c, "rows.1.s"),
        "rows of a table: count and presence");
  double l[3];
  char names[2][DCM_NAME_MAX];
  check(dcm_config_nums(c, "nested.a", l, 3, 3, err, sizeof err) == 3 && l[1] == 5 &&
            dcm_config_strs(c, "names", names, 1, 2, err, sizeof err) == 2 && !strcmp(names[1], "q"),
        "lists of numbers and strings");
  check(dcm_config_num_or(c, "absent", 7, &v, err, sizeof err) == 0 && v == 7, "an optional key takes its default");

  rc = dcm_config_num(c, "nested.b", &v, err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "Config/robots/t/dcm.lua + Config/platforms/P/dcm.lua: missing key 'nested.b'"),
         "a missing key names the files and the key", err);
  rc = dcm_config_num(c, "rows.2.s", &v, err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "key 'rows[2].s' must be a number, got string"), "a wrong type names the key as Lua writes it", err);
  rc = dcm_config_int(c, "frac", &i, err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "key 'frac' must be an integer"), "a fraction where an integer belongs", err);
  rc = dcm_config_nums(c, "list", l, 3, 3, err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "key 'list' must be a list of 3 numbers, has 2"), "a list of the wrong length", err);
  rc = dcm_config_num(c, "name.x", &v, err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "key 'name' must be a table, got string"), "a path through a non-table", err);
  rc = dcm_config_num_or(c, "name", 1, &v, err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "key 'name' must be a number"), "an optional key of the wrong type is still an error", err);
  dcm_config_free(c);

  /* errors of the layers themselves (Lib/Config.lua's) */
  write_file("Config/platforms/P/dcm.lua", "return { rate = 250, rtae = 1 }\n");
  rc = dcm_config_load("dcm", "t", "P", &c, err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "Config/platforms/P/dcm.lua") && strstr(err, "rtae"), "a typo in an overlay names file and key", err);
  write_file("Config/platforms/P/dcm.lua", "return { rate = }\n");
  rc = dcm_config_load("dcm", "t", "P", &c, err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "Config/platforms/P/dcm.lua"), "a syntax error names the file", err);
  rc = dcm_config_load("dcm", "nobody", "P", &c, err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "nobody"), "an unknown robot is named", err);
  rc = dcm_config_load("nothing", "t", "P", &c, err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "nothing"), "a concern without files is named", err);

  /* a body's safe pose (robot.lua safe_pose), by joint name */
  setenv("PLATFORM", "P", 1);
  dcm_safe_pose sp;
  write_file("Config/robots/t/robot.lua",
             "return { joints = { 'a', 'b', 'c' }, safe_pose = { ramp = 0.25, q = { b = -0.5 } } }\n");
  rc = dcm_safe_pose_load("t", 3, &sp, err, sizeof err);
  tap_ok(rc == 1 && sp.ramp == 0.25 && isnan(sp.q[0]) && sp.q[1] == -0.5 && isnan(sp.q[2]) && isnan(sp.hardness),
         "a body's safe pose by joint name; the joints it does not name are held", err);
  write_file("Config/robots/t/robot.lua",
             "return { joints = { 'a', 'b', 'c' }, safe_pose = { ramp = 0.25, hardness = 0.8, q = { a = 1, c = 2 } } }\n");
  rc = dcm_safe_pose_load("t", 3, &sp, err, sizeof err);
  tap_ok(rc == 2 && sp.hardness == 0.8 && sp.q[0] == 1 && sp.q[2] == 2, "a safe pose's own hardness", err);
  write_file("Config/robots/t/robot.lua", "return { joints = { 'a', 'b', 'c' }, safe_pose = { ramp = 'x', q = {} } }\n");
  rc = dcm_safe_pose_load("t", 3, &sp, err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "robot.lua") && strstr(err, "safe_pose.ramp"), "a bad safe pose names file and key", err);
  write_file("Config/robots/t/robot.lua",
             "return { joints = { 'a', 'b', 'c' }, safe_pose = { ramp = 0.2, hardness = 1.5, q = {} } }\n");
  rc = dcm_safe_pose_load("t", 3, &sp, err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "robot.lua") && strstr(err, "safe_pose.hardness"), "a safe pose's hardness beyond 1 is refused",
         err);
  write_file("Config/robots/t/robot.lua", "return { joints = { 'a', 'b', 'c' } }\n");
  rc = dcm_safe_pose_load("t", 3, &sp, err, sizeof err);
  tap_ok(rc == 0 && sp.ramp == 0 && isnan(sp.q[0]) && isnan(sp.q[1]) && isnan(sp.q[2]),
         "no safe pose: every joint held where it is", err);
  unsetenv("PLATFORM");

  char cmd[600];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", g_root);
  if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", g_root);
  unsetenv("HRP_ROOT");
}

/* ---------------------------------------------------------------- command line */

/* What a test table writes into. */
struct cli {
  int quiet, n;
  long cycles;
  double rate;
  const char *port;
  int buses[4];
};

/* A DCM_OPT_FUNC option: "BUS=NAME" with BUS 1..4; counts each bus given. */
static int parse_bus(const char *v, void *out, char *err, size_t n) {
  int *buses = out;
  long b;
  const char *eq = strchr(v, '=');
  if (!eq) {
    snprintf(err, n, "'%s' is not BUS=NAME", v);
    return -EINVAL;
  }
  char num[8] = "";
  snprintf(num, sizeof num, "%.*s", (int)(eq - v), v);
  if (dcm_args_long(num, 1, 4, &b, err, n) < 0) return -EINVAL;
  buses[b - 1]++;
  return 0;
}

static int g_cli_required;   /* the tests of a required option set it */

/* Parses the NULL-terminated words into c (zeroed first, the defaults of a DCM's main). */
static int cli_parse(struct cli *c, char *err, size_t n, ...) {
  memset(c, 0, sizeof *c);
  c->cycles = -1;
  const dcm_opt opts[] = {
    { "--quiet", DCM_OPT_FLAG, &c->quiet, 0, 0, NULL, "no log lines", NULL, 0 },
    { "--n", DCM_OPT_INT, &c->n, -3, 8, "N", "a small integer", NULL, 0 },
    { "--cycles", DCM_OPT_LONG, &c->cycles, 0, (double)LONG_MAX, "N", "cycles", NULL, 0 },
    { "--rate", DCM_OPT_DOUBLE, &c->rate, 1, 1000, "HZ", "control rate", NULL, 0 },
    { "--port", DCM_OPT_STRING, &c->port, 0, 0, "PATH", "serial port", NULL, g_cli_required },
    { "--bus", DCM_OPT_FUNC, c->buses, 0, 0, "BUS=NAME", "a bus", parse_bus, 0 },
    DCM_OPT_END,
  };
  char *argv[16] = { "dcm_test" };
  int argc = 1;
  va_list ap;
  va_start(ap, n);
  for (const char *a; argc < 15 && (a = va_arg(ap, const char *));) argv[argc++] = (char *)a;
  va_end(ap);
  err[0] = 0;
  return dcm_args_parse(opts, argc, argv, err, n);
}

/* Runs dcm_args in a child on the words; returns its exit status, its stdout and stderr in out, err. */
static int cli_exit(char *out, size_t outlen, char *errs, size_t errlen, char *const *words) {
  char po[] = "/tmp/dcm_unit_outXXXXXX", pe[] = "/tmp/dcm_unit_errXXXXXX";
  const int fo = mkstemp(po), fe = mkstemp(pe);
  fflush(stdout);
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(fo, 1);
    dup2(fe, 2);
    double rate = 0;
    int quiet = 0;
    const dcm_opt opts[] = {
      { "--rate", DCM_OPT_DOUBLE, &rate, 1, 1000, "HZ", "control rate", NULL, 0 },
      { "--quiet", DCM_OPT_FLAG, &quiet, 0, 0, NULL, "no log lines", NULL, 0 },
      DCM_OPT_END,
    };
    int argc = 0;
    while (words[argc]) argc++;
    dcm_args("dcm_test", "PLATFORM=T ./run_dcm", opts, argc, words);
    printf("parsed rate %g\n", rate);
    fflush(stdout);
    _exit(0);   /* no atexit handlers of the parent's (its TAP plan) */
  }
  int st = -1;
  waitpid(pid, &st, 0);
  const ssize_t no = pread(fo, out, outlen - 1, 0), ne = pread(fe, errs, errlen - 1, 0);
  out[no > 0 ? no : 0] = 0;
  errs[ne > 0 ? ne : 0] = 0;
  close(fo);
  close(fe);
  unlink(po);
  unlink(pe);
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* A TAP detail is one line: the text up to its first newline (a copy: the text itself is checked
 * in the same call). */
static const char *first_line(const char *text) {
  static char line[256];
  snprintf(line, sizeof line, "%.*s", (int)strcspn(text, "\n"), text);
  return line;
}

static void test_args(void) {
  struct cli c;
  char err[256];
  int rc = cli_parse(&c, err, sizeof err, NULL);
  check(rc == 0 && c.cycles == -1 && c.rate == 0 && !c.port && !c.quiet, "no arguments: the defaults stay");
  rc = cli_parse(&c, err, sizeof err, "--quiet", "--n", "-3", "--cycles", "9000000000", "--rate", "125.5", "--port",
                 "/dev/ttyUSB0", "--bus", "2=can1", "--bus", "4=can3", NULL);
  tap_ok(rc == 0 && c.quiet == 1 && c.n == -3 && c.cycles == 9000000000L && c.rate == 125.5 &&
             !strcmp(c.port, "/dev/ttyUSB0") && c.buses[1] == 1 && c.buses[3] == 1,
         "good values of every kind", err);
  rc = cli_parse(&c, err, sizeof err, "--rate", "1e2", "--rate", "1000", "--n", "+8", NULL);
  check(rc == 0 && c.rate == 1000 && c.n == 8, "the ends of a range are inside it; given twice, the last counts");

  /* garbage: the whole argument must be a number of the kind */
  const char *not_int[] = { "abc", "12abc", "", " 12", "0x10", "1.5", "1e3", "--quiet" };
  int ok = 1;
  for (size_t k = 0; k < sizeof not_int / sizeof not_int[0]; k++) {
    rc = cli_parse(&c, err, sizeof err, "--n", not_int[k], NULL);
    char want[64];
    snprintf(want, sizeof want, "--n: '%s' is not an integer", not_int[k]);
    if (rc != -EINVAL || strcmp(err, want) || c.n != 0) {
      ok = 0;
      tap_ok(0, "garbage for an integer is refused", err);
    }
  }
  if (ok) check(1, "garbage for an integer is refused, naming the option and the value (no silent 0)");
  const char *not_num[] = { "fast", "12x", "", " 5", "nan", "inf", "0x1p3", "1..2", "." };
  ok = 1;
  for (size_t k = 0; k < sizeof not_num / sizeof not_num[0]; k++) {
    rc = cli_parse(&c, err, sizeof err, "--rate", not_num[k], NULL);
    if (rc != -EINVAL || !strstr(err, "--rate: '") || !strstr(err, "is not a number") || c.rate != 0) {
      ok = 0;
      tap_ok(0, "garbage for a number is refused", err);
    }
  }
  if (ok) check(1, "garbage for a number is refused: letters, blanks, nan, inf, hex");

  /* out of range */
  rc = cli_parse(&c, err, sizeof err, "--n", "9", NULL);
  tap_ok(rc == -EINVAL && !strcmp(err, "--n: 9 is out of range (-3..8)"), "an integer above its range", err);
  rc = cli_parse(&c, err, sizeof err, "--rate", "0.5", NULL);
  tap_ok(rc == -EINVAL && !strcmp(err, "--rate: 0.5 is out of range (1..1000)"), "a number below its range", err);
  rc = cli_parse(&c, err, sizeof err, "--cycles", "-1", NULL);
  tap_ok(rc == -EINVAL && !strcmp(err, "--cycles: -1 is out of range (>= 0)"), "a range open above", err);
  rc = cli_parse(&c, err, sizeof err, "--cycles", "99999999999999999999", NULL);
  tap_ok(rc == -EINVAL && strstr(err, "out of range") && c.cycles == -1, "beyond a long: out of range, not LONG_MAX", err);
  rc = cli_parse(&c, err, sizeof err, "--rate", "1e999", NULL);
  tap_ok(rc == -EINVAL && strstr(err, "out of range"), "beyond a double: out of range", err);
  rc = cli_parse(&c, err, sizeof err, "--bus", "7=can0", NULL);
  tap_ok(rc == -EINVAL && !strcmp(err, "--bus: 7 is out of range (1..4)"), "a parser's own error is named by its option",
         err);
  rc = cli_parse(&c, err, sizeof err, "--bus", "can0", NULL);
  tap_ok(rc == -EINVAL && !strcmp(err, "--bus: 'can0' is not BUS=NAME"), "a parser's own message", err);
  rc = cli_parse(&c, err, sizeof err, "--port", "", NULL);
  tap_ok(rc == -EINVAL && !strcmp(err, "--port: an empty value"), "an empty string is refused", err);

  /* unknown, missing */
  rc = cli_parse(&c, err, sizeof err, "--quiet", "--rtae", "125", NULL);
  tap_ok(rc == -EINVAL && !strcmp(err, "unknown argument '--rtae'"), "an unknown argument is named", err);
  rc = cli_parse(&c, err, sizeof err, "125", NULL);
  tap_ok(rc == -EINVAL && !strcmp(err, "unknown argument '125'"), "a stray value is an unknown argument", err);
  rc = cli_parse(&c, err, sizeof err, "--quiet", "--rate", NULL);
  tap_ok(rc == -EINVAL && !strcmp(err, "--rate needs a value (HZ)"), "a missing value is named", err);
  g_cli_required = 1;
  rc = cli_parse(&c, err, sizeof err, "--quiet", NULL);
  tap_ok(rc == -EINVAL && !strcmp(err, "--port PATH is required"), "a missing required option is named", err);
  rc = cli_parse(&c, err, sizeof err, "--port", "/dev/x", NULL);
  check(rc == 0 && !strcmp(c.port, "/dev/x"), "a required option given");

  /* --help */
  rc = cli_parse(&c, err, sizeof err, "--help", NULL);
  check(rc == DCM_ARGS_HELP, "--help asks for the usage");
  rc = cli_parse(&c, err, sizeof err, "--n", "2", "-h", "--bogus", NULL);
  check(rc == DCM_ARGS_HELP && c.n == 2, "-h asks for the usage; nothing after it is read");
  g_cli_required = 0;

  /* the usage, from the table */
  const dcm_opt opts[] = {
    { "--log", DCM_OPT_STRING, &c.port, 0, 0, "FILE", "the recording", NULL, 1 },
    { "--rate", DCM_OPT_DOUBLE, &c.rate, 1, 1000, "HZ", "control rate", NULL, 0 },
    { "--cycles", DCM_OPT_LONG, &c.cycles, 0, (double)LONG_MAX, "N", "cycles", NULL, 0 },
    { "--quiet", DCM_OPT_FLAG, &c.quiet, 0, 0, NULL, "no log lines", NULL, 0 },
    DCM_OPT_END,
  };
  char usage[1024];
  const int need = dcm_args_usage("PLATFORM=T ./run_dcm", opts, usage, sizeof usage);
  tap_ok(need == (int)strlen(usage) && !strncmp(usage, "usage: PLATFORM=T ./run_dcm --log FILE [options]\n", 49) &&
             strstr(usage, "\n  --rate HZ   control rate [1..1000]\n") && strstr(usage, "\n  --cycles N  cycles [>= 0]\n") &&
             strstr(usage, "\n  --quiet     no log lines\n") && strstr(usage, "\n  -h, --help  this text\n"),
         "the usage: required options first, a line per option with its range", first_line(usage));
  char small[16];
  check(dcm_args_usage("x", opts, small, sizeof small) == need - (int)strlen("PLATFORM=T ./run_dcm") + 1 &&
            strlen(small) == sizeof small - 1,
        "a short buffer: the usage is cut, the length needed returned");

  /* dcm_args: the exit statuses and where the text goes */
  char out[2048], errs[2048];
  char *good[] = { "dcm_test", "--rate", "50", NULL };
  rc = cli_exit(out, sizeof out, errs, sizeof errs, good);
  check(rc == 0 && !strcmp(out, "parsed rate 50\n") && !errs[0], "good arguments: dcm_args returns");
  char *bad[] = { "dcm_test", "--rate", "fast", NULL };
  rc = cli_exit(out, sizeof out, errs, sizeof errs, bad);
  tap_ok(rc == 2 && !out[0] && !strncmp(errs, "dcm_test: --rate: 'fast' is not a number\nusage: PLATFORM=T ./run_dcm", 66),
         "a bad argument: one line naming it, the usage on stderr, exit status 2", first_line(errs));
  char *unknown[] = { "dcm_test", "--rtae", NULL };
  rc = cli_exit(out, sizeof out, errs, sizeof errs, unknown);
  tap_ok(rc == 2 && !strncmp(errs, "dcm_test: unknown argument '--rtae'\nusage:", 42), "an unknown argument: exit status 2",
         first_line(errs));
  char *missing[] = { "dcm_test", "--quiet", "--rate", NULL };
  rc = cli_exit(out, sizeof out, errs, sizeof errs, missing);
  tap_ok(rc == 2 && !strncmp(errs, "dcm_test: --rate needs a value (HZ)\n", 36), "a missing value: exit status 2",
         first_line(errs));
  char *help[] = { "dcm_test", "--help", NULL };
  rc = cli_exit(out, sizeof out, errs, sizeof errs, help);
  tap_ok(rc == 0 && !strncmp(out, "usage: PLATFORM=T ./run_dcm [options]\n", 38) && strstr(out, "--rate HZ") && !errs[0],
         "--help: the usage on stdout, exit status 0", first_line(out));
}

int main(void) {
  /* Tests/run_all.sh gives every run an id of its own; by hand, one away from a running robot */
  g_id = getenv("ROBOT_ID") ? shm_robot_id() : 9000 + (int)(getpid() % 500);
  remove_blocks();
  test_blocks();
  test_pacing();
  test_guard();
  test_torque();
  test_verdict();
  test_stall();
  test_lockstep();
  remove_blocks();
  test_config();
  test_args();
  return tap_done();
}
