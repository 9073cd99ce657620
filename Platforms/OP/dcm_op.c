/* dcm_op: the DCM of the OP platform: Dynamixel buses <-> dcm.sensor / dcm.actuator / dcm.stats.
 * DARwIn-OP (MX-28 + CM-730, protocol 1.0) or ROBOTIS OP3 (XM430 + OpenCR, protocol 2.0), or any
 * body whose robot.lua has a device table (op_devices.h).
 *
 *   PLATFORM=OP [ROBOT=darwin] ./run_dcm [--robot NAME (sets ROBOT)] [--port PATH (bus 1)] [--rate HZ]
 *                                        [--baud N] [--cycles N] [--timeout-margin S] [--quiet]
 *
 * A driver of the DCM library (Modules/dcm), which paces the cycles at absolute deadlines, checks
 * the commands (NaN, hardness, the watchdog's safe pose) and writes the blocks. Lifecycle:
 * configure (robot.lua with its devices, Config/platforms/OP/dcm.lua; no I/O) -> open the ports
 * (retried) -> enable: ping every servo, read the pose, hold it -> each cycle one sync write and
 * one bulk read per bus (op_bus.h).
 */
#include "dcm/args.h"
#include "dcm/dcm.h"
#include "op_bus.h"

#include <errno.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct op_dcm {
  /* options */
  const char *port;
  double rate, margin;
  int baud;
  /* config */
  op_body body;
  op_bus_settings set;
  double start_hardness, watchdog, safe_hardness, stall_cpu;
  int latency_timer, rt_priority, stall_cycles;
  /* state */
  int prepared;
  op_bus bus[OP_BUS_MAX];
  op_state st;
  double last;                          /* clock of the previous cycle */
  uint64_t win_bytes0;                  /* bus bytes at the start of the statistics window */
  double bytes_per_cycle;
} op_dcm;

static uint64_t bus_bytes(const op_dcm *o) {
  uint64_t n = 0;
  for (int k = 0; k < o->body.nbus; k++) n += o->bus[k].bus.stats.tx_bytes + o->bus[k].bus.stats.rx_bytes;
  return n;
}

/* ---------------------------------------------------------------- the driver */

static int op_configure(void *hw, dcm *d, char *err, size_t n) {
  op_dcm *o = (op_dcm *)hw;
  dcm_config *rc = NULL, *pc = NULL;
  int r = dcm_config_load("robot", NULL, "OP", &rc, err, n);
  if (r == 0) r = op_body_load(rc, &o->body, err, n);
  if (r == 0) r = dcm_config_load("dcm", dcm_config_robot(rc), "OP", &pc, err, n);
  if (r == 0) r = dcm_config_num(pc, "start_hardness", &o->start_hardness, err, n);
  if (r == 0) r = dcm_config_num(pc, "watchdog", &o->watchdog, err, n);
  if (r == 0) r = dcm_config_int(pc, "stall_cycles", &o->stall_cycles, err, n);
  if (r == 0) r = dcm_config_num(pc, "stall_cpu", &o->stall_cpu, err, n);
  if (r == 0) r = dcm_config_num(pc, "safe_hardness", &o->safe_hardness, err, n);
  if (r == 0) r = dcm_config_num(pc, "retry_period", &o->set.retry_period, err, n);
  if (r == 0) r = dcm_config_num(pc, "timeout_margin", &o->set.timeout_margin, err, n);
  if (r == 0) r = dcm_config_int(pc, "dead_after", &o->set.dead_after, err, n);
  if (r == 0) r = dcm_config_int(pc, "latency_timer", &o->latency_timer, err, n);
  if (r == 0) r = dcm_config_int(pc, "rt_priority", &o->rt_priority, err, n);
  dcm_config_free(rc);
  dcm_config_free(pc);
  if (r < 0) return -EINVAL;
  if (o->port) snprintf(o->body.bus[0].port, sizeof o->body.bus[0].port, "%s", o->port);
  if (o->baud > 0)
    for (int k = 0; k < o->body.nbus; k++) o->body.bus[k].baud = o->baud;
  if (o->margin >= 0) o->set.timeout_margin = o->margin;
  d->nrobots = 1;
  d->robot[0].id = shm_robot_id();
  d->robot[0].nj = o->body.nj;
  snprintf(d->robot[0].name, sizeof d->robot[0].name, "%s", o->body.name);
  d->period = o->rate > 0 ? 1.0 / o->rate : o->body.period;
  d->watchdog = o->watchdog;
  d->stall_cycles = o->stall_cycles;
  d->stall_cpu = o->stall_cpu;
  d->safe_hardness = o->safe_hardness;
  d->start_hardness = o->start_hardness;
  d->simulated = 0;
  for (int k = 0; k < o->body.nbus; k++) op_bus_init(&o->bus[k], &o->body, k, o->set);
  return 0;
}

