/* dxl_sim: see dxl_sim.h. */
#include "dxl_sim.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#define COUNTS_PER_RAD (4096.0 / (2.0 * OP_PI))

int dxl_body_load(op_body *b, double *stall, char *err, size_t errlen) {
  dcm_config *rc = NULL;
  int r = dcm_config_load("robot", NULL, "OP", &rc, err, errlen);
  if (r == 0) r = op_body_load(rc, b, err, errlen);
  if (r == 0 && b->nbus != 1) {
    snprintf(err, errlen, "robot '%s' has %d buses; the emulator serves one", b->name, b->nbus);
    r = -1;
  }
  dcm_config *ac = NULL;
  if (r == 0 && stall) r = dcm_config_load("actuators", dcm_config_robot(rc), "OP", &ac, err, errlen);
  for (int i = 0; r == 0 && stall && i < b->bus[0].nservo; i++) {
    char key[DCM_NAME_MAX + 16];
    snprintf(key, sizeof key, "%s.torque", b->bus[0].servo[i].model->name);
    r = dcm_config_num(ac, key, &stall[i], err, errlen);
  }
  if (ac) dcm_config_free(ac);
  if (rc) dcm_config_free(rc);
  return r;
}

int dxl_sim_open(dxl_sim *s, int sim_id, char *err, size_t errlen) {
  memset(s, 0, sizeof *s);
  int r = dxl_body_load(&s->body, s->stall, err, errlen);
  if (r < 0) return r;
  s->bus = &s->body.bus[0];
  if ((r = dcm_robot_attach(sim_id, &s->schema, &s->sensor, &s->actuator, err, errlen)) < 0) return r;
  /* until the DCM asks for anything, the simulated robot holds where it is */
  for (int i = 0; i < s->bus->nservo; i++) {
    const op_servo *sv = &s->bus->servo[i];
    s->cmd[sv->joint] = s->sensor.position[sv->joint];
    s->hard[sv->joint] = 0;
    s->torque[sv->joint] = 0;
  }
  return 0;
}

void dxl_sim_close(dxl_sim *s) { dcm_robot_detach(&s->schema, &s->sensor, &s->actuator); }

void dxl_sim_command(dxl_sim *s, int i, double goal_count, int torque, double hard_reg) {
  const op_servo *sv = &s->bus->servo[i];
  s->cmd[sv->joint] = op_count_to_rad(sv, (int)lround(goal_count));
  s->torque[sv->joint] = torque != 0;
  double h = hard_reg / sv->model->hard_max;
  s->hard[sv->joint] = h < 0 ? 0 : h > 1 ? 1 : h;
}

void dxl_sim_flush(dxl_sim *s) {
  const int nj = s->body.nj;
  shm_write_begin(s->actuator.blk);
  memcpy(s->actuator.command, s->cmd, sizeof(double) * (size_t)nj);
  memcpy(s->actuator.hardness, s->hard, sizeof(double) * (size_t)nj);
  memcpy(s->actuator.torque_enable, s->torque, sizeof(int32_t) * (size_t)nj);
  /* the sim DCM's watchdog sees the emulator as its motion process */
  *s->actuator.tick_ack = *(volatile uint32_t *)s->sensor.tick;
  *s->actuator.writer_pid = (uint32_t)getpid();
  shm_write_end(s->actuator.blk);
}

void dxl_sim_read(dxl_sim *s, dxl_sim_state *st) {
  uint32_t seq;
  do {
    seq = shm_read_begin(s->sensor.blk);
    for (int i = 0; i < s->bus->nservo; i++) {
      const op_servo *sv = &s->bus->servo[i];
      st->count[i] = sv->zero + sv->dir * s->sensor.position[sv->joint] * COUNTS_PER_RAD;
      st->count_speed[i] = sv->dir * s->sensor.velocity[sv->joint] * COUNTS_PER_RAD;
      st->load[i] = sv->dir * s->sensor.load[sv->joint] / s->stall[i];
    }
    memcpy(st->gyro, s->sensor.gyro, sizeof st->gyro);
    memcpy(st->accel, s->sensor.accelerometer, sizeof st->accel);
    st->buttons = (s->sensor.button[0] ? 1 : 0) | (s->sensor.button[1] ? 2 : 0);
  } while (shm_read_retry(s->sensor.blk, seq));
}
