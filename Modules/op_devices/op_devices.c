/* op_devices: the models the OP DCM knows; reading and checking a body's device table. */
#include "op_devices.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static const op_servo_model SERVOS[] = {
  /* MX-28 (1.0): 36 pos(2) 38 speed(2) 40 load(2) 42 voltage(1) 43 temperature(1) */
  { "MX-28", 1, OP_MX, 30, 2, 36, 2, 36, 8, 24, 34, 2, 1023, 4095 },
  /* XM430-W350 (2.0): 126 current(2) 128 velocity(4) 132 pos(4) ... 144 voltage(2) 146 temp(1) */
  { "XM430-W350", 2, OP_XM, 116, 4, 132, 4, 126, 21, 64, 84, 2, 800, 4095 },
};

static const op_board_model BOARDS[] = {
  { "CM-730", 1, OP_CM730, 30, 21 },   /* 30 button, 38 gyro Z/Y/X (10 bit, 512 = 0), 44 accel X/Y/Z, 50 voltage */
  { "OpenCR", 2, OP_OPENCR, 30, 22 },  /* 30 button, 38 gyro X/Y/Z, 44 accel X/Y/Z (int16), 50 voltage(2) */
};

#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

static void names(char *out, size_t n, int servos) {
  size_t o = 0;
  out[0] = '\0';
  for (int k = 0; k < (servos ? COUNT(SERVOS) : COUNT(BOARDS)) && o < n; k++)
    o += (size_t)snprintf(out + o, n - o, "%s%s", k ? ", " : "", servos ? SERVOS[k].name : BOARDS[k].name);
}

int op_rad_to_count(const op_body *b, const op_servo *s, double rad) {
  const double lo = b->lo[s->joint], hi = b->hi[s->joint];
  if (rad < lo) rad = lo;
  if (rad > hi) rad = hi;
  long c = s->zero + lround(s->dir * rad / OP_RAD_PER_COUNT);
  if (c < 0) c = 0;
  if (c > s->model->max_count) c = s->model->max_count;
  return (int)c;
}

double op_count_to_rad(const op_servo *s, int count) { return s->dir * (count - s->zero) * OP_RAD_PER_COUNT; }

/* ---------------------------------------------------------------- reading */

static int load_joints(const dcm_config *c, op_body *b, char *err, size_t n) {
  int nj = dcm_config_joints(c, b->joint, b->lo, b->hi, err, n);
  if (nj < 0) return nj;
  b->nj = nj;
  if (dcm_config_num(c, "period", &b->period, err, n) < 0) return -EINVAL;
  return dcm_config_str(c, "name", b->name, sizeof b->name, err, n);
}

static int load_buses(const dcm_config *c, op_body *b, char *err, size_t n) {
  int nb = dcm_config_len(c, "buses", err, n);
  if (nb < 0) return nb;
  if (nb < 1 || nb > OP_BUS_MAX) return dcm_config_fail(c, err, n, "buses: 1 to %d buses, has %d", OP_BUS_MAX, nb);
  b->nbus = nb;
  for (int k = 0; k < nb; k++) {
    char key[64];
    op_busdef *bd = &b->bus[k];
    snprintf(key, sizeof key, "buses.%d.port", k + 1);
    if (dcm_config_str(c, key, bd->port, sizeof bd->port, err, n) < 0) return -EINVAL;
    snprintf(key, sizeof key, "buses.%d.baud", k + 1);
    if (dcm_config_int(c, key, &bd->baud, err, n) < 0) return -EINVAL;
    bd->protocol = 0;
  }
  return 0;
}

/* "devices[r] (joint 'x')" or "devices[r] (board 'x')": how messages name a row. */
static const char *row_name(const dcm_config *c, int r, char *buf, size_t n) {
  char key[64], v[DCM_NAME_MAX], e[8];
  snprintf(key, sizeof key, "devices.%d.joint", r);
  if (dcm_config_str(c, key, v, sizeof v, e, sizeof e) == 0) {
    snprintf(buf, n, "devices[%d] (joint '%s')", r, v);
    return buf;
  }
  snprintf(key, sizeof key, "devices.%d.board", r);
  if (dcm_config_str(c, key, v, sizeof v, e, sizeof e) == 0) {
    snprintf(buf, n, "devices[%d] (board '%s')", r, v);
    return buf;
  }
  snprintf(buf, n, "devices[%d]", r);
  return buf;
}

