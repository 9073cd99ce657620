/* can_proto: the Hubo2+ motor-board CAN protocol (hubo-ach / HuboCan, see the facts collected in
 * shared/robots/hubo_can.md): frames the host sends, frames the boards send, their units, the bit
 * timing of a classic CAN frame, and the host's per-board bookkeeping of one bus.
 *
 * No I/O and no config here: the DCM (dcm_hubo), the emulator (Platforms/Hubo/emulator), the tests and
 * the fuzzer all use this one file. Prefix hcan_. Frames are plain structs laid out like Linux's
 * struct can_frame (id with the same EFF / RTR / ERR flag bits, dlc, 8 data bytes).
 *
 * Byte orders and encodings (section numbers of hubo_can.md):
 *   reference 0x10+#      DLC 6: two 24-bit sign-magnitude counts, LE (4.1); in current mode two
 *                         24-bit sign-magnitude currents in 0.01 A (our reading: see hcan_cur_ref)
 *   command   0x001       [board, code, args...] (4.2); sensor request 0x002 [$, type...] (4.3)
 *   encoder   0x60+#      DLC 8: two int32 LE counts (5.1); the power board answers on 0x06E (5.7)
 *   status    0x150+#     4 bytes per channel: flags, faults, limits (5.2)
 *   current   0x1C0+#     10-bit currents in 0.01 A, temperature byte 2 (5.3)
 *   F/T       0x40+$      int16 LE Mx, My (0.01 N*m), Fz (0.1 N) (5.5)
 *   tilt, IMU 0x50+$      tilt: int16 /100 deg, /750 (5.6); IMU: int16 0.01 deg, 0.01 deg/s
 */
#ifndef HRP_CAN_PROTO_H
#define HRP_CAN_PROTO_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- frames */

#define HCAN_EFF 0x80000000u   /* extended (29-bit) identifier: Hubo boards never use one */
#define HCAN_RTR 0x40000000u   /* remote request: never used */
#define HCAN_ERR 0x20000000u   /* a controller's error frame (SocketCAN error class in the id) */
#define HCAN_SFF_MASK 0x7FFu

typedef struct hcan_frame {
  uint32_t id;      /* 11-bit identifier and flags (as struct can_frame's can_id) */
  uint8_t dlc;      /* 0..8 data bytes */
  uint8_t data[8];
} hcan_frame;

/* Identifiers (section 3). # = board number, $ = sensor number. */
#define HCAN_ID_CMD 0x001u
#define HCAN_ID_SENSOR_REQ 0x002u
#define HCAN_ID_REF(b) (0x010u + (unsigned)(b))
#define HCAN_ID_FT(s) (0x040u + (unsigned)(s))
#define HCAN_ID_IMU(s) (0x050u + (unsigned)(s))
#define HCAN_ID_ENC(b) (0x060u + (unsigned)(b))
#define HCAN_ID_POWER 0x06Eu
#define HCAN_ID_STATUS(b) (0x150u + (unsigned)(b))
#define HCAN_ID_CURRENT(b) (0x1C0u + (unsigned)(b))
#define HCAN_SENSOR_BOARD(s) (0x2F + (s))   /* a sensor board's number in command frames */
#define HCAN_POWER_BOARD 0x0E
#define HCAN_BOARD_MAX 0x30                 /* motor boards 0x00..0x2F */
#define HCAN_SENSOR_MAX 16                  /* sensor numbers 0..15 */

/* Command codes (byte 1 of id 0x001). */
enum {
  HCAN_C_STATUS = 0x02, HCAN_C_ENCODER = 0x03, HCAN_C_CURRENT = 0x04, HCAN_C_ENC_ZERO = 0x06,
  HCAN_C_FET = 0x0B, HCAN_C_CTRL_ON = 0x0E, HCAN_C_CTRL_OFF = 0x0F, HCAN_C_CTRL_MODE = 0x10, HCAN_C_HOME = 0x11,
  HCAN_C_NULL = 0x81, HCAN_C_POWER = 0xE0, HCAN_C_INIT = 0xFA,
};
/* Sensor request types (byte 1 of id 0x002). */
enum { HCAN_S_FT = 0x12, HCAN_S_TILT = 0x22, HCAN_S_IMU = 0x00 };
#define HCAN_ALL_CHANNELS 0x0F   /* channel argument of 0x06 / 0x11 for every channel */
#define HCAN_HOME_OK 6           /* home state of a homed channel */
#define HCAN_REF_MAX 8388607     /* largest magnitude of a 24-bit sign-magnitude reference */
/* Control modes of H_SET_CTRL_MODE (4.2: 0 position, 1 current -- the 2008 sheet's "torque" --, 2 the
 * DRC finger boards' hybrid mode, which no Hubo2+ body board has). */
enum { HCAN_MODE_POSITION = 0, HCAN_MODE_CURRENT = 1 };
#define HCAN_CUR_UNIT 0.01       /* A per count of a current reference (4.1 DRC finger currents, 5.3 replies) */

/* ---------------------------------------------------------------- host -> boards */

