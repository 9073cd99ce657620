/* op_bus: one Dynamixel bus of the OP DCM (see op_bus.h). */
#include "op_bus.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

void op_bus_init(op_bus *b, const op_body *body, int index, op_bus_settings set) {
  memset(b, 0, sizeof *b);
  b->body = body;
  b->def = &body->bus[index];
  b->index = index;
  b->set = set;
  for (int k = 0; k < b->def->nservo; k++) b->sent_en[k] = b->sent_hard[k] = -1;
}

int op_bus_open(op_bus *b, const dcm *d, char *err, size_t n) {
  if (!b->port) {
    if (dxl_port_open(b->def->port, b->def->baud, &b->port, err, n)) {
      b->reported = 1;
      return -EAGAIN;
    }
  } else if (dxl_port_reopen(b->port, err, n)) {
    if (!b->reported) dcm_log(d, "bus %d: port lost: %s (retrying)", b->index + 1, err);
    b->reported = 1;
    return -EAGAIN;
  }
  if (b->reported) dcm_log(d, "bus %d: port %s open", b->index + 1, b->def->port);
  b->reported = 0;
  dxl_bus_stats keep = b->bus.stats;
  dxl_bus_init(&b->bus, b->port, b->def->protocol);
  b->bus.stats = keep;
  b->bus.timeout_margin = b->set.timeout_margin;
  /* resend everything after a reconnection */
  for (int k = 0; k < b->def->nservo; k++) {
    b->sent_en[k] = b->sent_hard[k] = -1;
    b->miss[k] = 0;
  }
  return 0;
}

void op_bus_close(op_bus *b) {
  if (b->port) dxl_port_close(b->port);
  b->port = NULL;
}

static int get_count(const op_servo_model *m, const uint8_t *p) {
  return m->pos_len == 2 ? dxl_get16(p) : (int32_t)dxl_get32(p);
}

/* No servo answered the probe: one line for the likely cause instead of a timeout per servo. The
 * servos answering a ping in the other protocol means the body (ROBOT) or the servos' protocol
 * setting is wrong; bytes that parse as neither point at another baud rate (or a noisy bus);
 * silence at the power, the cable or the port. `garbled` is the first servo whose read brought
 * bytes back, -1 if none did. */
static void diagnose(op_bus *b, const dcm *d, int garbled, uint64_t bytes) {
  const op_busdef *bd = b->def;
  const int proto = bd->protocol, other = 3 - proto;
  /* a few pings, each as patient as the probe: the first servos of the table are enough to tell */
  static dxl_bus ob;
  dxl_bus_init(&ob, b->port, other);
  ob.timeout_margin = b->bus.timeout_margin;
  for (int k = 0; k < bd->nservo && k < 3; k++) {
    if (dxl_ping(&ob, bd->servo[k].id, NULL, NULL, NULL) == 0) {
      dcm_log(d, "servo %d answers in another protocol? (got protocol %d.0 bytes, expected %d.0; check ROBOT and the bus)",
              bd->servo[k].id, other, proto);
      return;
    }
  }
  if (garbled >= 0) {
    dcm_log(d, "servo %d answers in another protocol or baud? (got %llu bytes, no protocol %d.0 packet at %d baud; "
            "check ROBOT, the baud and the bus)", bd->servo[garbled].id, (unsigned long long)bytes, proto,
            dxl_port_baud(b->port));
    return;
  }
  dcm_log(d, "bus %d: none of its %d servos answers (%s, protocol %d.0, %d baud): check the power, the cable and the port",
          b->index + 1, bd->nservo, bd->port, proto, dxl_port_baud(b->port));
}

