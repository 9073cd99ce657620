/* hubo_bus: the Hubo DCM's bring-up and cycle over its buses (see hubo_bus.h). */
#include "hubo_bus.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define G 9.80665

static hio_bus *bus_of(hubo *h, int k) { return &h->bus[h->t.board[k].bus]; }

const hcan_board *hubo_board(const hubo *h, int k) {
  return h->idx[k] < 0 ? NULL : &h->bus[h->t.board[k].bus].net.b[h->idx[k]];
}

static hcan_board *board(hubo *h, int k) { return (hcan_board *)hubo_board(h, k); }

void hubo_setup(hubo *h) {
  h->nbus = h->t.nbus;
  for (int b = 0; b < h->nbus; b++) hio_init(&h->bus[b], h->t.iface[b]);
  for (int k = 0; k < h->t.nboard; k++) {
    const ht_board *d = &h->t.board[k];
    /* boards not driven (the Hubo2+ neck: formats unknown) are not asked anything */
    h->idx[k] = d->active && d->kind != HT_JMC3 ? hcan_net_add(&h->bus[d->bus].net, ht_hcan_kind(d->kind), d->number) : -1;
  }
  for (int j = 0; j < h->t.nj; j++) h->seeded[j] = 0;
}

int hubo_open(hubo *h, char *err, size_t n) {
  for (int b = 0; b < h->nbus; b++)
    if (h->bus[b].fd < 0 && hio_open(&h->bus[b], err, n) < 0) return -EAGAIN;
  return 0;
}

int hubo_joint_down(const hubo *h, int j) {
  const int k = h->t.joint_board[j];
  const hcan_board *b = hubo_board(h, k);
  return !b || b->dead || h->bus[h->t.board[k].bus].fd < 0;
}

/* Queues a request to board k owing `owe`. */
static void request(hubo *h, int k, const hcan_frame *f, uint32_t owe) {
  hio_bus *b = bus_of(h, k);
  if (b->fd < 0) return;
  hio_queue(b, f);
  hcan_net_owe(&b->net, h->idx[k], owe);
}

static int is_motor(const hubo *h, int k) { return h->idx[k] >= 0 && h->t.board[k].kind == HT_JMC; }

/* Sends what is queued and collects the answers for up to `secs`; then closes the exchange. */
static void exchange(hubo *h, double secs) {
  hio_settle(h->bus, h->nbus, hio_now() + secs);
}

static void end_cycle(hubo *h, int dead_after) {
  for (int b = 0; b < h->nbus; b++) hcan_net_end_cycle(&h->bus[b].net, dead_after);
}

/* Status of every motor board; returns how many answered (their status in the net). */
static int status_sweep(hubo *h, int *answered) {
  int n = 0;
  for (int k = 0; k < h->t.nboard; k++) {
    if (!is_motor(h, k)) continue;
    hcan_frame f;
    hcan_req_status(&f, h->t.board[k].number);
    request(h, k, &f, HCAN_R_STATUS);
  }
  exchange(h, 0.05);
  for (int k = 0; k < h->t.nboard; k++) {
    answered[k] = is_motor(h, k) && !(board(h, k)->owed & HCAN_R_STATUS);
    n += answered[k];
  }
  end_cycle(h, 0);
  return n;
}

static int homed(hubo *h, int k) {
  const hcan_board *b = board(h, k);
  for (int c = 0; c < h->t.board[k].nch; c++)
    if (HCAN_ST_HOME(b->status[h->t.board[k].ch[c].ch < 2 ? h->t.board[k].ch[c].ch : 0]) != HCAN_HOME_OK) return 0;
  return 1;
}

/* Encoder replies of this cycle into positions (and velocities), per board. */
static void take_encoders(hubo *h, int k, double now) {
  const hcan_board *b = board(h, k);
  const ht_board *d = &h->t.board[k];
  for (int c = 0; c < d->nch; c++) {
    const ht_channel *ch = &d->ch[c];
    const int j = ch->joint;
    const double q = ht_counts_to_rad(ch, b->enc[ch->ch < 2 ? ch->ch : 0]);
    const double dt = now - h->enc_time[j];
    h->st.vel[j] = h->enc_time[j] > 0 && dt > 1e-4 ? (q - h->st.pos[j]) / dt : 0;
    h->st.pos[j] = q;
    h->enc_time[j] = now;
    if (!h->seeded[j]) {
      h->ref[j] = q;   /* the first reference is where the joint is */
      h->seeded[j] = 1;
    }
  }
}

