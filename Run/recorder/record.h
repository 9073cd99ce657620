/* record: the recorder's parts (build/bin/hrp_record, started by ./run_main --record [DIR]).
 *
 *   sampler (main thread)  sleeps on dcm.sensor's write counter; on every DCM tick copies each block
 *                          (sequence lock: it never blocks a writer) and queues those whose content
 *                          changed, CDR-encoded (Modules/shmlog); a raw camera frame goes as it is
 *   queue                  bounded in bytes: when the writer falls behind, new items are dropped and
 *                          counted, so no robot process ever waits for the recorder
 *   writer (a thread)      JPEG-compresses frames (OpenCV), writes MCAP files (Modules/mcap), closes
 *                          a file past file_mb and deletes the oldest past total_mb
 * The recorder only reads the blocks and counts the DCM ticks it missed (dcm.sensor.tick gaps); with
 * --lockstep it is a lockstep observer (observer.c) and misses none.
 */
#ifndef HRP_RECORD_H
#define HRP_RECORD_H

#include <pthread.h>
#include <signal.h>
#include <stddef.h>
#include <stdint.h>

#include "shmlog/shmlog.h"

#ifdef __cplusplus
extern "C" {
#endif

#define REC_BLOCKS_MAX 64
#define REC_CONCERNS_MAX 32

typedef struct rec_opts {
  char dir[1024];
  double file_mb, total_mb, chunk_kb, flush_s, queue_mb;
  int zstd_level, jpeg_quality;
  char camera[16];                          /* jpeg | raw | off */
  char camera_block[SHM_NAME_MAX], camera_field[SHM_NAME_MAX];
  char exclude[REC_BLOCKS_MAX][64];         /* = DCM_NAME_MAX: filled by dcm_config_strs */
  int nexclude;
  char concerns[REC_CONCERNS_MAX][64];      /* = DCM_NAME_MAX */
  int nconcerns;
  double seconds;                           /* stop after this long (< 0: until a signal) */
  double history_s;                         /* s of each block kept for history() (0: none) */
  int robot_id, quiet;
  char robot[64], platform[64];
} rec_opts;

/* ---- one queued message */
/* REC_ITEM_TICK_END (no data) follows the items of one sample: files are rotated only there, so a tick
 * is never split across two files */
enum { REC_ITEM_BLOCK = 0, REC_ITEM_FRAME = 1, REC_ITEM_PACKET = 2, REC_ITEM_TICK_END = 3 };
typedef struct rec_item {
  struct rec_item *next;
  int kind;
  int channel;             /* block index (REC_ITEM_BLOCK), the camera block's index, or for a packet
                              0 GameController, 1 team */
  uint64_t log_time;       /* ns, robot clock */
  uint64_t publish_time;   /* ns, wall clock */
  int width, height;       /* REC_ITEM_FRAME */
  size_t len;
  uint8_t data[];          /* CDR message, or the raw YUYV frame */
} rec_item;

typedef struct rec_queue {
  pthread_mutex_t mu;
  pthread_cond_t cv, room;
  rec_item *head, *tail;
  size_t bytes, cap;
  uint64_t dropped;
  int closed;
  int wait_for_room;       /* lockstep: a full queue holds the sampler (and so the tick) instead of dropping */
} rec_queue;

void rec_queue_init(rec_queue *q, size_t cap);
/* Takes ownership of it; 0, or -1 when the queue is full (it is freed and counted as dropped). With
 * wait_for_room it waits until the writer made room instead (a lockstep run has time, and a replay
 * needs every tick). */
int rec_queue_push(rec_queue *q, rec_item *it);
/* The oldest item, waiting up to timeout_s; NULL on timeout or when closed and empty. */
rec_item *rec_queue_pop(rec_queue *q, double timeout_s);
void rec_queue_close(rec_queue *q);
/* Marks the end of a sample's items (a REC_ITEM_TICK_END item). */
void rec_queue_tick_end(rec_queue *q);
uint64_t rec_queue_dropped(rec_queue *q);

/* ---- the blocks being recorded */
/* a block's field `name` if it has the type `type` (SHM_*), else NULL; its element count in *count */
void *rec_field(shm_block *b, const char *name, int type, int *count);

typedef struct rec_block {
  shm_block *blk;
  shmlog_block msg;        /* its message (the camera's raw field left out when frames go as JPEG) */
  uint8_t *last, *now;     /* copies of the segment: last recorded, this sample */
  size_t size;
  int has_frame;           /* the camera block: its raw field is recorded as frames */
  uint64_t frame_offset;   /* of the raw field */
  size_t frame_bytes;
  int width_off, height_off; /* offsets of its width / height fields (-1: none) */
  int stale;               /* its writer died mid-update (shm_read_begin_checked): left out, said once */
  uint32_t stale_seq;      /* the odd sequence it was left at */
} rec_block;

typedef struct rec_blocks {
  int n;
  int sensor;              /* index of dcm.sensor (-1: none): its own time stamps each sample */
  uint64_t time_offset;    /* of its f64 time field */
  int64_t tick_offset;     /* of its u32 tick field (-1: none) */
  uint32_t last_tick;      /* the tick of the last dcm.sensor copy that changed */
  int have_tick;
  uint64_t missed;         /* DCM ticks between two recorded copies: the ticks the recorder missed */
  rec_block b[REC_BLOCKS_MAX];
  shm_schema *schema;
} rec_blocks;

/* Opens every block of the schema but the excluded ones. */
int rec_blocks_open(rec_blocks *bs, const rec_opts *o, char *err, size_t errlen);
void rec_blocks_close(rec_blocks *bs);
/* Samples every block once, queueing what changed at robot time `log_time` (and appending it to the
 * history h, when not NULL). Returns items queued. */
struct rec_history;
int rec_blocks_sample(rec_blocks *bs, rec_queue *q, struct rec_history *h, uint64_t log_time, uint64_t wall_ns);

/* ---- the UDP datagrams the behavior read (net.packets, Lib/netlog.lua): channels of their own */
#define REC_PACKETS_BLOCK "net.packets"
typedef struct rec_packets {
  shm_block *blk;
  const uint32_t *count, *host;
  const int32_t *source, *length, *port;
  const double *time;
  const uint8_t *data;
  int slots;
  size_t slot_bytes;
  uint32_t next;           /* the next datagram number to take */
  uint64_t taken, lost;    /* recorded; overwritten in the ring before the recorder took them */
} rec_packets;
int rec_packets_open(rec_packets *p, shm_schema *schema, int robot_id, char *err, size_t errlen);
/* Queues the datagrams written since the last call; returns how many. */
int rec_packets_sample(rec_packets *p, rec_queue *q, uint64_t log_time, uint64_t wall_ns);
void rec_packets_close(rec_packets *p);

/* ---- the recent past of every small block in shared memory, for history() (Lib/history.lua) */
typedef struct rec_history {
  uint8_t *base;
  size_t size;
  char name[64];
  int entry_of[REC_BLOCKS_MAX];   /* block index -> ring entry, -1 none */
} rec_history;
/* Creates /hrp-history.<robot_id> with history_s seconds of rings at one sample per period. */
int rec_history_open(rec_history *h, const rec_blocks *bs, const rec_opts *o, double period, char *err,
                     size_t errlen);
/* Appends block i's present copy (bs->b[i].now) at robot time t. */
void rec_history_append(rec_history *h, const rec_blocks *bs, int i, double t);
void rec_history_close(rec_history *h);

/* ---- the recorder as a lockstep observer (--lockstep): every tick recorded, after the others did it */
typedef struct rec_observer {
  shm_block *blk;
  int32_t *lockstep, *pid, *observer;
  uint32_t *tick, *done_count, *wake, *done;
  int n, slot;
} rec_observer;
int rec_observer_join(rec_observer *ob, shm_schema *schema, int robot_id, char *err, size_t errlen);
/* The tick to record once the other participants due at it are done; 0 when there is none within
 * timeout_s (no lockstep, or the tick is already recorded). */
uint32_t rec_observer_wait(rec_observer *ob, double timeout_s);
void rec_observer_done(rec_observer *ob, uint32_t tick);
void rec_observer_leave(rec_observer *ob);

/* ---- the configuration in force: one JSON document per concern (Run/config_dump.lua) */
typedef struct rec_doc {
  char name[64];
  char files[1024];
  char *json;
} rec_doc;
/* Fills docs (up to max); returns how many, or a negative code with the Lua error. */
int rec_config_docs(const rec_opts *o, rec_doc *docs, int max, char *err, size_t errlen);
void rec_config_free(rec_doc *docs, int n);

/* ---- the writer thread */
typedef struct rec_writer rec_writer;
typedef struct rec_figures {
  uint64_t messages, bytes, frames, files;
  double jpeg_cpu;         /* s of CPU spent compressing frames */
} rec_figures;
int rec_writer_start(rec_writer **out, const rec_opts *o, const rec_blocks *bs, rec_queue *q, const rec_doc *docs,
                     int ndocs, char *err, size_t errlen);
void rec_writer_figures(rec_writer *w, rec_figures *f);
/* Waits until the queue is drained and closed, closes the file, gives the totals and frees w. Returns 0
 * or the first write error. */
int rec_writer_join(rec_writer *w, rec_figures *f, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
