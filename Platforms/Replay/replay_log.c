/* replay_log: see replay_log.h. */
#include "replay_log.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static size_t type_size(int type) {
  static const size_t sizes[] = { 0, 8, 4, 4, 4, 8, 8, 1, 2, 2 };
  return type >= 1 && type <= 9 ? sizes[type] : 0;
}

static int i32_offset(shm_block *b, const char *name) {
  int type, count;
  const uint8_t *p = (const uint8_t *)shm_field_ptr(b, name, &type, &count);
  return p && type == SHM_I32 ? (int)(p - (const uint8_t *)shm_block_header(b)) : -1;
}

/* The log's channel for topic, or NULL. */
static const mcap_channel_info *channel_of(const mcap_reader *r, const char *topic) {
  for (int id = 0; id < REPLAY_CHANNELS_MAX; id++) {
    const mcap_channel_info *c = mcap_reader_channel(r, id);
    if (c && strcmp(c->topic, topic) == 0) return c;
  }
  return NULL;
}

/* Binds served block `name`: opens it, checks the log's definition against the present layout. */
static int bind_block(replay_log *L, const char *path, const shm_schema *schema, int robot_id, const char *name,
                      const char *camera_field, char *err, size_t errlen) {
  replay_block *rb = &L->b[L->nblocks];
  char topic[SHM_NAME_MAX + 8], e[512];
  snprintf(topic, sizeof topic, "/%s", name);
  const mcap_channel_info *c = channel_of(L->r, topic);
  if (!c) {
    if (strcmp(name, "dcm.sensor") == 0) {
      snprintf(err, errlen, "%s: the log has no channel '%s': nothing to replay", path, topic);
      return -EINVAL;
    }
    return 0;   /* not recorded (e.g. no sim truth on a real robot): left as it is */
  }
  char ftopic[SHM_NAME_MAX + 16];
  snprintf(ftopic, sizeof ftopic, "%s/jpeg", topic);
  const mcap_channel_info *fc = channel_of(L->r, ftopic);
  const mcap_schema_info *s = mcap_reader_schema(L->r, c->schema_id);
  if (!s || strcmp(s->encoding, "ros2msg") != 0 || strcmp(c->encoding, "cdr") != 0) {
    snprintf(err, errlen, "%s: channel '%s' is not a ros2msg / CDR shm block", path, topic);
    return -EINVAL;
  }
  int rc = shm_block_open(schema, name, robot_id, SHM_OPEN_CREATE, &rb->blk, err, errlen);
  if (rc < 0) return rc;
  const char *skip[] = { camera_field };
  static shmlog_block logdef;
  if ((rc = shmlog_from_block(rb->blk, skip, fc ? 1 : 0, &rb->now, err, errlen)) < 0 ||
      (rc = shmlog_parse(name, (const char *)s->data, s->len, &logdef, e, sizeof e)) < 0) {
    if (rc < 0 && !err[0]) snprintf(err, errlen, "%s: %s", path, e);
    shm_block_close(rb->blk);
    return rc;
  }
  if (shmlog_diff(&logdef, &rb->now, e, sizeof e)) {
    snprintf(err, errlen, "%s was recorded with another shm schema: %s", path, e);
    shm_block_close(rb->blk);
    return -EINVAL;
  }
  rb->stage = (uint8_t *)calloc(1, shm_block_header(rb->blk)->total_size);
  if (!rb->stage) {
    snprintf(err, errlen, "replay: out of memory");
    shm_block_close(rb->blk);
    return -ENOMEM;
  }
  memcpy(rb->stage, shm_block_header(rb->blk), shm_block_header(rb->blk)->total_size);
  if (fc) {
    int type, count;
    const uint8_t *p = (const uint8_t *)shm_field_ptr(rb->blk, camera_field, &type, &count);
    rb->width_off = i32_offset(rb->blk, "width");
    rb->height_off = i32_offset(rb->blk, "height");
    if (p && type == SHM_U8 && rb->width_off >= 0 && rb->height_off >= 0 && fc->id < REPLAY_CHANNELS_MAX) {
      rb->has_frames = 1;
      rb->frame_offset = (uint64_t)(p - (const uint8_t *)shm_block_header(rb->blk));
      rb->frame_bytes = (size_t)count;
      L->chan_frame[fc->id] = L->nblocks;
    }
  }
  if (strcmp(name, "dcm.sensor") == 0) L->sensor = L->nblocks;
  L->chan_block[c->id] = L->nblocks;
  L->nblocks++;
  return 0;
}

