/* emu_boards: what the emulated Hubo2+ boards do with the host's frames (hubo_can.md 10):
 * motor boards (references while the controller is on, encoders, status bits, currents, FETs,
 * controller on/off, homing, encoder zero), F/T and tilt boards, the IMU, the power board. */
#include "emu.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void emu_init(emu_world *w, const ht_table *t, int homed, double tau) {
  memset(w, 0, sizeof *w);
  w->tau = tau;
  w->home_time = 1.0;
  w->power[0] = 48.0;   /* the emulator's own numbers: no source gives the Hubo2+ battery */
  w->power[1] = 2.0;
  w->power[2] = 96.0;
  w->n = t->nboard;
  for (int k = 0; k < t->nboard; k++) {
    emu_board *b = &w->b[k];
    b->def = &t->board[k];
    b->home_state = homed ? HCAN_HOME_OK : 0;
    for (int c = 0; c < b->def->nch; c++) {
      const ht_channel *ch = &b->def->ch[c];
      b->vmax[c] = ch->max_speed * ch->cpr;
      const double e0 = ht_rad_to_counts(ch, t->lo[ch->joint]), e1 = ht_rad_to_counts(ch, t->hi[ch->joint]);
      b->stop_lo[c] = e0 < e1 ? e0 : e1;
      b->stop_hi[c] = e0 < e1 ? e1 : e0;
    }
    if (b->def->kind == HT_FT_TILT) b->ft[2] = 38.5 * 9.81 / 2;   /* standing on both feet */
  }
}

emu_board *emu_find(emu_world *w, const char *name) {
  char *end;
  const long num = strtol(name, &end, 0);
  for (int k = 0; k < w->n; k++) {
    const ht_board *d = w->b[k].def;
    if (!strcmp(d->name, name) || (*end == '\0' && end != name && d->number == num)) return &w->b[k];
  }
  return NULL;
}

void emu_step(emu_world *w, double now, double dt) {
  const double a = w->tau > 0 ? 1 - exp(-dt / w->tau) : 1;
  for (int k = 0; k < w->n; k++) {
    emu_board *b = &w->b[k];
    if (b->def->kind != HT_JMC) continue;
    if (b->homing_until > 0) {
      if (now >= b->homing_until) {
        b->homing_until = 0;
        b->home_state = HCAN_HOME_OK;
        for (int c = 0; c < b->def->nch; c++) b->pos[c] = b->ref[c] = 0;   /* the index is the new zero */
      }
      continue;
    }
    if (!b->fet || !b->ctrl) continue;
    if (b->mode == HCAN_MODE_CURRENT) {
      for (int c = 0; c < b->def->nch; c++) {
        const ht_channel *ch = &b->def->ch[c];
        if (!(ch->kt > 0) || !(ch->torque > 0)) continue;   /* no data for a drive: it does not move */
        const double nm = b->amps[c] * ch->kt * ch->ratio;   /* motor-side sign: counts follow the current */
        double v = nm * ch->speed / ch->torque * ch->cpr;    /* counts/s */
        v = v > b->vmax[c] ? b->vmax[c] : v < -b->vmax[c] ? -b->vmax[c] : v;
        b->pos[c] += v * dt;
        if (b->stop_hi[c] > b->stop_lo[c]) b->pos[c] = fmin(fmax(b->pos[c], b->stop_lo[c]), b->stop_hi[c]);
        b->ref[c] = b->pos[c];
      }
      continue;
    }
    for (int c = 0; c < b->def->nch; c++) {
      double step = (b->ref[c] - b->pos[c]) * a;
      const double cap = b->vmax[c] * dt;
      step = step > cap ? cap : step < -cap ? -cap : step;
      b->pos[c] += step;
    }
  }
}

/* The board on this bus with this motor-board or sensor number, or NULL. */
static emu_board *on_bus(emu_world *w, int bus, int number, int sensor) {
  for (int k = 0; k < w->n; k++) {
    const ht_board *d = w->b[k].def;
    const int is_sensor = d->kind == HT_FT || d->kind == HT_FT_TILT || d->kind == HT_IMU;
    if (d->bus == bus && d->number == number && is_sensor == sensor) return &w->b[k];
  }
  return NULL;
}

static void status(const emu_board *b, hcan_frame *f) {
  hcan_status st[2];
  memset(st, 0, sizeof st);
  for (int c = 0; c < b->def->nch && c < 2; c++) {
    st[c].flags = (uint8_t)((b->fet ? HCAN_ST_DRIVER : 0) | (b->ctrl ? HCAN_ST_CTRL : 0) |
                            (b->mode == HCAN_MODE_CURRENT ? HCAN_ST_MODE : 0) | (b->home_state << 4));
    st[c].faults = b->faults;
    st[c].limits = b->limits;
  }
  hcan_rep_status(f, b->def->number, st);
}

