/* emu_sim: the emulated boards backed by the physics world (hubo_emulator --sim-id N).
 *
 * The motor boards' encoders read the sim DCM's robot N (its dcm.sensor positions through each
 * channel's counts per radian, direction and zero), and their references drive it: a channel whose
 * board has FETs and position controller on and is homed commands its joint at full hardness; a
 * board switched off leaves its joints unpowered (torque off); a board in current mode puts its
 * joints in torque mode with the torque its current gives (current x torque constant x ratio). Joints
 * on no board (the Hubo2+ neck: its board's formats are unknown) keep what the sim DCM commanded them
 * at its start. The F/T boards
 * read the robot's dcm.sensor.ft slot of their mount (Mx, My, Fz, the table's signs applied as the
 * DCM undoes them), the IMU its roll, pitch and their rates.
 */
#ifndef HRP_HUBO_EMU_SIM_H
#define HRP_HUBO_EMU_SIM_H

#include "dcm_blocks.h"
#include "emu.h"

typedef struct emu_sim {
  shm_schema *schema;
  dcm_blk_dcm_sensor sensor;     /* the simulated robot's */
  dcm_blk_dcm_actuator actuator;
} emu_sim;

/* Attaches to robot sim_id's blocks (those of its sim DCM). */
int emu_sim_open(emu_sim *s, int sim_id, char *err, size_t errlen);
void emu_sim_close(emu_sim *s);
/* The boards' references and power into the robot's dcm.actuator (acknowledging its tick), then its
 * dcm.sensor into the boards' encoders, F/T and IMU. */
void emu_sim_step(emu_sim *s, emu_world *w);

#endif
