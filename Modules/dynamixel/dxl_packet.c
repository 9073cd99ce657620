/* dxl_packet.c: Dynamixel protocol 1.0 / 2.0 packets: build, parse, checksum, CRC-16, stuffing.
 * No I/O and no allocation; every read is bounds-checked against the caller's length. */
#include "dynamixel/dynamixel.h"

#include <stdio.h>
#include <string.h>

/* ---------------------------------------------------------------- result text */

const char *dxl_result_str(int result) {
  switch (result) {
  case DXL_COMM_SUCCESS: return "success";
  case DXL_COMM_PORT_BUSY: return "port busy";
  case DXL_COMM_TX_FAIL: return "write to port failed";
  case DXL_COMM_RX_FAIL: return "read from port failed";
  case DXL_COMM_TX_ERROR: return "bad instruction packet";
  case DXL_COMM_RX_WAITING: return "receiving";
  case DXL_COMM_RX_TIMEOUT: return "no answer (timeout)";
  case DXL_COMM_RX_CORRUPT: return "corrupt answer";
  case DXL_COMM_NOT_AVAILABLE: return "not available in this protocol";
  case DXL_EARG: return "bad argument";
  case DXL_ETRUNC: return "truncated packet";
  case DXL_ETOOLONG: return "packet too long";
  case DXL_EID: return "answer from an unexpected id";
  case DXL_EORDER: return "answer out of order";
  case DXL_ESTATUS: return "servo reported an error";
  case DXL_EPORT: return "port unavailable";
  default: return "unknown result";
  }
}

static void append(char *buf, size_t len, size_t *n, const char *s) {
  if (*n + 1 >= len) return;
  int w = snprintf(buf + *n, len - *n, "%s%s", *n ? "|" : "", s);
  if (w > 0) *n += (size_t)w;
  if (*n >= len) *n = len - 1;
}

const char *dxl_error_str(int protocol, uint8_t error, char *buf, size_t len) {
  if (!buf || len == 0) return "";
  buf[0] = 0;
  if (error == 0) { snprintf(buf, len, "ok"); return buf; }
  size_t n = 0;
  if (protocol == 1) {
    static const char *names[7] = { "voltage", "angle_limit", "overheat", "range", "checksum",
                                     "overload", "instruction" };
    for (int b = 0; b < 7; b++) if (error & (1 << b)) append(buf, len, &n, names[b]);
    if (error & 0x80) append(buf, len, &n, "bit7");
  } else {
    static const char *names[8] = { "none", "result_fail", "instruction", "crc", "data_range",
                                     "data_length", "data_limit", "access" };
    int num = error & 0x7F;
    if (num) append(buf, len, &n, num < 8 ? names[num] : "unknown");
    if (error & DXL2_ERR_ALERT) append(buf, len, &n, "hardware_alert");
  }
  return buf;
}

/* ---------------------------------------------------------------- checksums */

static uint16_t crc_table[256];
static int crc_ready;

static void crc_init(void) {
  for (int i = 0; i < 256; i++) {
    uint16_t c = (uint16_t)(i << 8);
    for (int b = 0; b < 8; b++) c = (uint16_t)((c & 0x8000) ? (c << 1) ^ 0x8005 : c << 1);
    crc_table[i] = c;
  }
  crc_ready = 1;
}

uint16_t dxl_crc16(uint16_t crc, const uint8_t *data, size_t len) {
  if (!crc_ready) crc_init();   /* idempotent: a race only computes the same table twice */
  for (size_t i = 0; i < len; i++)
    crc = (uint16_t)((crc << 8) ^ crc_table[((crc >> 8) ^ data[i]) & 0xFF]);
  return crc;
}

uint8_t dxl_checksum1(const uint8_t *data, size_t len) {
  unsigned sum = 0;
  for (size_t i = 0; i < len; i++) sum += data[i];
  return (uint8_t)(~sum & 0xFF);
}

/* ---------------------------------------------------------------- stuffing */