/* Once, before the ports open: USB latency timers, real-time priority, what the buses carry. */
static void prepare(op_dcm *o, const dcm *d) {
  char err[256];
  const size_t n = sizeof err;
  /* the USB adapters' latency timers (skipped cleanly where there is none) and the priority */
  dxl_usb_info usb[8];
  const int nusb = dxl_usb_find(usb, 8, err, n);
  for (int k = 0; k < nusb; k++)
    dcm_log(d, "USB adapter %04x:%04x %s (bus %d, device %d)", usb[k].vendor, usb[k].product, usb[k].name, usb[k].bus,
            usb[k].address);
  for (int k = 0; k < o->body.nbus; k++) {
    const int nset = dxl_usb_set_latency(o->body.bus[k].port, o->latency_timer, err, n);
    if (nset > 0) dcm_log(d, "latency timer %d ms set on %d adapter(s)", o->latency_timer, nset);
  }
  if (o->rt_priority > 0) {
    struct sched_param sp = { .sched_priority = o->rt_priority };
    if (sched_setscheduler(0, SCHED_FIFO, &sp) != 0)
      dcm_log(d, "no real-time priority %d (%s): running as a normal process", o->rt_priority, strerror(errno));
  }
  dcm_log(d, "%s: %d joints at %.0f Hz on %d bus(es)", o->body.name, o->body.nj, 1.0 / d->period, o->body.nbus);
  for (int k = 0; k < o->body.nbus; k++) {
    const op_busdef *bd = &o->body.bus[k];
    int tx, rx, wire = op_bus_wire_bytes(&o->bus[k], &tx, &rx);
    dcm_log(d, "bus %d: %s at %d baud, protocol %d.0, %d servos%s%s", k + 1, bd->port, bd->baud, bd->protocol,
            bd->nservo, bd->has_board ? " and the " : "", bd->has_board ? bd->board.model->name : "");
    dcm_log(d, "wire per cycle: %d bytes (sent %d, answers %d) = %.1f ms at %d baud, bus-limited %.0f Hz", wire, tx, rx,
            wire * 10e3 / bd->baud, bd->baud, bd->baud / (10.0 * wire));
  }
}

static int op_open(void *hw, dcm *d, char *err, size_t n) {
  op_dcm *o = (op_dcm *)hw;
  if (!o->prepared) prepare(o, d);
  o->prepared = 1;
  /* every bus or none: a DCM that drives half a robot is no use */
  for (int k = 0; k < o->body.nbus; k++)
    if (!o->bus[k].port && op_bus_open(&o->bus[k], d, err, n) < 0) return -EAGAIN;
  return 0;
}

static int op_enable(void *hw, dcm *d, char *err, size_t n) {
  op_dcm *o = (op_dcm *)hw;
  int found = 0;
  for (int k = 0; k < o->body.nbus; k++) found += op_bus_probe(&o->bus[k], d, &o->st);
  dcm_log(d, "%d of %d servos answer", found, o->body.nj);
  o->last = d->pacer.clock.now(d->pacer.clock.ctx);
  o->win_bytes0 = bus_bytes(o);
  (void)err;
  (void)n;
  return 0;
}

static void op_write(void *hw, dcm *d) {
  op_dcm *o = (op_dcm *)hw;
  for (int k = 0; k < o->body.nbus; k++) op_bus_write(&o->bus[k], d, &d->robot[0].cmd, d->now);
}

static void op_read(void *hw, dcm *d) {
  op_dcm *o = (op_dcm *)hw;
  const double dt = d->now - o->last;
  o->last = d->now;
  for (int k = 0; k < o->body.nbus; k++) op_bus_read(&o->bus[k], d, &o->st, d->now, dt);
}