/* The fields every row has: bus, id, protocol; the bus takes the row's protocol. */
static int load_common(const dcm_config *c, op_body *b, int r, int *bus, int *id, int *protocol, char *err, size_t n) {
  char key[64], rn[128];
  snprintf(key, sizeof key, "devices.%d.bus", r);
  if (dcm_config_int(c, key, bus, err, n) < 0) return -EINVAL;
  if (*bus < 1 || *bus > b->nbus)
    return dcm_config_fail(c, err, n, "%s: bus %d is not one of buses (1 to %d)", row_name(c, r, rn, sizeof rn), *bus, b->nbus);
  snprintf(key, sizeof key, "devices.%d.id", r);
  if (dcm_config_int(c, key, id, err, n) < 0) return -EINVAL;
  if (*id < 0 || *id > 252) return dcm_config_fail(c, err, n, "%s: id %d is not 0..252", row_name(c, r, rn, sizeof rn), *id);
  snprintf(key, sizeof key, "devices.%d.protocol", r);
  if (dcm_config_int(c, key, protocol, err, n) < 0) return -EINVAL;
  if (*protocol != 1 && *protocol != 2)
    return dcm_config_fail(c, err, n, "%s: protocol must be 1 or 2, got %d", row_name(c, r, rn, sizeof rn), *protocol);
  op_busdef *bd = &b->bus[*bus - 1];
  if (bd->protocol && bd->protocol != *protocol)
    return dcm_config_fail(c, err, n, "%s: protocol %d on bus %d, whose other devices speak protocol %d",
                           row_name(c, r, rn, sizeof rn), *protocol, *bus, bd->protocol);
  bd->protocol = *protocol;
  return 0;
}

static int load_servo(const dcm_config *c, op_body *b, int r, char *err, size_t n) {
  char key[64], s[DCM_NAME_MAX], rn[128];
  int bus, id, protocol;
  if (load_common(c, b, r, &bus, &id, &protocol, err, n) < 0) return -EINVAL;
  op_busdef *bd = &b->bus[bus - 1];
  op_servo *sv = &bd->servo[bd->nservo];
  sv->row = r;
  sv->id = (uint8_t)id;
  snprintf(key, sizeof key, "devices.%d.joint", r);
  if (dcm_config_str(c, key, s, sizeof s, err, n) < 0) return -EINVAL;
  sv->joint = -1;
  for (int j = 0; j < b->nj; j++)
    if (!strcmp(b->joint[j], s)) sv->joint = j;
  if (sv->joint < 0) return dcm_config_fail(c, err, n, "%s: '%s' is not one of the robot's joints", row_name(c, r, rn, sizeof rn), s);
  snprintf(key, sizeof key, "devices.%d.model", r);
  if (dcm_config_str(c, key, s, sizeof s, err, n) < 0) return -EINVAL;
  sv->model = NULL;
  for (int k = 0; k < COUNT(SERVOS); k++)
    if (!strcmp(SERVOS[k].name, s)) sv->model = &SERVOS[k];
  if (!sv->model) {
    char known[256];
    names(known, sizeof known, 1);
    return dcm_config_fail(c, err, n, "%s: unknown model '%s' (known: %s)", row_name(c, r, rn, sizeof rn), s, known);
  }
  if (sv->model->protocol != protocol)
    return dcm_config_fail(c, err, n, "%s: the %s speaks protocol %d, the row says %d", row_name(c, r, rn, sizeof rn),
                           s, sv->model->protocol, protocol);
  snprintf(key, sizeof key, "devices.%d.direction", r);
  if (dcm_config_int(c, key, &sv->dir, err, n) < 0) return -EINVAL;
  if (sv->dir != 1 && sv->dir != -1)
    return dcm_config_fail(c, err, n, "%s: direction must be 1 or -1, got %d", row_name(c, r, rn, sizeof rn), sv->dir);
  snprintf(key, sizeof key, "devices.%d.zero", r);
  if (dcm_config_int(c, key, &sv->zero, err, n) < 0) return -EINVAL;
  if (sv->zero < 0 || sv->zero > sv->model->max_count)
    return dcm_config_fail(c, err, n, "%s: zero %d is not 0..%d", row_name(c, r, rn, sizeof rn), sv->zero, sv->model->max_count);
  /* one sync write per register serves the bus: its servos must share those registers */
  const op_servo_model *m0 = bd->servo[0].model;
  if (bd->nservo > 0 && (m0->goal_addr != sv->model->goal_addr || m0->goal_len != sv->model->goal_len ||
                         m0->torque_addr != sv->model->torque_addr || m0->hard_addr != sv->model->hard_addr ||
                         m0->hard_len != sv->model->hard_len))
    return dcm_config_fail(c, err, n, "%s: the %s's goal, torque or hardness registers differ from the %s's (devices[%d]) on bus %d",
                           row_name(c, r, rn, sizeof rn), s, m0->name, bd->servo[0].row, bus);
  bd->nservo++;
  return 0;
}

/* A board's axes: three of 'x', 'y', 'z' (each once), each optionally signed. */
static int load_axes(const dcm_config *c, int r, const char *what, int axis[3], double sign[3], char *err, size_t n) {
  char key[64], v[3][DCM_NAME_MAX], rn[128];
  snprintf(key, sizeof key, "devices.%d.%s", r, what);
  if (dcm_config_strs(c, key, v, 3, 3, err, n) < 0) return -EINVAL;
  int used = 0;
  for (int i = 0; i < 3; i++) {
    const char *p = v[i];
    sign[i] = *p == '-' ? -1 : 1;
    if (*p == '-' || *p == '+') p++;
    axis[i] = (p[0] == 'x' || p[0] == 'X') ? 0 : (p[0] == 'y' || p[0] == 'Y') ? 1 : (p[0] == 'z' || p[0] == 'Z') ? 2 : -1;
    if (axis[i] < 0 || p[1] || (used & (1 << axis[i])))
      return dcm_config_fail(c, err, n, "%s: %s must give each of 'x', 'y', 'z' once (with an optional sign), got '%s' '%s' '%s'",
                             row_name(c, r, rn, sizeof rn), what, v[0], v[1], v[2]);
    used |= 1 << axis[i];
  }
  return 0;
}

