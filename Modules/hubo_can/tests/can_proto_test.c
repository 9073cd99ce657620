/* The Hubo CAN frames, byte by byte from the facts of shared/robots/hubo_can.md (section numbers
 * in the names): every expected frame below is written out by hand from the document's layouts,
 * never produced by the encoder under test; then the decoders, the units, the wire bits and the
 * per-bus bookkeeping (corrupt, misaddressed, unexpected, late, timeouts, dead boards). */
#include "can_proto.h"
#include "tap.h"
#include "hubo_can/tests/frame_by_hand.h"

#include <math.h>
#include <stdarg.h>
#include <string.h>

static int same(const hcan_frame *a, const hcan_frame *b) {
  if (a->id != b->id || a->dlc != b->dlc || memcmp(a->data, b->data, a->dlc) != 0) {
    printf("# got id %03X dlc %d:", a->id, a->dlc);
    for (int i = 0; i < a->dlc; i++) printf(" %02X", a->data[i]);
    printf("\n# want id %03X dlc %d:", b->id, b->dlc);
    for (int i = 0; i < b->dlc; i++) printf(" %02X", b->data[i]);
    printf("\n");
    return 0;
  }
  return 1;
}

static int near(double a, double b, double tol) { return fabs(a - b) <= tol; }

static void host_frames(void) {
  hcan_frame f, w;
  /* 4.1: 0x10 + #, DLC 6, two 24-bit sign-magnitude LE; 159155 = 0x026DB3, -201203 = -0x0311F3 */
  check(hcan_ref(&f, 0x03, 159155, -201203) == 0, "4.1 reference encodes");
  w = F(0x013, 6, 0xB3, 0x6D, 0x02, 0xF3, 0x11, 0x83);
  check(same(&f, &w), "4.1 reference 0x13: [B3 6D 02 F3 11 83] (bit 23 = negative)");
  hcan_ref(&f, 0x01, -640000, -640000);   /* a one-joint board: channel 0 repeated; 640000 = 0x09C400 */
  w = F(0x011, 6, 0x00, 0xC4, 0x89, 0x00, 0xC4, 0x89);
  check(same(&f, &w), "4.1 one-joint board: the channel-0 value in both slots");
  check(hcan_ref(&f, 0x00, 8388607, -8388607) == 0 && f.data[2] == 0x7F && f.data[5] == 0xFF,
        "4.1 +-8388607 is the largest magnitude");
  check(hcan_ref(&f, 0x00, 8388608, 0) < 0 && hcan_ref(&f, 0x00, 0, -8388608) < 0,
        "4.1 a count beyond 24-bit sign-magnitude is refused, not wrapped");
  int32_t c[2];
  w = F(0x013, 6, 0xB3, 0x6D, 0x02, 0xF3, 0x11, 0x83);
  check(hcan_dec_ref(&w, c) == 0 && c[0] == 159155 && c[1] == -201203, "4.1 reference decodes (emulator side)");

  hcan_req_encoder(&f, 0x08, 0);
  w = F(0x001, 3, 0x08, 0x03, 0x00);
  check(same(&f, &w), "4.2 encoder request [#, 0x03, 0] on 0x001");
  hcan_req_status(&f, 0x23);
  w = F(0x001, 3, 0x23, 0x02, 0x00);
  check(same(&f, &w), "4.2 status request [#, 0x02] with DLC 3 as hubo-ach");
  hcan_req_current(&f, 0x05);
  w = F(0x001, 2, 0x05, 0x04);
  check(same(&f, &w), "4.2 current request [#, 0x04]");
  hcan_home(&f, 0x04, HCAN_ALL_CHANNELS);
  w = F(0x001, 8, 0x04, 0x11, 0xF2, 0, 0, 0, 0, 0);
  check(same(&f, &w), "4.2 home all channels [#, 0x11, (0x0F<<4)|2, 0 x5]");
  hcan_home(&f, 0x04, 1);
  w = F(0x001, 8, 0x04, 0x11, 0x22, 0, 0, 0, 0, 0);
  check(same(&f, &w), "4.2 home channel 1: ((ch+1)<<4)|2 = 0x22");
  hcan_fet(&f, 0x0A, 1);
  w = F(0x001, 3, 0x0A, 0x0B, 0x01);
  check(same(&f, &w), "4.2 FET on [#, 0x0B, 1]");
  hcan_ctrl(&f, 0x0A, 1);
  w = F(0x001, 2, 0x0A, 0x0E);
  check(same(&f, &w), "4.2 controller on [#, 0x0E]");
  hcan_ctrl(&f, 0x0A, 0);
  w = F(0x001, 2, 0x0A, 0x0F);
  check(same(&f, &w), "4.2 controller off [#, 0x0F]");
  hcan_enc_zero(&f, 0x02, HCAN_ALL_CHANNELS);
  w = F(0x001, 3, 0x02, 0x06, 0x0F);
  check(same(&f, &w), "4.2 encoder zero [#, 0x06, 0x0F]");
  /* 4.2: H_SET_CTRL_MODE [#, 0x10, mode], DLC 3: 0 position, 1 current */
  hcan_ctrl_mode(&f, 0x09, 1);
  w = F(0x001, 3, 0x09, 0x10, 0x01);
  check(same(&f, &w), "4.2 control mode current [#, 0x10, 1]");
  hcan_ctrl_mode(&f, 0x20, 0);
  w = F(0x001, 3, 0x20, 0x10, 0x00);
  check(same(&f, &w), "4.2 control mode position [#, 0x10, 0] (EJMC0)");
  /* current reference: 0x10 + #, DLC 6, the 4.1 layout, each slot a current in 0.01 A (the DRC finger
   * currents' unit, 4.1, and the current replies', 5.3) as 24-bit sign-magnitude LE:
   * 4.16 A = 416 = 0x0001A0; -0.28 A = -28 = 0x00001C with bit 23 */
  check(hcan_cur_ref(&f, 0x09, 4.16, -0.28) == 0, "current reference encodes");
  w = F(0x019, 6, 0xA0, 0x01, 0x00, 0x1C, 0x00, 0x80);
  check(same(&f, &w), "current reference 0x19: [A0 01 00 1C 00 80] (4.16 A, -0.28 A)");
  /* a one-joint board: 9.89 A = 989 = 0x0003DD on channel 0, 0 A on channel 1 */
  hcan_cur_ref(&f, 0x02, 9.89, 0);
  w = F(0x012, 6, 0xDD, 0x03, 0x00, 0x00, 0x00, 0x00);
  check(same(&f, &w), "current reference of a one-joint board: [DD 03 00 00 00 00]");
  hcan_cur_ref(&f, 0x0B, 0.299, -0.299);
  w = F(0x01B, 6, 0x1D, 0x00, 0x00, 0x1D, 0x00, 0x80);
  check(same(&f, &w), "a current is truncated toward zero: +-0.299 A -> +-29 (0.29 A), never more than asked");
  hcan_cur_ref(&f, 0x0B, 0.29, -0.57);
  w = F(0x01B, 6, 0x1D, 0x00, 0x00, 0x39, 0x00, 0x80);
  check(same(&f, &w), "0.29 A is 29 and -0.57 A is -57, not one count less (binary fractions)");
  check(hcan_cur_ref(&f, 0x0B, NAN, 0) < 0 && hcan_cur_ref(&f, 0x0B, 0, INFINITY) < 0,
        "a NaN or infinite current is refused");
  check(hcan_cur_ref(&f, 0x0B, 83886.08, 0) < 0 && hcan_cur_ref(&f, 0x0B, 0, -83886.08) < 0 &&
            hcan_cur_ref(&f, 0x0B, 83886.07, 0) == 0 && f.data[0] == 0xFF && f.data[1] == 0xFF && f.data[2] == 0x7F,
        "a current beyond 24 bits of 0.01 A is refused, not wrapped");
  double amps[2];
  w = F(0x019, 6, 0xA0, 0x01, 0x00, 0x1C, 0x00, 0x80);
  check(hcan_dec_cur_ref(&w, amps) == 0 && near(amps[0], 4.16, 1e-12) && near(amps[1], -0.28, 1e-12),
        "current reference decodes (emulator side)");
  w.dlc = 5;
  check(hcan_dec_cur_ref(&w, amps) == HCAN_E_SHORT, "a 5-byte current reference is refused");

  hcan_req_ft(&f, 1);
  w = F(0x002, 2, 0x01, 0x12);
  check(same(&f, &w), "4.3 F/T request [$, 0x12] on 0x002");
  hcan_req_tilt(&f, 2);
  w = F(0x002, 2, 0x02, 0x22);
  check(same(&f, &w), "4.3 tilt request [$, 0x22]");
  hcan_req_imu(&f, 3);
  w = F(0x002, 3, 0x03, 0x00, 0x01);
  check(same(&f, &w), "4.3 IMU request [$, 0x00, 0x01]");
  hcan_req_power(&f);
  w = F(0x001, 2, 0x0E, 0xE0);
  check(same(&f, &w), "4.2 power board request [0x0E, 0xE0]");
}

