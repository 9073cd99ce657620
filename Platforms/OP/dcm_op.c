/* dcm_op: the DCM of the OP platform (DARwIn-OP: MX-28 + CM-730, protocol 1.0; OP3: XM430 +
 * OpenCR, protocol 2.0). PLATFORM=OP ./run_dcm [--port PATH] [--robot darwin|op3 (sets ROBOT)] [--rate HZ]
 * [--baud N] [--cycles N] [--timeout-margin S] [--quiet]
 *
 * Lifecycle (one job per step): parse config (robot.lua with its devices, dcm.lua; no I/O) -> open
 * the shm blocks -> open the port (retried) -> ping, read the pose, hold it -> cycle.
 * Each cycle, at an absolute deadline: read dcm.actuator; one sync write of goal positions
 * (and of torque enable / hardness only when they change); one bulk read of positions (one
 * servo in turn also gives speed, load, temperature) plus IMU and buttons of the board; write
 * dcm.sensor; statistics in dcm.stats. Dead servos leave the bulk read and are retried
 * every retry_period. A lost port is reported and reopened. Watchdog: when the motion process
 * stops acknowledging ticks, hold the present pose at safe_hardness until it returns.
 */
#include "dynamixel/dynamixel.h"
#include "shm/shm.h"

#include <errno.h>
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
#include <math.h>
#include <sched.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define NJ_MAX 32
#define PI 3.14159265358979323846
#define RAD_PER_COUNT (2.0 * PI / 4096.0)

/* ---------------------------------------------------------------- servo models */

typedef struct servo_model {
  const char *name;
  uint16_t goal_addr, goal_len;          /* goal position */
  uint16_t pos_addr, pos_len;            /* present position */
  uint16_t ext_addr, ext_len;            /* round-robin extended read (speed, load, temp...) */
  uint16_t torque_addr;                  /* torque enable (1 byte) */
  uint16_t hard_addr, hard_len, hard_max;/* hardness: MX torque limit / XM position P gain */
  int max_count;
} servo_model;

static const servo_model MODELS[] = {
  /* MX-28 (1.0): 36 pos(2) 38 speed(2) 40 load(2) 42 voltage(1) 43 temperature(1) */
  { "MX-28", 30, 2, 36, 2, 36, 8, 24, 34, 2, 1023, 4095 },
  /* XM430 (2.0): 126 current(2) 128 velocity(4) 132 pos(4) ... 144 voltage(2) 146 temp(1) */
  { "XM430", 116, 4, 132, 4, 126, 21, 64, 84, 2, 800, 4095 },
};

typedef struct board_model {
  const char *name;
  uint16_t addr, len;                    /* one read: buttons .. voltage */
} board_model;

static const board_model BOARDS[] = {
  { "CM-730", 30, 21 },   /* 30 button, 38 gyro Z/Y/X (10 bit, 512 = 0), 44 accel X/Y/Z, 50 voltage */
  { "OpenCR", 30, 22 },   /* 30 button, 38 gyro X/Y/Z, 44 accel X/Y/Z (int16), 50 voltage(2) */
};

/* ---------------------------------------------------------------- config */

typedef struct config {
  int nj;
  char joint[NJ_MAX][32];
  double lo[NJ_MAX], hi[NJ_MAX];
  double period;
  int protocol, baud, board_id;
  char port[256], robot[32];
  const servo_model *servo;
  const board_model *board;
  int id[NJ_MAX], dir[NJ_MAX], zero[NJ_MAX];
  double start_hardness, watchdog, safe_hardness, retry_period, timeout_margin;
  int dead_after, latency_timer, rt_priority;
  double gyro_sign[3], accel_sign[3];
} config;

static int lua_num(lua_State *L, const char *file, const char *key, double *out, char *err, size_t n) {
  lua_getfield(L, -1, key);
  if (!lua_isnumber(L, -1)) { snprintf(err, n, "%s: key '%s' missing or not a number", file, key); lua_pop(L, 1); return -1; }
  *out = lua_tonumber(L, -1);
  lua_pop(L, 1);
  return 0;
}

static int lua_str(lua_State *L, const char *file, const char *key, char *out, size_t len, char *err, size_t n) {
  lua_getfield(L, -1, key);
  if (!lua_isstring(L, -1)) { snprintf(err, n, "%s: key '%s' missing or not a string", file, key); lua_pop(L, 1); return -1; }
  snprintf(out, len, "%s", lua_tostring(L, -1));
  lua_pop(L, 1);
  return 0;
}