/* 1 if name is "block.field" of this block */
static int of_block(const char *name, const char *block) {
  const size_t n = strlen(block);
  return strncmp(name, block, n) == 0 && name[n] == '.';
}

/* Marks the fields named in leave ("block.field") as not served. A field of a served block that the
 * block lacks, or of a block not served, is an error; a served block the log lacks has nothing to leave. */
static int leave_fields(replay_log *L, const char *const *serve, int nserve, const char *const *leave, int nleave,
                        char *err, size_t errlen) {
  for (int k = 0; k < nleave; k++) {
    int served = 0, found = 0, bound = 0;
    for (int i = 0; i < nserve; i++) served |= of_block(leave[k], serve[i]);
    for (int i = 0; i < L->nblocks && !found; i++) {
      replay_block *rb = &L->b[i];
      if (!of_block(leave[k], rb->now.name)) continue;
      bound = 1;
      for (int f = 0; f < rb->now.nfields && !found; f++)
        if (strcmp(rb->now.field[f].name, leave[k] + strlen(rb->now.name) + 1) == 0) found = rb->left[f] = 1;
    }
    if (!served || (bound && !found)) {
      snprintf(err, errlen, "Config/platforms/Replay/dcm.lua: 'leave' names '%s', not a field of a served block",
               leave[k]);
      return -EINVAL;
    }
  }
  return 0;
}

int replay_log_open(replay_log *L, const char *path, const shm_schema *schema, int robot_id, const char *const *serve,
                    int nserve, const char *const *leave, int nleave, const char *camera_field,
                    replay_frame_fn frame_fn, void *frame_ctx, char *err, size_t errlen) {
  memset(L, 0, sizeof *L);
  L->sensor = -1;
  for (int i = 0; i < REPLAY_CHANNELS_MAX; i++) L->chan_block[i] = L->chan_frame[i] = -1;
  L->frame_fn = frame_fn;
  L->frame_ctx = frame_ctx;
  int rc = mcap_reader_open(path, &L->r, err, errlen);
  if (rc < 0) return rc;
  if (mcap_reader_scan_channels(L->r) == 0) {
    snprintf(err, errlen, "%s: no channels%s%s", path, mcap_reader_error(L->r)[0] ? ": " : "",
             mcap_reader_error(L->r));
    replay_log_close(L);
    return -EINVAL;
  }
  if (nserve > REPLAY_BLOCKS_MAX) nserve = REPLAY_BLOCKS_MAX;
  for (int i = 0; i < nserve; i++) {
    err[0] = 0;
    if ((rc = bind_block(L, path, schema, robot_id, serve[i], camera_field, err, errlen)) < 0) {
      replay_log_close(L);
      return rc;
    }
  }
  if (L->sensor < 0) {
    snprintf(err, errlen, "Config/platforms/Replay/dcm.lua: 'serve' must name dcm.sensor");
    replay_log_close(L);
    return -EINVAL;
  }
  if ((rc = leave_fields(L, serve, nserve, leave, nleave, err, errlen)) < 0) {
    replay_log_close(L);
    return rc;
  }
  return 0;
}

void replay_log_close(replay_log *L) {
  for (int i = 0; i < L->nblocks; i++) {
    shm_block_close(L->b[i].blk);
    free(L->b[i].stage);
    free(L->b[i].pending);
  }
  L->nblocks = 0;
  if (L->r) mcap_reader_close(L->r);
  L->r = NULL;
}

void replay_log_rewind(replay_log *L) {
  mcap_reader_rewind(L->r);
  L->have_next = L->ended = 0;
  L->ticks = 0;
  L->damage[0] = 0;
}

static void take_frame(replay_log *L, replay_block *rb, const uint8_t *msg, size_t msg_len);

/* One message into its block's stage. */
static void take(replay_log *L, const mcap_message *m) {
  const int bi = m->channel < REPLAY_CHANNELS_MAX ? L->chan_block[m->channel] : -1;
  if (bi >= 0) {
    replay_block *rb = &L->b[bi];
    if (shmlog_decode(&rb->now, m->data, m->len, rb->stage) == 0) rb->dirty = 1;
    return;
  }
  const int fi = m->channel < REPLAY_CHANNELS_MAX ? L->chan_frame[m->channel] : -1;
  if (fi < 0 || !L->frame_fn) return;
  replay_block *rb = &L->b[fi];
  if (L->seeking) {
    /* a seek decodes only the last frame it passes (replay_log_seek) */
    if (m->len > rb->pending_cap) {
      uint8_t *p = (uint8_t *)realloc(rb->pending, m->len);
      if (!p) return;
      rb->pending = p;
      rb->pending_cap = m->len;
    }
    memcpy(rb->pending, m->data, m->len);
    rb->pending_len = m->len;
    return;
  }
  take_frame(L, rb, m->data, m->len);
}