int hubo_bringup(hubo *h, dcm *d, char *err, size_t n) {
  int ans[HT_BOARD_MAX];
  int nmotor = 0;
  for (int k = 0; k < h->t.nboard; k++) nmotor += is_motor(h, k);
  const int nans = status_sweep(h, ans);
  dcm_log(d, "%d of %d motor boards answer", nans, nmotor);
  for (int k = 0; k < h->t.nboard; k++) {
    const ht_board *b = &h->t.board[k];
    if (is_motor(h, k) && !ans[k]) {
      dcm_log(d, "board %s (0x%02X, bus %d) does not answer: its joints are reported dead until it does", b->name,
              b->number, b->bus + 1);
      h->to_enable[k] = h->set.enable_at_start;   /* switched on when its status comes */
    }
    if (!b->active) dcm_log(d, "board %s (0x%02X, bus %d) is not driven (can.lua: active = false)", b->name, b->number, b->bus + 1);
  }
  if (h->set.home_at_start) {
    for (int k = 0; k < h->t.nboard; k++) {
      if (!is_motor(h, k) || !ans[k]) continue;
      hcan_frame f;
      hcan_home(&f, h->t.board[k].number, HCAN_ALL_CHANNELS);
      request(h, k, &f, 0);
    }
    exchange(h, 0.01);
    dcm_log(d, "homing every answering motor board (up to %.0f s)", h->set.home_timeout);
    const double until = hio_now() + h->set.home_timeout;
    int all = 0;
    while (!all && hio_now() < until && !*d->stop) {
      d->pacer.clock.sleep_until(d->pacer.clock.ctx, hio_now() + 0.1);
      int now_ans[HT_BOARD_MAX];
      status_sweep(h, now_ans);
      all = 1;
      for (int k = 0; k < h->t.nboard; k++)
        if (is_motor(h, k) && ans[k] && (!now_ans[k] || !homed(h, k))) all = 0;
    }
    dcm_log(d, all ? "every board homed" : "homing timed out: boards not homed stay off");
  }
  if (h->set.enable_at_start) {
    int on = 0;
    for (int k = 0; k < h->t.nboard; k++) {
      if (!is_motor(h, k) || !ans[k]) continue;
      if (!homed(h, k)) {
        dcm_log(d, "board %s is not homed (home state %d): left off", h->t.board[k].name, HCAN_ST_HOME(board(h, k)->status[0]));
        continue;
      }
      hcan_frame f;
      hcan_fet(&f, h->t.board[k].number, 1);
      request(h, k, &f, 0);
      hcan_ctrl(&f, h->t.board[k].number, 1);
      request(h, k, &f, 0);
      h->enabled[k] = 1;
      on++;
    }
    exchange(h, 0.01);
    dcm_log(d, "FETs and position controllers on: %d boards", on);
  }
  /* one encoder sweep: every reference starts at the measured pose */
  for (int k = 0; k < h->t.nboard; k++) {
    if (!is_motor(h, k)) continue;
    hcan_frame f;
    hcan_req_encoder(&f, h->t.board[k].number, 0);
    request(h, k, &f, HCAN_R_ENC);
  }
  exchange(h, 0.05);
  const double now = hio_now();
  for (int k = 0; k < h->t.nboard; k++)
    if (is_motor(h, k) && (board(h, k)->fresh & HCAN_R_ENC)) take_encoders(h, k, now);
  end_cycle(h, 0);
  h->refs_from = now + h->set.startup_hold;
  (void)err;
  (void)n;
  return 0;
}

/* ---------------------------------------------------------------- the cycle: write */

/* The next reference of joint j toward `target` (rad): clamped to the limits, at most
 * max_speed * period away from the last one sent. */
