/* Tests of the DCM library (TAP): generated shm bindings, pacing statistics on a fake clock, the
 * guard (NaN refusal, hardness clamp, watchdog trip and resume, dead writer), the lockstep wait
 * (dead participants dropped, live ones waited for) and the config reader's errors. */
#include "dcm/dcm.h"
#include "tap.h"

#include <math.h>
#include <signal.h>
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
  const double pose[NJ] = { 1.1, NAN, 0.3, -0.6 };
  dcm_guard_set_safe_pose(&g, pose, 0.3);
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

  /* no watchdog (lockstep): silence is not a fault */
  dcm_guard_init(&g, NJ, 0, 0.3, present, 0);
  fill(&c, NJ, 0.5, 0.8, 3);
  dcm_guard_apply(&g, 0, present, &c);
  check(dcm_guard_apply(&g, 100, present, &c) == 0 && g.trips == 0, "timeout 0: no watchdog");
}

/* ---------------------------------------------------------------- lockstep */

/* idle hook of the start_with test: asks the wait to stop after a few calls */
static void idle_count(void *ctx, int alone) {
  struct idle_ctx { volatile sig_atomic_t *stop; int *n; } *c = ctx;
  (void)alone;
  if (++*c->n >= 5) *c->stop = 1;
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
  memset(&l, 0, sizeof l);
  l.n = 1;
  l.sync[0] = &y;
  l.spin = 50e-6;
  l.drop_after = 0.05;
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
  pid_t worker = fork();
  if (worker == 0) {
    struct timespec ts = { 0, 200000000 };
    nanosleep(&ts, NULL);
    __atomic_store_n(&y.done_tick[0], 6u, __ATOMIC_RELEASE);
    shm_fetch_add_u32(y.done_count, 1);
    shm_futex_wake(y.done_count);
    _exit(0);
  }
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
  pid_t late = fork();
  if (late == 0) {
    struct timespec ts = { 2, 0 };
    nanosleep(&ts, NULL);
    __atomic_store_n(&y.done_tick[0], 7u, __ATOMIC_RELEASE);
    shm_fetch_add_u32(y.done_count, 1);
    shm_futex_wake(y.done_count);
    _exit(0);
  }
  rc = dcm_lockstep_wait(&l, 7, NULL, NULL, NULL);
  const uint32_t at_return = __atomic_load_n(&y.done_tick[0], __ATOMIC_ACQUIRE);
  kill(late, SIGKILL);
  waitpid(late, NULL, 0);
  check(rc == 0 && at_return != 7, "wake_tick ahead: not consulted at this tick");

  /* a stop request ends a wait for somebody who never joins */
  y.pid[0] = 0;
  volatile sig_atomic_t stop = 1;
  check(dcm_lockstep_wait(&l, 8, NULL, NULL, &stop) == 1, "nobody joined: the wait holds the clock until stopped");

  /* start_with: a fresh clock waits for that many participants; once it ran, one is enough */
  dcm_lockstep f;
  memset(&f, 0, sizeof f);
  f.n = 1;
  f.sync[0] = &y;
  f.spin = 50e-6;
  f.drop_after = 0.05;
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
  double pose[3], ramp;
  write_file("Config/robots/t/robot.lua",
             "return { joints = { 'a', 'b', 'c' }, safe_pose = { ramp = 0.25, q = { b = -0.5 } } }\n");
  rc = dcm_safe_pose_load("t", 3, pose, &ramp, err, sizeof err);
  tap_ok(rc == 0 && ramp == 0.25 && isnan(pose[0]) && pose[1] == -0.5 && isnan(pose[2]),
         "a body's safe pose by joint name; the joints it does not name are held", err);
  write_file("Config/robots/t/robot.lua", "return { joints = { 'a', 'b', 'c' }, safe_pose = { ramp = 'x', q = {} } }\n");
  rc = dcm_safe_pose_load("t", 3, pose, &ramp, err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "robot.lua") && strstr(err, "safe_pose.ramp"), "a bad safe pose names file and key", err);
  write_file("Config/robots/t/robot.lua", "return { joints = { 'a', 'b', 'c' } }\n");
  rc = dcm_safe_pose_load("t", 3, pose, &ramp, err, sizeof err);
  tap_ok(rc == 0 && ramp == 0 && isnan(pose[0]) && isnan(pose[1]) && isnan(pose[2]),
         "no safe pose: every joint held where it is", err);
  unsetenv("PLATFORM");

  char cmd[600];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", g_root);
  if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", g_root);
  unsetenv("HRP_ROOT");
}

int main(void) {
  /* Tests/run_all.sh gives every run an id of its own; by hand, one away from a running robot */
  g_id = getenv("ROBOT_ID") ? shm_robot_id() : 9000 + (int)(getpid() % 500);
  remove_blocks();
  test_blocks();
  test_pacing();
  test_guard();
  test_lockstep();
  remove_blocks();
  test_config();
  return tap_done();
}
