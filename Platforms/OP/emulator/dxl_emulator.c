/* dxl_emulator: a virtual Dynamixel bus on a pseudo-terminal, for tests and bring-up without
 * hardware.
 *
 *   dxl_emulator [--link PATH] [--robot NAME | --protocol 1|2 [--ids A-B]] [--baud N] [--timing]
 *                [--drop P] [--corrupt P] [--delay S] [--dead ID]... [--tau S] [--seed N]
 *                [--stdin] [--realtime] [--quiet] [--sim-id N] [--trace FILE]
 *
 * The devices are the body's by default: $ROBOT's (--robot NAME: that body's) robot.lua `devices`,
 * bus 1, read by the OP DCM's own reader (Modules/op_devices): its protocol, ids, models and board,
 * so `PLATFORM=OP ./run_dcm` finds every servo it expects. Its baud rate is the bus's unless --baud.
 * A generic chain instead, with --protocol or --ids (servos A-B, default 1-20, and the board at 200):
 * --protocol 1 (default): a DARwIn-OP chain: MX-28 servos and the CM-730.
 * --protocol 2: an OP3 chain: XM430-W350 servos and the OpenCR.
 * Servos move first-order towards the goal (time constant --tau, capped at the servo's no-load
 * speed). --timing adds the wire time of every packet at --baud (10 bits a byte) and each
 * device's return delay time. Faults: --drop P (no answer), --corrupt P (one byte of an answer
 * flipped), --delay S (extra latency before every answer), --dead ID (never answers).
 * --realtime asks for SCHED_FIFO so answers leave on time on a loaded machine.
 * --stdin reads commands, one per line:  button MASK | gyro X Y Z (rad/s) | accel X Y Z (m/s^2)
 *   | dead ID | alive ID | stats | quit.
 * --sim-id N: hardware in the loop. The devices are the body's and the physics world moves them:
 *   goals, torque enables and hardness registers go to the sim DCM's robot N (dcm.actuator), present
 *   positions, speeds, loads, IMU and buttons come from its dcm.sensor (dxl_sim.h); --tau and the
 *   stdin IMU commands do not apply, --protocol and --ids are refused.
 * --trace FILE: what the servos receive, one line per change, wall-clock (CLOCK_REALTIME) seconds
 *   first: "T ID torque V" and "T ID hardness V" (MX torque limit, XM position P gain), and "T goals N"
 *   for a packet that changed the goals of N servos (Tests/fault/dxl_faults_test.sh times the
 *   DCM's safe state and the commands' return with it).
 * Prints "dxl_emulator: ready <pty>" on stderr when the port can be opened.
 */
#include "dcm/args.h"
#include "dynamixel/dynamixel.h"
#include "dxl_sim.h"

#include <errno.h>
#include <limits.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

enum { MX28, XM430, CM730, OPENCR };

#define TABLE 256
#define MAXDEV 32
#define PI 3.14159265358979323846

typedef struct device {
  int kind;
  uint8_t id;
  uint8_t t[TABLE];        /* control table */
  double pos;              /* counts */
  double vel;              /* counts/s */
  int dead;
  int servo;               /* --sim-id: index in the body's bus (dxl_sim), else -1 */
} device;

static device dev[MAXDEV];
static int ndev;
static int protocol;        /* 0 until --protocol or the body sets it */
static int baud = 1000000;
static int timing;
static double p_drop, p_corrupt, extra_delay, tau = 0.03;
static int quiet;
static volatile sig_atomic_t stop;
static double last_update;
/* IMU truth in SI, torso frame; buttons bit mask */
static double gyro[3], accel[3] = { 0, 0, 9.81 };
static int buttons;
static unsigned long n_rx, n_tx, n_dropped, n_corrupted, n_bad;
static int sim_mode;
static dxl_sim sim;
static FILE *trace;        /* --trace */
static int goals_changed;  /* servos whose goal the packet being handled changed */

/* ---------------------------------------------------------------- control tables */

/* Address ranges that a WRITE may touch, per kind (others: access error). */
static int writable(int kind, int addr, int len) {
  int end = addr + len;
  switch (kind) {
  case MX28:   /* EEPROM 3..18, RAM 24..35 (torque..torque limit), 47..49 (lock, punch), 73 */
    return (addr >= 3 && end <= 19) || (addr >= 24 && end <= 36) || (addr >= 47 && end <= 50) ||
           (addr == 73 && end == 74);
  case XM430:  /* EEPROM 7..63, RAM 64..68, 76..119 (gains, profiles, goals) */
    return (addr >= 7 && end <= 69) || (addr >= 76 && end <= 120);
  case CM730:
  case OPENCR: /* power, LEDs */
    return addr >= 24 && end <= 30;
  default: return 0;
  }
}

