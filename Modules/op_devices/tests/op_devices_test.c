/* The OP DCM's device tables (TAP): the bodies in Config/robots load; a bad table stops start-up
 * with the file and the row named (a joint without a servo, an unknown joint, a joint twice, two
 * devices with one id on a bus, an unknown model or board, a protocol the model does not speak,
 * a bus that does not exist, bad IMU axes, a missing key). */
#include "op_devices.h"
#include "tap.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char g_root[256];

/* Loads robot `name` for the OP platform; on an error returns -1 with the message in err. */
static int load(const char *name, op_body *b, char *err, size_t n) {
  dcm_config *c = NULL;
  int rc = dcm_config_load("robot", name, "OP", &c, err, n);
  if (rc == 0) rc = op_body_load(c, b, err, n);
  dcm_config_free(c);
  return rc;
}

/* Config/robots/t/robot.lua in the test tree: joints a, b; the given buses and devices. */
static void write_robot(const char *buses, const char *devices) {
  char path[512];
  snprintf(path, sizeof path, "%s/Config/robots/t/robot.lua", g_root);
  FILE *f = fopen(path, "w");
  fprintf(f, "return {\n  name = 't', period = 0.008, joints = { 'a', 'b' },\n"
             "  limits = { a = { -1, 1 }, b = { -2, 2 } },\n  buses = { %s },\n  devices = {\n%s\n  },\n}\n",
          buses, devices);
  fclose(f);
}

#define BUS1 "{ port = '/dev/null', baud = 1000000 }"
#define ROW_A "    { joint = 'a', bus = 1, id = 1, model = 'MX-28', protocol = 1, direction = 1, zero = 2048 },\n"
#define ROW_B "    { joint = 'b', bus = 1, id = 2, model = 'MX-28', protocol = 1, direction = -1, zero = 1000 },\n"
#define BOARD "    { board = 'CM-730', bus = 1, id = 200, protocol = 1, gyro_axes = { '-x', '-y', 'z' }, accel_axes = { 'y', '-x', 'z' } },\n"

/* A table that must fail: the message names the file and contains `want`. */
static void bad(const char *buses, const char *devices, const char *want, const char *name) {
  op_body b;
  char err[1024] = "";
  write_robot(buses, devices);
  int rc = load("t", &b, err, sizeof err);
  tap_ok(rc < 0 && strstr(err, "Config/robots/t/robot.lua") && strstr(err, want), name, err);
}

static void make_tree(void) {
  snprintf(g_root, sizeof g_root, "/tmp/op_devices_test.XXXXXX");
  if (!mkdtemp(g_root)) exit(1);
  char p[512], lib[512];
  snprintf(p, sizeof p, "%s/Config/robots/t", g_root);
  snprintf(lib, sizeof lib, "%s/Config", g_root);
  mkdir(lib, 0700);
  snprintf(lib, sizeof lib, "%s/Config/robots", g_root);
  mkdir(lib, 0700);
  mkdir(p, 0700);
  snprintf(p, sizeof p, "%s/Config/platforms", g_root);
  mkdir(p, 0700);
  snprintf(p, sizeof p, "%s/Config/platforms/OP", g_root);
  mkdir(p, 0700);
  snprintf(lib, sizeof lib, "%s/Lib", dcm_root());
  snprintf(p, sizeof p, "%s/Lib", g_root);
  if (symlink(lib, p) != 0) exit(1);
}

static void remove_tree(void) {
  char cmd[600];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", g_root);
  if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", g_root);
}