static double next_ref(hubo *h, const dcm *d, double target, const ht_channel *ch) {
  const int j = ch->joint;
  if (target < h->t.lo[j]) target = h->t.lo[j];
  if (target > h->t.hi[j]) target = h->t.hi[j];
  if (!isfinite(target)) target = h->ref[j];
  const double step = ch->max_speed * d->period;
  if (target > h->ref[j] + step) {
    target = h->ref[j] + step;
    h->ref_limited++;
  } else if (target < h->ref[j] - step) {
    target = h->ref[j] - step;
    h->ref_limited++;
  }
  return target;
}

/* Where joint j's position reference goes: the command, where the joint is when compliant, or the
 * pose it is held at while in torque mode on a board in position mode. */
static double target_of(const hubo *h, const dcm_command *cmd, int j) {
  if (h->split[j]) return h->split_hold[j];
  if (!cmd->enable[j] || cmd->hardness[j] < h->set.compliant_below) return h->st.pos[j];
  return cmd->position[j];
}

static const char *joints_of(const hubo *h, const ht_board *bd, char *out, size_t len) {
  size_t o = 0;
  out[0] = 0;
  for (int c = 0; c < bd->nch && o < len; c++)
    o += (size_t)snprintf(out + o, len - o, "%s%s", c ? " " : "", h->t.joint[bd->ch[c].joint]);
  return out;
}

/* The control mode board k is to be in: current when every joint on it is in torque mode (the guard
 * lets torque mode through only for joints with a current path), else position. A board whose mode is
 * unknown (it died in current mode) goes to position mode first. Joints in torque mode on a board
 * that stays in position mode are held (split). */
static int board_mode(hubo *h, dcm *d, const dcm_command *cmd, int k) {
  const ht_board *bd = &h->t.board[k];
  int ntq = 0;
  for (int i = 0; i < bd->nch; i++) ntq += cmd->mode[bd->ch[i].joint] == DCM_MODE_TORQUE;
  const int back = h->mode[k] < 0;   /* answers again after dying in current mode: one cycle in position mode */
  const int want = ntq == bd->nch && !back ? HCAN_MODE_CURRENT : HCAN_MODE_POSITION;
  for (int i = 0; i < bd->nch; i++) {
    const int j = bd->ch[i].joint;
    const int held = want == HCAN_MODE_POSITION && cmd->mode[j] == DCM_MODE_TORQUE;
    if (held && !h->split[j]) {
      char js[128];
      h->split_hold[j] = h->st.pos[j];
      if (!back)
        dcm_log(d, "joint %s in torque mode, but board %s (%s) is one control mode for all its joints: it stays in "
                   "position mode, %s held at %.4f rad", h->t.joint[j], bd->name, joints_of(h, bd, js, sizeof js),
                h->t.joint[j], h->split_hold[j]);
    }
    if (held && !back) {
      h->split_refused++;
      d->robot[0].guard.torque_refused++;   /* a torque-mode command refused: the joint held in position mode */
    }
    h->split[j] = held;
  }
  return want;
}

/* The mode frame for board k when its mode changes; back in position mode, its references restart at
 * the measured position (sent in this same cycle, right after the mode frame). */
static void switch_mode(hubo *h, dcm *d, int k, int want) {
  const ht_board *bd = &h->t.board[k];
  if (want == h->mode[k]) return;
  hcan_frame f;
  hcan_ctrl_mode(&f, bd->number, want);
  hio_queue(bus_of(h, k), &f);
  h->mode_frames++;
  char js[128];
  if (want == HCAN_MODE_POSITION) {
    for (int i = 0; i < bd->nch; i++) {
      const int j = bd->ch[i].joint;
      h->ref[j] = h->st.pos[j];
      h->amps[j] = 0;
    }
    dcm_log(d, "board %s (%s): position mode, holding the measured pose", bd->name, joints_of(h, bd, js, sizeof js));
  } else {
    dcm_log(d, "board %s (%s): current mode (torque)", bd->name, joints_of(h, bd, js, sizeof js));
  }
  h->mode[k] = want;
}

