/* hubo_table: reading and checking a body's CAN board table (can.lua) against its joints. */
#include "hubo_table.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static const struct { const char *name; ht_kind kind; int nch; } KINDS[] = {
  { "jmc", HT_JMC, 2 }, { "jmc3", HT_JMC3, 3 }, { "ft", HT_FT, 0 }, { "ft_tilt", HT_FT_TILT, 0 },
  { "imu", HT_IMU, 0 }, { "power", HT_POWER, 0 },
};
static const char *MOUNTS[HT_FT_SLOTS] = { "left_foot", "right_foot", "left_hand", "right_hand" };
#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

hcan_board_kind ht_hcan_kind(ht_kind k) {
  switch (k) {
  case HT_FT: return HCAN_B_FT;
  case HT_FT_TILT: return HCAN_B_TILT_FT;
  case HT_IMU: return HCAN_B_IMU;
  case HT_POWER: return HCAN_B_POWER;
  default: return HCAN_B_JMC;
  }
}

int32_t ht_rad_to_counts(const ht_channel *c, double rad) {
  return c->zero + hcan_rad_to_counts(c->dir * rad, c->cpr);
}

double ht_counts_to_rad(const ht_channel *c, int32_t counts) {
  return c->dir * hcan_counts_to_rad(counts - c->zero, c->cpr);
}

double ht_torque_limit(const ht_channel *c) {
  if (!(c->kt > 0) || !(c->torque > 0)) return 0;
  const double by_current = c->max_current * c->kt * c->ratio;
  return c->torque < by_current ? c->torque : by_current;
}

double ht_torque_to_current(const ht_channel *c, double nm) {
  return c->kt > 0 ? c->dir * nm / (c->kt * c->ratio) : 0;
}

/* ---------------------------------------------------------------- the body */

static int load_body(const dcm_config *c, ht_table *t, char *err, size_t n) {
  int nj = dcm_config_joints(c, t->joint, t->lo, t->hi, err, n);
  if (nj < 0) return nj;
  t->nj = nj;
  for (int j = 0; j < nj; j++) t->joint_board[j] = t->joint_ch[j] = -1;
  if (dcm_config_num(c, "period", &t->period, err, n) < 0) return -EINVAL;
  return dcm_config_str(c, "name", t->name, sizeof t->name, err, n);
}

/* ---------------------------------------------------------------- the buses and boards */

static int load_buses(const dcm_config *c, ht_table *t, char *err, size_t n) {
  if (dcm_config_num(c, "bitrate", &t->bitrate, err, n) < 0) return -EINVAL;
  if (!(t->bitrate > 0)) return dcm_config_fail(c, err, n, "bitrate: must be > 0, got %g", t->bitrate);
  const int nb = dcm_config_len(c, "buses", err, n);
  if (nb < 0) return -EINVAL;
  if (nb < 1 || nb > HT_BUS_MAX) return dcm_config_fail(c, err, n, "buses: 1 to %d buses, has %d", HT_BUS_MAX, nb);
  t->nbus = nb;
  for (int k = 0; k < nb; k++) {
    char key[64];
    snprintf(key, sizeof key, "buses.%d.name", k + 1);
    if (dcm_config_str(c, key, t->bus_name[k], sizeof t->bus_name[k], err, n) < 0) return -EINVAL;
    snprintf(key, sizeof key, "buses.%d.interface", k + 1);
    if (dcm_config_str(c, key, t->iface[k], sizeof t->iface[k], err, n) < 0) return -EINVAL;
  }
  return 0;
}

static int joint_index(const ht_table *t, const char *name) {
  for (int j = 0; j < t->nj; j++)
    if (!strcmp(t->joint[j], name)) return j;
  return -1;
}

