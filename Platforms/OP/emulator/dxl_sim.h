/* dxl_sim: the emulator's bus backed by the physics world (dxl_emulator --sim-id N).
 *
 * The servos and the board are the body's device table (Config/robots/<ROBOT>/robot.lua `devices`,
 * read by the OP DCM's own reader, Modules/op_devices/op_devices.c), so the ids, directions and zeros are
 * the ones dcm_op uses. The simulated robot is the sim DCM's robot N (its own id, not dcm_op's): the
 * emulator writes that robot's dcm.actuator from the goals, torque enables and hardness registers it
 * receives, and answers reads from its dcm.sensor (positions, speeds, loads, IMU, buttons).
 */
#ifndef HRP_DXL_SIM_H
#define HRP_DXL_SIM_H

#include <stddef.h>
#include <stdint.h>

#include "dcm_blocks.h"
#include "op_devices/op_devices.h"

typedef struct dxl_sim {
  op_body body;
  const op_busdef *bus;          /* the bus the emulator serves (bus 1) */
  shm_schema *schema;
  dcm_blk_dcm_sensor sensor;     /* the simulated robot's */
  dcm_blk_dcm_actuator actuator;
  double cmd[DCM_NJ_MAX], hard[DCM_NJ_MAX];   /* staged for the next write, per joint */
  int32_t torque[DCM_NJ_MAX];
  double stall[DCM_NJ_MAX];      /* N m, per servo of the bus: its model's torque (actuators.lua) */
} dxl_sim;

/* The sensors of one read of the simulated robot, in the bus's units, per servo of the bus. */
typedef struct dxl_sim_state {
  double count[DCM_NJ_MAX];       /* present position, counts */
  double count_speed[DCM_NJ_MAX]; /* counts/s */
  double load[DCM_NJ_MAX];        /* fraction of the stall torque, in the servo's own direction */
  double gyro[3], accel[3];       /* torso frame: rad/s, m/s^2 */
  int buttons;                    /* bit mask */
} dxl_sim_state;

/* Reads the body ($ROBOT's robot.lua through op_devices) and checks that it has one bus, the one an
 * emulator serves; with stall non-NULL also each servo's stall torque (actuators.lua), per servo of
 * the bus. The emulator's default devices and --sim-id both come from here. */
int dxl_body_load(op_body *b, double *stall, char *err, size_t errlen);
/* Reads the body (dxl_body_load) and attaches to robot sim_id's blocks (those of its sim DCM). */
int dxl_sim_open(dxl_sim *s, int sim_id, char *err, size_t errlen);
void dxl_sim_close(dxl_sim *s);
/* Stages servo i's (bus order) goal (counts), torque enable and hardness register value. */
void dxl_sim_command(dxl_sim *s, int i, double goal_count, int torque, double hard_reg);
/* Writes the staged commands into the simulated robot's dcm.actuator, acknowledging its tick. */
void dxl_sim_flush(dxl_sim *s);
/* One consistent read of the simulated robot's dcm.sensor. */
void dxl_sim_read(dxl_sim *s, dxl_sim_state *st);

#endif
