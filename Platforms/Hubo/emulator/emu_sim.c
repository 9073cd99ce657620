/* emu_sim: see emu_sim.h. */
#include "emu_sim.h"

#include <string.h>
#include <unistd.h>

int emu_sim_open(emu_sim *s, int sim_id, char *err, size_t errlen) {
  memset(s, 0, sizeof *s);
  return dcm_robot_attach(sim_id, &s->schema, &s->sensor, &s->actuator, err, errlen);
}

void emu_sim_close(emu_sim *s) { dcm_robot_detach(&s->schema, &s->sensor, &s->actuator); }

static void command(emu_sim *s, const emu_world *w) {
  shm_write_begin(s->actuator.blk);
  for (int k = 0; k < w->n; k++) {
    const emu_board *b = &w->b[k];
    if (b->def->kind != HT_JMC) continue;
    const int on = b->fet && b->ctrl && b->home_state == HCAN_HOME_OK && b->homing_until <= 0;
    for (int c = 0; c < b->def->nch; c++) {
      const ht_channel *ch = &b->def->ch[c];
      if (ch->joint < 0) continue;
      s->actuator.command[ch->joint] = on ? ht_counts_to_rad(ch, (int32_t)b->ref[c]) : s->sensor.position[ch->joint];
      s->actuator.hardness[ch->joint] = on ? 1 : 0;
      s->actuator.torque_enable[ch->joint] = on;
      /* current mode: the torque the current gives (current x constant x ratio, joint-side sign), applied by
       * the sim's drive model */
      const int cur = on && b->mode == HCAN_MODE_CURRENT;
      s->actuator.mode[ch->joint] = cur ? 1 : 0;
      s->actuator.torque[ch->joint] = cur ? ch->dir * b->amps[c] * ch->kt * ch->ratio : 0;
    }
  }
  /* the sim DCM's watchdog sees the emulator as its motion process */
  *s->actuator.tick_ack = *(volatile uint32_t *)s->sensor.tick;
  *s->actuator.writer_pid = (uint32_t)getpid();
  shm_write_end(s->actuator.blk);
}

static void sense(emu_sim *s, emu_world *w) {
  uint32_t seq;
  do {
    seq = shm_read_begin(s->sensor.blk);
    for (int k = 0; k < w->n; k++) {
      emu_board *b = &w->b[k];
      const ht_board *d = b->def;
      if (d->kind == HT_JMC) {
        for (int c = 0; c < d->nch; c++)
          if (d->ch[c].joint >= 0) b->pos[c] = ht_rad_to_counts(&d->ch[c], s->sensor.position[d->ch[c].joint]);
      } else if ((d->kind == HT_FT || d->kind == HT_FT_TILT) && d->mount >= 0) {
        const double *f = &s->sensor.ft[6 * d->mount];
        b->ft[0] = d->sign[0] * f[3];
        b->ft[1] = d->sign[1] * f[4];
        b->ft[2] = d->sign[2] * f[2];
      }
    }
    w->imu[0] = s->sensor.angle[0];
    w->imu[1] = s->sensor.angle[1];
    w->imu[2] = s->sensor.gyro[0];
    w->imu[3] = s->sensor.gyro[1];
  } while (shm_read_retry(s->sensor.blk, seq));
}

void emu_sim_step(emu_sim *s, emu_world *w) {
  command(s, w);
  sense(s, w);
}
