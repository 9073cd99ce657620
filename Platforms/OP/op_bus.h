/* op_bus: one Dynamixel bus of the OP DCM -- its port, the servos and board on it, one cycle's
 * traffic: a sync write of goal positions (torque enable and hardness only when they change) and
 * one bulk read of positions (one servo in turn also gives speed, load and temperature) and of the
 * board (IMU, buttons). Dead servos leave the bulk read and are retried every retry_period; a lost
 * port is reopened. */
#ifndef HRP_OP_BUS_H
#define HRP_OP_BUS_H

#include "dynamixel/dynamixel.h"
#include "op_devices/op_devices.h"

/* What the buses read: per joint (shm order) and from the board. */
typedef struct op_state {
  double pos[DCM_NJ_MAX], vel[DCM_NJ_MAX], load[DCM_NJ_MAX], temp[DCM_NJ_MAX];  /* rad, rad/s, N*m, deg C */
  int have_pos[DCM_NJ_MAX];
  uint32_t serr[DCM_NJ_MAX], stimeout[DCM_NJ_MAX];   /* error bits reported; no answer */
  int32_t dead[DCM_NJ_MAX];
  double gyro[3], acc[3], angle[3], batt;            /* rad/s, m/s^2, rad, V (torso frame) */
  int button[2];
} op_state;

/* Settings from Config/platforms/OP/dcm.lua. */
typedef struct op_bus_settings {
  double timeout_margin;   /* s added to the wire time of expected answers */
  double retry_period;     /* s between retries of a dead servo */
  int dead_after;          /* consecutive missed answers before a servo is dead */
} op_bus_settings;

typedef struct op_bus {
  const op_body *body;
  const op_busdef *def;
  int index;                                   /* 0-based bus number */
  op_bus_settings set;
  dxl_port *port;
  dxl_bus bus;
  int reported;                                /* a port failure was logged */
  double port_retry_at;
  /* per servo of the bus (def->servo[k]) */
  int sent_en[DCM_NJ_MAX], sent_hard[DCM_NJ_MAX], miss[DCM_NJ_MAX];
  double retry_at[DCM_NJ_MAX];
  int rr;                                      /* servo of the extended read */
  uint8_t store[DCM_NJ_MAX + 1][32];
} op_bus;

void op_bus_init(op_bus *b, const op_body *body, int index, op_bus_settings set);
/* Opens the port (or reopens a lost one); -EAGAIN while it cannot be opened. */
int op_bus_open(op_bus *b, const dcm *d, char *err, size_t errlen);
/* Reads every servo once (start-up): the missing ones are marked dead, each with a line; when none
 * answers, one line instead says what the bus gave back (another protocol, bytes of no packet, or
 * silence). Returns how many answer. */
int op_bus_probe(op_bus *b, const dcm *d, op_state *st);
/* A cycle's commands out (reopens a lost port every 0.5 s); then the state in, one dead servo retried. */
void op_bus_write(op_bus *b, const dcm *d, const dcm_command *c, double now);
void op_bus_read(op_bus *b, const dcm *d, op_state *st, double now, double dt);
/* Bytes on the wire of one regular cycle (no changes of torque / hardness); sent and answers. */
int op_bus_wire_bytes(const op_bus *b, int *tx, int *rx);
void op_bus_close(op_bus *b);

#endif
