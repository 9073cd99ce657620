/* dcm_hubo: the DCM of the Hubo platform: Hubo2+ motor boards on SocketCAN buses <-> dcm.sensor /
 * dcm.actuator / dcm.stats.
 *
 *   PLATFORM=Hubo ROBOT=hubo2plus ./run_dcm [--robot NAME (sets ROBOT)] [--iface BUS=NAME]...
 *                                           [--rate HZ] [--cycles N] [--quiet]
 *
 * A driver of the DCM library (Modules/dcm), which paces the cycles at absolute deadlines (200 Hz:
 * the body's period), checks the commands (NaN, hardness, the watchdog's safe pose) and writes the
 * blocks. Lifecycle: configure (robot.lua, can.lua, Config/platforms/Hubo/dcm.lua; no I/O) -> open
 * one raw CAN socket per bus (retried) -> enable: the bring-up (hubo_bus.h) -> each cycle
 * references and requests out (write), replies in until the reply window closes (read).
 * Statistics per bus (frames, bits, load, errors) and per board (timeouts, faults, status, dead)
 * in dcm.stats. Torque mode maps to the boards' current mode (hubo_bus.h).
 */
#include "dcm/args.h"
#include "dcm/dcm.h"
#include "hubo_bus.h"

#include <errno.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct hubo_dcm {
  hubo h;
  double rate;
  const char *iface[HT_BUS_MAX];
  double start_hardness, watchdog, safe_hardness, stall_cpu;
  int rt_priority, stall_cycles;
  int prepared;                         /* the first open: priority set, the plan logged */
  /* statistics window */
  uint64_t frames0[HT_BUS_MAX], bits0[HT_BUS_MAX];
  double frames_pc[HT_BUS_MAX], bits_pc[HT_BUS_MAX], load[HT_BUS_MAX];
} hubo_dcm;

static int load_settings(const dcm_config *c, hubo_dcm *o, char *err, size_t n) {
  hubo_settings *s = &o->h.set;
  struct { const char *key; double *v; } nums[] = {
    { "start_hardness", &o->start_hardness }, { "watchdog", &o->watchdog }, { "safe_hardness", &o->safe_hardness },
    { "stall_cpu", &o->stall_cpu }, { "compliant_below", &s->compliant_below }, { "retry_period", &s->retry_period },
    { "reply_window", &s->reply_window }, { "startup_hold", &s->startup_hold },
    { "home_timeout", &s->home_timeout }, { "reopen_period", &s->reopen_period },
  };
  for (size_t k = 0; k < sizeof nums / sizeof nums[0]; k++)
    if (dcm_config_num(c, nums[k].key, nums[k].v, err, n) < 0) return -EINVAL;
  struct { const char *key; int *v; } ints[] = {
    { "dead_after", &s->dead_after }, { "status_every", &s->status_every }, { "current_every", &s->current_every },
    { "rt_priority", &o->rt_priority }, { "stall_cycles", &o->stall_cycles },
  };
  for (size_t k = 0; k < sizeof ints / sizeof ints[0]; k++)
    if (dcm_config_int(c, ints[k].key, ints[k].v, err, n) < 0) return -EINVAL;
  if (dcm_config_bool(c, "home_at_start", &s->home_at_start, err, n) < 0 ||
      dcm_config_bool(c, "enable_at_start", &s->enable_at_start, err, n) < 0)
    return -EINVAL;
  if (!(s->reply_window > 0 && s->reply_window < 1))
    return dcm_config_fail(c, err, n, "reply_window: a fraction of the period between 0 and 1, got %g", s->reply_window);
  if (s->dead_after < 1) return dcm_config_fail(c, err, n, "dead_after: at least 1 cycle, got %d", s->dead_after);
  return 0;
}

/* ---------------------------------------------------------------- the driver */