/* Board k's current reference: each joint's torque (the guard clamped it to the joint's limit) as a
 * motor current, no more than max_current; 0 A with torque off. A one-joint board's channel 1 gets 0 A,
 * not a copy of channel 0 as its position reference does: with no motor there nothing changes, and
 * were a second motor on the joint, a copy would double the torque. */
static int current_ref(hubo *h, const dcm_command *cmd, int k, hcan_frame *f) {
  const ht_board *bd = &h->t.board[k];
  double a[2] = { 0, 0 };
  for (int i = 0; i < bd->nch; i++) {
    const ht_channel *ch = &bd->ch[i];
    const int j = ch->joint;
    double amps = cmd->enable[j] ? ht_torque_to_current(ch, cmd->torque[j]) : 0;
    if (amps > ch->max_current) amps = ch->max_current;
    if (amps < -ch->max_current) amps = -ch->max_current;
    a[ch->ch] = amps;
  }
  if (hcan_cur_ref(f, bd->number, a[0], a[1]) < 0) return -1;
  for (int i = 0; i < bd->nch; i++) h->amps[bd->ch[i].joint] = a[bd->ch[i].ch];
  return 0;
}

static void send_refs(hubo *h, dcm *d, const dcm_command *cmd) {
  for (int k = 0; k < h->t.nboard; k++) {
    const ht_board *bd = &h->t.board[k];
    const hcan_board *b = hubo_board(h, k);
    if (!is_motor(h, k) || !h->enabled[k] || b->dead || bus_of(h, k)->fd < 0) continue;
    const int want = board_mode(h, d, cmd, k);
    int back_to_position = want == HCAN_MODE_POSITION && h->mode[k] != HCAN_MODE_POSITION;
    switch_mode(h, d, k, want);
    hcan_frame f;
    if (want == HCAN_MODE_CURRENT) {
      if (current_ref(h, cmd, k, &f) < 0) {
        h->ref_refused++;   /* cannot be: the guard passes finite torques within the limit only */
        switch_mode(h, d, k, HCAN_MODE_POSITION);
        back_to_position = 1;
      } else {
        hio_queue(bus_of(h, k), &f);
        continue;
      }
    }
    int32_t c[2] = { 0, 0 };
    double r[HT_CH_MAX];
    int ok = 1;
    for (int i = 0; i < bd->nch; i++) {
      const ht_channel *ch = &bd->ch[i];
      if (!h->seeded[ch->joint]) ok = 0;   /* never read: nothing to start from */
      /* the first reference after current mode is the measured position itself */
      r[i] = next_ref(h, d, back_to_position ? h->st.pos[ch->joint] : target_of(h, cmd, ch->joint), ch);
      ok = ok && isfinite(r[i]);
      if (ok) c[ch->ch] = ht_rad_to_counts(ch, r[i]);
    }
    if (bd->nch == 1) c[1] = c[0];   /* one-joint boards get channel 0 twice (hubo-ach) */
    if (!ok || hcan_ref(&f, bd->number, c[0], c[1]) < 0) {
      h->ref_refused++;
      continue;
    }
    for (int i = 0; i < bd->nch; i++) h->ref[bd->ch[i].joint] = r[i];
    hio_queue(bus_of(h, k), &f);
  }
}

void hubo_release(hubo *h, dcm *d) {
  int any = 0;
  for (int k = 0; k < h->t.nboard; k++) {
    const ht_board *bd = &h->t.board[k];
    if (!is_motor(h, k) || h->mode[k] == HCAN_MODE_POSITION || bus_of(h, k)->fd < 0) continue;
    switch_mode(h, d, k, HCAN_MODE_POSITION);
    int32_t c[2] = { 0, 0 };
    for (int i = 0; i < bd->nch; i++) c[bd->ch[i].ch] = ht_rad_to_counts(&bd->ch[i], h->ref[bd->ch[i].joint]);
    if (bd->nch == 1) c[1] = c[0];
    hcan_frame f;
    if (hcan_ref(&f, bd->number, c[0], c[1]) == 0) hio_queue(bus_of(h, k), &f);
    any = 1;
  }
  if (any) exchange(h, 0.01);
}