static void put16(device *d, int a, int v) { dxl_put16(d->t + a, (uint16_t)v); }
static void put32(device *d, int a, long v) { dxl_put32(d->t + a, (uint32_t)v); }

static void add_device(int kind, uint8_t id) {
  if (ndev >= MAXDEV) return;
  device *d = &dev[ndev++];
  memset(d, 0, sizeof *d);
  d->kind = kind;
  d->id = id;
  d->servo = -1;
  switch (kind) {
  case MX28:
    put16(d, 0, 29); d->t[2] = 30; d->t[3] = id; d->t[4] = 1; d->t[5] = 0;   /* return delay 0 */
    put16(d, 6, 0); put16(d, 8, 4095); d->t[11] = 80; d->t[12] = 60; d->t[13] = 160;
    put16(d, 14, 1023); d->t[16] = 2; d->t[17] = 36; d->t[18] = 36;
    d->t[28] = 32; put16(d, 30, 2048); put16(d, 34, 1023); put16(d, 36, 2048);
    d->t[42] = 120; d->t[43] = 40; put16(d, 48, 0);
    d->pos = 2048;
    break;
  case XM430:
    put16(d, 0, 1020); d->t[6] = 45; d->t[7] = id; d->t[8] = 3; d->t[9] = 0; d->t[11] = 3;
    d->t[13] = 2; d->t[31] = 80; put16(d, 32, 160); put16(d, 34, 95); put16(d, 36, 885);
    put16(d, 38, 1193); put32(d, 44, 200); put32(d, 48, 4095); put32(d, 52, 0);
    d->t[68] = 2; put16(d, 84, 800); put32(d, 116, 2048); put32(d, 132, 2048);
    put16(d, 144, 120); d->t[146] = 40;
    d->pos = 2048;
    break;
  case CM730:
    put16(d, 0, 0x7300); d->t[2] = 0x11; d->t[3] = id; d->t[4] = 1; d->t[16] = 2; d->t[24] = 1;
    break;
  case OPENCR:
    put16(d, 0, 0x7400); d->t[6] = 0x11; d->t[7] = id; d->t[8] = 3; d->t[16] = 2; d->t[24] = 1;
    break;
  }
}

static device *find(uint8_t id) {
  for (int i = 0; i < ndev; i++) if (dev[i].id == id) return &dev[i];
  return NULL;
}

static int clampi(double v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : (int)lround(v); }

/* Sensor registers of the sub-controller from the IMU truth (torso frame: x forward, y left, z up).
 * CM-730: 10-bit, 512 = 0, gyro +-1600 deg/s and accelerometer +-4 g over the range, words GYRO_Z,
 * GYRO_Y, GYRO_X at 38, 40, 42 and ACC_X, ACC_Y, ACC_Z at 44, 46, 48, mounted as in the DARwIn-OP
 * (shared/robots/darwin_reference.txt, IMU): GYRO_X = -wx, GYRO_Y = -wy, GYRO_Z = wz; ACC_X = the
 * specific force toward the robot's right (-y), ACC_Y = forward (+x), ACC_Z = up.
 * OpenCR (as emulated here): signed 16-bit, gyro 0.06103 deg/s and accel 1/2048 g per count, axes
 * as the torso's. */
static void update_board(device *d) {
  if (d->kind == CM730) {
    double gs = 512.0 / (1600.0 * PI / 180.0), as = 512.0 / (4 * 9.80665);
    d->t[30] = (uint8_t)buttons;
    put16(d, 38, clampi(512 + gyro[2] * gs, 0, 1023));
    put16(d, 40, clampi(512 - gyro[1] * gs, 0, 1023));
    put16(d, 42, clampi(512 - gyro[0] * gs, 0, 1023));
    put16(d, 44, clampi(512 - accel[1] * as, 0, 1023));
    put16(d, 46, clampi(512 + accel[0] * as, 0, 1023));
    put16(d, 48, clampi(512 + accel[2] * as, 0, 1023));
    d->t[50] = 121;
  } else if (d->kind == OPENCR) {
    double gs = 1.0 / (0.06103 * PI / 180.0), as = 2048.0 / 9.80665;
    d->t[30] = (uint8_t)buttons;
    for (int k = 0; k < 3; k++) {
      put16(d, 38 + 2 * k, (uint16_t)(int16_t)clampi(gyro[k] * gs, -32768, 32767));
      put16(d, 44 + 2 * k, (uint16_t)(int16_t)clampi(accel[k] * as, -32768, 32767));
    }
    put16(d, 50, 121);
  }
}