static void op_publish(void *hw, dcm *d, int r, const dcm_blk_dcm_sensor *s) {
  const op_dcm *o = (const op_dcm *)hw;
  const op_state *st = &o->st;
  const size_t nd = sizeof(double) * (size_t)d->robot[r].nj;
  memcpy(s->position, st->pos, nd);
  memcpy(s->velocity, st->vel, nd);
  memcpy(s->load, st->load, nd);
  memcpy(s->temperature, st->temp, nd);
  memcpy(s->gyro, st->gyro, sizeof st->gyro);
  memcpy(s->accelerometer, st->acc, sizeof st->acc);
  memcpy(s->angle, st->angle, sizeof st->angle);
  s->button[0] = st->button[0];
  s->button[1] = st->button[1];
  *s->battery = st->batt;
}

static void op_stats(void *hw, dcm *d, int r, const dcm_blk_dcm_stats *s) {
  op_dcm *o = (op_dcm *)hw;
  const op_state *st = &o->st;
  uint32_t rx = 0;
  for (int k = 0; k < o->body.nbus; k++) {
    const dxl_bus_stats *b = &o->bus[k].bus.stats;
    rx += (uint32_t)(b->corrupt + b->misaddressed + b->out_of_order);
  }
  *s->rx_errors = rx;
  if (d->pacer.closed && d->pacer.window_cycles > 0) {
    const uint64_t bytes = bus_bytes(o);
    o->bytes_per_cycle = (double)(bytes - o->win_bytes0) / d->pacer.window_cycles;
    o->win_bytes0 = bytes;
  }
  *s->bytes_per_cycle = o->bytes_per_cycle;
  const size_t nu = sizeof(uint32_t) * (size_t)d->robot[r].nj;
  memcpy(s->servo_errors, st->serr, nu);
  memcpy(s->servo_timeouts, st->stimeout, nu);
  memcpy(s->servo_dead, st->dead, sizeof(int32_t) * (size_t)d->robot[r].nj);
}

static void op_close(void *hw, dcm *d) {
  op_dcm *o = (op_dcm *)hw;
  for (int k = 0; k < o->body.nbus; k++) {
    const dxl_bus_stats *b = &o->bus[k].bus.stats;
    if (o->bus[k].port)
      dcm_log(d, "bus %d stopped after %u cycles (%u missed; %llu corrupt, %llu timeouts, %llu misaddressed)", k + 1,
              d->pacer.cycles, d->pacer.missed, (unsigned long long)b->corrupt, (unsigned long long)b->timeouts,
              (unsigned long long)b->misaddressed);
    op_bus_close(&o->bus[k]);   /* the servos keep holding where they are */
  }
}

/* ---------------------------------------------------------------- main */

int main(int argc, char **argv) {
  static op_dcm O;
  static dcm D;
  O.margin = -1;
  D.name = "dcm_op";
  D.max_cycles = -1;
  const char *robot = NULL;
  const dcm_opt opts[] = {
    { "--robot", DCM_OPT_STRING, &robot, 0, 0, "NAME", "the body (sets ROBOT)", NULL, 0 },
    { "--port", DCM_OPT_STRING, &O.port, 0, 0, "PATH", "serial port of bus 1 (default: robot.lua's)", NULL, 0 },
    { "--rate", DCM_OPT_DOUBLE, &O.rate, 1, 1000, "HZ", "control rate (default: robot.lua's period)", NULL, 0 },
    { "--baud", DCM_OPT_INT, &O.baud, 9600, 4500000, "N", "every bus's baud rate (default: robot.lua's)", NULL, 0 },
    DCM_OPT_CYCLES(&D, "stop after N cycles (default: at a signal)"),
    { "--timeout-margin", DCM_OPT_DOUBLE, &O.margin, 0, 1, "S",
      "s added to each answer's wire time before a timeout (default: dcm.lua's)", NULL, 0 },
    DCM_OPT_QUIET(&D),
    DCM_OPT_END,
  };
  dcm_args(D.name, "PLATFORM=OP ./run_dcm", opts, argc, argv);
  if (robot) setenv("ROBOT", robot, 1);
  static const dcm_driver drv = { op_configure, op_open, op_enable, op_write, op_read, op_publish,
                                  op_stats, NULL, NULL, op_close };
  return dcm_run(&D, &drv, &O);
}
