/* can_proto: Hubo2+ board frames -- encoders, decoders, wire bits, one bus's bookkeeping. */
#include "can_proto.h"

#include <errno.h>
#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

static void put16(uint8_t *p, int v) {
  p[0] = (uint8_t)(v & 0xFF);
  p[1] = (uint8_t)((v >> 8) & 0xFF);
}
static int16_t get16(const uint8_t *p) { return (int16_t)(uint16_t)(p[0] | (p[1] << 8)); }
static void put32(uint8_t *p, int32_t v) {
  const uint32_t u = (uint32_t)v;
  for (int k = 0; k < 4; k++) p[k] = (uint8_t)(u >> (8 * k));
}
static int32_t get32(const uint8_t *p) {
  return (int32_t)((uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24);
}
/* a value scaled into int16, saturated (a sensor reading beyond the range reads as the range) */
static int sat16(double v) {
  if (!(v == v)) return 0;
  double r = round(v);
  return r > 32767 ? 32767 : r < -32768 ? -32768 : (int)r;
}

static void frame(hcan_frame *f, uint32_t id, int dlc) {
  memset(f, 0, sizeof *f);
  f->id = id;
  f->dlc = (uint8_t)dlc;
}

/* ---------------------------------------------------------------- host -> boards */

/* 24-bit sign-magnitude: magnitude in bits 0-22, bit 23 = negative */
static void put_sm24(uint8_t *p, int32_t c) {
  const uint32_t m = (uint32_t)(c < 0 ? -(int64_t)c : c);
  p[0] = (uint8_t)(m & 0xFF);
  p[1] = (uint8_t)((m >> 8) & 0xFF);
  p[2] = (uint8_t)(((m >> 16) & 0x7F) | (c < 0 ? 0x80 : 0));
}
static int32_t get_sm24(const uint8_t *p) {
  const int32_t m = (int32_t)(p[0] | p[1] << 8 | (p[2] & 0x7F) << 16);
  return (p[2] & 0x80) ? -m : m;
}

int hcan_ref(hcan_frame *f, int board, int32_t c0, int32_t c1) {
  if (c0 > HCAN_REF_MAX || c0 < -HCAN_REF_MAX || c1 > HCAN_REF_MAX || c1 < -HCAN_REF_MAX) return -ERANGE;
  frame(f, HCAN_ID_REF(board), 6);
  put_sm24(f->data, c0);
  put_sm24(f->data + 3, c1);
  return 0;
}

/* A current into counts of HCAN_CUR_UNIT, truncated toward zero; -EINVAL / -ERANGE. */
static int cur_counts(double amps, int32_t *c) {
  if (!isfinite(amps)) return -EINVAL;
  /* 0.29 A / 0.01 is 28.999999999999996 in binary: a value within a millionth of a count of a whole
   * count is that count, anything else is truncated */
  const double x = amps / HCAN_CUR_UNIT, r = round(x);
  const double n = fabs(x - r) < 1e-6 ? r : trunc(x);
  if (n > HCAN_REF_MAX || n < -HCAN_REF_MAX) return -ERANGE;
  *c = (int32_t)n;
  return 0;
}

int hcan_cur_ref(hcan_frame *f, int board, double amps0, double amps1) {
  int32_t c0, c1;
  int r = cur_counts(amps0, &c0);
  if (r == 0) r = cur_counts(amps1, &c1);
  if (r < 0) return r;
  frame(f, HCAN_ID_REF(board), 6);
  put_sm24(f->data, c0);
  put_sm24(f->data + 3, c1);
  return 0;
}

void hcan_cmd(hcan_frame *f, int board, int code, const uint8_t *args, int nargs) {
  if (nargs < 0) nargs = 0;
  if (nargs > 6) nargs = 6;
  frame(f, HCAN_ID_CMD, 2 + nargs);
  f->data[0] = (uint8_t)board;
  f->data[1] = (uint8_t)code;
  if (nargs) memcpy(f->data + 2, args, (size_t)nargs);
}

void hcan_req_encoder(hcan_frame *f, int board, int sel) {
  const uint8_t a = (uint8_t)sel;
  hcan_cmd(f, board, HCAN_C_ENCODER, &a, 1);
}
void hcan_req_status(hcan_frame *f, int board) {
  const uint8_t a = 0;
  hcan_cmd(f, board, HCAN_C_STATUS, &a, 1);
}
void hcan_req_current(hcan_frame *f, int board) { hcan_cmd(f, board, HCAN_C_CURRENT, NULL, 0); }
void hcan_home(hcan_frame *f, int board, int ch) {
  /* the firmware numbers channels from 1 here; bit 1: home with the stored parameters */
  const int sel = ch == HCAN_ALL_CHANNELS ? 0x0F : ch + 1;
  const uint8_t a[6] = { (uint8_t)((sel << 4) | 0x02), 0, 0, 0, 0, 0 };
  hcan_cmd(f, board, HCAN_C_HOME, a, 6);
}
void hcan_fet(hcan_frame *f, int board, int on) {
  const uint8_t a = on ? 1 : 0;
  hcan_cmd(f, board, HCAN_C_FET, &a, 1);
}
void hcan_ctrl(hcan_frame *f, int board, int on) {
  hcan_cmd(f, board, on ? HCAN_C_CTRL_ON : HCAN_C_CTRL_OFF, NULL, 0);
}
void hcan_enc_zero(hcan_frame *f, int board, int ch) {
  const uint8_t a = (uint8_t)ch;
  hcan_cmd(f, board, HCAN_C_ENC_ZERO, &a, 1);
}
void hcan_ctrl_mode(hcan_frame *f, int board, int mode) {
  const uint8_t a = (uint8_t)mode;
  hcan_cmd(f, board, HCAN_C_CTRL_MODE, &a, 1);
}
static void sensor_req(hcan_frame *f, int sensor, const uint8_t *b, int n) {
  frame(f, HCAN_ID_SENSOR_REQ, 1 + n);
  f->data[0] = (uint8_t)sensor;
  memcpy(f->data + 1, b, (size_t)n);
}
void hcan_req_ft(hcan_frame *f, int sensor) {
  const uint8_t b[] = { HCAN_S_FT };
  sensor_req(f, sensor, b, 1);
}
void hcan_req_tilt(hcan_frame *f, int sensor) {
  const uint8_t b[] = { HCAN_S_TILT };
  sensor_req(f, sensor, b, 1);
}
void hcan_req_imu(hcan_frame *f, int sensor) {
  const uint8_t b[] = { HCAN_S_IMU, 0x01 };
  sensor_req(f, sensor, b, 2);
}
void hcan_req_power(hcan_frame *f) { hcan_cmd(f, HCAN_POWER_BOARD, HCAN_C_POWER, NULL, 0); }

/* ---------------------------------------------------------------- boards -> host */

void hcan_rep_encoder(hcan_frame *f, int board, int32_t c0, int32_t c1) {
  frame(f, HCAN_ID_ENC(board), 8);
  put32(f->data, c0);
  put32(f->data + 4, c1);
}

void hcan_rep_status(hcan_frame *f, int board, const hcan_status st[2]) {
  frame(f, HCAN_ID_STATUS(board), 8);
  for (int ch = 0; ch < 2; ch++) {
    f->data[4 * ch + 0] = st[ch].flags;
    f->data[4 * ch + 1] = st[ch].faults;
    f->data[4 * ch + 2] = st[ch].limits;
  }
}

void hcan_rep_current(hcan_frame *f, int board, const double amps[2], double temp) {
  frame(f, HCAN_ID_CURRENT(board), 4);
  for (int i = 0; i < 2; i++) {
    double a = round(amps[i] * 100);
    const int c = a < 0 || !(a == a) ? 0 : a > 1023 ? 1023 : (int)a;   /* 10-bit, unsigned */
    f->data[i] = (uint8_t)(c >> 2);
    f->data[3] |= (uint8_t)((c & 0x3) << (2 * i));
  }
  f->data[2] = (uint8_t)(temp < 0 || !(temp == temp) ? 0 : temp > 255 ? 255 : (int)round(temp));
}

void hcan_rep_ft(hcan_frame *f, int sensor, double mx, double my, double fz) {
  frame(f, HCAN_ID_FT(sensor), 6);
  put16(f->data, sat16(mx * 100));
  put16(f->data + 2, sat16(my * 100));
  put16(f->data + 4, sat16(fz * 10));
}

void hcan_rep_imu(hcan_frame *f, int sensor, double roll, double pitch, double roll_rate, double pitch_rate) {
  frame(f, HCAN_ID_IMU(sensor), 8);
  put16(f->data, sat16(roll / DEG * 100));
  put16(f->data + 2, sat16(pitch / DEG * 100));
  put16(f->data + 4, sat16(roll_rate / DEG * 100));
  put16(f->data + 6, sat16(pitch_rate / DEG * 100));
}

void hcan_rep_tilt(hcan_frame *f, int sensor, double tx, double ty, double az) {
  frame(f, HCAN_ID_IMU(sensor), 6);
  put16(f->data, sat16(tx / DEG * 100));
  put16(f->data + 2, sat16(ty / DEG * 100));
  put16(f->data + 4, sat16(az * 750));
}

void hcan_rep_power(hcan_frame *f, double volt, double amp, double watt) {
  frame(f, HCAN_ID_POWER, 6);
  put16(f->data, sat16(volt * 100));
  put16(f->data + 2, sat16(amp * 100));
  put16(f->data + 4, sat16(watt * 10));
}

/* ---------------------------------------------------------------- decoding */

hcan_kind hcan_classify(const hcan_frame *f, int *number) {
  int dummy;
  if (!number) number = &dummy;
  *number = -1;
  if (f->id & HCAN_ERR) return HCAN_K_ERROR;
  if (f->id & (HCAN_EFF | HCAN_RTR)) return HCAN_K_NONE;
  const uint32_t id = f->id & HCAN_SFF_MASK;
  if (id != f->id) return HCAN_K_NONE;
  if (id == HCAN_ID_CMD) return HCAN_K_CMD;
  if (id == HCAN_ID_SENSOR_REQ) return HCAN_K_SENSOR_REQ;
  struct { uint32_t base, count; hcan_kind kind; } R[] = {
    { 0x010, HCAN_BOARD_MAX, HCAN_K_REF }, { 0x040, HCAN_SENSOR_MAX, HCAN_K_FT },
    { 0x050, HCAN_SENSOR_MAX, HCAN_K_IMU }, { 0x060, HCAN_BOARD_MAX, HCAN_K_ENC },
    { 0x150, HCAN_BOARD_MAX, HCAN_K_STATUS }, { 0x1C0, HCAN_BOARD_MAX, HCAN_K_CURRENT },
  };
  for (size_t k = 0; k < sizeof R / sizeof R[0]; k++)
    if (id >= R[k].base && id < R[k].base + R[k].count) {
      *number = (int)(id - R[k].base);
      return R[k].kind;
    }
  return HCAN_K_NONE;
}

static int need(const hcan_frame *f, int n) { return f->dlc < n || f->dlc > 8 ? HCAN_E_SHORT : 0; }

int hcan_dec_ref(const hcan_frame *f, int32_t c[2]) {
  if (need(f, 6)) return HCAN_E_SHORT;
  c[0] = get_sm24(f->data);
  c[1] = get_sm24(f->data + 3);
  return 0;
}

int hcan_dec_cur_ref(const hcan_frame *f, double amps[2]) {
  if (need(f, 6)) return HCAN_E_SHORT;
  amps[0] = get_sm24(f->data) * HCAN_CUR_UNIT;
  amps[1] = get_sm24(f->data + 3) * HCAN_CUR_UNIT;
  return 0;
}

int hcan_dec_encoder(const hcan_frame *f, int32_t c[2]) {
  if (need(f, 8)) return HCAN_E_SHORT;   /* HuboCan checks DLC == 8 */
  c[0] = get32(f->data);
  c[1] = get32(f->data + 4);
  return 0;
}

int hcan_dec_status(const hcan_frame *f, hcan_status st[2]) {
  if (need(f, 8)) return HCAN_E_SHORT;
  for (int ch = 0; ch < 2; ch++) {
    st[ch].flags = f->data[4 * ch];
    st[ch].faults = f->data[4 * ch + 1];
    st[ch].limits = f->data[4 * ch + 2];
  }
  return 0;
}

int hcan_dec_current(const hcan_frame *f, double amps[2], double *temp) {
  if (need(f, 4)) return HCAN_E_SHORT;
  for (int i = 0; i < 2; i++) amps[i] = ((f->data[i] << 2) | ((f->data[3] >> (2 * i)) & 0x3)) / 100.0;
  *temp = f->data[2];
  return 0;
}

/* Three signed 16-bit fields, each divided by its scale: the layout of the ft, tilt and power frames. */
static int dec3(const hcan_frame *f, double out[3], double s0, double s1, double s2) {
  if (need(f, 6)) return HCAN_E_SHORT;
  out[0] = get16(f->data) / s0;
  out[1] = get16(f->data + 2) / s1;
  out[2] = get16(f->data + 4) / s2;
  return 0;
}

int hcan_dec_ft(const hcan_frame *f, double ft[3]) { return dec3(f, ft, 100.0, 100.0, 10.0); }

int hcan_dec_imu(const hcan_frame *f, double imu[4]) {
  if (need(f, 8)) return HCAN_E_SHORT;
  for (int k = 0; k < 4; k++) imu[k] = get16(f->data + 2 * k) / 100.0 * DEG;
  return 0;
}

int hcan_dec_tilt(const hcan_frame *f, double tilt[3]) {
  if (dec3(f, tilt, 100.0, 100.0, 750.0)) return HCAN_E_SHORT;
  tilt[0] *= DEG;   /* 0.01 deg -> rad */
  tilt[1] *= DEG;
  return 0;
}

int hcan_dec_power(const hcan_frame *f, double p[3]) { return dec3(f, p, 100.0, 100.0, 10.0); }

/* ---------------------------------------------------------------- units */

double hcan_counts_per_rad(int drive, int driven, int harmonic, int enc) {
  return (double)driven * harmonic * enc / ((double)drive * 2 * PI);
}

int32_t hcan_rad_to_counts(double rad, double counts_per_rad) {
  const double c = trunc(rad * counts_per_rad);
  if (!(c == c)) return 0;
  return c > INT32_MAX ? INT32_MAX : c < INT32_MIN ? INT32_MIN : (int32_t)c;
}

double hcan_counts_to_rad(int32_t counts, double counts_per_rad) { return counts / counts_per_rad; }

/* ---------------------------------------------------------------- wire bits */

int hcan_frame_bits(const hcan_frame *f) {
  const int dlc = f->dlc > 8 ? 8 : f->dlc;
  uint8_t bits[19 + 64 + 15];
  int n = 0;
  bits[n++] = 0;                                                    /* SOF */
  for (int k = 10; k >= 0; k--) bits[n++] = (uint8_t)((f->id >> k) & 1);   /* identifier */
  bits[n++] = 0;                                                    /* RTR: data frame */
  bits[n++] = 0;                                                    /* IDE: standard */
  bits[n++] = 0;                                                    /* r0 */
  for (int k = 3; k >= 0; k--) bits[n++] = (uint8_t)((f->dlc >> k) & 1);
  for (int b = 0; b < dlc; b++)
    for (int k = 7; k >= 0; k--) bits[n++] = (uint8_t)((f->data[b] >> k) & 1);
  uint16_t crc = 0;   /* CRC-15, polynomial 0x4599, over SOF .. data */
  for (int i = 0; i < n; i++) {
    const int nxt = bits[i] ^ ((crc >> 14) & 1);
    crc = (uint16_t)((crc << 1) & 0x7FFF);
    if (nxt) crc ^= 0x4599;
  }
  for (int k = 14; k >= 0; k--) bits[n++] = (uint8_t)((crc >> k) & 1);
  /* a stuff bit after five equal bits; the stuff bit starts the next run */
  int stuffed = 0, run = 0, last = -1;
  for (int i = 0; i < n; i++) {
    if (bits[i] == last) run++;
    else { last = bits[i]; run = 1; }
    if (run == 5) {
      stuffed++;
      last = !last;
      run = 1;
    }
  }
  /* + CRC delimiter, ACK slot and delimiter, 7 EOF, 3 interframe */
  return n + stuffed + 13;
}

/* ---------------------------------------------------------------- one bus */

void hcan_net_init(hcan_net *n) {
  memset(n, 0, sizeof *n);
  memset(n->by_board, -1, sizeof n->by_board);
  memset(n->by_sensor, -1, sizeof n->by_sensor);
}

int hcan_net_add(hcan_net *n, hcan_board_kind kind, int number) {
  if (n->n >= HCAN_NET_MAX) return -1;
  const int sensor = kind == HCAN_B_FT || kind == HCAN_B_TILT_FT || kind == HCAN_B_IMU;
  if (sensor ? number < 0 || number >= HCAN_SENSOR_MAX : number < 0 || number >= HCAN_BOARD_MAX) return -1;
  int8_t *slot = sensor ? &n->by_sensor[number] : &n->by_board[number];
  if (*slot >= 0) return -1;
  const int i = n->n++;
  memset(&n->b[i], 0, sizeof n->b[i]);
  n->b[i].kind = kind;
  n->b[i].number = number;
  *slot = (int8_t)i;
  return i;
}

void hcan_net_owe(hcan_net *n, int i, uint32_t mask) {
  if (i < 0 || i >= n->n) return;
  n->b[i].asked |= mask;
  n->b[i].owed |= mask;
}

static int bit_index(uint32_t bit) {
  int k = 0;
  while (bit > 1) {
    bit >>= 1;
    k++;
  }
  return k;
}

/* The board a reply of this kind names, and the reply bit it pays; -1 when none on this bus. */
static int reply_board(const hcan_net *n, hcan_kind k, int num, uint32_t *bit) {
  int i = -1;
  switch (k) {
  case HCAN_K_ENC:
    i = n->by_board[num];
    if (i >= 0) *bit = n->b[i].kind == HCAN_B_POWER ? HCAN_R_POWER : HCAN_R_ENC;
    break;
  case HCAN_K_STATUS: i = n->by_board[num]; *bit = HCAN_R_STATUS; break;
  case HCAN_K_CURRENT: i = n->by_board[num]; *bit = HCAN_R_CURRENT; break;
  case HCAN_K_FT: i = n->by_sensor[num]; *bit = HCAN_R_FT; break;
  case HCAN_K_IMU:
    i = n->by_sensor[num];
    if (i >= 0) *bit = n->b[i].kind == HCAN_B_IMU ? HCAN_R_IMU : HCAN_R_TILT;
    break;
  default: break;
  }
  return i;
}

/* Which reply kinds a board of this kind can give at all. */
static uint32_t can_give(hcan_board_kind k) {
  switch (k) {
  case HCAN_B_JMC: return HCAN_R_ENC | HCAN_R_STATUS | HCAN_R_CURRENT;
  case HCAN_B_FT: return HCAN_R_FT;
  case HCAN_B_TILT_FT: return HCAN_R_FT | HCAN_R_TILT;
  case HCAN_B_IMU: return HCAN_R_IMU;
  case HCAN_B_POWER: return HCAN_R_POWER;
  }
  return 0;
}

static int decode_into(hcan_board *b, uint32_t bit, const hcan_frame *f) {
  hcan_board tmp = *b;   /* nothing changes unless the whole frame decodes */
  int r;
  switch (bit) {
  case HCAN_R_ENC: r = hcan_dec_encoder(f, tmp.enc); break;
  case HCAN_R_STATUS: r = hcan_dec_status(f, tmp.status); break;
  case HCAN_R_CURRENT: r = hcan_dec_current(f, tmp.current, &tmp.temp); break;
  case HCAN_R_FT: r = hcan_dec_ft(f, tmp.ft); break;
  case HCAN_R_TILT: r = f->dlc == 6 ? hcan_dec_tilt(f, tmp.tilt) : HCAN_E_SHORT; break;
  case HCAN_R_IMU: r = hcan_dec_imu(f, tmp.imu); break;
  case HCAN_R_POWER: r = f->dlc == 6 ? hcan_dec_power(f, tmp.power) : HCAN_E_SHORT; break;
  default: r = HCAN_E_FORMAT;
  }
  if (r == 0) *b = tmp;
  return r;
}

int hcan_net_rx(hcan_net *n, const hcan_frame *f) {
  n->rx++;
  if (f->dlc > 8) {
    n->corrupt++;
    return -1;
  }
  int num;
  const hcan_kind k = hcan_classify(f, &num);
  if (k == HCAN_K_ERROR) {
    n->error_frames++;
    n->corrupt++;
    return -1;
  }
  if (k == HCAN_K_REF || k == HCAN_K_CMD || k == HCAN_K_SENSOR_REQ) return -2;   /* another host's frame */
  if (k == HCAN_K_NONE) {
    n->unexpected++;
    return -1;
  }
  uint32_t bit = 0;
  const int i = reply_board(n, k, num, &bit);
  if (i < 0) {
    n->misaddressed++;
    return -1;
  }
  hcan_board *b = &n->b[i];
  if (!(can_give(b->kind) & bit)) {
    n->unexpected++;
    return -1;
  }
  uint8_t *carry = &b->carry[bit_index(bit)];
  if (!(b->owed & bit) && *carry == 0) {
    n->unexpected++;   /* nobody asked, or a second answer */
    return -1;
  }
  if (decode_into(b, bit, f) < 0) {
    n->corrupt++;
    return -1;
  }
  if (b->owed & bit) {
    b->owed &= ~bit;
  } else {
    (*carry)--;
    b->late++;
    b->paid_late |= bit;
  }
  b->fresh |= bit;
  b->replies++;
  if (bit == HCAN_R_STATUS && (hcan_status_fault(b->status[0]) || hcan_status_fault(b->status[1]))) b->faults++;
  return i;
}

int hcan_net_end_cycle(hcan_net *n, int dead_after) {
  int died = 0;
  for (int i = 0; i < n->n; i++) {
    hcan_board *b = &n->b[i];
    for (int k = 0; k < 8; k++) {
      const uint32_t bit = 1u << k;
      if (b->owed & bit) b->carry[k] = (uint8_t)(b->carry[k] < 2 ? b->carry[k] + 1 : 2);
      else if ((b->asked & bit) && !(b->paid_late & bit)) b->carry[k] = 0;
    }
    if (b->owed) {
      b->timeouts++;
      b->missed++;
      if (!b->dead && dead_after > 0 && b->missed >= dead_after) {
        b->dead = 1;
        died++;
      }
    } else if (b->asked) {
      b->missed = 0;
      b->dead = 0;
    }
    b->asked = b->owed = b->fresh = b->paid_late = 0;
  }
  return died;
}
