/* replay_control: pause, resume, seek, step and speed of the Replay DCM, from the `replay` shm block
 * (Config/shm.schema; Lib/replay.lua is the client: replay.pause() in the REPL).
 *
 * A client fills command and arg and bumps seq; the DCM takes the command at its next cycle (or at
 * once while it holds the clock), sets ack = seq and status, and publishes its state: paused,
 * holding (the clock held, the last tick served), steps left, speed, the log time served. While
 * paused the DCM publishes no tick: the robot's clock stops, every process waits for it as for a
 * stopped DCM. step(n) serves exactly n ticks and holds again; seek(t) serves t's tick next.
 */
#ifndef HRP_REPLAY_CONTROL_H
#define HRP_REPLAY_CONTROL_H

#include <stddef.h>
#include <stdint.h>

#include "dcm/dcm.h"
#include "replay_log.h"

#ifdef __cplusplus
extern "C" {
#endif

enum { REPLAY_PAUSE = 1, REPLAY_RESUME = 2, REPLAY_SEEK = 3, REPLAY_STEP = 4, REPLAY_SPEED = 5 };

typedef struct replay_control {
  dcm_blk_replay b;
  uint32_t seq;        /* the last command taken */
  int paused;
  uint32_t steps;      /* ticks to serve before holding again */
  int seek_pending;
  double seek_to;      /* s of log time */
  double speed;        /* times the recorded rate */
  int speed_changed;
} replay_control;

/* Opens robot_id's replay block; the commands written before this DCM started are ignored. */
int replay_control_open(replay_control *c, const shm_schema *schema, int robot_id, double speed, char *err,
                        size_t errlen);
void replay_control_close(replay_control *c);
/* Takes a new command, if any (ack, status). Returns 1 when one was taken. */
int replay_control_poll(replay_control *c);
/* Publishes the state and the position in the log L. */
void replay_control_publish(replay_control *c, const replay_log *L, int holding);
/* 1 while the clock is to be held (paused, no steps left, no seek pending). */
int replay_control_holds(const replay_control *c);

#ifdef __cplusplus
}
#endif
#endif
