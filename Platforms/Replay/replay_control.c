/* replay_control: see replay_control.h. */
#include "replay_control.h"

#include <errno.h>
#include <math.h>
#include <unistd.h>

int replay_control_open(replay_control *c, const shm_schema *schema, int robot_id, double speed, char *err,
                        size_t errlen) {
  int rc = dcm_blocks_open(schema, robot_id, DCM_BLK_replay(&c->b), err, errlen);
  if (rc < 0) return rc;
  c->seq = *c->b.seq;
  c->paused = c->steps = c->seek_pending = c->speed_changed = 0;
  c->speed = speed;
  shm_write_begin(c->b.blk);
  *c->b.pid = (int32_t)getpid();
  *c->b.ack = c->seq;
  *c->b.status = 0;
  *c->b.speed = speed;
  *c->b.paused = *c->b.holding = 0;
  *c->b.steps = 0;
  shm_write_end(c->b.blk);
  return 0;
}

void replay_control_close(replay_control *c) {
  if (!c->b.blk) return;
  *c->b.pid = 0;
  shm_block_close(c->b.blk);
  c->b.blk = NULL;
}

/* Applies one command; its status. */
static int take(replay_control *c, int command, double arg) {
  switch (command) {
  case REPLAY_PAUSE:
    c->paused = 1;
    c->steps = 0;
    return 0;
  case REPLAY_RESUME:
    c->paused = 0;
    c->steps = 0;
    return 0;
  case REPLAY_SEEK:
    if (!isfinite(arg)) return -2;
    c->seek_pending = 1;
    c->seek_to = arg;
    return 0;
  case REPLAY_STEP:
    if (!(arg >= 1 && arg <= 1e9) || arg != floor(arg)) return -2;
    c->paused = 1;
    c->steps += (uint32_t)arg;
    return 0;
  case REPLAY_SPEED:
    if (!(arg > 0 && arg <= 1e6)) return -2;
    c->speed = arg;
    c->speed_changed = 1;
    return 0;
  default:
    return -1;
  }
}

int replay_control_poll(replay_control *c) {
  const uint32_t seq = __atomic_load_n(c->b.seq, __ATOMIC_ACQUIRE);
  if (seq == c->seq) return 0;
  int command = 0;
  double arg = 0;
  uint32_t s;
  do {   /* the client writes under the block's lock */
    s = shm_read_begin(c->b.blk);
    command = *c->b.command;
    arg = *c->b.arg;
  } while (shm_read_retry(c->b.blk, s));
  const int status = take(c, command, arg);
  c->seq = seq;
  shm_write_begin(c->b.blk);
  *c->b.status = status;
  *c->b.paused = c->paused;
  *c->b.steps = c->steps;
  *c->b.speed = c->speed;
  if (!replay_control_holds(c)) *c->b.holding = 0;
  *c->b.ack = seq;
  shm_write_end(c->b.blk);
  return 1;
}

void replay_control_publish(replay_control *c, const replay_log *L, int holding) {
  shm_write_begin(c->b.blk);
  *c->b.paused = c->paused;
  *c->b.holding = holding;
  *c->b.steps = c->steps;
  *c->b.speed = c->speed;
  *c->b.time = L->time;
  *c->b.first_time = L->first_time;
  *c->b.ticks = L->ticks;
  shm_write_end(c->b.blk);
}

int replay_control_holds(const replay_control *c) { return c->paused && c->steps == 0 && !c->seek_pending; }
