/* Protocol 1.0 / 2.0 packets against byte vectors from the ROBOTIS e-Manual examples:
 * checksum, CRC-16, stuffing, status parsing with error bits, bad input. */
#include "dynamixel/dynamixel.h"
#include "tap.h"

#include <stdlib.h>

#define V(...) ((const uint8_t[]){ __VA_ARGS__ })
#define NV(...) ((int)sizeof((const uint8_t[]){ __VA_ARGS__ }))

static uint8_t out[DXL_MAX_PACKET];
static dxl_packet pkt;

static void test_build1(void) {
  int n = dxl_build_instruction(1, 1, DXL_INST_PING, NULL, 0, out, sizeof out);
  check_bytes(out, n, V(0xFF, 0xFF, 0x01, 0x02, 0x01, 0xFB), 6, "1.0 ping id 1");
  n = dxl_build_instruction(1, 1, DXL_INST_READ, V(0x2B, 0x01), 2, out, sizeof out);
  check_bytes(out, n, V(0xFF, 0xFF, 0x01, 0x04, 0x02, 0x2B, 0x01, 0xCC), 8, "1.0 read temperature");
  n = dxl_build_instruction(1, 0xFE, DXL_INST_WRITE, V(0x03, 0x01), 2, out, sizeof out);
  check_bytes(out, n, V(0xFF, 0xFF, 0xFE, 0x04, 0x03, 0x03, 0x01, 0xF6), 8, "1.0 broadcast write id");
  /* e-Manual sync write: 4 servos, goal position + speed (addr 0x1E, 4 bytes) */
  const uint8_t ids[4] = { 0, 1, 2, 3 };
  const uint8_t data[16] = { 0x10, 0x00, 0x50, 0x01, 0x20, 0x02, 0x60, 0x03,
                             0x30, 0x00, 0x70, 0x01, 0x20, 0x02, 0x80, 0x03 };
  uint8_t p[64];
  int np = dxl_sync_write_params(1, 0x1E, 4, ids, 4, data, p, sizeof p);
  n = dxl_build_instruction(1, 0xFE, DXL_INST_SYNC_WRITE, p, (size_t)np, out, sizeof out);
  check_bytes(out, n, V(0xFF, 0xFF, 0xFE, 0x18, 0x83, 0x1E, 0x04, 0x00, 0x10, 0x00, 0x50, 0x01, 0x01,
                      0x20, 0x02, 0x60, 0x03, 0x02, 0x30, 0x00, 0x70, 0x01, 0x03, 0x20, 0x02, 0x80,
                      0x03, 0x12), 28, "1.0 sync write (e-Manual example)");
  /* bulk read: e-Manual example, 2 bytes at 0x1E of id 1, 2 bytes at 0x24 of id 2 */
  dxl_bulk_item it[2] = { { 1, 0x1E, 2, NULL, 0, 0 }, { 2, 0x24, 2, NULL, 0, 0 } };
  np = dxl_bulk_read_params(1, it, 2, p, sizeof p);
  n = dxl_build_instruction(1, 0xFE, DXL_INST_BULK_READ, p, (size_t)np, out, sizeof out);
  check_bytes(out, n, V(0xFF, 0xFF, 0xFE, 0x09, 0x92, 0x00, 0x02, 0x01, 0x1E, 0x02, 0x02, 0x24, 0x1D),
            13, "1.0 bulk read (e-Manual example)");
}

static void test_build2(void) {
  int n = dxl_build_instruction(2, 1, DXL_INST_PING, NULL, 0, out, sizeof out);
  check_bytes(out, n, V(0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x03, 0x00, 0x01, 0x19, 0x4E), 10, "2.0 ping id 1");
  n = dxl_build_instruction(2, 1, DXL_INST_READ, V(0x84, 0x00, 0x04, 0x00), 4, out, sizeof out);
  check_bytes(out, n, V(0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x07, 0x00, 0x02, 0x84, 0x00, 0x04, 0x00, 0x1D,
                      0x15), 14, "2.0 read present position");
  n = dxl_build_instruction(2, 1, DXL_INST_WRITE, V(0x74, 0x00, 0x00, 0x02, 0x00, 0x00), 6, out,
                            sizeof out);
  check_bytes(out, n, V(0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x09, 0x00, 0x03, 0x74, 0x00, 0x00, 0x02, 0x00,
                      0x00, 0xCA, 0x89), 16, "2.0 write goal position 512");
  n = dxl_build_status(2, 1, 0, V(0xA6, 0x00, 0x00, 0x00), 4, out, sizeof out);
  check_bytes(out, n, V(0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x08, 0x00, 0x55, 0x00, 0xA6, 0x00, 0x00, 0x00,
                      0x8C, 0xC0), 15, "2.0 status present position 166");
  n = dxl_build_status(2, 1, 0, V(0x06, 0x04, 0x26), 3, out, sizeof out);
  check_bytes(out, n, V(0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x07, 0x00, 0x55, 0x00, 0x06, 0x04, 0x26, 0x65,
                      0x5D), 14, "2.0 ping status model 1030 fw 38");
  check(dxl_crc16(0, V('1', '2', '3', '4', '5', '6', '7', '8', '9'), 9) == 0xFEE8,
         "CRC-16 check value of 123456789 is 0xFEE8 (CRC-16/BUYPASS)");
}