int op_bus_probe(op_bus *b, const dcm *d, op_state *st) {
  int found = 0, garbled = -1, result[DCM_NJ_MAX];
  const double margin = b->bus.timeout_margin;
  const uint64_t rx_bytes0 = b->bus.stats.rx_bytes;
  b->bus.timeout_margin = 0.05;   /* start-up is not real time: be patient once */
  for (int k = 0; k < b->def->nservo; k++) {
    const op_servo *s = &b->def->servo[k];
    uint8_t buf[4], e;
    const uint64_t rx0 = b->bus.stats.rx_bytes;
    result[k] = dxl_read(&b->bus, s->id, s->model->pos_addr, s->model->pos_len, buf, &e);
    if (result[k] == 0) {
      st->pos[s->joint] = op_count_to_rad(s, get_count(s->model, buf));
      st->have_pos[s->joint] = 1;
      found++;
    } else {
      st->dead[s->joint] = 1;
      b->retry_at[k] = 0;
      if (garbled < 0 && b->bus.stats.rx_bytes > rx0) garbled = k;
    }
  }
  if (found == 0 && b->def->nservo > 0 && b->port && dxl_port_is_open(b->port))
    diagnose(b, d, garbled, b->bus.stats.rx_bytes - rx_bytes0);
  else
    for (int k = 0; k < b->def->nservo; k++) {
      const op_servo *s = &b->def->servo[k];
      if (result[k]) dcm_log(d, "servo %d (%s) does not answer: %s", s->id, b->body->joint[s->joint], dxl_result_str(result[k]));
    }
  b->bus.timeout_margin = margin;
  return found;
}

static void put_n(uint8_t *p, int len, long v) {
  if (len == 1) p[0] = (uint8_t)v;
  else if (len == 2) dxl_put16(p, (uint16_t)v);
  else dxl_put32(p, (uint32_t)v);
}

static void write_goals(op_bus *b, const dcm_command *c) {
  const op_busdef *bd = b->def;
  const op_servo_model *m = bd->servo[0].model;   /* the bus's servos share these registers */
  uint8_t ids[DCM_NJ_MAX], data[DCM_NJ_MAX * 4];
  int hv[DCM_NJ_MAX], ch_en = 0, ch_h = 0;
  const int ns = bd->nservo;
  for (int k = 0; k < ns; k++) {
    const op_servo *s = &bd->servo[k];
    ids[k] = s->id;
    hv[k] = (int)lround(c->hardness[s->joint] * s->model->hard_max);
    if (c->enable[s->joint] != b->sent_en[k]) ch_en = 1;
    if (hv[k] != b->sent_hard[k]) ch_h = 1;
  }
  /* torque enable and hardness only when they change */
  if (ch_h) {
    for (int k = 0; k < ns; k++) put_n(data + k * m->hard_len, m->hard_len, hv[k]);
    if (dxl_sync_write(&b->bus, m->hard_addr, m->hard_len, ids, ns, data) == 0)
      for (int k = 0; k < ns; k++) b->sent_hard[k] = hv[k];
  }
  if (ch_en) {
    for (int k = 0; k < ns; k++) data[k] = (uint8_t)(c->enable[bd->servo[k].joint] ? 1 : 0);
    if (dxl_sync_write(&b->bus, m->torque_addr, 1, ids, ns, data) == 0)
      for (int k = 0; k < ns; k++) b->sent_en[k] = c->enable[bd->servo[k].joint];
  }
  for (int k = 0; k < ns; k++) {
    const op_servo *s = &bd->servo[k];
    put_n(data + k * m->goal_len, m->goal_len, op_rad_to_count(b->body, s, c->position[s->joint]));
  }
  dxl_sync_write(&b->bus, m->goal_addr, m->goal_len, ids, ns, data);
}

/* A servo's extended read (speed, load, temperature) into SI. */
static void decode_ext(const op_servo *s, const uint8_t *p, op_state *st) {
  const int j = s->joint;
  if (s->model->family == OP_MX) {        /* MX-28 from 36 */
    int sp = dxl_get16(p + 2), ld = dxl_get16(p + 4);
    double rpm = (sp & 1023) * 0.114 * ((sp & 1024) ? -1 : 1);
    st->vel[j] = s->dir * rpm * 2 * OP_PI / 60;
    st->load[j] = s->dir * (ld & 1023) / 1023.0 * ((ld & 1024) ? -1 : 1);   /* fraction of max torque */
    st->temp[j] = p[7];
  } else {                                /* XM430 from 126 */
    int16_t cur = (int16_t)dxl_get16(p);
    int32_t v = (int32_t)dxl_get32(p + 2);
    st->vel[j] = s->dir * v * 0.229 * 2 * OP_PI / 60;
    st->load[j] = s->dir * cur * 2.69e-3 * 1.78;      /* mA -> N*m (XM430-W350 ~1.78 N*m/A) */
    st->temp[j] = p[20];
  }
}