/* A motor board's command. */
static int motor_cmd(emu_world *w, emu_board *b, const hcan_frame *f, double now, hcan_frame *out) {
  const int nch = b->def->nch;
  const int arg = f->dlc > 2 ? f->data[2] : 0;
  switch (f->data[1]) {
  case HCAN_C_ENCODER:
    b->enc_reqs++;
    hcan_rep_encoder(out, b->def->number, (int32_t)lround(b->pos[0]), nch > 1 ? (int32_t)lround(b->pos[1]) : 0);
    return 1;
  case HCAN_C_STATUS:
    status(b, out);
    return 1;
  case HCAN_C_CURRENT: {
    /* the emulator's model: 20 A per rad of error, at most 10 A; in current mode the reference's
     * magnitude (the reply has no sign) */
    double amps[2] = { 0, 0 };
    for (int c = 0; c < nch && c < 2; c++)
      amps[c] = b->mode == HCAN_MODE_CURRENT ? fabs(b->amps[c])
                                             : fmin(10.0, fabs(b->ref[c] - b->pos[c]) / b->def->ch[c].cpr * 20);
    hcan_rep_current(out, b->def->number, amps, 35);
    return 1;
  }
  case HCAN_C_FET:
    b->fet = arg != 0;
    if (!b->fet) b->ctrl = 0;
    return 0;
  case HCAN_C_INIT:
    b->fet = 1;   /* defaults and FETs on (hubo-ach README) */
    return 0;
  case HCAN_C_CTRL_ON:
    if (b->fet && !b->ctrl)
      for (int c = 0; c < nch; c++) b->ref[c] = b->pos[c];   /* it holds where it is */
    b->ctrl = b->fet;
    return 0;
  case HCAN_C_CTRL_OFF:
    b->ctrl = 0;
    return 0;
  case HCAN_C_CTRL_MODE:
    /* 0 position, 1 current; 2 (hybrid) is the DRC finger boards' only */
    if (f->dlc < 3 || (arg != HCAN_MODE_POSITION && arg != HCAN_MODE_CURRENT)) {
      w->unparsed++;
      return 0;
    }
    b->mode_frames++;
    if (arg == b->mode) return 0;
    b->mode = arg;
    for (int c = 0; c < nch; c++) {
      b->amps[c] = 0;          /* a new mode starts from rest: no current, */
      b->ref[c] = b->pos[c];   /* holding where it is */
    }
    return 0;
  case HCAN_C_HOME:
    b->home_state = 0;
    b->homing_until = now + w->home_time;
    return 0;
  case HCAN_C_ENC_ZERO:
    for (int c = 0; c < nch; c++)
      if (arg == HCAN_ALL_CHANNELS || arg == c) b->pos[c] = b->ref[c] = 0;
    b->faults = b->limits = 0;
    return 0;
  default:
    return 0;   /* gains, limits, parameters: accepted, not modelled */
  }
}

static int sensor_req(emu_world *w, emu_board *b, const hcan_frame *f, hcan_frame *out) {
  const int type = f->data[1];
  const int s = b->def->number;
  if (type == HCAN_S_FT && (b->def->kind == HT_FT || b->def->kind == HT_FT_TILT)) {
    hcan_rep_ft(out, s, b->ft[0], b->ft[1], b->ft[2]);
    return 1;
  }
  if (type == HCAN_S_TILT && b->def->kind == HT_FT_TILT) {
    hcan_rep_tilt(out, s, w->imu[0], w->imu[1], 0);
    return 1;
  }
  if (type == HCAN_S_IMU && b->def->kind == HT_IMU) {
    hcan_rep_imu(out, s, w->imu[0], w->imu[1], w->imu[2], w->imu[3]);
    return 1;
  }
  return 0;
}

int emu_handle(emu_world *w, int bus, const hcan_frame *f, double now, hcan_frame *out) {
  int num;
  const hcan_kind k = hcan_classify(f, &num);
  if (k == HCAN_K_REF) {
    emu_board *b = on_bus(w, bus, num, 0);
    if (!b || b->dead || b->def->kind != HT_JMC) return 0;
    int32_t c[2];
    double a[2];
    if (hcan_dec_ref(f, c) < 0 || hcan_dec_cur_ref(f, a) < 0) {
      w->unparsed++;
      return 0;
    }
    if (!(b->fet && b->ctrl) || b->homing_until > 0) {
      b->refs_ignored++;   /* ignored while the controller is off */
      return 0;
    }
    /* the board reads the frame by its mode: counts, or currents in 0.01 A */
    for (int ch = 0; ch < b->def->nch; ch++) {
      if (b->mode == HCAN_MODE_CURRENT) b->amps[ch] = a[ch];
      else b->ref[ch] = c[ch];
    }
    if (b->mode == HCAN_MODE_CURRENT) b->cur_refs++;
    else b->refs++;
    return 0;
  }
  if ((k == HCAN_K_CMD || k == HCAN_K_SENSOR_REQ) && f->dlc < 2) {
    w->unparsed++;
    return 0;
  }
  if (k != HCAN_K_CMD && k != HCAN_K_SENSOR_REQ) {
    w->unparsed++;   /* a board's reply or an id no frame has: nothing a board takes */
    return 0;
  }
  if (k == HCAN_K_CMD && f->dlc >= 2) {
    const int board = f->data[0];
    if (board == HCAN_POWER_BOARD && f->data[1] == HCAN_C_POWER) {
      emu_board *b = on_bus(w, bus, HCAN_POWER_BOARD, 0);
      if (!b || b->dead || b->def->kind != HT_POWER) return 0;
      hcan_rep_power(out, w->power[0], w->power[1], w->power[2]);
      return 1;
    }
    if (board >= HCAN_SENSOR_BOARD(0) + 1 && board < HCAN_SENSOR_BOARD(HCAN_SENSOR_MAX)) {
      emu_board *b = on_bus(w, bus, board - HCAN_SENSOR_BOARD(0), 1);
      if (b && !b->dead && f->data[1] == HCAN_C_NULL) memset(b->ft, 0, sizeof b->ft);
      return 0;
    }
    emu_board *b = on_bus(w, bus, board, 0);
    if (!b || b->dead || b->def->kind != HT_JMC) return 0;
    return motor_cmd(w, b, f, now, out);
  }
  if (k == HCAN_K_SENSOR_REQ && f->dlc >= 2) {
    emu_board *b = on_bus(w, bus, f->data[0], 1);
    if (!b || b->dead) return 0;
    return sensor_req(w, b, f, out);
  }
  return 0;
}