/* Present position, speed, load (register units: MX 0..1023 + sign bit, XM signed current) and the
 * moving flag of a servo from d->pos and d->vel. */
static void put_present(device *d, double goal, double load) {
  if (d->kind == MX28) {
    put16(d, 36, clampi(d->pos, 0, 4095));
    double rpm = d->vel / 4096.0 * 60.0;
    int sp = clampi(fabs(rpm) / 0.114, 0, 1023) | (rpm < 0 ? 1024 : 0);
    put16(d, 38, sp);
    put16(d, 40, clampi(fabs(load), 0, dxl_get16(d->t + 34)) | (load < 0 ? 1024 : 0));
    d->t[46] = fabs(goal - d->pos) > 1.0;
  } else {
    put32(d, 132, (long)lround(d->pos));
    put32(d, 128, (long)lround(d->vel / 4096.0 * 60.0 / 0.229));
    put16(d, 126, (uint16_t)(int16_t)clampi(load, -1193, 1193));
    d->t[122] = fabs(goal - d->pos) > 1.0;
  }
}

static double goal_of(const device *d) {
  return d->kind == MX28 ? dxl_get16(d->t + 30) : (double)(int32_t)dxl_get32(d->t + 116);
}

/* --sim-id: the commands to the simulated robot (when `send`), its state into the registers. */
static void update_sim(int send) {
  if (send) {
    for (int i = 0; i < ndev; i++) {
      device *d = &dev[i];
      if (d->servo < 0) continue;
      int mx = d->kind == MX28;
      /* hardness: the registers dcm_op writes for it (MX torque limit, XM position P gain) */
      dxl_sim_command(&sim, d->servo, goal_of(d), mx ? d->t[24] : d->t[64], dxl_get16(d->t + (mx ? 34 : 84)));
    }
    dxl_sim_flush(&sim);
  }
  dxl_sim_state st;
  dxl_sim_read(&sim, &st);
  for (int i = 0; i < ndev; i++) {
    device *d = &dev[i];
    if (d->servo >= 0) {
      d->pos = st.count[d->servo];
      d->vel = st.count_speed[d->servo];
      put_present(d, goal_of(d), st.load[d->servo] * (d->kind == MX28 ? 1023 : 1193));
    }
  }
  memcpy(gyro, st.gyro, sizeof gyro);
  memcpy(accel, st.accel, sizeof accel);
  buttons = st.buttons;
  for (int i = 0; i < ndev; i++) if (dev[i].kind == CM730 || dev[i].kind == OPENCR) update_board(&dev[i]);
}

/* First-order motion of every servo towards its goal since the last update. */
static void update_motion(double now) {
  double dt = now - last_update;
  last_update = now;
  if (dt <= 0) return;
  if (dt > 0.5) dt = 0.5;
  for (int i = 0; i < ndev; i++) {
    device *d = &dev[i];
    if (d->kind == MX28 || d->kind == XM430) {
      int mx = d->kind == MX28;
      int torque = mx ? d->t[24] : d->t[64];
      double goal = goal_of(d);
      /* no-load speed: MX-28 55 rpm, XM430-W350 46 rpm; moving speed / profile velocity cap */
      double vmax = (mx ? 55.0 : 46.0) / 60.0 * 4096.0;
      if (mx && dxl_get16(d->t + 32)) vmax = fmin(vmax, dxl_get16(d->t + 32) * 0.114 / 60 * 4096);
      if (!mx && dxl_get32(d->t + 112)) vmax = fmin(vmax, dxl_get32(d->t + 112) * 0.229 / 60 * 4096);
      double before = d->pos;
      if (torque) {
        double step = (goal - d->pos) * (1.0 - exp(-dt / tau));
        double lim = vmax * dt;
        if (step > lim) step = lim;
        if (step < -lim) step = -lim;
        d->pos += step;
      }
      d->vel = (d->pos - before) / dt;
      double err = torque ? goal - d->pos : 0;
      put_present(d, goal, err * (mx ? 4 : 2));
    } else {
      update_board(d);
    }
  }
}

/* ---------------------------------------------------------------- timing and faults */