/* Torso angles: roll / pitch from gravity blended with the gyro, yaw integrates the gyro. */
static void update_angle(op_state *st, double dt) {
  const double ax = st->acc[0], ay = st->acc[1], az = st->acc[2];
  const double roll_a = atan2(ay, az), pitch_a = atan2(-ax, sqrt(ay * ay + az * az));
  const double k = 0.98;
  st->angle[0] = k * (st->angle[0] + st->gyro[0] * dt) + (1 - k) * roll_a;
  st->angle[1] = k * (st->angle[1] + st->gyro[1] * dt) + (1 - k) * pitch_a;
  st->angle[2] += st->gyro[2] * dt;
}

static void decode_board(const op_board *bo, const uint8_t *p, op_state *st) {
  double g[3], a[3];
  const int btn = p[0];
  /* g, a: the board's X, Y, Z */
  if (bo->model->kind == OP_CM730) {     /* from 30: gyro Z Y X at 38, accel X Y Z at 44 */
    const double gs = 1600.0 * OP_PI / 180.0 / 512.0, as = 4 * 9.80665 / 512.0;
    g[2] = (dxl_get16(p + 8) - 512) * gs;
    g[1] = (dxl_get16(p + 10) - 512) * gs;
    g[0] = (dxl_get16(p + 12) - 512) * gs;
    for (int k = 0; k < 3; k++) a[k] = (dxl_get16(p + 14 + 2 * k) - 512) * as;
    st->batt = p[20] * 0.1;
  } else {                                /* OpenCR from 30: gyro X Y Z at 38, accel at 44, int16 */
    const double gs = 0.06103 * OP_PI / 180.0, as = 9.80665 / 2048.0;
    for (int k = 0; k < 3; k++) {
      g[k] = (int16_t)dxl_get16(p + 8 + 2 * k) * gs;
      a[k] = (int16_t)dxl_get16(p + 14 + 2 * k) * as;
    }
    st->batt = dxl_get16(p + 20) * 0.1;
  }
  for (int k = 0; k < 3; k++) {
    st->gyro[k] = bo->gyro_sign[k] * g[bo->gyro_axis[k]];
    st->acc[k] = bo->accel_sign[k] * a[bo->accel_axis[k]];
  }
  st->button[0] = btn & 1;
  st->button[1] = (btn >> 1) & 1;
}

