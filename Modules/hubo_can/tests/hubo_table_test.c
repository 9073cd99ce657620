/* The Hubo2+ board table (Config/robots/hubo2plus/can.lua) loads and matches hubo_can.md; bad
 * tables stop with an error naming the file and the element. Runs in a temporary tree: Lib and
 * the Hubo platform folder linked, the body's robot.lua (or Tests/hubo/fixture_robot.lua while the
 * body is not in the tree), and can.lua variants that change one thing of the real table. */
#include "hubo_table.h"
#include "tap.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char root[256], top[512];

static void put(const char *rel, const char *text) {
  char p[1024];
  snprintf(p, sizeof p, "%s/%s", root, rel);
  FILE *f = fopen(p, "w");
  if (!f) { perror(p); exit(1); }
  fputs(text, f);
  fclose(f);
}

/* can.lua = the real table with `mutation` applied (Lua statements on t). */
static int load(const char *mutation, ht_table *t, char *err, size_t n) {
  char text[2048];
  snprintf(text, sizeof text, "local t = dofile('%s/Config/robots/hubo2plus/can.lua')\n%s\nreturn t\n", top, mutation);
  put("Config/robots/hubo2plus/can.lua", text);
  dcm_config *rc = NULL, *cc = NULL;
  int r = dcm_config_load("robot", "hubo2plus", "Hubo", &rc, err, n);
  if (r == 0) r = dcm_config_load("can", "hubo2plus", "Hubo", &cc, err, n);
  if (r == 0) r = ht_load(rc, cc, t, err, n);
  dcm_config_free(rc);
  dcm_config_free(cc);
  return r;
}

static void refused(const char *mutation, const char *want1, const char *want2, const char *name) {
  static ht_table t;
  char err[1024] = "";
  const int r = load(mutation, &t, err, sizeof err);
  const int ok = r < 0 && strstr(err, "Config/robots/hubo2plus/can.lua") && strstr(err, want1) &&
                 (!want2 || strstr(err, want2));
  tap_ok(ok, name, err);
}