static double now_s(void) { return dxl_now(); }

static void sleep_until(double t) {
  struct timespec ts;
  ts.tv_sec = (time_t)t;
  ts.tv_nsec = (long)((t - (double)ts.tv_sec) * 1e9);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL) == EINTR && !stop) {}
}

static double urand(void) { return (double)rand() / ((double)RAND_MAX + 1.0); }

static double byte_time(void) { return 10.0 / baud; }

static int return_delay_us(device *d) {
  int v = (d->kind == MX28 || d->kind == CM730) ? d->t[5] : d->t[9];
  return 2 * v;
}

/* Output queue: status packets with the time they are due on the wire. */
static uint8_t outbuf[65536];
static size_t outlen;
#define MAXQ 256
static struct { size_t end; double due; } outq[MAXQ];   /* packet ends in outbuf, due times */
static int nq;
static double bus_free;    /* time the (emulated) half-duplex bus is free */

static void emit(device *d, uint8_t error, const uint8_t *data, size_t n) {
  if (d->dead) return;
  if (p_drop > 0 && urand() < p_drop) { n_dropped++; return; }
  uint8_t pk[DXL_MAX_PACKET];
  int len = dxl_build_status(protocol, d->id, error, data, n, pk, sizeof pk);
  if (len <= 0) return;
  if (p_corrupt > 0 && urand() < p_corrupt) {
    int at = 2 + rand() % (len - 2);
    pk[at] ^= (uint8_t)(1 + rand() % 255);
    n_corrupted++;
  }
  if (timing) {
    /* the answer starts after the return delay and occupies the bus for len byte times */
    double start = bus_free + return_delay_us(d) * 1e-6;
    bus_free = start + len * byte_time();
  }
  if (outlen + (size_t)len <= sizeof outbuf && nq < MAXQ) {
    memcpy(outbuf + outlen, pk, (size_t)len);
    outlen += (size_t)len;
    outq[nq].end = outlen;
    outq[nq].due = bus_free;
    nq++;
    n_tx++;
  }
}

/* ---------------------------------------------------------------- instructions */

static int status_level(device *d) {
  return (d->kind == XM430) ? d->t[68] : d->t[16];
}

static uint8_t err_access(void) { return protocol == 1 ? DXL1_ERR_RANGE : DXL2_ERR_ACCESS; }
static uint8_t err_inst(void) { return protocol == 1 ? DXL1_ERR_INSTRUCTION : DXL2_ERR_INSTRUCTION; }

static void do_read(device *d, int addr, int len, int reply) {
  if (addr < 0 || len <= 0 || addr + len > TABLE) { if (reply) emit(d, err_access(), NULL, 0); return; }
  if (reply) emit(d, 0, d->t + addr, (size_t)len);
}

