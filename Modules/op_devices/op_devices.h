/* op_devices: the Dynamixel models the OP DCM knows and a body's device table.
 *
 * The table is the form of ROBOTIS' .robot files: in Config/robots/<ROBOT>/robot.lua
 *   buses   = { { port = '/dev/ttyUSB0', baud = 1000000 }, ... }     -- bus 1, 2, ...
 *   devices = {
 *     { joint = 'head_pan', bus = 1, id = 19, model = 'MX-28', protocol = 1, direction = 1, zero = 2048 },
 *     ...
 *     { board = 'CM-730', bus = 1, id = 200, protocol = 1,
 *       gyro_axes = { '-x', '-y', 'z' }, accel_axes = { 'y', '-x', 'z' } },
 *   }
 * one row per servo (the joint it drives, keyed by name) or board (IMU and buttons), in any order.
 *   angle (rad) = direction * (count - zero) * 2*pi / 4096
 * A board's *_axes give the torso's x (forward), y (left), z (up) from the board's X / Y / Z
 * registers: 'y' = the board's Y, '-x' = minus its X.
 * Checked at start, each error naming the file and the row: a joint without a servo, a servo for
 * an unknown joint or a joint twice, two devices with one id on a bus, an unknown model or board,
 * a protocol the model does not speak, protocols or register layouts mixed on one bus.
 */
#ifndef HRP_OP_DEVICES_H
#define HRP_OP_DEVICES_H

#include <stddef.h>
#include <stdint.h>

#include "dcm/dcm.h"

#define OP_BUS_MAX 8
#define OP_PI 3.14159265358979323846
#define OP_RAD_PER_COUNT (2.0 * OP_PI / 4096.0)

typedef enum { OP_MX = 1, OP_XM = 2 } op_family;        /* how a servo's extended read decodes */
typedef enum { OP_CM730 = 1, OP_OPENCR = 2 } op_board_kind;

/* A servo model: its control table as the DCM uses it. */
typedef struct op_servo_model {
  const char *name;
  int protocol;
  op_family family;
  uint16_t goal_addr, goal_len;           /* goal position */
  uint16_t pos_addr, pos_len;             /* present position */
  uint16_t ext_addr, ext_len;             /* round-robin extended read (speed, load, temperature) */
  uint16_t torque_addr;                   /* torque enable (1 byte) */
  uint16_t hard_addr, hard_len, hard_max; /* hardness 1.0: MX torque limit / XM position P gain */
  int max_count;
} op_servo_model;

/* A sub-controller with IMU and buttons: one read covers buttons .. voltage. */
typedef struct op_board_model {
  const char *name;
  int protocol;
  op_board_kind kind;
  uint16_t addr, len;
} op_board_model;

typedef struct op_servo {            /* a servo row */
  int row;                           /* 1-based row of devices, for messages */
  int joint;                         /* index in robot.joints (the shm order) */
  uint8_t id;
  int dir, zero;
  const op_servo_model *model;
} op_servo;

typedef struct op_board {            /* the board row */
  int row;
  uint8_t id;
  const op_board_model *model;
  int gyro_axis[3], accel_axis[3];    /* torso axis i = sign[i] * board axis axis[i] */
  double gyro_sign[3], accel_sign[3];
} op_board;

typedef struct op_busdef {
  char port[256];
  int baud;
  int protocol;
  int nservo;
  op_servo servo[DCM_NJ_MAX];
  int has_board;
  op_board board;
} op_busdef;

typedef struct op_body {
  char name[DCM_NAME_MAX];
  int nj;
  char joint[DCM_NJ_MAX][DCM_NAME_MAX];
  double lo[DCM_NJ_MAX], hi[DCM_NJ_MAX];   /* rad, joint limits */
  double period;                           /* s */
  int nbus;
  op_busdef bus[OP_BUS_MAX];
  int imu_bus;                             /* bus of the board that gives IMU and buttons, -1: none */
} op_body;

/* Reads and checks robot.lua's joints, limits, period, buses and devices. */
int op_body_load(const dcm_config *robot, op_body *b, char *err, size_t errlen);

/* Joint angle <-> servo counts. */
int op_rad_to_count(const op_body *b, const op_servo *s, double rad);
double op_count_to_rad(const op_servo *s, int count);

#endif
