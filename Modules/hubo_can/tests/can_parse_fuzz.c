/* libFuzzer target: the Hubo CAN frame decoders and one bus's bookkeeping on arbitrary frames.
 * Input: 11-byte records (id high byte with the flag bits, id low byte, dlc 0..255, 8 data bytes);
 * the first byte of each record also picks which replies the boards owe before it arrives. Checks:
 * every frame is counted once, board indices stay in range, a decoded encoder reply re-encodes to
 * the same bytes, and the wire-bit count stays inside a classic frame's bounds. */
#include "can_proto.h"

#include <stdlib.h>
#include <string.h>

static hcan_net net;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  hcan_net_init(&net);
  static const struct { hcan_board_kind k; int num; } boards[] = {
    { HCAN_B_JMC, 0x00 }, { HCAN_B_JMC, 0x01 }, { HCAN_B_JMC, 0x23 }, { HCAN_B_TILT_FT, 1 },
    { HCAN_B_FT, 6 }, { HCAN_B_IMU, 3 }, { HCAN_B_POWER, 0x0E },
  };
  for (size_t k = 0; k < sizeof boards / sizeof boards[0]; k++)
    if (hcan_net_add(&net, boards[k].k, boards[k].num) != (int)k) abort();
  uint32_t skipped = 0, landed = 0, host = 0;
  for (size_t pos = 0; pos + 11 <= size; pos += 11) {
    const uint8_t *r = data + pos;
    hcan_frame f;
    f.id = ((uint32_t)(r[0] & 0xE7) << 24) | ((uint32_t)(r[0] & 0x07) << 8) | r[1];
    f.dlc = r[2];
    memcpy(f.data, r + 3, 8);
    net.b[r[0] % net.n].owed |= (uint32_t)r[2] & 0x7F;
    const int i = hcan_net_rx(&net, &f);
    if (i >= net.n || i < -2) abort();
    if (i == -1) skipped++;
    else if (i == -2) host++;
    else landed++;
    if ((r[0] & 0x18) == 0x18) hcan_net_end_cycle(&net, 3);
    /* every decoder on every frame: no reads beyond dlc 8, no crash */
    int32_t c[2];
    hcan_status st[2];
    double d4[4], t;
    hcan_dec_ref(&f, c);
    if (hcan_dec_cur_ref(&f, d4) == 0) {   /* a decoded current reference re-encodes to the same bytes */
      hcan_frame g;
      if (hcan_cur_ref(&g, 0, d4[0], d4[1]) != 0 || memcmp(g.data, f.data, 6) != 0) {
        /* -0 (bit 23 with a zero magnitude) decodes to 0, which encodes without the sign bit */
        if (!((f.data[2] & 0x80) && !(f.data[0] | f.data[1] | (f.data[2] & 0x7F))) &&
            !((f.data[5] & 0x80) && !(f.data[3] | f.data[4] | (f.data[5] & 0x7F))))
          abort();
      }
    }
    hcan_dec_status(&f, st);
    hcan_dec_current(&f, d4, &t);
    hcan_dec_ft(&f, d4);
    hcan_dec_imu(&f, d4);
    hcan_dec_tilt(&f, d4);
    hcan_dec_power(&f, d4);
    if (hcan_dec_encoder(&f, c) == 0) {
      hcan_frame g;
      hcan_rep_encoder(&g, 0, c[0], c[1]);
      if (memcmp(g.data, f.data, 8) != 0) abort();
    }
    const int bits = hcan_frame_bits(&f);
    if (bits < 47 || bits > 135) abort();
    int num;
    hcan_classify(&f, &num);
    if (num < -1 || num >= HCAN_BOARD_MAX) abort();
  }
  const uint32_t counted = net.corrupt + net.misaddressed + net.unexpected;
  if (counted != skipped || net.rx != skipped + landed + host) abort();
  return 0;
}