int dxl_stuff(const uint8_t *in, size_t len, uint8_t *out, size_t outlen) {
  if ((!in && len) || !out) return DXL_EARG;
  size_t o = 0;
  for (size_t i = 0; i < len; i++) {
    if (o >= outlen) return DXL_EARG;
    out[o++] = in[i];
    if (i >= 2 && in[i - 2] == 0xFF && in[i - 1] == 0xFF && in[i] == 0xFD) {
      if (o >= outlen) return DXL_EARG;
      out[o++] = 0xFD;
    }
  }
  return (int)o;
}

/* Unstuffing state: the last two bytes produced, so a pattern may cross calls. */
typedef struct unstuff_state { uint8_t b1, b2; int skip_next; } unstuff_state;

/* Feeds one stuffed byte; returns 1 if it is a data byte (in *v), 0 if it was a stuffing byte. */
static int unstuff_byte(unstuff_state *s, uint8_t in, uint8_t *v) {
  if (s->skip_next) {
    s->skip_next = 0;
    if (in == 0xFD) { s->b1 = s->b2 = 0; return 0; }
    /* FF FF FD not followed by FD: invalid stuffing, keep the byte (caller's CRC decided). */
  }
  *v = in;
  if (s->b1 == 0xFF && s->b2 == 0xFF && in == 0xFD) s->skip_next = 1;
  s->b1 = s->b2;
  s->b2 = in;
  return 1;
}

int dxl_unstuff(const uint8_t *in, size_t len, uint8_t *out, size_t outlen) {
  if ((!in && len) || !out) return DXL_EARG;
  unstuff_state s = { 0, 0, 0 };
  size_t o = 0;
  for (size_t i = 0; i < len; i++) {
    uint8_t v;
    if (!unstuff_byte(&s, in[i], &v)) continue;
    if (o >= outlen) return DXL_EARG;
    out[o++] = v;
  }
  return (int)o;
}

/* ---------------------------------------------------------------- building */

int dxl_instruction_size(int protocol, int nparams) {
  return protocol == 1 ? 6 + nparams : 10 + nparams;
}

int dxl_status_size(int protocol, int nparams) {
  return protocol == 1 ? 6 + nparams : 11 + nparams;
}

/* body = instruction/error byte(s) then params; 1.0 writes them as they are. */
static int build(int protocol, uint8_t id, const uint8_t *head, size_t nhead, const uint8_t *params,
                 size_t nparams, uint8_t *out, size_t outlen) {
  if (!out || (!params && nparams) || id == 0xFF) return DXL_EARG;
  if (protocol == 1) {
    size_t total = 4 + nhead + nparams + 1;
    if (nhead + nparams + 1 > 255) return DXL_COMM_TX_ERROR;
    if (total > outlen) return DXL_EARG;
    out[0] = 0xFF; out[1] = 0xFF; out[2] = id; out[3] = (uint8_t)(nhead + nparams + 1);
    memcpy(out + 4, head, nhead);
    if (nparams) memcpy(out + 4 + nhead, params, nparams);
    out[total - 1] = dxl_checksum1(out + 2, total - 3);
    return (int)total;
  }
  if (protocol != 2) return DXL_EARG;
  if (outlen < 10 + nhead) return DXL_EARG;
  out[0] = 0xFF; out[1] = 0xFF; out[2] = 0xFD; out[3] = 0x00; out[4] = id;
  /* stuff head+params as one sequence, so a pattern crossing the boundary is caught */
  size_t o = 7;
  uint8_t b1 = 0, b2 = 0;
  for (size_t i = 0; i < nhead + nparams; i++) {
    uint8_t v = i < nhead ? head[i] : params[i - nhead];
    if (o + 1 + 2 > outlen) return DXL_EARG;
    out[o++] = v;
    if (b1 == 0xFF && b2 == 0xFF && v == 0xFD) {
      if (o + 1 + 2 > outlen) return DXL_EARG;
      out[o++] = 0xFD;
      b1 = b2 = 0;   /* the stuffing byte does not start a new pattern */
    } else {
      b1 = b2; b2 = v;
    }
  }
  size_t length = o - 7 + 2;
  if (length > 0xFFFF) return DXL_COMM_TX_ERROR;
  dxl_put16(out + 5, (uint16_t)length);
  uint16_t crc = dxl_crc16(0, out, o);
  dxl_put16(out + o, crc);
  return (int)(o + 2);
}

