/* hubo_table: a Hubo body's CAN buses and boards (Config/robots/<ROBOT>/can.lua, the `can`
 * concern) checked against its joints (robot.lua `joints`, `limits`, `period`).
 *
 * Checked at start, each error naming the file and the element (boards[3] (JMC2) channels[1]):
 * an unknown kind or mount, a bus that is not one of `buses`, a board or sensor number twice on a
 * bus (or out of range), a channel number twice or beyond the board's channels, a joint that is
 * not one of the body's or on two channels, a body joint on no channel, gear numbers <= 0, a
 * direction other than +-1, a speed limit <= 0, a torque constant or a current limit <= 0 or one
 * of the two without the other.
 *
 * Current mode (H_SET_CTRL_MODE 1): a channel with `torque_constant` (N*m/A of its motor) and
 * `max_current` (A) has a current path; joint torque = current * torque_constant * ratio, the ratio
 * the channel's gears give (driven * harmonic / drive). ht_load_actuators adds each such joint's
 * drive (robot.lua `actuator` naming a model of the `actuators` concern: its stall torque and
 * no-load speed).
 */
#ifndef HRP_HUBO_TABLE_H
#define HRP_HUBO_TABLE_H

#include <stddef.h>
#include <stdint.h>

#include "can_proto.h"
#include "dcm/dcm.h"

#define HT_BUS_MAX 4
#define HT_BOARD_MAX 32
#define HT_CH_MAX 3
#define HT_FT_SLOTS 4   /* dcm.sensor.ft: left foot, right foot, left hand, right hand */

typedef enum { HT_JMC = 1, HT_JMC3, HT_FT, HT_FT_TILT, HT_IMU, HT_POWER } ht_kind;

typedef struct ht_channel {
  int ch;                 /* motor index on the board */
  int joint;              /* index in the body's joints */
  double cpr;             /* encoder counts per radian of the joint */
  int dir;                /* +1 / -1 */
  int32_t zero;           /* counts at the joint's zero */
  double max_speed;       /* rad/s */
  double ratio;           /* motor turns per joint turn: driven * harmonic / drive */
  double kt;              /* N*m/A of the motor (0: no current mode for this channel) */
  double max_current;     /* A, the largest current reference ever sent */
  double torque;          /* N*m, the joint's drive's stall torque (ht_load_actuators; 0 unknown) */
  double speed;           /* rad/s, its no-load speed (ht_load_actuators; 0 unknown) */
} ht_channel;

typedef struct ht_board {
  int row;                /* 1-based row of `boards` */
  char name[DCM_NAME_MAX];
  int bus;                /* 0-based */
  ht_kind kind;
  int number;             /* board number #, or sensor number $ */
  int active;
  int nch;
  ht_channel ch[HT_CH_MAX];
  int mount;              /* F/T slot 0..3, -1 */
  double sign[3];         /* Mx, My, Fz */
} ht_board;

typedef struct ht_table {
  char name[DCM_NAME_MAX];   /* the body */
  int nj;
  char joint[DCM_NJ_MAX][DCM_NAME_MAX];
  double lo[DCM_NJ_MAX], hi[DCM_NJ_MAX];   /* rad */
  double period;                           /* s */
  double bitrate;                          /* bit/s */
  int nbus;
  char bus_name[HT_BUS_MAX][DCM_NAME_MAX], iface[HT_BUS_MAX][DCM_NAME_MAX];
  int nboard;
  ht_board board[HT_BOARD_MAX];
  int joint_board[DCM_NJ_MAX], joint_ch[DCM_NJ_MAX];   /* where each joint is */
} ht_table;

/* Reads and checks both concerns (robot.lua and can.lua of one body). */
int ht_load(const dcm_config *robot, const dcm_config *can, ht_table *t, char *err, size_t errlen);
/* Each current-mode channel's drive: robot.lua's `actuator.<joint>` names a model of the actuators
 * concern (Config/common/actuators.lua + the body's), whose `torque` and `speed` are read. An error
 * names the file and key (a current-mode joint with no actuator, a model without them). */
int ht_load_actuators(const dcm_config *robot, const dcm_config *actuators, ht_table *t, char *err, size_t errlen);
/* The joint torque a channel's current path gives at most (N*m): its drive's torque, and no more than
 * max_current gives; 0 for a channel without current mode. */
double ht_torque_limit(const ht_channel *c);
/* Joint torque (N*m) -> the motor current (A) of a current-mode channel (its direction applied). */
double ht_torque_to_current(const ht_channel *c, double nm);
/* The board kind can_proto keeps per board. */
hcan_board_kind ht_hcan_kind(ht_kind k);
/* Joint angle <-> motor counts of a channel. */
int32_t ht_rad_to_counts(const ht_channel *c, double rad);
double ht_counts_to_rad(const ht_channel *c, int32_t counts);

#endif