int main(void) {
  op_body b;
  char err[1024] = "";
  /* the bodies of the repository */
  int rc = load("darwin", &b, err, sizeof err);
  tap_ok(rc == 0 && b.nbus == 1 && b.bus[0].nservo == 20 && b.bus[0].protocol == 1 && b.bus[0].has_board,
         "Config/robots/darwin: 20 MX-28 and the CM-730 on one bus, protocol 1.0", err);
  int ok = rc == 0;
  for (int k = 0; ok && k < b.bus[0].nservo; k++) {
    const op_servo *s = &b.bus[0].servo[k];
    ok = s->dir == 1 && s->zero == 2048 && !strcmp(s->model->name, "MX-28");
  }
  check(ok, "darwin: every servo direction +1, zero 2048 (the joint convention is the servos' own)");
  const char *expect[][2] = { { "head_pan", "19" }, { "head_tilt", "20" }, { "l_sho_pitch", "2" }, { "r_sho_pitch", "1" },
                              { "l_knee", "14" },   { "r_knee", "13" },    { "l_ank_roll", "18" }, { "r_el", "5" } };
  ok = rc == 0;
  for (size_t e = 0; ok && e < sizeof expect / sizeof expect[0]; e++) {
    int found = 0;
    for (int k = 0; k < b.bus[0].nservo; k++)
      if (!strcmp(b.joint[b.bus[0].servo[k].joint], expect[e][0])) found = b.bus[0].servo[k].id == atoi(expect[e][1]);
    ok = found;
  }
  check(ok, "darwin: ROBOTIS ids (odd right, even left, 19/20 head) as in darwin_reference.txt");
  const op_board *bo = &b.bus[0].board;
  check(rc == 0 && bo->gyro_axis[0] == 0 && bo->gyro_sign[0] == -1 && bo->accel_axis[0] == 1 && bo->accel_sign[0] == 1 &&
            bo->accel_axis[1] == 0 && bo->accel_sign[1] == -1 && bo->gyro_axis[2] == 2 && bo->gyro_sign[2] == 1,
        "darwin: the CM-730's axes (GYRO_X = -wx; ACC_Y forward, ACC_X to the right)");
  rc = load("op3", &b, err, sizeof err);
  tap_ok(rc == 0 && b.bus[0].nservo == 20 && b.bus[0].protocol == 2 && !strcmp(b.bus[0].servo[0].model->name, "XM430-W350") &&
             !strcmp(b.bus[0].board.model->name, "OpenCR"),
         "Config/robots/op3: 20 XM430-W350 and the OpenCR, protocol 2.0", err);

  make_tree();
  setenv("HRP_ROOT", g_root, 1);
  write_robot(BUS1, ROW_B ROW_A BOARD);
  rc = load("t", &b, err, sizeof err);
  tap_ok(rc == 0 && b.bus[0].nservo == 2 && b.bus[0].servo[0].joint == 1 && b.bus[0].servo[0].dir == -1 &&
             b.bus[0].servo[0].zero == 1000 && b.imu_bus == 0,
         "rows in any order, keyed by joint name", err);
  check(rc == 0 && op_rad_to_count(&b, &b.bus[0].servo[0], 0.5) == 1000 - 326 &&
            op_rad_to_count(&b, &b.bus[0].servo[1], 5.0) == 2048 + 652,
        "counts: direction and zero applied, clamped to the joint limits");

  bad(BUS1, ROW_A BOARD, "joint 'b' (joints[2]) has no servo", "a joint missing from the table");
  bad(BUS1, ROW_A ROW_B "    { joint = 'c', bus = 1, id = 3, model = 'MX-28', protocol = 1, direction = 1, zero = 2048 },\n",
      "devices[3] (joint 'c'): 'c' is not one of the robot's joints", "a device naming an unknown joint");
  bad(BUS1, ROW_A ROW_B "    { joint = 'a', bus = 1, id = 3, model = 'MX-28', protocol = 1, direction = 1, zero = 2048 },\n",
      "devices[3] (joint 'a'): the joint has a servo already (devices[1])", "a joint driven twice");
  bad(BUS1, ROW_A "    { joint = 'b', bus = 1, id = 1, model = 'MX-28', protocol = 1, direction = 1, zero = 2048 },\n",
      "devices[2] (joint 'b'): id 1 on bus 1 is taken by devices[1] too", "duplicate ids on a bus");
  bad(BUS1, ROW_A ROW_B "    { board = 'CM-730', bus = 1, id = 2, protocol = 1, gyro_axes = { 'x', 'y', 'z' }, accel_axes = { 'x', 'y', 'z' } },\n",
      "id 2 on bus 1 is taken by devices[2] too", "a board with a servo's id");
  write_robot(BUS1 ", { port = '/dev/null', baud = 1000000 }",
              ROW_A "    { joint = 'b', bus = 2, id = 1, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },\n");
  rc = load("t", &b, err, sizeof err);
  tap_ok(rc == 0 && b.nbus == 2 && b.bus[1].protocol == 2 && b.imu_bus == -1,
         "the same id on two buses, the second bus in protocol 2.0, no board", err);
  bad(BUS1, "    { joint = 'a', bus = 1, id = 1, model = 'MX-29', protocol = 1, direction = 1, zero = 2048 },\n" ROW_B,
      "devices[1] (joint 'a'): unknown model 'MX-29' (known: MX-28, XM430-W350)", "an unknown model");
  bad(BUS1, ROW_A ROW_B "    { board = 'CM-530', bus = 1, id = 200, protocol = 1, gyro_axes = { 'x', 'y', 'z' }, accel_axes = { 'x', 'y', 'z' } },\n",
      "devices[3] (board 'CM-530'): unknown board 'CM-530'", "an unknown board");
  bad(BUS1, "    { joint = 'a', bus = 1, id = 1, model = 'XM430-W350', protocol = 1, direction = 1, zero = 2048 },\n" ROW_B,
      "devices[1] (joint 'a'): the XM430-W350 speaks protocol 2, the row says 1", "a protocol the model does not speak");
  bad(BUS1, ROW_A "    { joint = 'b', bus = 1, id = 2, model = 'XM430-W350', protocol = 2, direction = 1, zero = 2048 },\n",
      "devices[2] (joint 'b'): protocol 2 on bus 1, whose other devices speak protocol 1", "protocols mixed on one bus");
  bad(BUS1, ROW_A "    { joint = 'b', bus = 2, id = 2, model = 'MX-28', protocol = 1, direction = 1, zero = 2048 },\n",
      "devices[2] (joint 'b'): bus 2 is not one of buses (1 to 1)", "a bus that does not exist");
  bad(BUS1, ROW_A "    { joint = 'b', bus = 1, id = 2, model = 'MX-28', protocol = 1, direction = 2, zero = 2048 },\n",
      "devices[2] (joint 'b'): direction must be 1 or -1", "a direction other than +-1");
  bad(BUS1, ROW_A "    { joint = 'b', bus = 1, id = 2, model = 'MX-28', protocol = 1, direction = 1 },\n",
      "missing key 'devices[2].zero'", "a row without its zero");
  bad(BUS1, ROW_A ROW_B "    { board = 'CM-730', bus = 1, id = 200, protocol = 1, gyro_axes = { 'x', 'x', 'z' }, accel_axes = { 'x', 'y', 'z' } },\n",
      "devices[3] (board 'CM-730'): gyro_axes must give each of 'x', 'y', 'z' once", "IMU axes that are no permutation");
  bad(BUS1, ROW_A ROW_B "    { bus = 1, id = 9, protocol = 1 },\n", "devices[3]: a row names either a joint (a servo) or a board",
      "a row that is neither servo nor board");
  bad("{ port = '/dev/null' }", ROW_A ROW_B, "missing key 'buses[1].baud'", "a bus without its baud rate");
  remove_tree();
  return tap_done();
}