static void test_stuffing(void) {
  uint8_t s[32], u[32];
  int n = dxl_stuff(V(0x01, 0xFF, 0xFF, 0xFD, 0x02), 5, s, sizeof s);
  check_bytes(s, n, V(0x01, 0xFF, 0xFF, 0xFD, 0xFD, 0x02), 6, "stuffing inserts FD after FF FF FD");
  int m = dxl_unstuff(s, (size_t)n, u, sizeof u);
  check_bytes(u, m, V(0x01, 0xFF, 0xFF, 0xFD, 0x02), 5, "unstuffing removes it");
  n = dxl_stuff(V(0xFF, 0xFF, 0xFD, 0xFD, 0xFF, 0xFF, 0xFD), 7, s, sizeof s);
  check_bytes(s, n, V(0xFF, 0xFF, 0xFD, 0xFD, 0xFD, 0xFF, 0xFF, 0xFD, 0xFD), 9, "stuffing twice");
  m = dxl_unstuff(s, (size_t)n, u, sizeof u);
  check_bytes(u, m, V(0xFF, 0xFF, 0xFD, 0xFD, 0xFF, 0xFF, 0xFD), 7, "unstuffing twice");
  check(dxl_stuff(V(0xFF, 0xFF, 0xFD), 3, s, 3) == DXL_EARG, "stuffing never overruns its output");

  /* write of FF FF FD at 0x0000 of id 1: stuffed in the packet, length counts the extra byte */
  int len = dxl_build_instruction(2, 1, DXL_INST_WRITE, V(0x00, 0x00, 0xFF, 0xFF, 0xFD), 5, out,
                                  sizeof out);
  check(len == 10 + 5 + 1 && out[5] == 9 && out[12] == 0xFD && out[13] == 0xFD,
         "2.0 instruction with FF FF FD in params is stuffed (length 9)");
  size_t used;
  int r = dxl_parse(2, 0, out, (size_t)len, 0, &pkt, &used);
  check(r == 1 && used == (size_t)len && pkt.nparams == 5 && pkt.params[4] == 0xFD &&
         pkt.instruction == DXL_INST_WRITE, "parser unstuffs it back");
  /* status whose data is FF FF FD xx */
  len = dxl_build_status(2, 7, 0, V(0xFF, 0xFF, 0xFD, 0x10), 4, out, sizeof out);
  r = dxl_parse(2, 1, out, (size_t)len, 4, &pkt, &used);
  check(r == 1 && pkt.nparams == 4 && pkt.params[3] == 0x10 && pkt.id == 7,
         "stuffed status packet parses to 4 data bytes");
}