/* Reference of a 1- or 2-channel board: counts c0, c1 as 24-bit sign-magnitude, DLC 6 (a
 * one-joint board gets c0 twice). -ERANGE when a count does not fit (nothing is written). */
int hcan_ref(hcan_frame *f, int board, int32_t c0, int32_t c1);
/* [board, code, args...] on 0x001, DLC 2 + nargs (nargs <= 6). */
void hcan_cmd(hcan_frame *f, int board, int code, const uint8_t *args, int nargs);
void hcan_req_encoder(hcan_frame *f, int board, int sel);   /* [#, 0x03, sel] */
void hcan_req_status(hcan_frame *f, int board);             /* [#, 0x02, 0], DLC 3 as hubo-ach */
void hcan_req_current(hcan_frame *f, int board);            /* [#, 0x04] */
void hcan_home(hcan_frame *f, int board, int ch);           /* ch 0.. or HCAN_ALL_CHANNELS; DLC 8 */
void hcan_fet(hcan_frame *f, int board, int on);            /* [#, 0x0B, on] */
void hcan_ctrl(hcan_frame *f, int board, int on);           /* [#, 0x0E] / [#, 0x0F] */
void hcan_enc_zero(hcan_frame *f, int board, int ch);       /* [#, 0x06, ch] */
/* H_SET_CTRL_MODE [#, 0x10, mode], DLC 3 (4.2): one mode for the whole board, every channel. */
void hcan_ctrl_mode(hcan_frame *f, int board, int mode);
/* The current reference of a 1- or 2-channel board in current mode (mode 1): id 0x10+#, DLC 6, the
 * position reference's layout (4.1) with each channel's slot holding a signed current in 0.01 A as
 * 24-bit sign-magnitude, truncated toward zero (never more than asked). hubo_can.md does not give
 * this frame for the body boards; why this reading: Platforms/Hubo/README.md, "Current mode".
 * -EINVAL for a current that is not finite, -ERANGE beyond 24 bits (nothing is written). */
int hcan_cur_ref(hcan_frame *f, int board, double amps0, double amps1);
void hcan_req_ft(hcan_frame *f, int sensor);                /* 0x002 [$, 0x12] */
void hcan_req_tilt(hcan_frame *f, int sensor);              /* 0x002 [$, 0x22] */
void hcan_req_imu(hcan_frame *f, int sensor);               /* 0x002 [$, 0x00, 0x01] */
void hcan_req_power(hcan_frame *f);                         /* 0x001 [0x0E, 0xE0] */

/* ---------------------------------------------------------------- boards -> host */

/* Status of one channel of a 1/2-channel board: the three bytes 4ch+0..2 of section 5.2. */
typedef struct hcan_status {
  uint8_t flags;    /* bit 0 driver (FET) on, 1 controller on, 2 mode, 3 limit switch, 4-7 home state */
  uint8_t faults;   /* 0 jam, 1 PWM saturated, 2 big error, 3 encoder error, 4 driver fault, 5-6 motor fail */
  uint8_t limits;   /* 0 below min, 1 above max, 2 velocity, 3 acceleration, 4 temperature error */
} hcan_status;
#define HCAN_ST_DRIVER 0x01
#define HCAN_ST_CTRL 0x02
#define HCAN_ST_MODE 0x04   /* set: not position mode */
#define HCAN_ST_HOME(s) ((s).flags >> 4)
/* hubo-ach's isError: any fault or limit flag. */
static inline int hcan_status_fault(hcan_status s) { return (s.faults & 0x7F) || (s.limits & 0x1F); }

void hcan_rep_encoder(hcan_frame *f, int board, int32_t c0, int32_t c1);
void hcan_rep_status(hcan_frame *f, int board, const hcan_status st[2]);
/* amps 0..10.23 (0.01 A), temperature 0..255 */
void hcan_rep_current(hcan_frame *f, int board, const double amps[2], double temp);
/* N*m, N; saturated to the int16 range */
void hcan_rep_ft(hcan_frame *f, int sensor, double mx, double my, double fz);
/* rad, rad/s */
void hcan_rep_imu(hcan_frame *f, int sensor, double roll, double pitch, double roll_rate, double pitch_rate);
/* tilt about x and y (rad), the third field raw / 750 as the drivers read it */
void hcan_rep_tilt(hcan_frame *f, int sensor, double tx, double ty, double az);
void hcan_rep_power(hcan_frame *f, double volt, double amp, double watt);

/* ---------------------------------------------------------------- decoding */

/* Errors of the decoders: the frame is skipped and counted by its class. */
enum { HCAN_E_SHORT = -1, HCAN_E_ID = -2, HCAN_E_FORMAT = -3 };

/* What a frame on the bus is, from its identifier alone. */
typedef enum {
  HCAN_K_NONE = 0, HCAN_K_REF, HCAN_K_CMD, HCAN_K_SENSOR_REQ,  /* host frames */
  HCAN_K_ENC, HCAN_K_STATUS, HCAN_K_CURRENT, HCAN_K_FT, HCAN_K_IMU,  /* board frames */
  HCAN_K_ERROR,                                                /* a controller's error frame */
} hcan_kind;