static void send_requests(hubo *h, double now) {
  const int se = h->set.status_every > 0 ? h->set.status_every : 1;
  const int ce = h->set.current_every > 0 ? h->set.current_every : 1;
  for (int k = 0; k < h->t.nboard; k++) {
    hcan_board *b = board(h, k);
    if (!b || bus_of(h, k)->fd < 0) continue;
    if (b->dead) {
      if (now - h->last_try[k] < h->set.retry_period) continue;
      h->last_try[k] = now;
    }
    const ht_board *bd = &h->t.board[k];
    hcan_frame f;
    switch (bd->kind) {
    case HT_JMC:
      hcan_req_encoder(&f, bd->number, 0);
      request(h, k, &f, HCAN_R_ENC);
      if (h->to_enable[k] || h->cycle % (uint32_t)se == (uint32_t)(k % se)) {
        hcan_req_status(&f, bd->number);
        request(h, k, &f, HCAN_R_STATUS);
      }
      if (h->cycle % (uint32_t)ce == (uint32_t)((k + ce / 2) % ce)) {
        hcan_req_current(&f, bd->number);
        request(h, k, &f, HCAN_R_CURRENT);
      }
      break;
    case HT_FT_TILT:   /* the foot tilt is not asked for: dcm.sensor has no field for it (7 % of bus 1) */
    case HT_FT:
      hcan_req_ft(&f, bd->number);
      request(h, k, &f, HCAN_R_FT);
      break;
    case HT_IMU:
      hcan_req_imu(&f, bd->number);
      request(h, k, &f, HCAN_R_IMU);
      break;
    case HT_POWER:
      hcan_req_power(&f);
      request(h, k, &f, HCAN_R_POWER);
      break;
    default:
      break;
    }
  }
}

void hubo_write(hubo *h, dcm *d, const dcm_command *cmd) {
  for (int b = 0; b < h->nbus; b++) hio_receive(&h->bus[b]);   /* late replies of the last cycle */
  if (d->now >= h->refs_from) send_refs(h, d, cmd);
  send_requests(h, d->now);
  for (int b = 0; b < h->nbus; b++) hio_flush(&h->bus[b]);
  h->cycle++;
}

/* ---------------------------------------------------------------- the cycle: read */

static void take_sensors(hubo *h, int k) {
  const hcan_board *b = board(h, k);
  const ht_board *bd = &h->t.board[k];
  hubo_state *s = &h->st;
  if ((b->fresh & HCAN_R_FT) && bd->mount >= 0) {
    double *w = &s->ft[bd->mount * 6];
    w[0] = w[1] = w[5] = 0;   /* the Hubo2+ boards measure Mx, My, Fz only */
    w[2] = bd->sign[2] * b->ft[2];
    w[3] = bd->sign[0] * b->ft[0];
    w[4] = bd->sign[1] * b->ft[1];
    if (bd->mount < 2) s->foot[bd->mount] = w[2];
  }
  if (b->fresh & HCAN_R_IMU) {
    const double roll = b->imu[0], pitch = b->imu[1];
    s->angle[0] = roll;
    s->angle[1] = pitch;
    s->angle[2] = 0;   /* no yaw on this IMU */
    s->gyro[0] = b->imu[2];
    s->gyro[1] = b->imu[3];
    s->gyro[2] = 0;
    /* no accelerometer output either: gravity in the torso frame as the angles give it */
    s->acc[0] = -G * sin(pitch);
    s->acc[1] = G * sin(roll) * cos(pitch);
    s->acc[2] = G * cos(roll) * cos(pitch);
  }
  if (b->fresh & HCAN_R_POWER) s->battery = b->power[0];
}