static int load_channel(const dcm_config *c, ht_table *t, ht_board *b, int k, int maxch, char *err, size_t n) {
  char key[128], pre[64], jn[DCM_NAME_MAX];
  snprintf(pre, sizeof pre, "boards.%d.channels.%d", b->row, k + 1);
  char where[128];
  snprintf(where, sizeof where, "boards[%d] (%s) channels[%d]", b->row, b->name, k + 1);
  ht_channel *ch = &b->ch[k];
  snprintf(key, sizeof key, "%s.channel", pre);
  if (dcm_config_int(c, key, &ch->ch, err, n) < 0) return -EINVAL;
  if (ch->ch < 0 || ch->ch >= maxch)
    return dcm_config_fail(c, err, n, "%s: channel %d is not 0..%d on a '%s' board", where, ch->ch, maxch - 1,
                           b->kind == HT_JMC3 ? "jmc3" : "jmc");
  for (int i = 0; i < k; i++)
    if (b->ch[i].ch == ch->ch) return dcm_config_fail(c, err, n, "%s: channel %d twice", where, ch->ch);
  snprintf(key, sizeof key, "%s.joint", pre);
  if (dcm_config_str(c, key, jn, sizeof jn, err, n) < 0) return -EINVAL;
  ch->joint = joint_index(t, jn);
  if (ch->joint < 0) return dcm_config_fail(c, err, n, "%s: joint '%s' is not one of the body's joints", where, jn);
  if (t->joint_board[ch->joint] >= 0) {
    const ht_board *o = &t->board[t->joint_board[ch->joint]];
    return dcm_config_fail(c, err, n, "%s: joint '%s' is already on boards[%d] (%s)", where, jn, o->row, o->name);
  }
  static const char *gear[] = { "drive", "driven", "harmonic", "encoder" };
  int g[4];
  for (int i = 0; i < 4; i++) {
    snprintf(key, sizeof key, "%s.%s", pre, gear[i]);
    if (dcm_config_int(c, key, &g[i], err, n) < 0) return -EINVAL;
    if (g[i] <= 0) return dcm_config_fail(c, err, n, "%s: %s must be > 0, got %d", where, gear[i], g[i]);
  }
  ch->cpr = hcan_counts_per_rad(g[0], g[1], g[2], g[3]);
  ch->ratio = (double)g[1] * g[2] / g[0];
  snprintf(key, sizeof key, "%s.direction", pre);
  if (dcm_config_int(c, key, &ch->dir, err, n) < 0) return -EINVAL;
  if (ch->dir != 1 && ch->dir != -1) return dcm_config_fail(c, err, n, "%s: direction must be 1 or -1, got %d", where, ch->dir);
  int zero;
  snprintf(key, sizeof key, "%s.zero", pre);
  if (dcm_config_int(c, key, &zero, err, n) < 0) return -EINVAL;
  ch->zero = zero;
  snprintf(key, sizeof key, "%s.max_speed", pre);
  if (dcm_config_num(c, key, &ch->max_speed, err, n) < 0) return -EINVAL;
  if (!(ch->max_speed > 0)) return dcm_config_fail(c, err, n, "%s: max_speed must be > 0, got %g", where, ch->max_speed);
  /* current mode: both keys or neither */
  char kkey[128], ikey[128];
  snprintf(kkey, sizeof kkey, "%s.torque_constant", pre);
  snprintf(ikey, sizeof ikey, "%s.max_current", pre);
  const int hk = dcm_config_has(c, kkey), hi = dcm_config_has(c, ikey);
  if (hk != hi)
    return dcm_config_fail(c, err, n, "%s: torque_constant and max_current go together (current mode), %s is missing",
                           where, hk ? "max_current" : "torque_constant");
  if (hk) {
    if (dcm_config_num(c, kkey, &ch->kt, err, n) < 0 || dcm_config_num(c, ikey, &ch->max_current, err, n) < 0)
      return -EINVAL;
    if (!(ch->kt > 0 && isfinite(ch->kt)))
      return dcm_config_fail(c, err, n, "%s: torque_constant must be > 0 N*m/A, got %g", where, ch->kt);
    if (!(ch->max_current > 0 && isfinite(ch->max_current)))
      return dcm_config_fail(c, err, n, "%s: max_current must be > 0 A, got %g", where, ch->max_current);
  }
  return 0;
}

static int load_sensor(const dcm_config *c, ht_board *b, char *err, size_t n) {
  char key[64], m[DCM_NAME_MAX];
  b->mount = -1;
  b->sign[0] = b->sign[1] = b->sign[2] = 1;
  if (b->kind != HT_FT && b->kind != HT_FT_TILT) return 0;
  snprintf(key, sizeof key, "boards.%d.mount", b->row);
  if (dcm_config_str(c, key, m, sizeof m, err, n) < 0) return -EINVAL;
  for (int k = 0; k < HT_FT_SLOTS; k++)
    if (!strcmp(m, MOUNTS[k])) b->mount = k;
  if (b->mount < 0)
    return dcm_config_fail(c, err, n, "boards[%d] (%s): mount '%s' is not left_foot, right_foot, left_hand or right_hand",
                           b->row, b->name, m);
  snprintf(key, sizeof key, "boards.%d.signs", b->row);
  if (dcm_config_has(c, key) && dcm_config_nums(c, key, b->sign, 3, 3, err, n) < 0) return -EINVAL;
  return 0;
}