int dxl_build_instruction(int protocol, uint8_t id, uint8_t inst, const uint8_t *params,
                          size_t nparams, uint8_t *out, size_t outlen) {
  return build(protocol, id, &inst, 1, params, nparams, out, outlen);
}

int dxl_build_status(int protocol, uint8_t id, uint8_t error, const uint8_t *params,
                     size_t nparams, uint8_t *out, size_t outlen) {
  if (protocol == 1) return build(1, id, &error, 1, params, nparams, out, outlen);
  uint8_t head[2] = { DXL_INST_STATUS, error };
  return build(protocol, id, head, 2, params, nparams, out, outlen);
}

/* ---------------------------------------------------------------- parsing */

static int parse1(int is_status, const uint8_t *buf, size_t len, size_t max_params,
                  dxl_packet *pkt, size_t *consumed) {
  size_t i = 0;
  for (;;) {
    /* find FF FF with a non-FF id after it */
    while (i + 1 < len && !(buf[i] == 0xFF && buf[i + 1] == 0xFF)) i++;
    if (i + 1 >= len) {                       /* no header: keep a trailing FF */
      *consumed = (len > 0 && buf[len - 1] == 0xFF) ? len - 1 : len;
      return 0;
    }
    if (i + 2 < len && buf[i + 2] == 0xFF) { i++; continue; }  /* FF FF FF: slide */
    break;
  }
  if (len - i < 4) { *consumed = i; return 0; }
  size_t l = buf[i + 3];
  if (l < 2) { *consumed = i + 1; return DXL_COMM_RX_CORRUPT; }
  if (l - 2 > max_params) { *consumed = i + 1; return DXL_ETOOLONG; }
  size_t total = 4 + l;
  if (len - i < total) { *consumed = i; return 0; }
  const uint8_t *p = buf + i;
  if (dxl_checksum1(p + 2, total - 3) != p[total - 1]) { *consumed = i + 1; return DXL_COMM_RX_CORRUPT; }
  pkt->protocol = 1;
  pkt->id = p[2];
  if (is_status) { pkt->instruction = 0; pkt->error = p[4]; }
  else { pkt->instruction = p[4]; pkt->error = 0; }
  pkt->nparams = (uint16_t)(l - 2);
  memcpy(pkt->params, p + 5, l - 2);
  *consumed = i + total;
  return 1;
}

static int parse2(const uint8_t *buf, size_t len, size_t max_params, dxl_packet *pkt,
                  size_t *consumed) {
  size_t i = 0;
  for (;;) {
    while (i + 2 < len && !(buf[i] == 0xFF && buf[i + 1] == 0xFF && buf[i + 2] == 0xFD)) i++;
    if (i + 2 >= len) {   /* keep a possible partial header at the end */
      size_t keep = 0;
      if (len >= 1 && buf[len - 1] == 0xFF) keep = 1;
      if (len >= 2 && buf[len - 2] == 0xFF && buf[len - 1] == 0xFF) keep = 2;
      *consumed = len - keep;
      return 0;
    }
    if (i + 3 < len && buf[i + 3] != 0x00) { i++; continue; }   /* not a header (e.g. FF FF FD FD) */
    break;
  }
  if (len - i < 8) { *consumed = i; return 0; }   /* header, id, length, instruction */
  const uint8_t *p = buf + i;
  size_t l = dxl_get16(p + 5);
  if (l < 3 || p[4] == 0xFF) { *consumed = i + 1; return DXL_COMM_RX_CORRUPT; }
  /* stuffing adds at most one byte per three: bound the stuffed length by max_params */
  size_t body_max = max_params + 2;             /* instruction + error + params */
  if (l - 2 > body_max + body_max / 3 + 1) { *consumed = i + 1; return DXL_ETOOLONG; }
  size_t total = 7 + l;
  if (len - i < total) { *consumed = i; return 0; }
  if (dxl_crc16(0, p, total - 2) != dxl_get16(p + total - 2)) {
    *consumed = i + 1;
    return DXL_COMM_RX_CORRUPT;
  }
  unstuff_state s = { 0, 0, 0 };
  size_t k = 0, np = 0;
  int status = 0;
  pkt->error = 0;
  for (size_t j = 7; j < total - 2; j++) {
    uint8_t v;
    if (!unstuff_byte(&s, p[j], &v)) continue;
    if (k == 0) { pkt->instruction = v; status = (v == DXL_INST_STATUS); }
    else if (k == 1 && status) pkt->error = v;
    else {
      if (np >= max_params) { *consumed = i + total; return DXL_ETOOLONG; }
      pkt->params[np++] = v;
    }
    k++;
  }
  if (status && k < 2) { *consumed = i + total; return DXL_COMM_RX_CORRUPT; }  /* no error byte */
  pkt->protocol = 2;
  pkt->id = p[4];
  pkt->nparams = (uint16_t)np;
  *consumed = i + total;
  return 1;
}