static int hubo_configure(void *hw, dcm *d, char *err, size_t n) {
  hubo_dcm *o = (hubo_dcm *)hw;
  dcm_config *rc = NULL, *cc = NULL, *pc = NULL, *ac = NULL;
  int r = dcm_config_load("robot", NULL, "Hubo", &rc, err, n);
  if (r == 0) r = dcm_config_load("can", dcm_config_robot(rc), "Hubo", &cc, err, n);
  if (r == 0) r = ht_load(rc, cc, &o->h.t, err, n);
  if (r == 0) r = dcm_config_load("actuators", dcm_config_robot(rc), "Hubo", &ac, err, n);
  if (r == 0) r = ht_load_actuators(rc, ac, &o->h.t, err, n);
  if (r == 0) r = dcm_config_load("dcm", dcm_config_robot(rc), "Hubo", &pc, err, n);
  if (r == 0) r = load_settings(pc, o, err, n);
  dcm_config_free(rc);
  dcm_config_free(cc);
  dcm_config_free(ac);
  dcm_config_free(pc);
  if (r < 0) return -EINVAL;
  for (int b = 0; b < HT_BUS_MAX; b++)
    if (o->iface[b] && b < o->h.t.nbus) snprintf(o->h.t.iface[b], sizeof o->h.t.iface[b], "%s", o->iface[b]);
  d->nrobots = 1;
  d->robot[0].id = shm_robot_id();
  d->robot[0].nj = o->h.t.nj;
  snprintf(d->robot[0].name, sizeof d->robot[0].name, "%s", o->h.t.name);
  /* torque mode for the joints of driven boards with a current path (can.lua torque_constant): the
   * guard clamps their torque to the drive's, within what max_current gives; the others have none */
  for (int k = 0; k < o->h.t.nboard; k++) {
    const ht_board *b = &o->h.t.board[k];
    for (int i = 0; i < b->nch; i++)
      d->robot[0].torque_limit[b->ch[i].joint] = b->active && b->kind == HT_JMC ? ht_torque_limit(&b->ch[i]) : 0;
  }
  d->period = o->rate > 0 ? 1.0 / o->rate : o->h.t.period;
  d->watchdog = o->watchdog;
  d->stall_cycles = o->stall_cycles;
  d->stall_cpu = o->stall_cpu;
  d->safe_hardness = o->safe_hardness;
  d->start_hardness = o->start_hardness;
  d->simulated = 0;
  hubo_setup(&o->h);
  return 0;
}

static int hubo_open_buses(void *hw, dcm *d, char *err, size_t n) {
  hubo_dcm *o = (hubo_dcm *)hw;
  if (!o->prepared) {
    o->prepared = 1;
    if (o->rt_priority > 0) {
      struct sched_param sp = { .sched_priority = o->rt_priority };
      if (sched_setscheduler(0, SCHED_FIFO, &sp) != 0)
        dcm_log(d, "no real-time priority %d (%s): running as a normal process", o->rt_priority, strerror(errno));
    }
    dcm_log(d, "%s: %d joints, %d boards at %.0f Hz on %d bus(es) at %.0f kbit/s", o->h.t.name, o->h.t.nj,
            o->h.t.nboard, 1.0 / d->period, o->h.t.nbus, o->h.t.bitrate / 1000);
  }
  return hubo_open(&o->h, err, n);
}

static int hubo_enable(void *hw, dcm *d, char *err, size_t n) {
  hubo_dcm *o = (hubo_dcm *)hw;
  const int r = hubo_bringup(&o->h, d, err, n);
  for (int b = 0; b < o->h.nbus; b++) {
    o->frames0[b] = o->h.bus[b].tx_frames + o->h.bus[b].rx_frames;
    o->bits0[b] = o->h.bus[b].tx_bits + o->h.bus[b].rx_bits;
  }
  return r;
}

static void hubo_write_cycle(void *hw, dcm *d) {
  hubo_dcm *o = (hubo_dcm *)hw;
  hubo_write(&o->h, d, &d->robot[0].cmd);
}

static void hubo_read_cycle(void *hw, dcm *d) {
  hubo_dcm *o = (hubo_dcm *)hw;
  hubo_read(&o->h, d, d->now + o->h.set.reply_window * d->period);
}

static void hubo_publish(void *hw, dcm *d, int r, const dcm_blk_dcm_sensor *s) {
  const hubo_dcm *o = (const hubo_dcm *)hw;
  const hubo_state *st = &o->h.st;
  const size_t nd = sizeof(double) * (size_t)d->robot[r].nj;
  memcpy(s->position, st->pos, nd);
  memcpy(s->velocity, st->vel, nd);
  memset(s->load, 0, nd);   /* the boards report currents, not torques */
  memcpy(s->temperature, st->temp, nd);
  memcpy(s->gyro, st->gyro, sizeof st->gyro);
  memcpy(s->accelerometer, st->acc, sizeof st->acc);
  memcpy(s->angle, st->angle, sizeof st->angle);
  memcpy(s->foot_force, st->foot, sizeof st->foot);
  memcpy(s->ft, st->ft, sizeof st->ft);
  s->button[0] = s->button[1] = 0;
  *s->battery = st->battery;
}

