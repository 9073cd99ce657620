/* blocks: the recorder's sampler -- every block of the schema, copied under its sequence lock once per
 * DCM tick and queued (CDR) when its content changed; the camera's raw frame as its own item. */
#include "record.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int excluded(const rec_opts *o, const char *name) {
  for (int k = 0; k < o->nexclude; k++)
    if (strcmp(o->exclude[k], name) == 0) return 1;
  return 0;
}

static size_t type_size(int type) {
  static const size_t sizes[] = { 0, 8, 4, 4, 4, 8, 8, 1, 2, 2 };
  return type >= 1 && type <= 9 ? sizes[type] : 0;
}

void *rec_field(shm_block *b, const char *name, int type, int *count) {
  int t, n;
  void *p = shm_field_ptr(b, name, &t, &n);
  if (!p || t != type) return NULL;
  if (count) *count = n;
  return p;
}

/* offset of an i32 field named `name`, or -1 */
static int i32_field(shm_block *b, const char *name) {
  int type, count;
  const uint8_t *p = (const uint8_t *)shm_field_ptr(b, name, &type, &count);
  return p && type == SHM_I32 ? (int)(p - (const uint8_t *)shm_block_header(b)) : -1;
}

static int open_one(rec_block *rb, shm_block *blk, const rec_opts *o, char *err, size_t errlen) {
  rb->blk = blk;
  rb->size = shm_block_header(blk)->total_size;
  const char *name = shm_block_name(blk);
  const int camera = strcmp(name, o->camera_block) == 0 && strcmp(o->camera, "raw") != 0;
  const char *skip[] = { o->camera_field };
  int rc = shmlog_from_block(blk, skip, camera ? 1 : 0, &rb->msg, err, errlen);
  if (rc < 0) return rc;
  if (camera && strcmp(o->camera, "jpeg") == 0) {
    int type, count;
    const uint8_t *p = (const uint8_t *)shm_field_ptr(blk, o->camera_field, &type, &count);
    rb->width_off = i32_field(blk, "width");
    rb->height_off = i32_field(blk, "height");
    if (!p || type != SHM_U8 || rb->width_off < 0 || rb->height_off < 0) {
      snprintf(err, errlen, "recorder: block '%s' has no u8 field '%s' and i32 width / height (recorder.camera_block, "
               "camera_field)", name, o->camera_field);
      return -EINVAL;
    }
    rb->has_frame = 1;
    rb->frame_offset = (uint64_t)(p - (const uint8_t *)shm_block_header(blk));
    rb->frame_bytes = (size_t)count;
  }
  rb->last = (uint8_t *)calloc(1, rb->size);
  rb->now = (uint8_t *)calloc(1, rb->size);
  if (!rb->last || !rb->now) {
    snprintf(err, errlen, "recorder: out of memory");
    return -ENOMEM;
  }
  return 0;
}

int rec_blocks_open(rec_blocks *bs, const rec_opts *o, char *err, size_t errlen) {
  memset(bs, 0, sizeof *bs);
  bs->sensor = -1;
  int rc = shm_schema_load(NULL, &bs->schema, err, errlen);
  if (rc < 0) return rc;
  for (int i = 0; i < shm_schema_nblocks(bs->schema); i++) {
    const char *name = shm_schema_block_name(bs->schema, i);
    if (excluded(o, name) || !strcmp(name, REC_PACKETS_BLOCK)) continue;   /* packets.c takes that one */
    if (bs->n >= REC_BLOCKS_MAX) {
      snprintf(err, errlen, "recorder: more than %d blocks", REC_BLOCKS_MAX);
      return -EINVAL;
    }
    shm_block *blk;
    if ((rc = shm_block_open(bs->schema, name, o->robot_id, SHM_OPEN_CREATE, &blk, err, errlen)) < 0) return rc;
    if ((rc = open_one(&bs->b[bs->n++], blk, o, err, errlen)) < 0) return rc;
    int type, count;
    const uint8_t *t = (const uint8_t *)shm_field_ptr(blk, "time", &type, &count);
    if (!strcmp(name, "dcm.sensor") && t && type == SHM_F64) {
      bs->sensor = bs->n - 1;
      bs->time_offset = (uint64_t)(t - (const uint8_t *)shm_block_header(blk));
      const uint8_t *k = (const uint8_t *)shm_field_ptr(blk, "tick", &type, &count);
      bs->tick_offset = k && type == SHM_U32 ? (int64_t)(k - (const uint8_t *)shm_block_header(blk)) : -1;
    }
  }
  return 0;
}

void rec_blocks_close(rec_blocks *bs) {
  for (int i = 0; i < bs->n; i++) {
    shm_block_close(bs->b[i].blk);
    free(bs->b[i].last);
    free(bs->b[i].now);
  }
  if (bs->schema) shm_schema_free(bs->schema);
  bs->n = 0;
  bs->schema = NULL;
}