static int lua_nums(lua_State *L, const char *file, const char *key, double *out, int count, char *err, size_t n) {
  lua_getfield(L, -1, key);
  if (!lua_istable(L, -1) || (int)lua_objlen(L, -1) != count) {
    snprintf(err, n, "%s: key '%s' must be a list of %d numbers", file, key, count);
    lua_pop(L, 1);
    return -1;
  }
  for (int i = 0; i < count; i++) {
    lua_rawgeti(L, -1, i + 1);
    if (!lua_isnumber(L, -1)) { snprintf(err, n, "%s: %s[%d] is not a number", file, key, i + 1); lua_pop(L, 2); return -1; }
    out[i] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return 0;
}

/* Pushes Config.export(concern) of Lib/Config.lua (the layers of Config/, the one reader of the
 * Lua processes too); the files it came from go into `files`. */
static int load_concern(lua_State *L, const char *root, const char *concern, char *files, size_t flen,
                        char *err, size_t n) {
  static const char script[] =
      "local root, concern = ...\n"
      "package.path = root .. '/Lib/?.lua;' .. package.path\n"
      "return require('Config').export(concern)\n";
  if (luaL_loadstring(L, script) != 0) { snprintf(err, n, "%s", lua_tostring(L, -1)); return -1; }
  lua_pushstring(L, root);
  lua_pushstring(L, concern);
  if (lua_pcall(L, 2, 2, 0) != 0) { snprintf(err, n, "%s", lua_tostring(L, -1)); return -1; }
  snprintf(files, flen, "%s", lua_isstring(L, -1) ? lua_tostring(L, -1) : concern);
  lua_pop(L, 1);
  return 0;
}

static int load_config(config *c, char *err, size_t n) {
  const char *root = getenv("HRP_ROOT");
  if (!root) root = HRP_ROOT_DEFAULT;
  lua_State *L = luaL_newstate();
  if (!L) { snprintf(err, n, "no memory for Lua"); return -1; }
  luaL_openlibs(L);
  int rc = -1;
  double v, tmp[NJ_MAX];
  char s[64];
  /* robot.lua: joints, limits, period, the bus devices */
  char rf[200], df[200];
  if (load_concern(L, root, "robot", rf, sizeof rf, err, n)) goto out;
  lua_getfield(L, -1, "joints");
  if (!lua_istable(L, -1)) { snprintf(err, n, "%s: key 'joints' missing", rf); goto out; }
  c->nj = (int)lua_objlen(L, -1);
  if (c->nj <= 0 || c->nj > NJ_MAX) { snprintf(err, n, "%s: %d joints", rf, c->nj); goto out; }
  for (int j = 0; j < c->nj; j++) {
    lua_rawgeti(L, -1, j + 1);
    snprintf(c->joint[j], sizeof c->joint[j], "%s", lua_isstring(L, -1) ? lua_tostring(L, -1) : "?");
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  lua_getfield(L, -1, "limits");
  if (!lua_istable(L, -1)) { snprintf(err, n, "%s: key 'limits' missing", rf); goto out; }
  for (int j = 0; j < c->nj; j++) {
    lua_getfield(L, -1, c->joint[j]);
    double lh[2];
    if (!lua_istable(L, -1)) { snprintf(err, n, "%s: limits.%s missing", rf, c->joint[j]); goto out; }
    for (int k = 0; k < 2; k++) { lua_rawgeti(L, -1, k + 1); lh[k] = lua_tonumber(L, -1); lua_pop(L, 1); }
    c->lo[j] = lh[0]; c->hi[j] = lh[1];
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  if (lua_num(L, rf, "period", &c->period, err, n)) goto out;
  if (lua_str(L, rf, "name", c->robot, sizeof c->robot, err, n)) goto out;
  lua_getfield(L, -1, "devices");
  if (!lua_istable(L, -1)) { snprintf(err, n, "%s: key 'devices' missing (the Dynamixel bus table)", rf); goto out; }
  const char *f = rf;
  if (lua_num(L, f, "protocol", &v, err, n)) goto out;
  c->protocol = (int)v;
  if (lua_num(L, f, "board_id", &v, err, n)) goto out;
  c->board_id = (int)v;
  if (lua_str(L, f, "servo", s, sizeof s, err, n)) goto out;
  c->servo = NULL;
  for (size_t k = 0; k < sizeof MODELS / sizeof MODELS[0]; k++) if (!strcmp(MODELS[k].name, s)) c->servo = &MODELS[k];
  if (!c->servo) { snprintf(err, n, "%s: servo '%s' unknown (MX-28, XM430)", f, s); goto out; }
  if (lua_str(L, f, "board", s, sizeof s, err, n)) goto out;
  c->board = NULL;
  for (size_t k = 0; k < sizeof BOARDS / sizeof BOARDS[0]; k++) if (!strcmp(BOARDS[k].name, s)) c->board = &BOARDS[k];
  if (!c->board) { snprintf(err, n, "%s: board '%s' unknown (CM-730, OpenCR)", f, s); goto out; }
  if (lua_nums(L, f, "ids", tmp, c->nj, err, n)) goto out;
  for (int j = 0; j < c->nj; j++) c->id[j] = (int)tmp[j];
  if (lua_nums(L, f, "direction", tmp, c->nj, err, n)) goto out;
  for (int j = 0; j < c->nj; j++) c->dir[j] = tmp[j] < 0 ? -1 : 1;
  if (lua_nums(L, f, "zero", tmp, c->nj, err, n)) goto out;
  for (int j = 0; j < c->nj; j++) c->zero[j] = (int)tmp[j];
  lua_pop(L, 2);
  /* dcm.lua: the platform's bus settings */
  if (load_concern(L, root, "dcm", df, sizeof df, err, n)) goto out;
  f = df;
  if (lua_num(L, f, "baud", &v, err, n)) goto out;
  c->baud = (int)v;
  if (lua_str(L, f, "port", c->port, sizeof c->port, err, n)) goto out;
  if (lua_num(L, f, "start_hardness", &c->start_hardness, err, n)) goto out;
  if (lua_num(L, f, "watchdog", &c->watchdog, err, n)) goto out;
  if (lua_num(L, f, "safe_hardness", &c->safe_hardness, err, n)) goto out;
  if (lua_num(L, f, "retry_period", &c->retry_period, err, n)) goto out;
  if (lua_num(L, f, "timeout_margin", &c->timeout_margin, err, n)) goto out;
  if (lua_num(L, f, "dead_after", &v, err, n)) goto out;
  c->dead_after = (int)v;
  if (lua_num(L, f, "rt_priority", &v, err, n)) goto out;
  c->rt_priority = (int)v;
  if (lua_num(L, f, "latency_timer", &v, err, n)) goto out;
  c->latency_timer = (int)v;
  if (lua_nums(L, f, "gyro_sign", c->gyro_sign, 3, err, n)) goto out;
  if (lua_nums(L, f, "accel_sign", c->accel_sign, 3, err, n)) goto out;
  if (c->protocol != 1 && c->protocol != 2) { snprintf(err, n, "%s: protocol must be 1 or 2", f); goto out; }
  rc = 0;
out:
  lua_close(L);
  return rc;
}

/* ---------------------------------------------------------------- state */

typedef struct dcm {
  config c;
  dxl_port *port;
  dxl_bus bus;
  int quiet;
  /* shm */
  shm_block *sb, *ab, *stb;
  double *s_time, *s_period, *s_pos, *s_vel, *s_load, *s_temp, *s_gyro, *s_acc, *s_angle, *s_batt;
  uint32_t *s_tick;
  int32_t *s_button, *s_pid;
  double *a_cmd, *a_hard;
  int32_t *a_en;
  uint32_t *a_ack, *a_writer;
  double *st_rate, *st_jp99, *st_jmax, *st_bytes;
  uint32_t *st_cycles, *st_missed, *st_nan, *st_wd, *st_rx;
  uint32_t *st_serr, *st_stimeout;
  int32_t *st_dead;
  /* bus-side state */
  int goal[NJ_MAX];              /* counts last commanded */
  int sent_en[NJ_MAX], sent_hard[NJ_MAX];
  int have_pos[NJ_MAX];
  int pos_count[NJ_MAX];
  double pos[NJ_MAX], vel[NJ_MAX], load[NJ_MAX], temp[NJ_MAX];
  int miss[NJ_MAX], dead[NJ_MAX];
  double retry_at[NJ_MAX];
  uint32_t serr[NJ_MAX], stimeout[NJ_MAX];
  int rr;                         /* round-robin joint for the extended read */
  double gyro[3], acc[3], angle[3], batt;
  int button[2];
  /* watchdog */
  uint32_t last_ack;
  double ack_time;
  int safe, managed;
  uint32_t wd_trips, nan;
  double port_retry_at;
  int port_reported;
} dcm;

static volatile sig_atomic_t g_stop;
static void on_signal(int s) { (void)s; g_stop = 1; }

static void logmsg(dcm *d, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void logmsg(dcm *d, const char *fmt, ...) {
  if (d->quiet) return;
  va_list ap;
  va_start(ap, fmt);
  fprintf(stderr, "dcm_op: ");
  vfprintf(stderr, fmt, ap);
  fprintf(stderr, "\n");
  va_end(ap);
}

#define REQ(blk, var, name, type, cnt) \
  do { var = shm_field_require(blk, name, type, cnt, err, sizeof err); if (!var) { fprintf(stderr, "dcm_op: %s\n", err); return -1; } } while (0)

static int open_shm(dcm *d) {
  char err[256];
  int rid = shm_robot_id(), nj = d->c.nj;
  if (shm_block_open(NULL, "dcm.sensor", rid, SHM_OPEN_CREATE, &d->sb, err, sizeof err) ||
      shm_block_open(NULL, "dcm.actuator", rid, SHM_OPEN_CREATE, &d->ab, err, sizeof err) ||
      shm_block_open(NULL, "dcm.stats", rid, SHM_OPEN_CREATE, &d->stb, err, sizeof err)) {
    fprintf(stderr, "dcm_op: %s\n", err);
    return -1;
  }
  REQ(d->sb, d->s_time, "time", SHM_F64, 1); REQ(d->sb, d->s_tick, "tick", SHM_U32, 1);
  REQ(d->sb, d->s_period, "period", SHM_F64, 1); REQ(d->sb, d->s_pos, "position", SHM_F64, nj);
  REQ(d->sb, d->s_vel, "velocity", SHM_F64, nj); REQ(d->sb, d->s_load, "load", SHM_F64, nj);
  REQ(d->sb, d->s_temp, "temperature", SHM_F64, nj); REQ(d->sb, d->s_gyro, "gyro", SHM_F64, 3);
  REQ(d->sb, d->s_acc, "accelerometer", SHM_F64, 3); REQ(d->sb, d->s_angle, "angle", SHM_F64, 3);
  REQ(d->sb, d->s_button, "button", SHM_I32, 2); REQ(d->sb, d->s_batt, "battery", SHM_F64, 1);
  REQ(d->sb, d->s_pid, "dcm_pid", SHM_I32, 1);
  REQ(d->ab, d->a_cmd, "command", SHM_F64, nj); REQ(d->ab, d->a_hard, "hardness", SHM_F64, nj);
  REQ(d->ab, d->a_en, "torque_enable", SHM_I32, nj); REQ(d->ab, d->a_ack, "tick_ack", SHM_U32, 1);
  REQ(d->ab, d->a_writer, "writer_pid", SHM_U32, 1);
  REQ(d->stb, d->st_rate, "rate", SHM_F64, 1); REQ(d->stb, d->st_jp99, "jitter_p99", SHM_F64, 1);
  REQ(d->stb, d->st_jmax, "jitter_max", SHM_F64, 1); REQ(d->stb, d->st_bytes, "bytes_per_cycle", SHM_F64, 1);
  REQ(d->stb, d->st_cycles, "cycles", SHM_U32, 1); REQ(d->stb, d->st_missed, "missed_cycles", SHM_U32, 1);
  REQ(d->stb, d->st_nan, "nan_commands", SHM_U32, 1); REQ(d->stb, d->st_wd, "watchdog_trips", SHM_U32, 1);
  REQ(d->stb, d->st_rx, "rx_errors", SHM_U32, 1); REQ(d->stb, d->st_serr, "servo_errors", SHM_U32, nj);
  REQ(d->stb, d->st_stimeout, "servo_timeouts", SHM_U32, nj); REQ(d->stb, d->st_dead, "servo_dead", SHM_I32, nj);
  return 0;
}

/* ---------------------------------------------------------------- conversions */

static int rad_to_count(dcm *d, int j, double rad) {
  double lo = d->c.lo[j], hi = d->c.hi[j];
  if (rad < lo) rad = lo;
  if (rad > hi) rad = hi;
  long c = d->c.zero[j] + lround(d->c.dir[j] * rad / RAD_PER_COUNT);
  if (c < 0) c = 0;
  if (c > d->c.servo->max_count) c = d->c.servo->max_count;
  return (int)c;
}

static double count_to_rad(dcm *d, int j, int count) {
  return d->c.dir[j] * (count - d->c.zero[j]) * RAD_PER_COUNT;
}

static void put_n(uint8_t *p, int len, long v) {
  if (len == 1) p[0] = (uint8_t)v;
  else if (len == 2) dxl_put16(p, (uint16_t)v);
  else dxl_put32(p, (uint32_t)v);
}

/* Decodes a servo's extended read (speed, load, temperature) into SI. */
static void decode_ext(dcm *d, int j, const uint8_t *b) {
  if (d->c.protocol == 1) {        /* MX-28 from 36 */
    int sp = dxl_get16(b + 2), ld = dxl_get16(b + 4);
    double rpm = (sp & 1023) * 0.114 * ((sp & 1024) ? -1 : 1);
    d->vel[j] = d->c.dir[j] * rpm * 2 * PI / 60;
    d->load[j] = d->c.dir[j] * (ld & 1023) / 1023.0 * ((ld & 1024) ? -1 : 1);   /* fraction of max torque */
    d->temp[j] = b[7];
  } else {                         /* XM430 from 126 */
    int16_t cur = (int16_t)dxl_get16(b);
    int32_t v = (int32_t)dxl_get32(b + 2);
    d->vel[j] = d->c.dir[j] * v * 0.229 * 2 * PI / 60;
    d->load[j] = d->c.dir[j] * cur * 2.69e-3 * 1.78;      /* mA -> N*m (XM430-W350 ~1.78 N*m/A) */
    d->temp[j] = b[20];
  }
}

static void decode_board(dcm *d, const uint8_t *b) {
  double g[3], a[3];
  int btn = b[0];
  if (d->c.protocol == 1) {        /* CM-730 from 30: gyro Z Y X at 38, accel X Y Z at 44 */
    double gs = 1600.0 * PI / 180.0 / 512.0, as = 4 * 9.80665 / 512.0;
    g[2] = (dxl_get16(b + 8) - 512) * gs;
    g[1] = (dxl_get16(b + 10) - 512) * gs;
    g[0] = (dxl_get16(b + 12) - 512) * gs;
    for (int k = 0; k < 3; k++) a[k] = (dxl_get16(b + 14 + 2 * k) - 512) * as;
    d->batt = b[20] * 0.1;
  } else {                         /* OpenCR from 30: gyro X Y Z at 38, accel at 44, int16 */
    double gs = 0.06103 * PI / 180.0, as = 9.80665 / 2048.0;
    for (int k = 0; k < 3; k++) {
      g[k] = (int16_t)dxl_get16(b + 8 + 2 * k) * gs;
      a[k] = (int16_t)dxl_get16(b + 14 + 2 * k) * as;
    }
    d->batt = dxl_get16(b + 20) * 0.1;
  }
  for (int k = 0; k < 3; k++) { d->gyro[k] = g[k] * d->c.gyro_sign[k]; d->acc[k] = a[k] * d->c.accel_sign[k]; }
  d->button[0] = btn & 1;
  d->button[1] = (btn >> 1) & 1;
}

/* Torso angles: roll/pitch from gravity blended with the gyro, yaw integrates the gyro. */
static void update_angle(dcm *d, double dt) {
  double ax = d->acc[0], ay = d->acc[1], az = d->acc[2];
  double roll_a = atan2(ay, az), pitch_a = atan2(-ax, sqrt(ay * ay + az * az));
  double k = 0.98;
  d->angle[0] = k * (d->angle[0] + d->gyro[0] * dt) + (1 - k) * roll_a;
  d->angle[1] = k * (d->angle[1] + d->gyro[1] * dt) + (1 - k) * pitch_a;
  d->angle[2] += d->gyro[2] * dt;
}

/* ---------------------------------------------------------------- bus steps */

static int open_port(dcm *d) {
  char err[256];
  if (!d->port) {
    if (dxl_port_open(d->c.port, d->c.baud, &d->port, err, sizeof err)) {
      if (!d->port_reported) logmsg(d, "%s (retrying)", err);
      d->port_reported = 1;
      return -1;
    }
  } else if (dxl_port_reopen(d->port, err, sizeof err)) {
    if (!d->port_reported) logmsg(d, "port lost: %s (retrying)", err);
    d->port_reported = 1;
    return -1;
  }
  if (d->port_reported) logmsg(d, "port %s open again", d->c.port);
  d->port_reported = 0;
  dxl_bus_stats keep = d->bus.stats;
  dxl_bus_init(&d->bus, d->port, d->c.protocol);
  d->bus.stats = keep;
  d->bus.timeout_margin = d->c.timeout_margin;
  /* resend everything after a reconnection */
  for (int j = 0; j < d->c.nj; j++) { d->sent_en[j] = -1; d->sent_hard[j] = -1; }
  return 0;
}

/* Reads every servo once (at start): marks the missing ones dead. */
static void probe(dcm *d) {
  int found = 0;
  double margin = d->bus.timeout_margin;
  d->bus.timeout_margin = 0.05;   /* start-up is not real time: be patient once */
  for (int j = 0; j < d->c.nj; j++) {
    uint8_t b[4], e;
    int r = dxl_read(&d->bus, (uint8_t)d->c.id[j], d->c.servo->pos_addr, d->c.servo->pos_len, b, &e);
    if (r == 0) {
      d->pos_count[j] = d->c.servo->pos_len == 2 ? dxl_get16(b) : (int32_t)dxl_get32(b);
      d->pos[j] = count_to_rad(d, j, d->pos_count[j]);
      d->have_pos[j] = 1;
      found++;
    } else {
      d->dead[j] = 1;
      d->retry_at[j] = 0;
      logmsg(d, "servo %d (%s) does not answer: %s", d->c.id[j], d->c.joint[j], dxl_result_str(r));
    }
  }
  d->bus.timeout_margin = margin;
  logmsg(d, "%d of %d servos answer (%s, protocol %d.0, %s)", found, d->c.nj, d->c.servo->name,
         d->c.protocol, d->c.board->name);
}

static void write_goals(dcm *d, const int *en, const double *hard, const double *cmd) {
  uint8_t ids[NJ_MAX], data[NJ_MAX * 4];
  int n = 0, nj = d->c.nj;
  const servo_model *m = d->c.servo;
  /* torque enable / hardness only when they change */
  int ch_en = 0, ch_h = 0;
  int hv[NJ_MAX];
  for (int j = 0; j < nj; j++) {
    hv[j] = (int)lround(hard[j] * m->hard_max);
    if (en[j] != d->sent_en[j]) ch_en = 1;
    if (hv[j] != d->sent_hard[j]) ch_h = 1;
  }
  if (ch_h) {
    n = 0;
    for (int j = 0; j < nj; j++) { ids[n] = (uint8_t)d->c.id[j]; put_n(data + n * m->hard_len, m->hard_len, hv[j]); n++; }
    if (dxl_sync_write(&d->bus, m->hard_addr, m->hard_len, ids, n, data) == 0)
      for (int j = 0; j < nj; j++) d->sent_hard[j] = hv[j];
  }
  if (ch_en) {
    n = 0;
    for (int j = 0; j < nj; j++) { ids[n] = (uint8_t)d->c.id[j]; data[n] = (uint8_t)(en[j] ? 1 : 0); n++; }
    if (dxl_sync_write(&d->bus, m->torque_addr, 1, ids, n, data) == 0)
      for (int j = 0; j < nj; j++) d->sent_en[j] = en[j];
  }
  n = 0;
  for (int j = 0; j < nj; j++) {
    d->goal[j] = rad_to_count(d, j, cmd[j]);
    ids[n] = (uint8_t)d->c.id[j];
    put_n(data + n * m->goal_len, m->goal_len, d->goal[j]);
    n++;
  }
  dxl_sync_write(&d->bus, m->goal_addr, m->goal_len, ids, n, data);
}

/* One bulk read of live servos' positions (one servo in turn extended) and the board. */
static void read_state(dcm *d, double now, double dt) {
  const servo_model *m = d->c.servo;
  int nj = d->c.nj;
  static uint8_t store[NJ_MAX + 1][32];
  dxl_bulk_item items[NJ_MAX + 1];
  int joint_of[NJ_MAX + 1], n = 0;
  /* pick the round-robin servo among the live ones */
  for (int k = 0; k < nj; k++) { d->rr = (d->rr + 1) % nj; if (!d->dead[d->rr]) break; }
  for (int j = 0; j < nj; j++) {
    if (d->dead[j]) continue;
    int ext = j == d->rr;
    items[n] = (dxl_bulk_item){ (uint8_t)d->c.id[j], ext ? m->ext_addr : m->pos_addr,
                                ext ? m->ext_len : m->pos_len, store[n], 0, 0 };
    joint_of[n++] = j;
  }
  items[n] = (dxl_bulk_item){ (uint8_t)d->c.board_id, d->c.board->addr, d->c.board->len, store[n], 0, 0 };
  joint_of[n++] = -1;
  int r = dxl_bulk_read(&d->bus, items, n);
  if (r < 0) return;   /* port trouble: the caller reopens */
  /* no answer at all is a bus problem (power, cable, adapter), not n dead servos */
  int bus_silent = r == 0;
  for (int k = 0; k < n; k++) {
    int j = joint_of[k];
    if (j < 0) {
      if (items[k].result == 0) { decode_board(d, store[k]); update_angle(d, dt); }
      continue;
    }
    if (items[k].result != 0) {
      d->stimeout[j]++;
      if (!bus_silent && ++d->miss[j] >= d->c.dead_after) {
        d->dead[j] = 1;
        d->retry_at[j] = now + d->c.retry_period;
        logmsg(d, "servo %d (%s) marked dead after %d missed answers", d->c.id[j], d->c.joint[j], d->miss[j]);
      }
      continue;
    }
    d->miss[j] = 0;
    if (items[k].error) d->serr[j]++;
    int ext = items[k].addr == m->ext_addr && items[k].len == m->ext_len;
    const uint8_t *p = store[k] + (ext ? m->pos_addr - m->ext_addr : 0);
    int count = m->pos_len == 2 ? dxl_get16(p) : (int32_t)dxl_get32(p);
    double rad = count_to_rad(d, j, count);
    if (ext) decode_ext(d, j, store[k]);
    else if (d->have_pos[j] && dt > 0) d->vel[j] = 0.7 * d->vel[j] + 0.3 * (rad - d->pos[j]) / dt;
    d->pos[j] = rad;
    d->pos_count[j] = count;
    d->have_pos[j] = 1;
  }
}

/* A dead servo gets one short read every retry_period; it rejoins when it answers. */
static void retry_dead(dcm *d, double now) {
  for (int j = 0; j < d->c.nj; j++) {
    if (!d->dead[j] || now < d->retry_at[j]) continue;
    d->retry_at[j] = now + d->c.retry_period;
    uint8_t b[4], e;
    if (dxl_read(&d->bus, (uint8_t)d->c.id[j], d->c.servo->pos_addr, d->c.servo->pos_len, b, &e) == 0) {
      d->dead[j] = 0;
      d->miss[j] = 0;
      d->sent_en[j] = -1;
      d->sent_hard[j] = -1;
      logmsg(d, "servo %d (%s) answers again", d->c.id[j], d->c.joint[j]);
    }
    return;   /* at most one retry per cycle */
  }
}

/* Bytes on the wire of one regular cycle (no stuffing, no changes of torque/hardness):
 * sync write of goals + bulk read request + the answers of n servos (one extended) and board. */
static int wire_bytes(const dcm *d, int *tx, int *rx) {
  const servo_model *m = d->c.servo;
  int n = d->c.nj, p = d->c.protocol;
  int sw = dxl_instruction_size(p, (p == 1 ? 2 : 4) + n * (1 + m->goal_len));
  int br = dxl_instruction_size(p, p == 1 ? 1 + 3 * (n + 1) : 5 * (n + 1));
  int ans = (n - 1) * dxl_status_size(p, m->pos_len) + dxl_status_size(p, m->ext_len) +
            dxl_status_size(p, d->c.board->len);
  *tx = sw + br;
  *rx = ans;
  return sw + br + ans;
}

/* ---------------------------------------------------------------- main loop */

static int cmp_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

static void sleep_until(double t) {
  struct timespec ts;
  ts.tv_sec = (time_t)t;
  ts.tv_nsec = (long)((t - (double)ts.tv_sec) * 1e9);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL) == EINTR && !g_stop) {}
}

static void usage(void) {
  fprintf(stderr, "usage: PLATFORM=OP ./run_dcm [--port PATH] [--robot darwin|op3 (sets ROBOT)] [--rate HZ] [--baud N]\n"
                  "                             [--cycles N] [--timeout-margin S] [--quiet]\n");
}

int main(int argc, char **argv) {
  static dcm D;
  dcm *d = &D;
  const char *port = NULL;
  double rate = 0;
  long max_cycles = -1;
  int baud = 0;
  double margin = -1;
  for (int i = 1; i < argc; i++) {
    const char *o = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
    if (!strcmp(o, "--port") && v) { port = v; i++; }
    else if (!strcmp(o, "--robot") && v) { setenv("ROBOT", v, 1); i++; }
    else if (!strcmp(o, "--rate") && v) { rate = atof(v); i++; }
    else if (!strcmp(o, "--baud") && v) { baud = atoi(v); i++; }
    else if (!strcmp(o, "--cycles") && v) { max_cycles = atol(v); i++; }
    else if (!strcmp(o, "--timeout-margin") && v) { margin = atof(v); i++; }
    else if (!strcmp(o, "--quiet")) d->quiet = 1;
    else { usage(); return 2; }
  }
  char err[512];
  if (load_config(&d->c, err, sizeof err)) { fprintf(stderr, "dcm_op: %s\n", err); return 2; }
  if (port) snprintf(d->c.port, sizeof d->c.port, "%s", port);
  if (rate > 0) d->c.period = 1.0 / rate;
  if (baud > 0) d->c.baud = baud;
  if (margin >= 0) d->c.timeout_margin = margin;
  if (open_shm(d)) return 1;
  signal(SIGINT, on_signal);
  signal(SIGTERM, on_signal);
  signal(SIGPIPE, SIG_IGN);
  logmsg(d, "%s: %d joints at %.0f Hz on %s (%d baud)", d->c.robot, d->c.nj, 1.0 / d->c.period,
         d->c.port, d->c.baud);

  /* the USB adapter's latency timer (skipped cleanly when there is none) */
  dxl_usb_info usb[8];
  int nusb = dxl_usb_find(usb, 8, err, sizeof err);
  for (int k = 0; k < nusb; k++)
    logmsg(d, "USB adapter %04x:%04x %s (bus %d, device %d)", usb[k].vendor, usb[k].product,
           usb[k].name, usb[k].bus, usb[k].address);
  int nset = dxl_usb_set_latency(d->c.port, d->c.latency_timer, err, sizeof err);
  if (nset > 0) logmsg(d, "latency timer %d ms set on %d adapter(s)", d->c.latency_timer, nset);

  if (d->c.rt_priority > 0) {
    struct sched_param sp = { .sched_priority = d->c.rt_priority };
    if (sched_setscheduler(0, SCHED_FIFO, &sp) != 0)
      logmsg(d, "no real-time priority %d (%s): running as a normal process", d->c.rt_priority, strerror(errno));
  }
  int wtx, wrx, wire = wire_bytes(d, &wtx, &wrx);
  logmsg(d, "wire per cycle: %d bytes (sent %d, answers %d) = %.1f ms at %d baud, bus-limited %.0f Hz",
         wire, wtx, wrx, wire * 10e3 / d->c.baud, d->c.baud, d->c.baud / (10.0 * wire));
  while (!g_stop && open_port(d) != 0) sleep_until(dxl_now() + 0.5);
  if (g_stop) return 0;
  probe(d);

  int nj = d->c.nj;
  /* a blank actuator block (fresh) gets the present pose, so nothing jumps */
  int blank = 1;
  for (int j = 0; j < nj; j++) blank = blank && d->a_cmd[j] == 0 && d->a_hard[j] == 0 && d->a_en[j] == 0;
  shm_write_begin(d->ab);
  for (int j = 0; j < nj; j++) {
    if (blank || !d->have_pos[j]) d->a_cmd[j] = d->have_pos[j] ? d->pos[j] : 0;
    if (blank) { d->a_hard[j] = d->c.start_hardness; d->a_en[j] = 1; }
  }
  *d->a_ack = 0;
  shm_write_end(d->ab);
  for (int j = 0; j < nj; j++) { d->sent_en[j] = -1; d->sent_hard[j] = -1; }
  *d->s_pid = getpid();

  double t0 = dxl_now(), deadline = t0, last = t0;
  uint32_t tick = 0, missed = 0, cycles = 0;
  int jn = 0, jcap = (int)(1.0 / d->c.period) + 8;
  double *jit = calloc((size_t)jcap, sizeof *jit), *sorted = calloc((size_t)jcap, sizeof *sorted);
  double win_start = t0, win_bytes0 = (double)(d->bus.stats.tx_bytes + d->bus.stats.rx_bytes);
  uint32_t win_cycles = 0;
  double last_cmd[NJ_MAX], cmd[NJ_MAX], hard[NJ_MAX];
  int en[NJ_MAX];
  for (int j = 0; j < nj; j++) last_cmd[j] = d->a_cmd[j];
  while (!g_stop && (max_cycles < 0 || (long)cycles < max_cycles)) {
    deadline += d->c.period;
    double now = dxl_now();
    if (now < deadline) { sleep_until(deadline); now = dxl_now(); }
    double late = now - deadline;
    if (late > d->c.period) {               /* overrun: count the lost cycles, do not race */
      missed += (uint32_t)(late / d->c.period);
      deadline = now;
      late = 0;
    }
    if (jn < jcap) jit[jn++] = fabs(late);
    double dt = now - last;
    last = now;

    if (!dxl_port_is_open(d->port)) {
      if (now >= d->port_retry_at) {
        d->port_retry_at = now + 0.5;
        if (open_port(d) == 0) for (int j = 0; j < nj; j++) d->miss[j] = 0;
      }
    }

    /* ---- commands */
    uint32_t seq, ack, writer;
    do {
      seq = shm_read_begin(d->ab);
      memcpy(cmd, d->a_cmd, sizeof(double) * (size_t)nj);
      memcpy(hard, d->a_hard, sizeof(double) * (size_t)nj);
      memcpy(en, d->a_en, sizeof(int) * (size_t)nj);
      ack = *d->a_ack;
      writer = *d->a_writer;
    } while (shm_read_retry(d->ab, seq));
    for (int j = 0; j < nj; j++) {
      if (!isfinite(cmd[j])) { d->nan++; cmd[j] = last_cmd[j]; }
      if (!isfinite(hard[j])) { d->nan++; hard[j] = 1; }
      hard[j] = hard[j] < 0 ? 0 : hard[j] > 1 ? 1 : hard[j];
      last_cmd[j] = cmd[j];
    }
    /* ---- watchdog: motion acknowledges ticks; silence (or its death) -> hold at safe hardness */
    if (ack != d->last_ack) {
      d->last_ack = ack;
      d->ack_time = now;
      if (ack) d->managed = 1;
      if (d->safe) { d->safe = 0; logmsg(d, "motion answers again: commands resume"); }
    }
    if (d->managed && !d->safe &&
        (now - d->ack_time > d->c.watchdog || (writer && !shm_pid_alive((int)writer)))) {
      d->safe = 1;
      d->wd_trips++;
      for (int j = 0; j < nj; j++) d->goal[j] = d->pos_count[j];
      logmsg(d, "watchdog: no tick_ack for %.2f s: holding the pose at hardness %.2f",
             now - d->ack_time, d->c.safe_hardness);
    }
    if (d->safe) {
      for (int j = 0; j < nj; j++) {
        cmd[j] = count_to_rad(d, j, d->goal[j]);
        hard[j] = fmin(hard[j], d->c.safe_hardness);
      }
    }

    /* ---- bus */
    uint64_t bytes0 = d->bus.stats.tx_bytes + d->bus.stats.rx_bytes;
    if (dxl_port_is_open(d->port)) {
      write_goals(d, en, hard, cmd);
      read_state(d, now, dt);
      retry_dead(d, now);
    }
    (void)bytes0;

    /* ---- sensors */
    tick++;
    cycles++;
    shm_write_begin(d->sb);
    *d->s_time = now - t0;
    *d->s_tick = tick;
    *d->s_period = d->c.period;
    for (int j = 0; j < nj; j++) {
      d->s_pos[j] = d->pos[j]; d->s_vel[j] = d->vel[j]; d->s_load[j] = d->load[j]; d->s_temp[j] = d->temp[j];
    }
    for (int k = 0; k < 3; k++) { d->s_gyro[k] = d->gyro[k]; d->s_acc[k] = d->acc[k]; d->s_angle[k] = d->angle[k]; }
    d->s_button[0] = d->button[0]; d->s_button[1] = d->button[1];
    *d->s_batt = d->batt;
    shm_write_end(d->sb);

    /* ---- statistics: every cycle the counters, every second rate/jitter/bytes */
    shm_write_begin(d->stb);
    *d->st_cycles = cycles;
    *d->st_missed = missed;
    *d->st_nan = d->nan;
    *d->st_wd = d->wd_trips;
    *d->st_rx = (uint32_t)(d->bus.stats.corrupt + d->bus.stats.misaddressed + d->bus.stats.out_of_order);
    for (int j = 0; j < nj; j++) {
      d->st_serr[j] = d->serr[j]; d->st_stimeout[j] = d->stimeout[j]; d->st_dead[j] = d->dead[j];
    }
    win_cycles++;
    if (now - win_start >= 1.0 || jn == jcap) {
      double bytes = (double)(d->bus.stats.tx_bytes + d->bus.stats.rx_bytes);
      *d->st_rate = win_cycles / (now - win_start);
      *d->st_bytes = (bytes - win_bytes0) / win_cycles;
      memcpy(sorted, jit, sizeof(double) * (size_t)jn);
      qsort(sorted, (size_t)jn, sizeof(double), cmp_double);
      *d->st_jp99 = jn ? sorted[(int)(0.99 * (jn - 1))] : 0;
      *d->st_jmax = jn ? sorted[jn - 1] : 0;
      win_start = now; win_bytes0 = bytes; win_cycles = 0; jn = 0;
    }
    shm_write_end(d->stb);
  }
  logmsg(d, "stopped after %u cycles (%u missed; bus: %llu corrupt, %llu timeouts, %llu misaddressed)",
         cycles, missed, (unsigned long long)d->bus.stats.corrupt, (unsigned long long)d->bus.stats.timeouts,
         (unsigned long long)d->bus.stats.misaddressed);
  /* leave the servos holding where they are */
  free(jit);
  free(sorted);
  if (d->port) dxl_port_close(d->port);
  shm_block_close(d->sb);
  shm_block_close(d->ab);
  shm_block_close(d->stb);
  return 0;
}
