/* hubo_bus: the Hubo DCM's cycle over its buses, as data flows (hubo_can.md 7, 8):
 *   bring-up   status of every motor board; homing if configured; FETs and controllers on for
 *              the homed boards; one encoder sweep so every reference starts at the measured pose
 *   write      references (0x10+#) for the enabled, answering boards -- clamped to the joint limits,
 *              never a step beyond max_speed * period, never NaN, never beyond 24 bits -- then the
 *              requests: every encoder, the F/T, IMU and power boards, a status and a current
 *              request in turn (not the foot tilt: dcm.sensor has no field for it)
 *   read       replies gathered until they are all in or the reply window closes; an answer
 *              missing `dead_after` cycles in a row marks the board dead: its joints get no
 *              references (the board holds its last one) and are reported; it is asked again every
 *              retry_period and, when it answers, resumes from its measured position (a board that
 *              was not there at bring-up is switched on then, if its status says it is homed)
 *   a bus whose interface goes away is reported and reopened every reopen_period.
 * Torque mode (dcm.actuator.mode 1, checked and clamped by the DCM's guard): a board goes into current
 * mode (H_SET_CTRL_MODE 1) when every joint on it is in torque mode -- the mode is the board's, not a
 * channel's, so a two-joint board with one joint in torque mode stays in position mode, that joint
 * held where it was (counted as refused, logged) --, then takes a current reference every cycle
 * (torque / (torque_constant * ratio)). When any of its joints leaves torque mode (Body, a guard
 * refusal of a NaN torque, a watchdog trip: a stale or dead writer), it gets H_SET_CTRL_MODE 0 and a
 * position reference at its measured position in the same cycle. A board that dies in current mode
 * keeps its last current (it cannot be reached); when it answers again it is put in position mode
 * first. On close every board in current mode is put back in position mode at its measured pose.
 */
#ifndef HRP_HUBO_BUS_H
#define HRP_HUBO_BUS_H

#include "dcm/dcm.h"
#include "hubo_io.h"
#include "hubo_can/hubo_table.h"

typedef struct hubo_settings {
  double compliant_below;   /* hardness below which a joint's reference follows its position */
  double retry_period;      /* s between requests to a dead board */
  double reply_window;      /* fraction of the period spent collecting replies */
  double startup_hold;      /* s after bring-up before references flow */
  double home_timeout;      /* s */
  double reopen_period;     /* s */
  int dead_after, status_every, current_every, home_at_start, enable_at_start;
} hubo_settings;

/* What the DCM publishes. */
typedef struct hubo_state {
  double pos[DCM_NJ_MAX], vel[DCM_NJ_MAX], temp[DCM_NJ_MAX];   /* rad, rad/s, deg C */
  double gyro[3], acc[3], angle[3];                             /* rad/s, m/s^2, rad */
  double ft[HT_FT_SLOTS * 6];                                   /* fx fy fz mx my mz per slot */
  double foot[2];                                               /* N: left, right */
  double battery;                                               /* V */
} hubo_state;

typedef struct hubo {
  ht_table t;
  hubo_settings set;
  int nbus;
  hio_bus bus[HT_BUS_MAX];
  int idx[HT_BOARD_MAX];              /* board (table order) -> index in its bus's net */
  int enabled[HT_BOARD_MAX];          /* controller switched on by this DCM */
  int to_enable[HT_BOARD_MAX];        /* answered late: enabled once its status says homed */
  int dead[HT_BOARD_MAX];             /* as reported last cycle */
  int mode[HT_BOARD_MAX];             /* control mode as last sent: HCAN_MODE_*, -1 unknown (died in current mode) */
  int split[DCM_NJ_MAX];              /* in torque mode on a board that is not: held at split_hold */
  double split_hold[DCM_NJ_MAX];      /* rad */
  double amps[DCM_NJ_MAX];            /* A, the last current reference sent (current mode) */
  double last_try[HT_BOARD_MAX];      /* s, last request to a dead board */
  double ref[DCM_NJ_MAX];             /* rad, the last reference sent */
  int seeded[DCM_NJ_MAX];             /* ref holds a measured position or a sent reference */
  double enc_time[DCM_NJ_MAX];        /* s, time of the last encoder reading */
  double refs_from;                   /* s, references are held back until then */
  uint32_t cycle;
  uint32_t ref_limited;               /* joint-cycles whose reference the speed limit held back */
  uint32_t ref_refused;               /* references not sent: beyond 24 bits or not finite */
  uint32_t mode_frames;               /* H_SET_CTRL_MODE frames sent */
  uint32_t split_refused;             /* joint-cycles in torque mode held because their board is not */
  hubo_state st;
} hubo;

/* Sets up the buses' bookkeeping from the table (no I/O). */
void hubo_setup(hubo *h);
/* Opens every closed bus; -EAGAIN (message in err) while one is missing. */
int hubo_open(hubo *h, char *err, size_t errlen);
/* The bring-up sequence; logs through d. */
int hubo_bringup(hubo *h, dcm *d, char *err, size_t errlen);
/* One cycle: references from cmd (checked by the DCM's guard), then the requests. */
void hubo_write(hubo *h, dcm *d, const dcm_command *cmd);
/* Every board in current mode back to position mode at its measured pose (the DCM's end). */
void hubo_release(hubo *h, dcm *d);
/* One cycle: the replies until `deadline` (monotonic s), decoded into h->st; dead boards and
 * vanished buses reported through d, closed buses reopened. */
void hubo_read(hubo *h, dcm *d, double deadline);
/* The joint is not driven (its board inactive, dead, or its bus closed). */
int hubo_joint_down(const hubo *h, int j);
/* Board k's bookkeeping in its bus's net. */
const hcan_board *hubo_board(const hubo *h, int k);

#endif