/* One bulk read of the live servos' positions (one servo in turn extended) and of the board. */
static void read_state(op_bus *b, const dcm *d, op_state *st, double now, double dt) {
  const op_busdef *bd = b->def;
  const int ns = bd->nservo;
  dxl_bulk_item items[DCM_NJ_MAX + 1];
  int servo_of[DCM_NJ_MAX + 1], n = 0;
  for (int k = 0; k < ns; k++) {   /* the round-robin servo among the live ones */
    b->rr = (b->rr + 1) % ns;
    if (!st->dead[bd->servo[b->rr].joint]) break;
  }
  for (int k = 0; k < ns; k++) {
    const op_servo *s = &bd->servo[k];
    if (st->dead[s->joint]) continue;
    const int ext = k == b->rr;
    items[n] = (dxl_bulk_item){ s->id, ext ? s->model->ext_addr : s->model->pos_addr,
                                ext ? s->model->ext_len : s->model->pos_len, b->store[n], 0, 0 };
    servo_of[n++] = k;
  }
  if (bd->has_board) {
    items[n] = (dxl_bulk_item){ bd->board.id, bd->board.model->addr, bd->board.model->len, b->store[n], 0, 0 };
    servo_of[n++] = -1;
  }
  if (n == 0) return;
  const int r = dxl_bulk_read(&b->bus, items, n);
  if (r < 0) return;   /* port trouble: reopened next cycle */
  /* no answer at all is a bus problem (power, cable, adapter), not n dead servos */
  const int bus_silent = r == 0;
  for (int i = 0; i < n; i++) {
    const int k = servo_of[i];
    if (k < 0) {
      if (items[i].result == 0) {
        decode_board(&bd->board, b->store[i], st);
        update_angle(st, dt);
      }
      continue;
    }
    const op_servo *s = &bd->servo[k];
    const int j = s->joint;
    if (items[i].result != 0) {
      st->stimeout[j]++;
      if (!bus_silent && ++b->miss[k] >= b->set.dead_after) {
        st->dead[j] = 1;
        b->retry_at[k] = now + b->set.retry_period;
        dcm_log(d, "servo %d (%s) marked dead after %d missed answers", s->id, b->body->joint[j], b->miss[k]);
      }
      continue;
    }
    b->miss[k] = 0;
    if (items[i].error) st->serr[j]++;
    const int ext = items[i].addr == s->model->ext_addr && items[i].len == s->model->ext_len;
    const uint8_t *p = b->store[i] + (ext ? s->model->pos_addr - s->model->ext_addr : 0);
    const double rad = op_count_to_rad(s, get_count(s->model, p));
    if (ext) decode_ext(s, b->store[i], st);
    else if (st->have_pos[j] && dt > 0) st->vel[j] = 0.7 * st->vel[j] + 0.3 * (rad - st->pos[j]) / dt;
    st->pos[j] = rad;
    st->have_pos[j] = 1;
  }
}

/* A dead servo gets one short read every retry_period; it rejoins when it answers. */
static void retry_dead(op_bus *b, const dcm *d, op_state *st, double now) {
  for (int k = 0; k < b->def->nservo; k++) {
    const op_servo *s = &b->def->servo[k];
    if (!st->dead[s->joint] || now < b->retry_at[k]) continue;
    b->retry_at[k] = now + b->set.retry_period;
    uint8_t buf[4], e;
    if (dxl_read(&b->bus, s->id, s->model->pos_addr, s->model->pos_len, buf, &e) == 0) {
      st->dead[s->joint] = 0;
      b->miss[k] = 0;
      b->sent_en[k] = b->sent_hard[k] = -1;
      dcm_log(d, "servo %d (%s) answers again", s->id, b->body->joint[s->joint]);
    }
    return;   /* at most one retry per cycle */
  }
}

void op_bus_write(op_bus *b, const dcm *d, const dcm_command *c, double now) {
  if (!dxl_port_is_open(b->port)) {
    if (now < b->port_retry_at) return;
    b->port_retry_at = now + 0.5;
    char err[256];
    if (op_bus_open(b, d, err, sizeof err) != 0) return;
  }
  write_goals(b, c);
}

void op_bus_read(op_bus *b, const dcm *d, op_state *st, double now, double dt) {
  if (!dxl_port_is_open(b->port)) return;
  read_state(b, d, st, now, dt);
  retry_dead(b, d, st, now);
}

int op_bus_wire_bytes(const op_bus *b, int *tx, int *rx) {
  const op_busdef *bd = b->def;
  const op_servo_model *m = bd->servo[0].model;
  const int n = bd->nservo, p = bd->protocol, items = n + (bd->has_board ? 1 : 0);
  const int sw = dxl_instruction_size(p, (p == 1 ? 2 : 4) + n * (1 + m->goal_len));
  const int br = dxl_instruction_size(p, p == 1 ? 1 + 3 * items : 5 * items);
  int ans = (n - 1) * dxl_status_size(p, m->pos_len) + dxl_status_size(p, m->ext_len);
  if (bd->has_board) ans += dxl_status_size(p, bd->board.model->len);
  *tx = sw + br;
  *rx = ans;
  return sw + br + ans;
}