static void test_parse(void) {
  size_t used;
  /* 1.0 status with error bits: overload + overheat */
  uint8_t st[16];
  int n = dxl_build_status(1, 5, DXL1_ERR_OVERLOAD | DXL1_ERR_OVERHEAT, V(0x00, 0x08), 2, st, sizeof st);
  int r = dxl_parse(1, 1, st, (size_t)n, 0, &pkt, &used);
  char eb[64];
  check(r == 1 && pkt.id == 5 && pkt.error == 0x24 && pkt.nparams == 2 && pkt.params[1] == 0x08,
         "1.0 status with error bits parses");
  check(strcmp(dxl_error_str(1, pkt.error, eb, sizeof eb), "overheat|overload") == 0,
         "1.0 error bits named");
  check(strcmp(dxl_error_str(2, 0x80 | DXL2_ERR_DATA_RANGE, eb, sizeof eb),
                "data_range|hardware_alert") == 0, "2.0 error number and alert named");
  /* e-Manual 1.0 status: temperature 32 */
  r = dxl_parse(1, 1, V(0xFF, 0xFF, 0x01, 0x03, 0x00, 0x20, 0xDB), 7, 0, &pkt, &used);
  check(r == 1 && used == 7 && pkt.params[0] == 0x20, "1.0 e-Manual status vector");

  /* garbage, then a packet, then half a packet */
  uint8_t buf[64];
  size_t k = 0;
  buf[k++] = 0x13; buf[k++] = 0xFF; buf[k++] = 0x00;
  memcpy(buf + k, st, (size_t)n); k += (size_t)n;
  memcpy(buf + k, st, 4); k += 4;
  r = dxl_parse(1, 1, buf, k, 0, &pkt, &used);
  check(r == 1 && used == 3 + (size_t)n, "1.0 leading garbage skipped");
  r = dxl_parse(1, 1, buf + used, k - used, 0, &pkt, &used);
  check(r == 0 && used == 0, "1.0 truncated packet waits for more bytes");
  /* FF FF FF header run */
  uint8_t ff[16] = { 0xFF };
  memcpy(ff + 1, st, (size_t)n);
  r = dxl_parse(1, 1, ff, (size_t)n + 1, 0, &pkt, &used);
  check(r == 1 && pkt.id == 5, "1.0 FF FF FF header run resynchronises");
  /* corrupt byte */
  memcpy(buf, st, (size_t)n);
  buf[5] ^= 0x40;
  r = dxl_parse(1, 1, buf, (size_t)n, 0, &pkt, &used);
  check(r == DXL_COMM_RX_CORRUPT && used >= 1, "1.0 bad checksum reported, bytes skipped");
  /* length bigger than allowed: rejected without waiting */
  r = dxl_parse(1, 1, V(0xFF, 0xFF, 0x01, 0xF0, 0x00), 5, 4, &pkt, &used);
  check(r == DXL_ETOOLONG && used == 1, "1.0 length beyond max_params rejected at once");
  r = dxl_parse(1, 1, V(0xFF, 0xFF, 0x01, 0x01, 0x00), 5, 0, &pkt, &used);
  check(r == DXL_COMM_RX_CORRUPT, "1.0 length 1 is corrupt");

  /* 2.0: corrupt CRC, truncated, two packets, FF FF FD FD is not a header */
  uint8_t s2[32];
  int n2 = dxl_build_status(2, 3, DXL2_ERR_ALERT, V(1, 2, 3, 4), 4, s2, sizeof s2);
  r = dxl_parse(2, 1, s2, (size_t)n2, 0, &pkt, &used);
  check(r == 1 && pkt.error == 0x80 && pkt.instruction == DXL_INST_STATUS && pkt.nparams == 4,
         "2.0 status with alert bit parses");
  for (int i = 0; i < n2; i++) {
    s2[i] ^= 0x01;
    r = dxl_parse(2, 1, s2, (size_t)n2, 0, &pkt, &used);
    s2[i] ^= 0x01;
    if (r == 1) { check(0, "2.0 every single-bit flip is detected"); break; }
    if (i == n2 - 1) check(1, "2.0 every single-bit flip is detected");
  }
  for (int cut = 0; cut < n2; cut++) {
    r = dxl_parse(2, 1, s2, (size_t)cut, 0, &pkt, &used);
    if (r != 0 || used > (size_t)cut) { check(0, "2.0 every truncation waits"); break; }
    if (cut == n2 - 1) check(1, "2.0 every truncation waits");
  }
  memcpy(buf, V(0xFF, 0xFF, 0xFD, 0xFD), 4);
  memcpy(buf + 4, s2, (size_t)n2);
  r = dxl_parse(2, 1, buf, 4 + (size_t)n2, 0, &pkt, &used);
  check(r == 1 && used == 4 + (size_t)n2 && pkt.id == 3, "2.0 FF FF FD FD is skipped as a header");
  r = dxl_parse(2, 1, V(0xFF, 0xFF, 0xFD, 0x00, 0x01, 0xFF, 0xFF, 0x55), 8, 16, &pkt, &used);
  check(r == DXL_ETOOLONG && used == 1, "2.0 huge length rejected at once");
  r = dxl_parse(2, 1, V(0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x02, 0x00, 0x55, 0, 0), 10, 0, &pkt, &used);
  check(r == DXL_COMM_RX_CORRUPT, "2.0 length 2 is corrupt");
  r = dxl_parse(3, 1, s2, (size_t)n2, 0, &pkt, &used);
  check(r == DXL_EARG, "unknown protocol refused");
}

int main(void) {
  test_build1();
  test_build2();
  test_stuffing();
  test_parse();
  return tap_done();
}