static void report_boards(hubo *h, dcm *d) {
  for (int k = 0; k < h->t.nboard; k++) {
    const hcan_board *b = hubo_board(h, k);
    if (!b || b->dead == h->dead[k]) continue;
    const ht_board *bd = &h->t.board[k];
    char joints[128] = "";
    size_t o = 0;
    for (int c = 0; c < bd->nch && o < sizeof joints; c++)
      o += (size_t)snprintf(joints + o, sizeof joints - o, "%s%s", c ? " " : "", h->t.joint[bd->ch[c].joint]);
    if (b->dead && bd->nch && h->mode[k] == HCAN_MODE_CURRENT) {
      dcm_log(d, "board %s (0x%02X, bus %d) stopped answering in current mode: joints %s keep its last current "
                 "(%.2f A) until it answers, then go to position mode", bd->name, bd->number, bd->bus + 1, joints,
              h->amps[bd->ch[0].joint]);
      h->mode[k] = -1;
    } else if (b->dead && bd->nch) {
      dcm_log(d, "board %s (0x%02X, bus %d) stopped answering: joints %s held (no references), the rest go on",
              bd->name, bd->number, bd->bus + 1, joints);
    } else if (b->dead) {
      dcm_log(d, "board %s (%d, bus %d) stopped answering: its last readings are kept", bd->name, bd->number, bd->bus + 1);
    } else {
      dcm_log(d, "board %s (0x%02X, bus %d) answers%s", bd->name, bd->number, bd->bus + 1,
              bd->nch && h->enabled[k] ? " again: references resume from its measured position" : "");
      for (int c = 0; c < bd->nch; c++) h->ref[bd->ch[c].joint] = h->st.pos[bd->ch[c].joint];
      if (bd->kind == HT_JMC && !h->enabled[k] && h->set.enable_at_start) h->to_enable[k] = 1;
    }
    if (b->dead) h->last_try[k] = d->now;
    h->dead[k] = b->dead;
  }
}

/* Boards that came after bring-up: FETs and controller on once their status says homed. */
static void late_enable(hubo *h, dcm *d) {
  for (int k = 0; k < h->t.nboard; k++) {
    if (!h->to_enable[k]) continue;
    const hcan_board *b = hubo_board(h, k);
    hcan_frame f;
    if (!(b->fresh & HCAN_R_STATUS)) continue;   /* asked for in send_requests */
    h->to_enable[k] = 0;
    if (!homed(h, k)) {
      dcm_log(d, "board %s is not homed (home state %d): left off", h->t.board[k].name, HCAN_ST_HOME(b->status[0]));
      continue;
    }
    hcan_fet(&f, h->t.board[k].number, 1);
    hio_queue(bus_of(h, k), &f);
    hcan_ctrl(&f, h->t.board[k].number, 1);
    hio_queue(bus_of(h, k), &f);
    h->enabled[k] = 1;
    dcm_log(d, "board %s: FETs and position controller on", h->t.board[k].name);
  }
}

void hubo_read(hubo *h, dcm *d, double deadline) {
  int was_open[HT_BUS_MAX];
  for (int b = 0; b < h->nbus; b++) was_open[b] = h->bus[b].fd >= 0;
  hio_settle(h->bus, h->nbus, deadline);
  const double now = hio_now();
  for (int k = 0; k < h->t.nboard; k++) {
    const hcan_board *b = hubo_board(h, k);
    if (!b) continue;
    if (h->t.board[k].kind == HT_JMC) {
      if (b->fresh & HCAN_R_ENC) take_encoders(h, k, now);
      if (b->fresh & HCAN_R_CURRENT)
        for (int c = 0; c < h->t.board[k].nch; c++) h->st.temp[h->t.board[k].ch[c].joint] = b->temp;
    } else {
      take_sensors(h, k);
    }
  }
  late_enable(h, d);
  end_cycle(h, h->set.dead_after);
  report_boards(h, d);
  for (int b = 0; b < h->nbus; b++) {
    hio_bus *bus = &h->bus[b];
    if (was_open[b] && bus->fd < 0) {
      dcm_log(d, "bus %d (%s) went away: its boards go dead; reopening every %.1f s", b + 1, bus->iface,
              h->set.reopen_period);
      bus->reopen_at = now + h->set.reopen_period;
    } else if (bus->fd < 0 && now >= bus->reopen_at) {
      char err[256];
      if (hio_open(bus, err, sizeof err) == 0) dcm_log(d, "bus %d (%s) reopened", b + 1, bus->iface);
      else bus->reopen_at = now + h->set.reopen_period;
    }
  }
}