static void board_frames(void) {
  hcan_frame f, w;
  int32_t c[2];
  /* 5.1: 0x60 + #, DLC 8, int32 LE: -1000 = FFFFFC18, 123456 = 0001E240 */
  w = F(0x063, 8, 0x18, 0xFC, 0xFF, 0xFF, 0x40, 0xE2, 0x01, 0x00);
  check(hcan_dec_encoder(&w, c) == 0 && c[0] == -1000 && c[1] == 123456, "5.1 encoder reply decodes -1000, 123456");
  hcan_rep_encoder(&f, 0x03, -1000, 123456);
  check(same(&f, &w), "5.1 encoder reply encodes (emulator side)");
  w.dlc = 7;
  check(hcan_dec_encoder(&w, c) == HCAN_E_SHORT, "5.1 a 7-byte encoder reply is refused (DLC must be 8)");

  /* 5.2: 4 bytes per channel: ch0 driver+controller on, home state 6 (0x63), jam; ch1 temperature */
  w = F(0x153, 8, 0x63, 0x01, 0x00, 0x00, 0x03, 0x00, 0x10, 0x00);
  hcan_status st[2];
  check(hcan_dec_status(&w, st) == 0 && (st[0].flags & HCAN_ST_DRIVER) && (st[0].flags & HCAN_ST_CTRL) &&
            HCAN_ST_HOME(st[0]) == 6 && st[0].faults == 0x01 && HCAN_ST_HOME(st[1]) == 0 && st[1].limits == 0x10,
        "5.2 status: driver, controller, home state 6, jam; channel 1 temperature error");
  check(hcan_status_fault(st[0]) && hcan_status_fault(st[1]), "5.2 jam and temperature errors are faults (isError)");
  hcan_status ok = { 0x63, 0, 0 };
  check(!hcan_status_fault(ok), "5.2 a homed running channel is no fault");
  hcan_rep_status(&f, 0x03, st);
  check(same(&f, &w), "5.2 status reply encodes (emulator side)");

  /* 5.3: current i = ((byte[i] << 2) | (byte3 >> 2i & 3)) / 100; temperature byte 2 */
  w = F(0x1C3, 4, 0x19, 0x02, 45, 0x0E);
  double amps[2], temp;
  check(hcan_dec_current(&w, amps, &temp) == 0 && near(amps[0], 1.02, 1e-9) && near(amps[1], 0.11, 1e-9) && temp == 45,
        "5.3 current 1.02 A, 0.11 A, 45 deg C");
  const double a2[2] = { 1.02, 0.11 };
  hcan_rep_current(&f, 0x03, a2, 45);
  check(same(&f, &w), "5.3 current reply encodes (emulator side)");

  /* 5.5: 0x40 + $, Mx My 0.01 N*m, Fz 0.1 N: 10000, -10000, 5000 */
  w = F(0x041, 6, 0x10, 0x27, 0xF0, 0xD8, 0x88, 0x13);
  double ft[3];
  check(hcan_dec_ft(&w, ft) == 0 && near(ft[0], 100, 1e-9) && near(ft[1], -100, 1e-9) && near(ft[2], 500, 1e-9),
        "5.5 F/T Mx 100 N*m, My -100 N*m, Fz 500 N");
  hcan_rep_ft(&f, 1, 100, -100, 500);
  check(same(&f, &w), "5.5 F/T reply encodes (emulator side)");

  /* 5.6: IMU 0x50 + $, DLC 8: roll 10.00 deg, pitch -2.50 deg, rates 45.00 and -0.01 deg/s */
  const double D = 3.14159265358979323846 / 180;
  w = F(0x053, 8, 0xE8, 0x03, 0x06, 0xFF, 0x94, 0x11, 0xFF, 0xFF);
  double imu[4];
  check(hcan_dec_imu(&w, imu) == 0 && near(imu[0], 10 * D, 1e-12) && near(imu[1], -2.5 * D, 1e-12) &&
            near(imu[2], 45 * D, 1e-12) && near(imu[3], -0.01 * D, 1e-12),
        "5.6 IMU roll 10 deg, pitch -2.5 deg, rates 45 and -0.01 deg/s (in rad)");
  hcan_rep_imu(&f, 3, 10 * D, -2.5 * D, 45 * D, -0.01 * D);
  check(same(&f, &w), "5.6 IMU reply encodes (emulator side)");
  /* tilt: int16 / 100 deg, third / 750: 2 deg, -3 deg, 1.0 */
  w = F(0x051, 6, 0xC8, 0x00, 0xD4, 0xFE, 0xEE, 0x02);
  double tilt[3];
  check(hcan_dec_tilt(&w, tilt) == 0 && near(tilt[0], 2 * D, 1e-12) && near(tilt[1], -3 * D, 1e-12) &&
            near(tilt[2], 1.0, 1e-12),
        "5.6 foot tilt 2 deg, -3 deg, az 750/750");

  /* 5.7: 0x06E: V /100, A /100, W /10 */
  w = F(0x06E, 6, 0xB0, 0x09, 0x64, 0x00, 0xF8, 0x00);
  double p[3];
  check(hcan_dec_power(&w, p) == 0 && near(p[0], 24.8, 1e-9) && near(p[1], 1.0, 1e-9) && near(p[2], 24.8, 1e-9),
        "5.7 power board 24.8 V, 1.00 A, 24.8 W");
  hcan_rep_power(&f, 24.8, 1.0, 24.8);
  check(same(&f, &w), "5.7 power reply encodes (emulator side)");
}