/* The message's fields (and the frame into `frame` when given) from the segment, one consistent read;
 * -1 when the block's writer died mid-update (said once, the block left out until it is whole again). */
static int snap(rec_block *rb, uint8_t *frame) {
  const uint8_t *seg = (const uint8_t *)shm_block_header(rb->blk);
  /* still as its dead writer left it: no need to wait SHM_STALE_S again on every tick */
  if (rb->stale && __atomic_load_n(&shm_block_header(rb->blk)->seq, __ATOMIC_ACQUIRE) == rb->stale_seq) return -1;
  for (int tries = 0;; tries++) {
    uint32_t seq;
    char err[200];
    if (shm_read_begin_checked(rb->blk, &seq, err, sizeof err) < 0) {
      if (!rb->stale) fprintf(stderr, "hrp_record: %s: not recorded until it is written again\n", err);
      rb->stale = 1;
      rb->stale_seq = seq;
      return -1;
    }
    rb->stale = 0;
    for (int i = 0; i < rb->msg.nfields; i++) {
      const shmlog_field *f = &rb->msg.field[i];
      memcpy(rb->now + f->shm_offset, seg + f->shm_offset, type_size(f->type) * (size_t)f->count);
    }
    if (frame) memcpy(frame, seg + rb->frame_offset, rb->frame_bytes);
    if (!shm_read_retry(rb->blk, seq) || tries > 100) return 0;
  }
}

static int changed(const rec_block *rb) {
  for (int i = 0; i < rb->msg.nfields; i++) {
    const shmlog_field *f = &rb->msg.field[i];
    if (memcmp(rb->now + f->shm_offset, rb->last + f->shm_offset, type_size(f->type) * (size_t)f->count)) return 1;
  }
  return 0;
}

static rec_item *item(int kind, int channel, uint64_t log_time, uint64_t wall_ns, size_t len) {
  rec_item *it = (rec_item *)malloc(sizeof *it + len);
  if (!it) return NULL;
  it->kind = kind;
  it->channel = channel;
  it->log_time = log_time;
  it->publish_time = wall_ns;
  it->len = len;
  it->width = it->height = 0;
  return it;
}

int rec_blocks_sample(rec_blocks *bs, rec_queue *q, struct rec_history *h, uint64_t log_time, uint64_t wall_ns) {
  int queued = 0;
  for (int i = 0; i < bs->n; i++) {
    rec_block *rb = &bs->b[i];
    if (snap(rb, NULL) < 0) continue;
    if (i == bs->sensor) {
      /* the pass is stamped with the sensor time of the copy itself (dcm.sensor comes first) */
      double t;
      memcpy(&t, rb->now + bs->time_offset, 8);
      if (t > 0) log_time = (uint64_t)(t * 1e9 + 0.5);
    }
    if (!changed(rb)) continue;
    if (i == bs->sensor && bs->tick_offset >= 0) {
      /* missed ticks from the copies themselves: a tick read beside the copy could be one the copy
       * already holds (the DCM wrote between the two reads) and count a gap the file does not have */
      uint32_t tick;
      memcpy(&tick, rb->now + bs->tick_offset, 4);
      if (bs->have_tick && tick > bs->last_tick + 1) bs->missed += tick - bs->last_tick - 1;
      bs->last_tick = tick;
      bs->have_tick = 1;
    }
    rec_item *frame = NULL;
    if (rb->has_frame) {
      /* a new frame: its pixels and its fields from one read */
      frame = item(REC_ITEM_FRAME, i, log_time, wall_ns, rb->frame_bytes);
      if (frame && snap(rb, frame->data) < 0) {
        free(frame);
        frame = NULL;
      }
      if (frame) {
        memcpy(&frame->width, rb->now + rb->width_off, 4);
        memcpy(&frame->height, rb->now + rb->height_off, 4);
        if ((size_t)frame->width * (size_t)frame->height * 2 > rb->frame_bytes || frame->width <= 0 ||
            frame->height <= 0) {
          free(frame);   /* no image yet (or a size the field cannot hold): nothing to compress */
          frame = NULL;
        }
      }
    }
    rec_item *it = item(REC_ITEM_BLOCK, i, log_time, wall_ns, rb->msg.cdr_size);
    if (it) {
      shmlog_encode(&rb->msg, rb->now, it->data);
      queued += rec_queue_push(q, it) == 0;
    }
    if (frame) queued += rec_queue_push(q, frame) == 0;
    if (h) rec_history_append(h, bs, i, (double)log_time * 1e-9);
    uint8_t *t = rb->last;
    rb->last = rb->now;
    rb->now = t;
  }
  return queued;
}