int main(void) {
  snprintf(top, sizeof top, "%s", dcm_root());
  snprintf(root, sizeof root, "/tmp/hubo_table_XXXXXX");
  if (!mkdtemp(root)) { perror("mkdtemp"); return 1; }
  char a[1024], b[1024];
  snprintf(a, sizeof a, "%s/Config", root);
  mkdir(a, 0700);
  snprintf(a, sizeof a, "%s/Config/robots", root);
  mkdir(a, 0700);
  snprintf(a, sizeof a, "%s/Config/robots/hubo2plus", root);
  mkdir(a, 0700);
  snprintf(a, sizeof a, "%s/Config/platforms", root);
  mkdir(a, 0700);
  snprintf(a, sizeof a, "%s/Lib", top);
  snprintf(b, sizeof b, "%s/Lib", root);
  if (symlink(a, b) != 0) { perror("symlink"); return 1; }
  snprintf(a, sizeof a, "%s/Config/common", top);
  snprintf(b, sizeof b, "%s/Config/common", root);
  if (symlink(a, b) != 0) { perror("symlink"); return 1; }
  snprintf(a, sizeof a, "%s/Config/platforms/Hubo", top);
  snprintf(b, sizeof b, "%s/Config/platforms/Hubo", root);
  if (symlink(a, b) != 0) { perror("symlink"); return 1; }
  snprintf(a, sizeof a, "%s/Config/robots/hubo2plus/robot.lua", top);
  if (access(a, R_OK) != 0) snprintf(a, sizeof a, "%s/Tests/hubo/fixture_robot.lua", top);
  snprintf(b, sizeof b, "%s/Config/robots/hubo2plus/robot.lua", root);
  if (symlink(a, b) != 0) { perror("symlink"); return 1; }
  setenv("HRP_ROOT", root, 1);

  static ht_table t;
  char err[1024] = "";
  int r = load("", &t, err, sizeof err);
  tap_ok(r == 0, "the Hubo2+ table loads", err);
  if (r == 0) {
    check(t.nbus == 2 && !strcmp(t.iface[0], "can0") && !strcmp(t.iface[1], "can1") && t.bitrate == 1e6,
          "two buses, can0 (lower) and can1 (upper), 1 Mbit/s");
    check(t.nboard == 22, "22 boards (15 motor boards, 5 sensor boards, the neck, the power board)");
    int rkn = -1, rhr = -1, nk1 = -1;
    for (int j = 0; j < t.nj; j++) {
      if (!strcmp(t.joint[j], "RKN")) rkn = j;
      if (!strcmp(t.joint[j], "RHR")) rhr = j;
      if (!strcmp(t.joint[j], "NK1")) nk1 = j;
    }
    const ht_board *kb = rkn >= 0 ? &t.board[t.joint_board[rkn]] : NULL;
    check(kb && kb->number == 0x02 && kb->bus == 0 && kb->nch == 1 && lround(kb->ch[0].cpr) == 101859,
          "RKN: JMC2 (0x02) on bus 1, one channel, 101859 counts/rad");
    const ht_board *hb = rhr >= 0 ? &t.board[t.joint_board[rhr]] : NULL;
    check(hb && hb->number == 0x00 && hb->ch[t.joint_ch[rhr]].ch == 1 && lround(hb->ch[t.joint_ch[rhr]].cpr) == 321925,
          "RHR: JMC0 channel 1, 321925 counts/rad");
    const ht_board *nb = nk1 >= 0 ? &t.board[t.joint_board[nk1]] : NULL;
    check(nb && nb->number == 0x22 && !nb->active && nb->kind == HT_JMC3, "NK1: the neck board EJMC2, not driven");
    int imu = 0, ft = 0, power = 0;
    for (int k = 0; k < t.nboard; k++) {
      const ht_board *bd = &t.board[k];
      if (bd->kind == HT_IMU && bd->number == 3 && bd->bus == 0) imu++;
      if ((bd->kind == HT_FT_TILT && bd->bus == 0 && (bd->number == 1 || bd->number == 2)) ||
          (bd->kind == HT_FT && bd->bus == 1 && (bd->number == 6 || bd->number == 7)))
        ft++;
      if (bd->kind == HT_POWER && bd->number == 0x0E && bd->bus == 1) power++;
    }
    check(imu == 1 && ft == 4 && power == 1, "IMU $3 and foot F/T $1 $2 on bus 1, hand F/T $6 $7 and power 0x0E on bus 2");
    const ht_channel *c = &kb->ch[0];
    check(ht_rad_to_counts(c, 1.0) == 101859 && fabs(ht_counts_to_rad(c, 101859) - 1.0) < 1e-5, "rad <-> counts");

    /* current mode: the drives' torques (actuators.lua) and what 10 A at 0.06 N*m/A gives through the gears */
    dcm_config *rc = NULL, *ac = NULL;
    r = dcm_config_load("robot", "hubo2plus", "Hubo", &rc, err, sizeof err);
    if (r == 0) r = dcm_config_load("actuators", "hubo2plus", "Hubo", &ac, err, sizeof err);
    if (r == 0) r = ht_load_actuators(rc, ac, &t, err, sizeof err);
    dcm_config_free(rc);
    dcm_config_free(ac);
    tap_ok(r == 0, "the current-mode joints' drives load", err);
    const ht_channel *hr = &hb->ch[t.joint_ch[rhr]];
    check(fabs(c->ratio - 160) < 1e-9 && c->kt == 0.06 && c->max_current == 10 && c->torque == 95,
          "RKN: ratio 160, 0.06 N*m/A, 10 A, drive 95 N*m");
    check(fabs(ht_torque_limit(c) - 95) < 1e-9 && fabs(ht_torque_to_current(c, 95) - 95 / 9.6) < 1e-9,
          "RKN: torque limit 95 N*m (10 A would give 96), 95 N*m is 9.90 A");
    check(fabs(hr->ratio - 1024.0 * 160 / 324) < 1e-9 && fabs(ht_torque_limit(hr) - 95) < 1e-9,
          "RHR: ratio 505.68, limit 95 N*m");
    check(ht_torque_limit(&nb->ch[0]) == 0 && nb->ch[0].kt == 0, "NK1: no current mode (no torque_constant)");
    ht_channel neg = *c;
    neg.dir = -1;
    check(fabs(ht_torque_to_current(&neg, 9.6) + 1) < 1e-12, "direction -1: 9.6 N*m at the knee is -1 A");
    ht_channel small = *c;
    small.max_current = 5;
    check(fabs(ht_torque_limit(&small) - 48) < 1e-9, "max_current 5 A caps the limit at 5 x 0.06 x 160 = 48 N*m");
  }
  refused("t.boards[3].channels[1].joint = 'RKX'", "boards[3] (JMC2) channels[1]", "joint 'RKX' is not one of",
          "an unknown joint is named with its board and channel");
  refused("t.boards[2].number = 0", "boards[2] (JMC1): board number 0x00 on bus 1 is already boards[1] (JMC0)", NULL,
          "a board number twice on a bus");
  refused("t.boards[11].sensor = 1", "boards[11] (LFFT): sensor 0x01 on bus 1 is already boards[10] (RFFT)", NULL,
          "a sensor number twice on a bus");
  refused("t.boards[2].channels[1].joint = 'RHY'", "boards[2] (JMC1) channels[1]: joint 'RHY' is already on boards[1] (JMC0)",
          NULL, "a joint on two channels");
  refused("table.remove(t.boards, 2)", "joint 'RHP'", "on no board's channels", "a body joint on no board");
  refused("t.boards[4].channels[2].channel = 2", "boards[4] (JMC3) channels[2]: channel 2 is not 0..1", NULL,
          "a channel beyond a 2-channel board");
  refused("t.boards[4].channels[2].channel = 0", "boards[4] (JMC3) channels[2]: channel 0 twice", NULL, "a channel twice");
  refused("t.boards[5].bus = 3", "boards[5] (JMC4): bus 3 is not one of buses", NULL, "a bus that is not there");
  refused("t.boards[6].kind = 'jmc9'", "boards[6] (JMC5): kind 'jmc9'", NULL, "an unknown kind");
  refused("t.boards[7].channels[1].direction = 0", "boards[7] (JMC6) channels[1]: direction must be 1 or -1", NULL,
          "a direction other than +-1");
  refused("t.boards[8].channels[1].harmonic = 0", "boards[8] (JMC7) channels[1]: harmonic must be > 0", NULL,
          "a gear ratio of 0");
  refused("t.boards[10].mount = 'right_knee'", "boards[10] (RFFT): mount 'right_knee'", NULL, "an unknown F/T mount");
  refused("t.boards[1].channels[1].max_speed = nil", "boards[1].channels[1].max_speed", NULL,
          "a missing speed limit is named by its key");
  refused("t.boards[2].channels[1].max_current = nil", "boards[2] (JMC1) channels[1]",
          "torque_constant and max_current go together", "a torque constant without a current limit");
  refused("t.boards[2].channels[1].torque_constant = 0", "boards[2] (JMC1) channels[1]: torque_constant must be > 0",
          NULL, "a torque constant of 0");
  refused("t.boards[2].channels[1].max_current = -1", "boards[2] (JMC1) channels[1]: max_current must be > 0", NULL,
          "a negative current limit");
  printf("1..%d\n", tap_count);
  char cmd[600];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", root);
  if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", root);
  return tap_failures ? 1 : 0;
}