static void identifiers(void) {
  static const struct {
    uint32_t id;
    hcan_kind kind;
    int num;   /* -1: not checked */
    const char *name;
  } cases[] = {
    {0x013, HCAN_K_REF, 3, "3: 0x013 is board 3's reference"},
    {0x041, HCAN_K_FT, 1, "3: 0x041 is sensor 1's F/T"},
    {0x053, HCAN_K_IMU, 3, "3: 0x053 is sensor 3's IMU reply"},
    {0x06E, HCAN_K_ENC, 0x0E, "3: 0x06E lies in the encoder range (power board 0x0E)"},
    {0x17F, HCAN_K_STATUS, 0x2F, "3: 0x17F is board 0x2F's status"},
    {0x1C0, HCAN_K_CURRENT, 0, "3: 0x1C0 is board 0's current"},
    {0x7FF, HCAN_K_NONE, -1, "an unused identifier is none of them"},
    {HCAN_EFF | 0x063, HCAN_K_NONE, -1, "an extended identifier is none of them"},
    {HCAN_ERR | 0x004, HCAN_K_ERROR, -1, "an error frame is classified as one"},
  };
  hcan_frame f = F(0x013, 6, 0, 0, 0, 0, 0, 0);
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    int num;
    f.id = cases[i].id;
    check(hcan_classify(&f, &num) == cases[i].kind && (cases[i].num < 0 || num == cases[i].num), cases[i].name);
  }
}