static double wall_s(void) {
  struct timespec ts;
  clock_gettime(CLOCK_REALTIME, &ts);
  return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* --trace: a servo's goal, torque enable and hardness registers (MX torque limit, XM P gain) */
typedef struct { long goal; int torque, hard; } servo_regs;
static servo_regs regs_of(const device *d) {
  servo_regs r = { 0, 0, 0 };
  if (d->kind == MX28) { r.goal = dxl_get16(d->t + 30); r.torque = d->t[24]; r.hard = dxl_get16(d->t + 34); }
  else if (d->kind == XM430) { r.goal = (int32_t)dxl_get32(d->t + 116); r.torque = d->t[64]; r.hard = dxl_get16(d->t + 84); }
  return r;
}
static void trace_change(const device *d, servo_regs was) {
  servo_regs now = regs_of(d);
  if (now.torque != was.torque) fprintf(trace, "%.6f %d torque %d\n", wall_s(), d->id, now.torque);
  if (now.hard != was.hard) fprintf(trace, "%.6f %d hardness %d\n", wall_s(), d->id, now.hard);
  if (now.goal != was.goal) goals_changed++;
}

static void do_write(device *d, int addr, const uint8_t *data, int len, int reply) {
  int ok = addr >= 0 && len > 0 && addr + len <= TABLE && writable(d->kind, addr, len);
  if (ok) {
    servo_regs was = regs_of(d);
    memcpy(d->t + addr, data, (size_t)len);
    /* a new goal while torque is off makes the servo hold where it is (as the real ones) */
    if (trace) trace_change(d, was);
  }
  if (reply && status_level(d) >= 2) emit(d, ok ? 0 : err_access(), NULL, 0);
}

static void handle_packet(const dxl_packet *p);
static void handle(const dxl_packet *p) {
  goals_changed = 0;
  handle_packet(p);
  if (trace && goals_changed) fprintf(trace, "%.6f goals %d\n", wall_s(), goals_changed);
}

static void handle_packet(const dxl_packet *p) {
  n_rx++;
  if (sim_mode) update_sim(0);
  else update_motion(now_s());
  const uint8_t *a = p->params;
  int n = p->nparams;
  int bcast = p->id == DXL_BROADCAST_ID;
  device *d = bcast ? NULL : find(p->id);
  if (!bcast && !d) return;
  int w = protocol == 1 ? 1 : 2;   /* address width */
  switch (p->instruction) {
  case DXL_INST_PING:
    if (bcast) { for (int i = 0; i < ndev; i++) { uint8_t m[3] = { dev[i].t[0], dev[i].t[1], protocol == 1 ? 0 : dev[i].t[6] };
                                                  emit(&dev[i], 0, m, protocol == 1 ? 0 : 3); } }
    else { uint8_t m[3] = { d->t[0], d->t[1], d->t[6] }; emit(d, 0, m, protocol == 1 ? 0 : 3); }
    break;
  case DXL_INST_READ:
    if (bcast || n != 2 * w) { if (d) emit(d, err_inst(), NULL, 0); break; }
    do_read(d, w == 1 ? a[0] : dxl_get16(a), w == 1 ? a[1] : dxl_get16(a + 2), 1);
    break;
  case DXL_INST_WRITE:
    if (n < w + 1) { if (d) emit(d, err_inst(), NULL, 0); break; }
    if (bcast) for (int i = 0; i < ndev; i++) do_write(&dev[i], w == 1 ? a[0] : dxl_get16(a), a + w, n - w, 0);
    else do_write(d, w == 1 ? a[0] : dxl_get16(a), a + w, n - w, 1);
    break;
  case DXL_INST_SYNC_WRITE: {
    if (!bcast || n < 2 * w) break;
    int addr = w == 1 ? a[0] : dxl_get16(a), len = w == 1 ? a[1] : dxl_get16(a + 2);
    for (int k = 2 * w; len > 0 && k + 1 + len <= n; k += 1 + len) {
      device *t = find(a[k]);
      if (t) do_write(t, addr, a + k + 1, len, 0);
    }
    break;
  }
  case DXL_INST_SYNC_READ: {
    if (protocol != 2 || !bcast || n < 4) break;
    int addr = dxl_get16(a), len = dxl_get16(a + 2);
    for (int k = 4; k < n; k++) { device *t = find(a[k]); if (t) do_read(t, addr, len, 1); }
    break;
  }
  case DXL_INST_BULK_READ:
    if (!bcast) break;
    if (protocol == 1) {
      for (int k = 1; k + 2 < n; k += 3) { device *t = find(a[k + 1]); if (t) do_read(t, a[k + 2], a[k], 1); }
    } else {
      for (int k = 0; k + 4 < n; k += 5) {
        device *t = find(a[k]);
        if (t) do_read(t, dxl_get16(a + k + 1), dxl_get16(a + k + 3), 1);
      }
    }
    break;
  default:
    if (d) emit(d, err_inst(), NULL, 0);
  }
}

/* ---------------------------------------------------------------- commands on stdin */

static void command(char *line) {
  char cmd[32];
  double x, y, z;
  int v;
  if (sscanf(line, "%31s", cmd) != 1) return;
  if (!strcmp(cmd, "button") && sscanf(line, "%*s %d", &v) == 1) buttons = v;
  else if (!strcmp(cmd, "gyro") && sscanf(line, "%*s %lf %lf %lf", &x, &y, &z) == 3) { gyro[0] = x; gyro[1] = y; gyro[2] = z; }
  else if (!strcmp(cmd, "accel") && sscanf(line, "%*s %lf %lf %lf", &x, &y, &z) == 3) { accel[0] = x; accel[1] = y; accel[2] = z; }
  else if (!strcmp(cmd, "dead") && sscanf(line, "%*s %d", &v) == 1) { device *d = find((uint8_t)v); if (d) d->dead = 1; }
  else if (!strcmp(cmd, "alive") && sscanf(line, "%*s %d", &v) == 1) { device *d = find((uint8_t)v); if (d) d->dead = 0; }
  else if (!strcmp(cmd, "corrupt") && sscanf(line, "%*s %lf", &x) == 1) p_corrupt = x;
  else if (!strcmp(cmd, "drop") && sscanf(line, "%*s %lf", &x) == 1) p_drop = x;
  else if (!strcmp(cmd, "quit")) stop = 1;
  else if (!strcmp(cmd, "stats")) {
    printf("rx %lu tx %lu dropped %lu corrupted %lu bad %lu\n", n_rx, n_tx, n_dropped, n_corrupted, n_bad);
    for (int i = 0; i < ndev; i++) {
      device *d = &dev[i];
      if (d->kind == MX28) printf("servo %d goal %d pos %d torque %d torque_limit %d\n", d->id,
                                  dxl_get16(d->t + 30), dxl_get16(d->t + 36), d->t[24], dxl_get16(d->t + 34));
      else if (d->kind == XM430) printf("servo %d goal %d pos %d torque %d\n", d->id,
                                        (int32_t)dxl_get32(d->t + 116), (int32_t)dxl_get32(d->t + 132), d->t[64]);
    }
    printf("end\n");
    fflush(stdout);
  }
}

/* ---------------------------------------------------------------- main */

static void on_signal(int s) { (void)s; stop = 1; }

/* --ids A-B: both ends strict, inside the unicast ids */
typedef struct { long lo, hi; int given; } id_range;
static int parse_ids(const char *v, void *out, char *err, size_t errlen) {
  id_range *r = out;
  char lo[16], hi[16];
  const char *dash = strchr(v, '-');
  if (!dash || dash == v || (size_t)(dash - v) >= sizeof lo || strlen(dash + 1) >= sizeof hi) {
    snprintf(err, errlen, "'%s' is not A-B", v);
    return -EINVAL;
  }
  snprintf(lo, sizeof lo, "%.*s", (int)(dash - v), v);
  snprintf(hi, sizeof hi, "%s", dash + 1);
  if (dcm_args_long(lo, 0, DXL_MAX_ID, &r->lo, err, errlen) < 0 || dcm_args_long(hi, r->lo, DXL_MAX_ID, &r->hi, err, errlen) < 0)
    return -EINVAL;
  r->given = 1;
  return 0;
}

/* --dead ID, once per servo */
#define MAXDEAD 64
typedef struct { long id[MAXDEAD]; int n; } id_list;
static int parse_dead(const char *v, void *out, char *err, size_t errlen) {
  id_list *l = out;
  long id;
  if (dcm_args_long(v, 0, DXL_MAX_ID, &id, err, errlen) < 0) return -EINVAL;
  if (l->n < MAXDEAD) l->id[l->n++] = id;
  return 0;
}

int main(int argc, char **argv) {
  const char *link_path = NULL, *robot = NULL, *trace_path = NULL;
  id_range ids = { 1, 20, 0 };
  id_list dead = { { 0 }, 0 };
  int use_stdin = 0, realtime = 0, sim_id = 0, baud_opt = 0;
  long seed = 1;
  const dcm_opt opts[] = {
    { "--link", DCM_OPT_STRING, &link_path, 0, 0, "PATH", "a symlink to the pseudo-terminal", NULL, 0 },
    { "--robot", DCM_OPT_STRING, &robot, 0, 0, "NAME", "serve that body's bus 1 (default: $ROBOT's; sets ROBOT)", NULL, 0 },
    { "--protocol", DCM_OPT_INT, &protocol, 1, 2, "1|2", "a generic chain instead of the body: 1 DARwIn-OP, 2 OP3", NULL, 0 },
    { "--ids", DCM_OPT_FUNC, &ids, 0, 0, "A-B", "the generic chain's servo ids (default 1-20; protocol 1 unless --protocol)",
      parse_ids, 0 },
    { "--baud", DCM_OPT_INT, &baud_opt, 9600, 4500000, "N", "bits/s of the timing model (default: the bus's, or 1000000)",
      NULL, 0 },
    { "--timing", DCM_OPT_FLAG, &timing, 0, 0, NULL, "answers take their wire time and return delay", NULL, 0 },
    { "--drop", DCM_OPT_DOUBLE, &p_drop, 0, 1, "P", "probability of no answer", NULL, 0 },
    { "--corrupt", DCM_OPT_DOUBLE, &p_corrupt, 0, 1, "P", "probability of one flipped byte in an answer", NULL, 0 },
    { "--delay", DCM_OPT_DOUBLE, &extra_delay, 0, 10, "S", "extra latency before every answer", NULL, 0 },
    { "--dead", DCM_OPT_FUNC, &dead, 0, 0, "ID", "a servo that never answers; repeatable", parse_dead, 0 },
    { "--tau", DCM_OPT_DOUBLE, &tau, 1e-6, 100, "S", "the servos' time constant (default 0.03)", NULL, 0 },
    { "--seed", DCM_OPT_LONG, &seed, 0, 4294967295.0, "N", "seed of the faults' random numbers", NULL, 0 },
    { "--stdin", DCM_OPT_FLAG, &use_stdin, 0, 0, NULL, "read commands from stdin (see dxl_emulator.c)", NULL, 0 },
    { "--realtime", DCM_OPT_FLAG, &realtime, 0, 0, NULL, "SCHED_FIFO, to answer on time on a loaded machine", NULL, 0 },
    { "--quiet", DCM_OPT_FLAG, &quiet, 0, 0, NULL, "no warnings and no closing stats", NULL, 0 },
    { "--sim-id", DCM_OPT_INT, &sim_id, 1, INT_MAX, "N", "the sim DCM's robot N behind the body's devices", NULL, 0 },
    { "--trace", DCM_OPT_STRING, &trace_path, 0, 0, "FILE", "what the servos receive, a line per change", NULL, 0 },
    DCM_OPT_END,
  };
  dcm_args("dxl_emulator", "Platforms/OP/emulator/dxl_emulator", opts, argc, argv);
  if (robot) setenv("ROBOT", robot, 1);
  sim_mode = sim_id > 0;
  const int generic = !sim_mode && (protocol || ids.given);
  if (sim_mode && (protocol || ids.given)) {
    fprintf(stderr, "dxl_emulator: --sim-id serves the body's devices: --protocol and --ids do not apply\n");
    return 2;
  }
  if (trace_path) {
    if (!(trace = fopen(trace_path, "w"))) {
      fprintf(stderr, "dxl_emulator: --trace %s: %s\n", trace_path, strerror(errno));
      return 2;
    }
    setvbuf(trace, NULL, _IOLBF, 0);   /* a line each: readable while the emulator runs */
  }
  srand((unsigned)seed);
  if (realtime) {   /* behave like hardware: answer on time even on a loaded machine */
    struct sched_param sp = { .sched_priority = 30 };
    if (sched_setscheduler(0, SCHED_FIFO, &sp) != 0 && !quiet)
      fprintf(stderr, "dxl_emulator: no real-time priority (%s): timing may slip\n", strerror(errno));
  }
  static op_body body;
  const op_busdef *bus = NULL;
  char err[512];
  if (sim_mode) {
    if (dxl_sim_open(&sim, sim_id, err, sizeof err) < 0) {
      fprintf(stderr, "dxl_emulator: --sim-id %d: %s\n", sim_id, err);
      return 1;
    }
    bus = sim.bus;
  } else if (!generic) {
    if (dxl_body_load(&body, NULL, err, sizeof err) < 0) {
      fprintf(stderr, "dxl_emulator: %s (--protocol 1|2: a generic chain instead)\n", err);
      return 1;
    }
    bus = &body.bus[0];
  }
  if (bus) {
    protocol = bus->protocol;
    if (!baud_opt) baud_opt = bus->baud;
    for (int i = 0; i < bus->nservo && ndev < MAXDEV - 1; i++) {
      add_device(bus->servo[i].model->family == OP_MX ? MX28 : XM430, bus->servo[i].id);
      if (sim_mode) dev[ndev - 1].servo = i;
    }
    if (bus->has_board) add_device(bus->board.model->kind == OP_CM730 ? CM730 : OPENCR, bus->board.id);
  } else {
    if (!protocol) protocol = 1;
    for (long id = ids.lo; id <= ids.hi && ndev < MAXDEV - 1; id++) add_device(protocol == 1 ? MX28 : XM430, (uint8_t)id);
    add_device(protocol == 1 ? CM730 : OPENCR, 200);
  }
  if (baud_opt) baud = baud_opt;
  for (int k = 0; k < dead.n; k++) { device *d = find((uint8_t)dead.id[k]); if (d) d->dead = 1; }

  int m = posix_openpt(O_RDWR | O_NOCTTY);
  if (m < 0 || grantpt(m) != 0 || unlockpt(m) != 0) { perror("dxl_emulator: posix_openpt"); return 1; }
  const char *sname = ptsname(m);
  char slave_name[128];
  snprintf(slave_name, sizeof slave_name, "%s", sname ? sname : "");
  /* keep a slave fd open: raw mode, and no hang-up when a client closes and reopens */
  int s = open(slave_name, O_RDWR | O_NOCTTY);
  if (s < 0) { perror("dxl_emulator: open slave"); return 1; }
  struct termios t;
  tcgetattr(s, &t);
  cfmakeraw(&t);
  cfsetspeed(&t, B1000000);
  tcsetattr(s, TCSANOW, &t);
  if (link_path) {
    unlink(link_path);
    if (symlink(slave_name, link_path) != 0) { fprintf(stderr, "dxl_emulator: symlink %s: %s\n", link_path, strerror(errno)); return 1; }
  }
  signal(SIGINT, on_signal);
  signal(SIGTERM, on_signal);
  signal(SIGPIPE, SIG_IGN);
  fcntl(m, F_SETFL, fcntl(m, F_GETFL) | O_NONBLOCK);
  fprintf(stderr, "dxl_emulator: ready %s%s%s (%s%s, protocol %d, %d devices, %s)\n", slave_name,
          link_path ? " -> " : "", link_path ? link_path : "", bus ? (sim_mode ? sim.body.name : body.name) : "generic chain",
          bus ? " bus 1" : "", protocol, ndev, timing ? "timing model on" : "no timing model");
  last_update = now_s();
  if (sim_mode) update_sim(0);
  else update_motion(last_update);

  static uint8_t in[8192];
  size_t inlen = 0;
  static dxl_packet pkt;
  char line[256];
  size_t linelen = 0;
  while (!stop) {
    struct pollfd pf[2] = { { m, POLLIN, 0 }, { 0, POLLIN, 0 } };
    int nf = use_stdin ? 2 : 1;
    int r = poll(pf, (nfds_t)nf, 50);
    if (r < 0) { if (errno == EINTR) continue; break; }
    if (use_stdin && (pf[1].revents & (POLLIN | POLLHUP))) {
      char c;
      ssize_t k = read(0, &c, 1);
      if (k <= 0) use_stdin = 0;
      else if (c == '\n') { line[linelen] = 0; command(line); linelen = 0; }
      else if (linelen + 1 < sizeof line) line[linelen++] = c;
    }
    if (!(pf[0].revents & POLLIN)) {
      if (sim_mode) update_sim(0);   /* no commands: the sim DCM's watchdog sees a silent bus */
      else update_motion(now_s());
      continue;
    }
    ssize_t k = read(m, in + inlen, sizeof in - inlen);
    if (k <= 0) continue;
    double arrived = now_s();
    inlen += (size_t)k;
    for (;;) {
      size_t used = 0;
      int pr = dxl_parse(protocol, 0, in, inlen, 0, &pkt, &used);
      if (pr < 0) n_bad++;
      if (pr == 1) {
        outlen = 0;
        nq = 0;
        if (timing) {
          /* on a real bus the request occupies it for its bytes: answers start after that */
          bus_free = (bus_free > arrived ? bus_free : arrived) + (double)used * byte_time();
        }
        handle(&pkt);
        if (sim_mode) update_sim(1);
        /* each answer leaves when the emulated bus has carried it (all at once without
         * the timing model), after the extra --delay */
        size_t off = 0;
        for (int q = 0; q < nq && !stop; q++) {
          if (timing || extra_delay > 0) sleep_until((timing ? outq[q].due : arrived) + extra_delay);
          while (off < outq[q].end && !stop) {
            size_t upto = (timing || extra_delay > 0) ? outq[q].end : outlen;
            ssize_t w = write(m, outbuf + off, upto - off);
            if (w > 0) off += (size_t)w;
            else if (w < 0 && errno != EAGAIN && errno != EINTR) { off = outlen; break; }
            else { struct pollfd po = { m, POLLOUT, 0 }; poll(&po, 1, 10); }
          }
        }
      }
      if (used) { memmove(in, in + used, inlen - used); inlen -= used; }
      if (pr == 0 || (pr != 1 && used == 0)) break;
      if (inlen == 0) break;
    }
    if (inlen == sizeof in) inlen = 0;
  }
  if (link_path) unlink(link_path);
  if (!quiet) fprintf(stderr, "dxl_emulator: stopped (rx %lu tx %lu dropped %lu corrupted %lu bad %lu)\n",
                      n_rx, n_tx, n_dropped, n_corrupted, n_bad);
  close(s);
  close(m);
  if (sim_mode) dxl_sim_close(&sim);
  if (trace) fclose(trace);
  return 0;
}
