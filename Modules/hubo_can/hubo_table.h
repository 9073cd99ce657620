/* hubo_table: a Hubo body's CAN buses and boards (Config/robots/<ROBOT>/can.lua, the `can`
 * concern) checked against its joints (robot.lua `joints`, `limits`, `period`).
 *
 * Checked at start, each error naming the file and the element (boards[3] (JMC2) channels[1]):
 * an unknown kind or mount, a bus that is not one of `buses`, a board or sensor number twice on a
 * bus (or out of range), a channel number twice or beyond the board's channels, a joint that is
 * not one of the body's or on two channels, a body joint on no channel, gear numbers <= 0, a
 * direction other than +-1, a speed limit <= 0.
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
/* The board kind can_proto keeps per board. */
hcan_board_kind ht_hcan_kind(ht_kind k);
/* Joint angle <-> motor counts of a channel. */
int32_t ht_rad_to_counts(const ht_channel *c, double rad);
double ht_counts_to_rad(const ht_channel *c, int32_t counts);

#endif