/* Kind and board / sensor number of a frame; HCAN_K_NONE for an identifier nobody uses
 * (extended, remote, out of every range). */
hcan_kind hcan_classify(const hcan_frame *f, int *number);

/* Field decoders; 0, or HCAN_E_SHORT when the DLC is below the layout's. */
int hcan_dec_ref(const hcan_frame *f, int32_t c[2]);
/* A current reference (the emulator's side of hcan_cur_ref): A per channel. */
int hcan_dec_cur_ref(const hcan_frame *f, double amps[2]);
int hcan_dec_encoder(const hcan_frame *f, int32_t c[2]);
int hcan_dec_status(const hcan_frame *f, hcan_status st[2]);
int hcan_dec_current(const hcan_frame *f, double amps[2], double *temp);
int hcan_dec_ft(const hcan_frame *f, double ft[3]);          /* Mx, My (N*m), Fz (N) */
int hcan_dec_imu(const hcan_frame *f, double imu[4]);        /* roll, pitch (rad), their rates (rad/s) */
int hcan_dec_tilt(const hcan_frame *f, double tilt[3]);      /* about x, y (rad), az (raw / 750) */
int hcan_dec_power(const hcan_frame *f, double p[3]);        /* V, A, W */

/* ---------------------------------------------------------------- units */

/* Counts of the motor encoder per radian of the joint: driven * harmonic * enc / (drive * 2 pi). */
double hcan_counts_per_rad(int drive, int driven, int harmonic, int enc);
/* rad -> counts, truncated toward zero as hubo-ach's ref2enc. */
int32_t hcan_rad_to_counts(double rad, double counts_per_rad);
double hcan_counts_to_rad(int32_t counts, double counts_per_rad);

/* Bits a classic CAN data frame with an 11-bit id takes on the wire: 47 + 8 * dlc plus the stuff
 * bits, counted exactly over SOF .. CRC (the CRC-15 computed), interframe space included. */
int hcan_frame_bits(const hcan_frame *f);

/* ---------------------------------------------------------------- one bus, the host's view */

typedef enum { HCAN_B_JMC = 1, HCAN_B_FT, HCAN_B_TILT_FT, HCAN_B_IMU, HCAN_B_POWER } hcan_board_kind;
/* Reply kinds a board may owe in a cycle (bit mask). */
enum { HCAN_R_ENC = 1, HCAN_R_STATUS = 2, HCAN_R_CURRENT = 4, HCAN_R_FT = 8, HCAN_R_TILT = 16, HCAN_R_IMU = 32,
       HCAN_R_POWER = 64 };

typedef struct hcan_board {
  hcan_board_kind kind;
  int number;                  /* board number #, or sensor number $ for FT / IMU boards */
  /* the latest values */
  int32_t enc[2];              /* counts */
  hcan_status status[2];
  double current[2], temp;     /* A, deg C */
  double ft[3];                /* Mx, My (N*m), Fz (N) */
  double tilt[3], imu[4], power[3];
  /* bookkeeping: a reply pays this cycle's request, else one left unanswered by an earlier cycle
   * (a late reply: used, counted late); with neither it is unexpected */
  uint32_t asked;              /* replies asked for this cycle */
  uint32_t owed;               /* of those, not answered yet */
  uint32_t fresh;              /* replies that came this cycle (this cycle's or late ones) */
  uint32_t paid_late;          /* reply kinds a late reply came for this cycle */
  uint8_t carry[8];            /* per reply kind: earlier requests still unanswered (at most 2) */
  uint32_t replies, timeouts, late, faults;
  int missed;                  /* cycles in a row with an answer missing */
  int dead;                    /* missed >= dead_after */
} hcan_board;

#define HCAN_NET_MAX 32
typedef struct hcan_net {
  int n;
  hcan_board b[HCAN_NET_MAX];
  int8_t by_board[0x80];       /* motor board number -> index, -1 */
  int8_t by_sensor[HCAN_SENSOR_MAX];
  /* frames skipped, by class */
  uint32_t rx, corrupt, misaddressed, unexpected, error_frames;
} hcan_net;

void hcan_net_init(hcan_net *n);
/* Adds a board; returns its index, or -1 (full, duplicate number, number out of range). */
int hcan_net_add(hcan_net *n, hcan_board_kind kind, int number);
/* Board i owes the replies in mask this cycle (the request was sent). */
void hcan_net_owe(hcan_net *n, int i, uint32_t mask);
/* Decodes a received frame into its board. Returns the board's index, or -1 when it was skipped
 * (counted: corrupt = wrong length or error frame, misaddressed = a board not on this bus,
 * unexpected = an id or reply nobody asked for). Host frames seen on the bus are ignored (-2). */
int hcan_net_rx(hcan_net *n, const hcan_frame *f);
/* Ends a cycle: a board with a reply still owed has a timeout (its request is carried: a late reply
 * is still taken); dead_after cycles in a row with one makes it dead until it answers in time again.
 * A kind answered in time with no late reply in the cycle drops its carry (the board is in step).
 * Returns the boards that died now. */
int hcan_net_end_cycle(hcan_net *n, int dead_after);

#ifdef __cplusplus
}
#endif
#endif
