/* The emulated motor boards' current mode (Platforms/Hubo/emulator/emu_boards.c): H_SET_CTRL_MODE and
 * current references taken, the joint turning at the speed the drive's speed-torque line gives for the
 * current's torque, back in position mode holding where it is, and the frames it cannot parse counted.
 * Frames written out by hand from hubo_can.md (4.1, 4.2), not by the encoder. TAP. */
#include "../emulator/emu.h"
#include "tap.h"
#include "hubo_can/tests/frame_by_hand.h"

#include <math.h>
#include <stdarg.h>
#include <string.h>

int main(void) {
  /* one 2-channel board 0x09 on bus 0, its channels as can.lua's RSY / REB: 1:1 x100, 4000 counts,
   * 0.06 N*m/A, the drive HUBO2-100-25 (25 N*m stall, 6.283 rad/s no-load) */
  static ht_table t;
  t.nbus = 1;
  t.bitrate = 1e6;
  t.nboard = 1;
  ht_board *b = &t.board[0];
  snprintf(b->name, sizeof b->name, "JMC9");
  b->kind = HT_JMC;
  b->number = 0x09;
  b->active = 1;
  b->nch = 2;
  for (int c = 0; c < 2; c++) {
    ht_channel *ch = &b->ch[c];
    ch->ch = c;
    ch->joint = c;
    ch->cpr = hcan_counts_per_rad(1, 1, 100, 4000);
    ch->ratio = 100;
    ch->dir = 1;
    ch->max_speed = 6;
    ch->kt = 0.06;
    ch->max_current = 10;
    ch->torque = 25;
    ch->speed = 6.283;
  }
  t.nj = 2;
  for (int j = 0; j < 2; j++) {
    t.lo[j] = -3;
    t.hi[j] = 3;
  }
  static emu_world w;
  emu_init(&w, &t, 1, 0.02);
  emu_board *e = &w.b[0];
  hcan_frame out[4], f;
  f = F(0x001, 3, 0x09, 0x0B, 0x01);   /* FETs on */
  emu_handle(&w, 0, &f, 0, out);
  f = F(0x001, 2, 0x09, 0x0E);         /* controller on */
  emu_handle(&w, 0, &f, 0, out);
  check(e->fet && e->ctrl && e->mode == HCAN_MODE_POSITION, "FETs and controller on, position mode");

  f = F(0x001, 3, 0x09, 0x10, 0x01);
  emu_handle(&w, 0, &f, 0, out);
  check(e->mode == HCAN_MODE_CURRENT && e->mode_frames == 1, "[#, 0x10, 1]: current mode");
  /* 0.50 A and -0.25 A: 50 = 0x32, -25 = 0x19 with bit 23 */
  f = F(0x019, 6, 0x32, 0x00, 0x00, 0x19, 0x00, 0x80);
  emu_handle(&w, 0, &f, 0, out);
  check(fabs(e->amps[0] - 0.5) < 1e-12 && fabs(e->amps[1] + 0.25) < 1e-12 && e->cur_refs == 1,
        "the reference frame in current mode is read as currents: 0.50 A, -0.25 A");
  /* 0.5 A x 0.06 x 100 = 3 N*m; 3 / 25 of the no-load 6.283 rad/s = 0.754 rad/s; 0.1 s: 0.0754 rad */
  for (int k = 0; k < 20; k++) emu_step(&w, 0.005 * (k + 1), 0.005);
  const double q0 = e->pos[0] / b->ch[0].cpr, q1 = e->pos[1] / b->ch[1].cpr;
  char d[96];
  snprintf(d, sizeof d, "%.5f and %.5f rad", q0, q1);
  tap_ok(fabs(q0 - 0.0754) < 1e-3 && fabs(q1 + 0.0377) < 1e-3,
         "0.1 s at 3 N*m / -1.5 N*m: the joints turn 0.0754 / -0.0377 rad (torque / stall x no-load speed)", d);
  /* the current reply: magnitude only (5.3), 0.50 A = 50 = (12 << 2) | 2 */
  f = F(0x001, 2, 0x09, 0x04);
  const int n = emu_handle(&w, 0, &f, 0.1, out);
  double amps[2], temp;
  check(n == 1 && hcan_dec_current(&out[0], amps, &temp) == 0 && fabs(amps[0] - 0.5) < 1e-9 &&
            fabs(amps[1] - 0.25) < 1e-9,
        "the current reply reads the reference's magnitude");
  f = F(0x001, 3, 0x09, 0x02, 0x00);
  emu_handle(&w, 0, &f, 0.1, out);
  hcan_status st[2];
  check(hcan_dec_status(&out[0], st) == 0 && (st[0].flags & HCAN_ST_MODE), "its status shows the mode bit (5.2 bit 2)");

  /* -10 A on channel 1 (-1000 = 0x3E8 with bit 23): 60 N*m, capped at max_speed 6 rad/s; 1 s would be
   * -6 rad, the joint's range ends at -3 */
  f = F(0x019, 6, 0x32, 0x00, 0x00, 0xE8, 0x03, 0x80);
  emu_handle(&w, 0, &f, 0.1, out);
  for (int k = 0; k < 200; k++) emu_step(&w, 0.1 + 0.005 * (k + 1), 0.005);
  snprintf(d, sizeof d, "%.4f rad", e->pos[1] / b->ch[1].cpr);
  tap_ok(fabs(e->pos[1] / b->ch[1].cpr + 3) < 1e-4, "at -10 A the joint runs into the end of its range and stays there",
         d);

  const double held = e->pos[0];
  f = F(0x001, 3, 0x09, 0x10, 0x00);
  emu_handle(&w, 0, &f, 0.1, out);
  for (int k = 0; k < 20; k++) emu_step(&w, 1.1 + 0.005 * (k + 1), 0.005);
  check(e->mode == HCAN_MODE_POSITION && e->amps[0] == 0 && fabs(e->pos[0] - held) < 1e-9,
        "[#, 0x10, 0]: position mode, no current, holding where it was");

  const uint32_t before = w.unparsed;
  f = F(0x001, 3, 0x09, 0x10, 0x02);
  emu_handle(&w, 0, &f, 0.2, out);
  check(w.unparsed == before + 1 && e->mode == HCAN_MODE_POSITION, "mode 2 (the DRC finger boards' hybrid): not parsed, counted");
  f = F(0x001, 2, 0x09, 0x10);
  emu_handle(&w, 0, &f, 0.2, out);
  check(w.unparsed == before + 2, "a mode frame without its mode byte: counted");
  f = F(0x019, 5, 0x32, 0x00, 0x00, 0x19, 0x00);
  emu_handle(&w, 0, &f, 0.2, out);
  check(w.unparsed == before + 3 && e->refs == 0, "a 5-byte reference: counted, not taken");
  f = F(0x001, 1, 0x09);
  emu_handle(&w, 0, &f, 0.2, out);
  check(w.unparsed == before + 4, "a 1-byte command: counted");
  f = F(0x063, 8, 0, 0, 0, 0, 0, 0, 0, 0);
  emu_handle(&w, 0, &f, 0.2, out);
  check(w.unparsed == before + 5, "a board's frame (an encoder reply) sent to the boards: counted");
  printf("1..%d\n", tap_count);
  return tap_failures ? 1 : 0;
}