static void units(void) {
  /* 6: counts per rad from drive:driven, harmonic, enc (the table's last column) */
  check(lround(hcan_counts_per_rad(10, 25, 100, 4000)) == 159155, "6 WST/RHY/RAP 10:25 x100 x4000: 159155 counts/rad");
  check(lround(hcan_counts_per_rad(324, 1024, 160, 4000)) == 321925, "6 RHR 324:1024 x160: 321925 counts/rad");
  check(lround(hcan_counts_per_rad(16, 16, 160, 4000)) == 101859, "6 RKN 16:16 x160: 101859 counts/rad");
  check(lround(hcan_counts_per_rad(11, 16, 100, 4000)) == 92599, "6 RSP 11:16 x100: 92599 counts/rad");
  check(lround(hcan_counts_per_rad(1, 1, 100, 128)) == 2037, "6 neck 1:1 x100 x128: 2037 counts/rad");
  const double k = hcan_counts_per_rad(16, 16, 160, 4000);
  check(hcan_rad_to_counts(0.5, k) == 50929 && hcan_rad_to_counts(-0.5, k) == -50929,
        "6 rad -> counts truncates toward zero (50929.58 -> 50929)");
  check(near(hcan_counts_to_rad(640000, k), 2 * 3.14159265358979323846, 1e-9), "6 640000 knee counts = one turn");
  check(hcan_rad_to_counts(NAN, k) == 0, "NaN never becomes a count");
}