static void hubo_stats(void *hw, dcm *d, int r, const dcm_blk_dcm_stats *s) {
  hubo_dcm *o = (hubo_dcm *)hw;
  const hubo *h = &o->h;
  if (d->pacer.closed && d->pacer.window_cycles > 0) {
    const double cyc = d->pacer.window_cycles;
    for (int b = 0; b < h->nbus; b++) {
      const uint64_t fr = h->bus[b].tx_frames + h->bus[b].rx_frames, bi = h->bus[b].tx_bits + h->bus[b].rx_bits;
      o->frames_pc[b] = (double)(fr - o->frames0[b]) / cyc;
      o->bits_pc[b] = (double)(bi - o->bits0[b]) / cyc;
      o->load[b] = 100.0 * o->bits_pc[b] / (d->period * h->t.bitrate);
      o->frames0[b] = fr;
      o->bits0[b] = bi;
    }
  }
  uint32_t rx = 0;
  double bits = 0;
  for (int b = 0; b < h->nbus && b < s->n.bus_frames; b++) {
    const hcan_net *net = &h->bus[b].net;
    s->bus_frames[b] = o->frames_pc[b];
    s->bus_bits[b] = o->bits_pc[b];
    s->bus_load[b] = o->load[b];
    s->bus_errors[b] = net->corrupt + net->misaddressed + net->unexpected;
    s->bus_down[b] = h->bus[b].fd < 0;
    rx += s->bus_errors[b];
    bits += o->bits_pc[b];
  }
  *s->rx_errors = rx;
  *s->bytes_per_cycle = bits / 8;
  for (int k = 0; k < h->t.nboard && k < s->n.board_dead; k++) {
    const hcan_board *b = hubo_board(h, k);
    s->board_timeouts[k] = b ? b->timeouts : 0;
    s->board_faults[k] = b ? b->faults : 0;
    s->board_status[k] = b ? (uint32_t)(b->status[0].flags | b->status[0].faults << 8 | b->status[0].limits << 16) : 0;
    s->board_dead[k] = b ? b->dead : 0;
  }
  for (int j = 0; j < d->robot[r].nj; j++) {
    const hcan_board *b = hubo_board(h, h->t.joint_board[j]);
    s->servo_errors[j] = b ? b->faults : 0;
    s->servo_timeouts[j] = b ? b->timeouts : 0;
    s->servo_dead[j] = hubo_joint_down(h, j);   /* also the joints of a board not driven */
  }
  *s->ref_limited = h->ref_limited;
  *s->ref_refused = h->ref_refused;
}

static void hubo_close(void *hw, dcm *d) {
  hubo_dcm *o = (hubo_dcm *)hw;
  hubo_release(&o->h, d);
  for (int b = 0; b < o->h.nbus; b++) {
    const hio_bus *bus = &o->h.bus[b];
    dcm_log(d, "bus %d (%s) stopped after %u cycles (%u missed): %llu frames out, %llu in; %u corrupt, %u misaddressed, "
               "%u unexpected, %u error frames",
            b + 1, bus->iface, d->pacer.cycles, d->pacer.missed, (unsigned long long)bus->tx_frames,
            (unsigned long long)bus->rx_frames, bus->net.corrupt, bus->net.misaddressed, bus->net.unexpected,
            bus->net.error_frames);
    hio_close(&o->h.bus[b]);   /* the boards keep holding their last reference */
  }
}

/* ---------------------------------------------------------------- main */

/* --iface BUS=NAME: bus BUS (1..) on the interface NAME; given once per bus. */
static int parse_iface(const char *v, void *out, char *err, size_t n) {
  const char **iface = (const char **)out;
  const char *eq = strchr(v, '=');
  char bus[16];
  if (!eq || eq == v || (size_t)(eq - v) >= sizeof bus || !eq[1]) {
    snprintf(err, n, "'%s' is not BUS=NAME", v);
    return -EINVAL;
  }
  memcpy(bus, v, (size_t)(eq - v));
  bus[eq - v] = 0;
  long b;
  if (dcm_args_long(bus, 1, HT_BUS_MAX, &b, err, n) < 0) return -EINVAL;
  iface[b - 1] = eq + 1;
  return 0;
}

int main(int argc, char **argv) {
  static hubo_dcm O;
  static dcm D;
  D.name = "dcm_hubo";
  D.max_cycles = -1;
  const char *robot = NULL;
  const dcm_opt opts[] = {
    { "--robot", DCM_OPT_STRING, &robot, 0, 0, "NAME", "the body (sets ROBOT)", NULL, 0 },
    { "--iface", DCM_OPT_FUNC, O.iface, 0, 0, "BUS=NAME", "CAN interface of bus BUS (default: can.lua's); per bus",
      parse_iface, 0 },
    { "--rate", DCM_OPT_DOUBLE, &O.rate, 1, 1000, "HZ", "control rate (default: robot.lua's period)", NULL, 0 },
    DCM_OPT_CYCLES(&D, "stop after N cycles (default: at a signal)"),
    DCM_OPT_QUIET(&D),
    DCM_OPT_END,
  };
  dcm_args(D.name, "PLATFORM=Hubo ./run_dcm", opts, argc, argv);
  if (robot) setenv("ROBOT", robot, 1);
  static const dcm_driver drv = { hubo_configure, hubo_open_buses, hubo_enable, hubo_write_cycle, hubo_read_cycle,
                                  hubo_publish, hubo_stats, NULL, NULL, hubo_close };
  return dcm_run(&D, &drv, &O);
}