static int load_board(const dcm_config *c, op_body *b, int r, char *err, size_t n) {
  char key[64], s[DCM_NAME_MAX], rn[128];
  int bus, id, protocol;
  if (load_common(c, b, r, &bus, &id, &protocol, err, n) < 0) return -EINVAL;
  if (b->imu_bus >= 0)
    return dcm_config_fail(c, err, n, "%s: a second board (devices[%d] is one; the DCM reads one IMU)",
                           row_name(c, r, rn, sizeof rn), b->bus[b->imu_bus].board.row);
  op_busdef *bd = &b->bus[bus - 1];
  op_board *bo = &bd->board;
  bo->row = r;
  bo->id = (uint8_t)id;
  snprintf(key, sizeof key, "devices.%d.board", r);
  if (dcm_config_str(c, key, s, sizeof s, err, n) < 0) return -EINVAL;
  bo->model = NULL;
  for (int k = 0; k < COUNT(BOARDS); k++)
    if (!strcmp(BOARDS[k].name, s)) bo->model = &BOARDS[k];
  if (!bo->model) {
    char known[256];
    names(known, sizeof known, 0);
    return dcm_config_fail(c, err, n, "%s: unknown board '%s' (known: %s)", row_name(c, r, rn, sizeof rn), s, known);
  }
  if (bo->model->protocol != protocol)
    return dcm_config_fail(c, err, n, "%s: the %s speaks protocol %d, the row says %d", row_name(c, r, rn, sizeof rn),
                           s, bo->model->protocol, protocol);
  if (load_axes(c, r, "gyro_axes", bo->gyro_axis, bo->gyro_sign, err, n) < 0 ||
      load_axes(c, r, "accel_axes", bo->accel_axis, bo->accel_sign, err, n) < 0)
    return -EINVAL;
  bd->has_board = 1;
  b->imu_bus = bus - 1;
  return 0;
}

int op_body_load(const dcm_config *c, op_body *b, char *err, size_t n) {
  memset(b, 0, sizeof *b);
  b->imu_bus = -1;
  if (load_joints(c, b, err, n) < 0 || load_buses(c, b, err, n) < 0) return -EINVAL;
  int nd = dcm_config_len(c, "devices", err, n);
  if (nd < 0) return nd;
  for (int r = 1; r <= nd; r++) {
    char key[64];
    snprintf(key, sizeof key, "devices.%d.joint", r);
    const int servo = dcm_config_has(c, key);
    snprintf(key, sizeof key, "devices.%d.board", r);
    const int board = dcm_config_has(c, key);
    if (servo == board)
      return dcm_config_fail(c, err, n, "devices[%d]: a row names either a joint (a servo) or a board", r);
    if ((servo ? load_servo(c, b, r, err, n) : load_board(c, b, r, err, n)) < 0) return -EINVAL;
  }
  /* every joint exactly once; ids unique on each bus */
  int row_of[DCM_NJ_MAX] = { 0 };
  for (int k = 0; k < b->nbus; k++) {
    const op_busdef *bd = &b->bus[k];
    int seen[253] = { 0 };
    if (bd->has_board) seen[bd->board.id] = bd->board.row;
    for (int i = 0; i < bd->nservo; i++) {
      const op_servo *sv = &bd->servo[i];
      char rn[128];
      if (row_of[sv->joint])
        return dcm_config_fail(c, err, n, "%s: the joint has a servo already (devices[%d])", row_name(c, sv->row, rn, sizeof rn),
                               row_of[sv->joint]);
      row_of[sv->joint] = sv->row;
      if (seen[sv->id]) {
        const int a = seen[sv->id] < sv->row ? seen[sv->id] : sv->row, z = seen[sv->id] < sv->row ? sv->row : seen[sv->id];
        return dcm_config_fail(c, err, n, "%s: id %d on bus %d is taken by devices[%d] too", row_name(c, z, rn, sizeof rn),
                               sv->id, k + 1, a);
      }
      seen[sv->id] = sv->row;
    }
  }
  for (int j = 0; j < b->nj; j++)
    if (!row_of[j]) return dcm_config_fail(c, err, n, "joint '%s' (joints[%d]) has no servo in devices", b->joint[j], j + 1);
  for (int k = 0; k < b->nbus; k++)
    if (!b->bus[k].protocol) return dcm_config_fail(c, err, n, "buses[%d]: no device is on this bus", k + 1);
  return 0;
}
