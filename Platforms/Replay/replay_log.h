/* replay_log: a recording (Run/recorder's MCAP) read back tick by tick for the Replay DCM.
 *
 * A tick is a recorded dcm.sensor message and the messages that follow it up to the next one (the
 * recorder samples every block right after each DCM tick). The blocks to serve (Config/platforms/
 * Replay/dcm.lua: serve) are checked against the present Config/shm.schema when the log is opened: a
 * log recorded with another layout is refused with the difference named. Reading stops at the first
 * damage (a truncated or corrupt file), which is reported with what was replayed before it.
 */
#ifndef HRP_REPLAY_LOG_H
#define HRP_REPLAY_LOG_H

#include <stddef.h>
#include <stdint.h>

#include "mcap/mcap.h"
#include "shmlog/shmlog.h"

#ifdef __cplusplus
extern "C" {
#endif

#define REPLAY_BLOCKS_MAX 16
#define REPLAY_CHANNELS_MAX 256

/* Decodes a compressed frame into a YUYV image of w x h (cap bytes); 0 or a negative code. */
typedef int (*replay_frame_fn)(void *ctx, const uint8_t *data, size_t len, int w, int h, uint8_t *yuyv, size_t cap);

typedef struct replay_block {
  shm_block *blk;
  shmlog_block now;        /* the fields served (the camera's raw field left out when the log has frames) */
  uint8_t *stage;          /* a copy of the segment: this tick's values */
  int dirty;               /* a message for it came in this tick */
  int has_frames;          /* the log has its compressed frames */
  uint64_t frame_offset;   /* of the raw field */
  size_t frame_bytes;
  int width_off, height_off;
  uint8_t left[SHMLOG_FIELDS_MAX]; /* 1: a field of `now` the processes under test write: not served */
  uint8_t *pending;        /* a seek's last frame message, decoded when the seek ends */
  size_t pending_len, pending_cap;
} replay_block;

typedef struct replay_log {
  mcap_reader *r;
  int nblocks;
  replay_block b[REPLAY_BLOCKS_MAX];
  int sensor;                          /* index of dcm.sensor in b */
  int chan_block[REPLAY_CHANNELS_MAX]; /* channel id -> block index, -1 not served */
  int chan_frame[REPLAY_CHANNELS_MAX]; /* channel id -> block index of its frames, -1 */
  mcap_message next;                   /* the next tick's dcm.sensor message, read ahead */
  int have_next, ended;
  int seeking;                         /* frames are stashed, not decoded (replay_log_seek) */
  uint64_t ticks, frames, bad_frames;
  double first_time, time;             /* s, robot clock of the first / current tick */
  replay_frame_fn frame_fn;
  void *frame_ctx;
  char damage[512];                    /* why reading stopped early ("" at a clean end) */
} replay_log;

/* Opens path for robot_id's blocks `serve` (one of them dcm.sensor); camera_field: the raw image
 * field the recorder compresses; leave: "block.field" names of served blocks whose fields are left
 * to the processes under test (nleave of them; each must name a field of a served block). Fails
 * naming the file and the difference. */
int replay_log_open(replay_log *L, const char *path, const shm_schema *schema, int robot_id, const char *const *serve,
                    int nserve, const char *const *leave, int nleave, const char *camera_field,
                    replay_frame_fn frame_fn, void *frame_ctx, char *err, size_t errlen);
void replay_log_close(replay_log *L);
/* Reads the next tick into the blocks' stages (dirty set). 1, 0 at the end, < 0 at damage (L->damage). */
int replay_log_next(replay_log *L);
/* Writes the dirty stages but dcm.sensor's into their segments (each under its lock). */
void replay_log_serve(replay_log *L);
/* Back to the start. */
void replay_log_rewind(replay_log *L);
/* Reads up to the tick of log time t -- the last tick at or before t (the first tick for a t before
 * it) -- into the stages, every block marked dirty, so that replay_log_serve serves it whole.
 * Backwards from the start of the log; the camera frames skipped are not decoded, only the last.
 * 1, or <= 0 as replay_log_next when no tick could be read. */
int replay_log_seek(replay_log *L, double t);

#ifdef __cplusplus
}
#endif
#endif
