/* The Hubo board emulator's pieces: the boards' behaviour (emu_boards.c) and the bus with its
 * timing model and faults (hubo_emulator.c). */
#ifndef HRP_HUBO_EMU_H
#define HRP_HUBO_EMU_H

#include "hubo_can/can_proto.h"
#include "hubo_can/hubo_table.h"

/* One emulated board (any kind), from a row of the body's can.lua. */
typedef struct emu_board {
  const ht_board *def;
  /* motor boards, per channel */
  double pos[HT_CH_MAX];        /* counts */
  double ref[HT_CH_MAX];        /* counts */
  double vmax[HT_CH_MAX];       /* counts/s */
  double stop_lo[HT_CH_MAX], stop_hi[HT_CH_MAX];   /* counts, the joint's range (robot.lua limits) */
  int fet, ctrl;                /* FETs on, position controller on */
  int mode;                     /* HCAN_MODE_POSITION / HCAN_MODE_CURRENT (H_SET_CTRL_MODE) */
  double amps[HT_CH_MAX];       /* A, the current reference in current mode */
  uint32_t mode_frames, cur_refs;   /* H_SET_CTRL_MODE frames taken; current references taken */
  uint32_t enc_reqs;            /* encoder requests answered (one per DCM cycle) */
  int home_state;               /* 6 once homed */
  double homing_until;          /* s, a homing in progress ends then */
  uint8_t faults, limits;       /* injected status flags */
  uint32_t refs, refs_ignored;  /* reference frames taken / ignored (controller off) */
  /* sensor boards */
  double ft[3];                 /* Mx, My (N*m), Fz (N) */
  /* faults */
  int dead;
} emu_board;

typedef struct emu_world {
  int n;
  emu_board b[HT_BOARD_MAX];
  double imu[4];                /* roll, pitch (rad), rates (rad/s) */
  double power[3];              /* V, A, W */
  double tau;                   /* s, first-order time constant of the joints */
  double home_time;             /* s a homing takes */
  uint32_t unparsed;            /* host frames it cannot parse: an id no host frame has, a DLC below the
                                   layout's, a control mode the board does not have */
} emu_world;

/* Boards of the table at their start state: homed (or not), FETs and controllers off, at zero. */
void emu_init(emu_world *w, const ht_table *t, int homed, double tau);
/* Advances every motor board to time `now`, dt s after the last call. In position mode a channel
 * moves first-order towards its reference (time constant tau, at most max_speed). In current mode it
 * is a current-controlled drive with nothing to move but itself: joint torque = current x torque
 * constant x ratio, and the joint turns at the speed where the drive's speed-torque line (its stall
 * torque at rest, nothing at its no-load speed: actuators.lua `torque`, `speed`) leaves that torque,
 * speed = torque x no-load speed / stall torque, at most max_speed, up to the ends of the joint's range
 * (robot.lua's limits taken as hard stops). No inertia, gravity or load: the standalone emulator has no
 * body (with --sim-id the simulated robot applies the torque). */
void emu_step(emu_world *w, double now, double dt);
/* A host frame on bus `bus`: acts on it and writes up to 4 replies into out; returns how many. */
int emu_handle(emu_world *w, int bus, const hcan_frame *f, double now, hcan_frame *out);
/* The board called name ("JMC2") or numbered ("0x02", "2") on any bus, or NULL. */
emu_board *emu_find(emu_world *w, const char *name);

#endif