/* A frame message: decoded into its block's stage. */
static void take_frame(replay_log *L, replay_block *rb, const uint8_t *msg, size_t msg_len) {
  char format[32];
  const uint8_t *data;
  size_t len;
  int32_t w, h;
  memcpy(&w, rb->stage + rb->width_off, 4);
  memcpy(&h, rb->stage + rb->height_off, 4);
  if (shmlog_image_decode(msg, msg_len, format, sizeof format, &data, &len) == 0 &&
      L->frame_fn(L->frame_ctx, data, len, w, h, rb->stage + rb->frame_offset, rb->frame_bytes) == 0) {
    rb->dirty = 1;
    L->frames++;
  } else {
    L->bad_frames++;
  }
}

int replay_log_next(replay_log *L) {
  if (L->ended) return 0;
  for (int i = 0; i < L->nblocks; i++) L->b[i].dirty = 0;
  mcap_message m;
  int rc;
  if (!L->have_next) {
    /* the first tick: skip to the first dcm.sensor message */
    while ((rc = mcap_reader_next(L->r, &m)) > 0 && (m.channel >= REPLAY_CHANNELS_MAX || L->chan_block[m.channel] != L->sensor))
      take(L, &m);
    if (rc <= 0) goto end;
    L->next = m;
  }
  take(L, &L->next);
  L->have_next = 0;
  const double t = (double)L->next.log_time * 1e-9;
  if (L->ticks == 0) L->first_time = t;
  L->time = t;
  L->ticks++;
  while ((rc = mcap_reader_next(L->r, &m)) > 0) {
    if (m.channel < REPLAY_CHANNELS_MAX && L->chan_block[m.channel] == L->sensor) {
      L->next = m;
      L->have_next = 1;
      return 1;
    }
    take(L, &m);
  }
  /* the last tick is served; the end (or the damage) shows at the next call */
  L->ended = 1;
  if (rc < 0) snprintf(L->damage, sizeof L->damage, "%s", mcap_reader_error(L->r));
  return 1;
end:
  L->ended = 1;
  if (rc < 0) {
    snprintf(L->damage, sizeof L->damage, "%s", mcap_reader_error(L->r));
    return -EINVAL;
  }
  return 0;
}

void replay_log_serve(replay_log *L) {
  for (int i = 0; i < L->nblocks; i++) {
    replay_block *rb = &L->b[i];
    if (!rb->dirty || i == L->sensor) continue;
    uint8_t *seg = (uint8_t *)shm_block_header(rb->blk);
    shm_write_begin(rb->blk);
    for (int k = 0; k < rb->now.nfields; k++) {
      const shmlog_field *f = &rb->now.field[k];
      if (!rb->left[k]) memcpy(seg + f->shm_offset, rb->stage + f->shm_offset, type_size(f->type) * (size_t)f->count);
    }
    if (rb->has_frames) memcpy(seg + rb->frame_offset, rb->stage + rb->frame_offset, rb->frame_bytes);
    shm_write_end(rb->blk);
  }
}

int replay_log_seek(replay_log *L, double t) {
  int rc = 1;
  for (int i = 0; i < L->nblocks; i++) L->b[i].pending_len = 0;
  L->seeking = 1;
  if (L->ticks == 0 || t < L->time) {
    replay_log_rewind(L);
    rc = replay_log_next(L);
  }
  /* the tick read ahead comes at or before t: it is the one, or one before it */
  while (rc > 0 && L->have_next && (double)L->next.log_time * 1e-9 <= t) rc = replay_log_next(L);
  L->seeking = 0;
  for (int i = 0; i < L->nblocks; i++) {
    replay_block *rb = &L->b[i];
    if (rb->pending_len) take_frame(L, rb, rb->pending, rb->pending_len);
    rb->pending_len = 0;
    rb->dirty = 1;
  }
  return rc > 0 || L->ticks > 0 ? 1 : rc;
}