static void wire_bits(void) {
  /* id 0, DLC 0: 34 zero bits SOF .. CRC (the CRC of zeros is zero) take a stuff bit after every
   * fifth: 6; + 13 fixed bits = 53 */
  hcan_frame f = F(0x000, 0);
  check(hcan_frame_bits(&f) == 53, "1: id 0 DLC 0 takes 34 + 6 stuff + 13 = 53 bits");
  int lo = 1000, hi = 0;
  for (int i = 0; i < 2000; i++) {
    f = F((uint32_t)(i * 37) & 0x7FF, 8, i, i * 3, i * 7, 0, 0xFF, i >> 3, 0x55, 0xAA);
    const int b = hcan_frame_bits(&f);
    if (b < lo) lo = b;
    if (b > hi) hi = b;
  }
  char d[64];
  snprintf(d, sizeof d, "%d..%d bits", lo, hi);
  tap_ok(lo >= 111 && hi <= 135, "1: an 8-byte frame takes 111 (HuboCan's 108 + 3 IFS) to 135 bits", d);
}

static void bus_bookkeeping(void) {
  hcan_net n;
  hcan_net_init(&n);
  const int j3 = hcan_net_add(&n, HCAN_B_JMC, 0x03);
  const int rf = hcan_net_add(&n, HCAN_B_TILT_FT, 1);
  const int im = hcan_net_add(&n, HCAN_B_IMU, 3);
  const int pw = hcan_net_add(&n, HCAN_B_POWER, 0x0E);
  check(j3 == 0 && rf == 1 && im == 2 && pw == 3, "boards added");
  check(hcan_net_add(&n, HCAN_B_JMC, 0x03) < 0 && hcan_net_add(&n, HCAN_B_FT, 1) < 0, "a number twice is refused");
  check(hcan_net_add(&n, HCAN_B_JMC, 0x30) < 0 && hcan_net_add(&n, HCAN_B_IMU, 16) < 0, "numbers out of range refused");

  hcan_net_owe(&n, j3, HCAN_R_ENC);
  hcan_net_owe(&n, rf, HCAN_R_FT | HCAN_R_TILT);
  hcan_net_owe(&n, im, HCAN_R_IMU);
  hcan_net_owe(&n, pw, HCAN_R_POWER);
  hcan_frame e = F(0x063, 8, 0x18, 0xFC, 0xFF, 0xFF, 0x40, 0xE2, 0x01, 0x00);
  hcan_frame t = e;
  t.dlc = 6;
  check(hcan_net_rx(&n, &t) == -1 && n.corrupt == 1 && n.b[j3].owed == HCAN_R_ENC, "truncated encoder: corrupt, still owed");
  check(hcan_net_rx(&n, &e) == j3 && n.b[j3].enc[0] == -1000 && n.b[j3].enc[1] == 123456, "encoder reply lands");
  check(hcan_net_rx(&n, &e) == -1 && n.unexpected == 1, "a second answer is unexpected");
  hcan_frame m = e;
  m.id = 0x065;
  check(hcan_net_rx(&n, &m) == -1 && n.misaddressed == 1, "a board not on this bus: misaddressed");
  hcan_frame s = F(0x153, 8, 0x63, 0, 0, 0, 0x63, 0, 0, 0);
  check(hcan_net_rx(&n, &s) == -1 && n.unexpected == 2, "a status nobody asked for: unexpected");
  hcan_frame ftf = F(0x041, 6, 0x10, 0x27, 0xF0, 0xD8, 0x88, 0x13);
  hcan_frame tl = F(0x051, 6, 0xC8, 0x00, 0xD4, 0xFE, 0xEE, 0x02);
  hcan_frame imf = F(0x053, 8, 0xE8, 0x03, 0x06, 0xFF, 0x94, 0x11, 0xFF, 0xFF);
  hcan_frame pwf = F(0x06E, 6, 0xB0, 0x09, 0x64, 0x00, 0xF8, 0x00);
  hcan_frame imshort = imf;
  imshort.dlc = 6;
  check(hcan_net_rx(&n, &imshort) == -1 && n.corrupt == 2, "a 6-byte reply from the IMU (tilt length) is corrupt");
  check(hcan_net_rx(&n, &ftf) == rf && hcan_net_rx(&n, &tl) == rf && hcan_net_rx(&n, &imf) == im &&
            hcan_net_rx(&n, &pwf) == pw,
        "F/T, tilt, IMU and power replies land on their boards");
  check(near(n.b[rf].ft[2], 500, 1e-9) && near(n.b[pw].power[0], 24.8, 1e-9), "their values decoded");
  hcan_frame err = F(HCAN_ERR | 0x008, 8, 0, 0, 0, 0, 0, 0, 0, 0);
  check(hcan_net_rx(&n, &err) == -1 && n.error_frames == 1, "a controller error frame is counted");
  hcan_frame host = F(0x013, 6, 0, 0, 0, 0, 0, 0);
  check(hcan_net_rx(&n, &host) == -2, "a host frame on the bus is not a reply");
  check(hcan_net_end_cycle(&n, 3) == 0 && n.b[j3].timeouts == 0 && n.b[rf].timeouts == 0, "all paid: no timeouts");

  /* the motor board stops answering: timeouts, dead after 3, a late reply still used */
  for (int c = 0; c < 3; c++) {
    hcan_net_owe(&n, j3, HCAN_R_ENC);
    const int died = hcan_net_end_cycle(&n, 3);
    if (c < 2) check(died == 0 && !n.b[j3].dead, "a missing answer is a timeout, not yet dead");
    else check(died == 1 && n.b[j3].dead && n.b[j3].timeouts == 3, "three cycles without an answer: dead");
  }
  hcan_frame e2 = F(0x063, 8, 0x10, 0, 0, 0, 0x20, 0, 0, 0);
  check(hcan_net_rx(&n, &e2) == j3 && n.b[j3].late == 1 && n.b[j3].enc[0] == 16, "the late answer is used and counted late");
  hcan_net_owe(&n, j3, HCAN_R_ENC);
  hcan_net_rx(&n, &e2);
  hcan_net_end_cycle(&n, 3);
  check(!n.b[j3].dead, "it answers in time again: alive");
  hcan_frame bad = F(0x063, 0);   /* a DLC over 8 set by hand: F() fills only what it was given */
  bad.dlc = 9;
  check(hcan_net_rx(&n, &bad) == -1, "DLC 9 is refused");
  hcan_frame fault = F(0x153, 8, 0x63, 0x04, 0, 0, 0x63, 0, 0, 0);
  hcan_net_owe(&n, j3, HCAN_R_STATUS);
  check(hcan_net_rx(&n, &fault) == j3 && n.b[j3].faults == 1, "a status with a fault bit is counted");
}

int main(void) {
  host_frames();
  board_frames();
  identifiers();
  units();
  wire_bits();
  bus_bookkeeping();
  printf("1..%d\n", tap_count);
  return tap_failures ? 1 : 0;
}