int dxl_parse(int protocol, int is_status, const uint8_t *buf, size_t len, size_t max_params,
              dxl_packet *pkt, size_t *consumed) {
  if (!consumed) return DXL_EARG;
  *consumed = 0;
  if (!pkt || (!buf && len)) return DXL_EARG;
  if (max_params == 0 || max_params > DXL_MAX_PARAMS) max_params = DXL_MAX_PARAMS;
  if (protocol == 1) return parse1(is_status, buf, len, max_params, pkt, consumed);
  if (protocol == 2) return parse2(buf, len, max_params, pkt, consumed);
  return DXL_EARG;
}

/* ---------------------------------------------------------------- group parameters */

int dxl_sync_write_params(int protocol, uint16_t addr, uint16_t len, const uint8_t *ids, int n,
                          const uint8_t *data, uint8_t *out, size_t outlen) {
  if (!ids || !data || !out || n <= 0 || len == 0) return DXL_EARG;
  size_t hdr = protocol == 1 ? 2 : 4;
  size_t need = hdr + (size_t)n * (1 + (size_t)len);
  if (need > outlen) return DXL_EARG;
  if (protocol == 1) {
    if (addr > 255 || len > 255) return DXL_COMM_TX_ERROR;
    out[0] = (uint8_t)addr; out[1] = (uint8_t)len;
  } else if (protocol == 2) {
    dxl_put16(out, addr); dxl_put16(out + 2, len);
  } else {
    return DXL_EARG;
  }
  uint8_t *o = out + hdr;
  for (int k = 0; k < n; k++) {
    *o++ = ids[k];
    memcpy(o, data + (size_t)k * len, len);
    o += len;
  }
  return (int)need;
}

int dxl_sync_read_params(uint16_t addr, uint16_t len, const uint8_t *ids, int n, uint8_t *out,
                         size_t outlen) {
  if (!ids || !out || n <= 0) return DXL_EARG;
  size_t need = 4 + (size_t)n;
  if (need > outlen) return DXL_EARG;
  dxl_put16(out, addr); dxl_put16(out + 2, len);
  memcpy(out + 4, ids, (size_t)n);
  return (int)need;
}

int dxl_bulk_read_params(int protocol, const dxl_bulk_item *items, int n, uint8_t *out,
                         size_t outlen) {
  if (!items || !out || n <= 0) return DXL_EARG;
  if (protocol == 1) {
    size_t need = 1 + 3 * (size_t)n;
    if (need > outlen) return DXL_EARG;
    out[0] = 0x00;
    for (int k = 0; k < n; k++) {
      if (items[k].addr > 255 || items[k].len > 255) return DXL_COMM_TX_ERROR;
      out[1 + 3 * k] = (uint8_t)items[k].len;
      out[2 + 3 * k] = items[k].id;
      out[3 + 3 * k] = (uint8_t)items[k].addr;
    }
    return (int)need;
  }
  if (protocol != 2) return DXL_EARG;
  size_t need = 5 * (size_t)n;
  if (need > outlen) return DXL_EARG;
  for (int k = 0; k < n; k++) {
    out[5 * k] = items[k].id;
    dxl_put16(out + 5 * k + 1, items[k].addr);
    dxl_put16(out + 5 * k + 3, items[k].len);
  }
  return (int)need;
}