static int load_board(const dcm_config *c, ht_table *t, int r, char *err, size_t n) {
  char key[64], kind[DCM_NAME_MAX];
  ht_board *b = &t->board[t->nboard];
  memset(b, 0, sizeof *b);
  b->row = r;
  snprintf(key, sizeof key, "boards.%d.board", r);
  if (dcm_config_str(c, key, b->name, sizeof b->name, err, n) < 0) return -EINVAL;
  snprintf(key, sizeof key, "boards.%d.kind", r);
  if (dcm_config_str(c, key, kind, sizeof kind, err, n) < 0) return -EINVAL;
  int maxch = -1;
  for (int k = 0; k < COUNT(KINDS); k++)
    if (!strcmp(kind, KINDS[k].name)) {
      b->kind = KINDS[k].kind;
      maxch = KINDS[k].nch;
    }
  if (maxch < 0)
    return dcm_config_fail(c, err, n, "boards[%d] (%s): kind '%s' is not jmc, jmc3, ft, ft_tilt, imu or power", r,
                           b->name, kind);
  snprintf(key, sizeof key, "boards.%d.bus", r);
  if (dcm_config_int(c, key, &b->bus, err, n) < 0) return -EINVAL;
  if (b->bus < 1 || b->bus > t->nbus)
    return dcm_config_fail(c, err, n, "boards[%d] (%s): bus %d is not one of buses (1 to %d)", r, b->name, b->bus, t->nbus);
  b->bus--;
  const int sensor = b->kind == HT_FT || b->kind == HT_FT_TILT || b->kind == HT_IMU;
  snprintf(key, sizeof key, "boards.%d.%s", r, sensor ? "sensor" : "number");
  if (dcm_config_int(c, key, &b->number, err, n) < 0) return -EINVAL;
  const int max = sensor ? HCAN_SENSOR_MAX : HCAN_BOARD_MAX;
  if (b->number < 0 || b->number >= max)
    return dcm_config_fail(c, err, n, "boards[%d] (%s): %s %d is not 0..%d", r, b->name, sensor ? "sensor" : "number",
                           b->number, max - 1);
  for (int i = 0; i < t->nboard; i++) {
    const ht_board *o = &t->board[i];
    const int osensor = o->kind == HT_FT || o->kind == HT_FT_TILT || o->kind == HT_IMU;
    if (o->bus == b->bus && osensor == sensor && o->number == b->number)
      return dcm_config_fail(c, err, n, "boards[%d] (%s): %s 0x%02X on bus %d is already boards[%d] (%s)", r, b->name,
                             sensor ? "sensor" : "board number", b->number, b->bus + 1, o->row, o->name);
  }
  b->active = 1;
  snprintf(key, sizeof key, "boards.%d.active", r);
  if (dcm_config_has(c, key) && dcm_config_bool(c, key, &b->active, err, n) < 0) return -EINVAL;
  if (load_sensor(c, b, err, n) < 0) return -EINVAL;
  if (maxch > 0) {
    snprintf(key, sizeof key, "boards.%d.channels", r);
    const int nch = dcm_config_len(c, key, err, n);
    if (nch < 0) return -EINVAL;
    if (nch < 1 || nch > maxch)
      return dcm_config_fail(c, err, n, "boards[%d] (%s): 1 to %d channels, has %d", r, b->name, maxch, nch);
    b->nch = nch;
    for (int k = 0; k < nch; k++) {
      if (load_channel(c, t, b, k, maxch, err, n) < 0) return -EINVAL;
      t->joint_board[b->ch[k].joint] = t->nboard;
      t->joint_ch[b->ch[k].joint] = k;
    }
  }
  t->nboard++;
  return 0;
}

int ht_load_actuators(const dcm_config *robot, const dcm_config *act, ht_table *t, char *err, size_t n) {
  for (int k = 0; k < t->nboard; k++) {
    ht_board *b = &t->board[k];
    for (int i = 0; i < b->nch; i++) {
      ht_channel *ch = &b->ch[i];
      if (!(ch->kt > 0)) continue;
      char key[DCM_NAME_MAX + 32], model[DCM_NAME_MAX];
      snprintf(key, sizeof key, "actuator.%s", t->joint[ch->joint]);
      if (!dcm_config_has(robot, key))
        return dcm_config_fail(robot, err, n, "%s: joint '%s' has current mode (can.lua boards[%d] (%s)) but no "
                               "actuator", key, t->joint[ch->joint], b->row, b->name);
      if (dcm_config_str(robot, key, model, sizeof model, err, n) < 0) return -EINVAL;
      snprintf(key, sizeof key, "%s.torque", model);
      if (dcm_config_num(act, key, &ch->torque, err, n) < 0) return -EINVAL;
      snprintf(key, sizeof key, "%s.speed", model);
      if (dcm_config_num(act, key, &ch->speed, err, n) < 0) return -EINVAL;
      if (!(ch->torque > 0) || !(ch->speed > 0))
        return dcm_config_fail(act, err, n, "%s: torque and speed must be > 0, got %g N*m and %g rad/s", model,
                               ch->torque, ch->speed);
    }
  }
  return 0;
}

int ht_load(const dcm_config *robot, const dcm_config *can, ht_table *t, char *err, size_t n) {
  memset(t, 0, sizeof *t);
  if (load_body(robot, t, err, n) < 0 || load_buses(can, t, err, n) < 0) return -EINVAL;
  const int nb = dcm_config_len(can, "boards", err, n);
  if (nb < 0) return -EINVAL;
  if (nb < 1 || nb > HT_BOARD_MAX) return dcm_config_fail(can, err, n, "boards: 1 to %d boards, has %d", HT_BOARD_MAX, nb);
  for (int r = 1; r <= nb; r++)
    if (load_board(can, t, r, err, n) < 0) return -EINVAL;
  for (int j = 0; j < t->nj; j++)
    if (t->joint_board[j] < 0)
      return dcm_config_fail(can, err, n, "joint '%s' of the body (robot.lua) is on no board's channels", t->joint[j]);
  return 0;
}
