/* mcap_write: the MCAP writer (see mcap.h for the file's layout). */
#include "mcap.h"
#include "mcap_buf.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <zlib.h>
#include <zstd.h>

#define MAGIC "\x89MCAP0\r\n"
#define MAX_SCHEMAS 1024
#define MAX_CHANNELS 1024

enum { OP_HEADER = 1, OP_FOOTER, OP_SCHEMA, OP_CHANNEL, OP_MESSAGE, OP_CHUNK, OP_MESSAGE_INDEX, OP_CHUNK_INDEX,
       OP_ATTACHMENT, OP_ATTACHMENT_INDEX, OP_STATISTICS, OP_METADATA, OP_METADATA_INDEX, OP_SUMMARY_OFFSET,
       OP_DATA_END };

struct mcap_writer {
  FILE *f;
  uint64_t pos;                 /* bytes written to f */
  int zstd_level;
  size_t chunk_bytes;
  mcap_buf rec;                 /* one record's content being built */
  mcap_buf chunk;               /* records of the open chunk */
  uint64_t chunk_start, chunk_end;
  int chunk_messages;
  mcap_buf schemas, channels;   /* their records again, for the summary */
  mcap_buf chunk_index, attachment_index, metadata_index;
  int nschemas, nchannels;
  uint64_t messages, chunks, attachments, metadata;
  uint64_t msg_start, msg_end;
  uint64_t channel_count[MAX_CHANNELS];
  void *zbuf;
  size_t zcap;
  char err[256];
};

/* The records' CRC-32 (the one zlib computes, as the MCAP specification says): zlib's is several
   times faster than a table walk, and the writer checksums every chunk it writes. */
uint32_t mcap_crc32(uint32_t crc, const void *data, size_t len) {
  return (uint32_t)crc32_z(crc, (const Bytef *)data, len);
}

static int fail(mcap_writer *w, int code, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(w->err, sizeof w->err, fmt, ap);
  va_end(ap);
  return code;
}

static int out(mcap_writer *w, const void *p, size_t n) {
  if (n && fwrite(p, 1, n, w->f) != n) return fail(w, -EIO, "mcap: write failed: %s", strerror(errno));
  w->pos += n;
  return 0;
}

/* opcode + length + w->rec into dst (a buffer) or the file (dst NULL) */
static int emit(mcap_writer *w, uint8_t op, mcap_buf *dst) {
  if (w->rec.oom) return fail(w, -ENOMEM, "mcap: out of memory");
  uint8_t head[9];
  head[0] = op;
  for (int i = 0; i < 8; i++) head[1 + i] = (uint8_t)((uint64_t)w->rec.len >> (8 * i));
  if (dst) {
    mb_put(dst, head, 9);
    mb_put(dst, w->rec.p, w->rec.len);
    return dst->oom ? fail(w, -ENOMEM, "mcap: out of memory") : 0;
  }
  int rc = out(w, head, 9);
  return rc < 0 ? rc : out(w, w->rec.p, w->rec.len);
}

static int close_chunk(mcap_writer *w) {
  if (w->chunk.len == 0) return 0;
  const char *compression = w->zstd_level > 0 ? "zstd" : "";
  const void *payload = w->chunk.p;
  size_t plen = w->chunk.len;
  if (w->zstd_level > 0) {
    const size_t need = ZSTD_compressBound(w->chunk.len);
    if (need > w->zcap) {
      void *z = realloc(w->zbuf, need);
      if (!z) return fail(w, -ENOMEM, "mcap: out of memory");
      w->zbuf = z;
      w->zcap = need;
    }
    plen = ZSTD_compress(w->zbuf, w->zcap, w->chunk.p, w->chunk.len, w->zstd_level);
    if (ZSTD_isError(plen)) return fail(w, -EIO, "mcap: zstd: %s", ZSTD_getErrorName(plen));
    payload = w->zbuf;
  }
  const uint64_t start = w->pos;
  w->rec.len = 0;
  mb_u64(&w->rec, w->chunk_start);
  mb_u64(&w->rec, w->chunk_end);
  mb_u64(&w->rec, w->chunk.len);
  mb_u32(&w->rec, mcap_crc32(0, w->chunk.p, w->chunk.len));
  mb_str(&w->rec, compression);
  mb_u64(&w->rec, plen);
  mb_put(&w->rec, payload, plen);
  int rc = emit(w, OP_CHUNK, NULL);
  if (rc < 0) return rc;
  /* its index entry for the summary (no message indexes: readers read the chunk whole) */
  w->rec.len = 0;
  mb_u64(&w->rec, w->chunk_start);
  mb_u64(&w->rec, w->chunk_end);
  mb_u64(&w->rec, start);
  mb_u64(&w->rec, w->pos - start);
  mb_u32(&w->rec, 0);            /* message_index_offsets: empty map */
  mb_u64(&w->rec, 0);            /* message_index_length */
  mb_str(&w->rec, compression);
  mb_u64(&w->rec, plen);
  mb_u64(&w->rec, w->chunk.len);
  if ((rc = emit(w, OP_CHUNK_INDEX, &w->chunk_index)) < 0) return rc;
  w->chunks++;
  w->chunk.len = 0;
  w->chunk_messages = 0;
  return 0;
}

int mcap_writer_open(const char *path, const char *profile, int zstd_level, size_t chunk_bytes,
                     mcap_writer **outp, char *err, size_t errlen) {
  mcap_writer *w = (mcap_writer *)calloc(1, sizeof *w);
  if (!w) {
    snprintf(err, errlen, "mcap: out of memory");
    return -ENOMEM;
  }
  w->f = fopen(path, "wb");
  if (!w->f) {
    const int e = errno;
    snprintf(err, errlen, "mcap: cannot create %s: %s", path, strerror(e));
    free(w);
    return -e;
  }
  w->zstd_level = zstd_level;
  w->chunk_bytes = chunk_bytes > 0 ? chunk_bytes : 1 << 20;
  int rc = out(w, MAGIC, 8);
  mb_str(&w->rec, profile ? profile : "");
  mb_str(&w->rec, "hrp Modules/mcap");
  if (rc == 0) rc = emit(w, OP_HEADER, NULL);
  if (rc < 0) {
    snprintf(err, errlen, "%s", w->err);
    fclose(w->f);
    mb_free(&w->rec);
    free(w);
    return rc;
  }
  *outp = w;
  return 0;
}

int mcap_writer_schema(mcap_writer *w, const char *name, const char *encoding, const void *data, size_t len) {
  if (w->nschemas >= MAX_SCHEMAS) return fail(w, -ENOSPC, "mcap: more than %d schemas", MAX_SCHEMAS);
  const int id = ++w->nschemas;
  w->rec.len = 0;
  mb_u16(&w->rec, (uint16_t)id);
  mb_str(&w->rec, name);
  mb_str(&w->rec, encoding);
  mb_bytes32(&w->rec, data, len);
  int rc = emit(w, OP_SCHEMA, NULL);
  if (rc == 0) rc = emit(w, OP_SCHEMA, &w->schemas);
  return rc < 0 ? rc : id;
}

int mcap_writer_channel(mcap_writer *w, int schema_id, const char *topic, const char *message_encoding,
                        const char *const *meta, int nmeta) {
  if (w->nchannels >= MAX_CHANNELS) return fail(w, -ENOSPC, "mcap: more than %d channels", MAX_CHANNELS);
  const int id = w->nchannels++;
  w->rec.len = 0;
  mb_u16(&w->rec, (uint16_t)id);
  mb_u16(&w->rec, (uint16_t)schema_id);
  mb_str(&w->rec, topic);
  mb_str(&w->rec, message_encoding);
  mb_map(&w->rec, meta, meta ? nmeta : 0);
  int rc = emit(w, OP_CHANNEL, NULL);
  if (rc == 0) rc = emit(w, OP_CHANNEL, &w->channels);
  return rc < 0 ? rc : id;
}

int mcap_writer_message(mcap_writer *w, int channel, uint32_t sequence, uint64_t log_time, uint64_t publish_time,
                        const void *data, size_t len) {
  if (channel < 0 || channel >= w->nchannels) return fail(w, -EINVAL, "mcap: no channel %d", channel);
  w->rec.len = 0;
  mb_u16(&w->rec, (uint16_t)channel);
  mb_u32(&w->rec, sequence);
  mb_u64(&w->rec, log_time);
  mb_u64(&w->rec, publish_time);
  mb_put(&w->rec, data, len);
  if (w->chunk_messages == 0 || log_time < w->chunk_start) w->chunk_start = log_time;
  if (w->chunk_messages == 0 || log_time > w->chunk_end) w->chunk_end = log_time;
  int rc = emit(w, OP_MESSAGE, &w->chunk);
  if (rc < 0) return rc;
  w->chunk_messages++;
  if (w->messages == 0 || log_time < w->msg_start) w->msg_start = log_time;
  if (w->messages == 0 || log_time > w->msg_end) w->msg_end = log_time;
  w->messages++;
  w->channel_count[channel]++;
  return w->chunk.len >= w->chunk_bytes ? close_chunk(w) : 0;
}

/* Writes the record staged in w->rec (it began at offset start), then stages the start of its summary
 * index record: the record's offset and length. */
static int emit_indexed(mcap_writer *w, uint8_t op, uint64_t start) {
  int rc = emit(w, op, NULL);
  if (rc < 0) return rc;
  w->rec.len = 0;
  mb_u64(&w->rec, start);
  mb_u64(&w->rec, w->pos - start);
  return 0;
}

int mcap_writer_attachment(mcap_writer *w, const char *name, const char *media_type, uint64_t log_time,
                           const void *data, size_t len) {
  const uint64_t start = w->pos;
  w->rec.len = 0;
  mb_u64(&w->rec, log_time);
  mb_u64(&w->rec, log_time);     /* create_time */
  mb_str(&w->rec, name);
  mb_str(&w->rec, media_type);
  mb_u64(&w->rec, len);
  mb_put(&w->rec, data, len);
  mb_u32(&w->rec, w->rec.oom ? 0 : mcap_crc32(0, w->rec.p, w->rec.len));
  int rc = emit_indexed(w, OP_ATTACHMENT, start);
  if (rc < 0) return rc;
  mb_u64(&w->rec, log_time);
  mb_u64(&w->rec, log_time);
  mb_u64(&w->rec, len);
  mb_str(&w->rec, name);
  mb_str(&w->rec, media_type);
  w->attachments++;
  return emit(w, OP_ATTACHMENT_INDEX, &w->attachment_index);
}

int mcap_writer_metadata(mcap_writer *w, const char *name, const char *const *meta, int nmeta) {
  const uint64_t start = w->pos;
  w->rec.len = 0;
  mb_str(&w->rec, name);
  mb_map(&w->rec, meta, meta ? nmeta : 0);
  int rc = emit_indexed(w, OP_METADATA, start);
  if (rc < 0) return rc;
  mb_str(&w->rec, name);
  w->metadata++;
  return emit(w, OP_METADATA_INDEX, &w->metadata_index);
}

int mcap_writer_flush(mcap_writer *w) {
  int rc = close_chunk(w);
  if (rc == 0 && fflush(w->f) != 0) rc = fail(w, -EIO, "mcap: flush failed: %s", strerror(errno));
  return rc;
}

uint64_t mcap_writer_size(const mcap_writer *w) { return w->pos; }
uint64_t mcap_writer_pending(const mcap_writer *w) { return w->chunk.len; }
const char *mcap_writer_error(const mcap_writer *w) { return w->err; }

/* One group of the summary: its records, and a SummaryOffset for it into offsets. */
static void summary_group(mcap_writer *w, mcap_buf *sum, mcap_buf *offsets, uint64_t sum_start, uint8_t op,
                          const mcap_buf *records) {
  if (records->len == 0) return;
  const uint64_t at = sum_start + sum->len;
  mb_put(sum, records->p, records->len);
  w->rec.len = 0;
  mb_u8(&w->rec, op);
  mb_u64(&w->rec, at);
  mb_u64(&w->rec, records->len);
  emit(w, OP_SUMMARY_OFFSET, offsets);
}

int mcap_writer_close(mcap_writer *w, char *err, size_t errlen) {
  int rc = close_chunk(w);
  if (rc == 0) {
    w->rec.len = 0;
    mb_u32(&w->rec, 0);   /* data section CRC not computed */
    rc = emit(w, OP_DATA_END, NULL);
  }
  mcap_buf sum = { 0 }, offsets = { 0 }, stats = { 0 };
  if (rc == 0) {
    const uint64_t sum_start = w->pos;
    w->rec.len = 0;
    mb_u64(&w->rec, w->messages);
    mb_u16(&w->rec, (uint16_t)w->nschemas);
    mb_u32(&w->rec, (uint32_t)w->nchannels);
    mb_u32(&w->rec, (uint32_t)w->attachments);
    mb_u32(&w->rec, (uint32_t)w->metadata);
    mb_u32(&w->rec, (uint32_t)w->chunks);
    mb_u64(&w->rec, w->msg_start);
    mb_u64(&w->rec, w->msg_end);
    mb_u32(&w->rec, (uint32_t)(w->nchannels * 10));
    for (int c = 0; c < w->nchannels; c++) {
      mb_u16(&w->rec, (uint16_t)c);
      mb_u64(&w->rec, w->channel_count[c]);
    }
    emit(w, OP_STATISTICS, &stats);
    summary_group(w, &sum, &offsets, sum_start, OP_SCHEMA, &w->schemas);
    summary_group(w, &sum, &offsets, sum_start, OP_CHANNEL, &w->channels);
    summary_group(w, &sum, &offsets, sum_start, OP_STATISTICS, &stats);
    summary_group(w, &sum, &offsets, sum_start, OP_CHUNK_INDEX, &w->chunk_index);
    summary_group(w, &sum, &offsets, sum_start, OP_ATTACHMENT_INDEX, &w->attachment_index);
    summary_group(w, &sum, &offsets, sum_start, OP_METADATA_INDEX, &w->metadata_index);
    const uint64_t offsets_start = sum_start + sum.len;
    mb_put(&sum, offsets.p, offsets.len);
    /* footer: its CRC covers the summary and the footer's own fields before it */
    mcap_buf foot = { 0 };
    mb_u8(&foot, OP_FOOTER);
    mb_u64(&foot, 8 + 8 + 4);
    mb_u64(&foot, sum.len ? sum_start : 0);
    mb_u64(&foot, offsets.len ? offsets_start : 0);
    uint32_t crc = mcap_crc32(0, sum.p, sum.len);
    crc = mcap_crc32(crc, foot.p, foot.len);
    mb_u32(&foot, crc);
    if (sum.oom || foot.oom) rc = fail(w, -ENOMEM, "mcap: out of memory");
    if (rc == 0) rc = out(w, sum.p, sum.len);
    if (rc == 0) rc = out(w, foot.p, foot.len);
    if (rc == 0) rc = out(w, MAGIC, 8);
    mb_free(&foot);
  }
  if (fclose(w->f) != 0 && rc == 0) rc = fail(w, -EIO, "mcap: close failed: %s", strerror(errno));
  if (rc < 0) snprintf(err, errlen, "%s", w->err);
  mb_free(&sum);
  mb_free(&offsets);
  mb_free(&stats);
  mcap_buf *bufs[] = { &w->rec, &w->chunk, &w->schemas, &w->channels, &w->chunk_index, &w->attachment_index,
                       &w->metadata_index };
  for (size_t i = 0; i < sizeof bufs / sizeof bufs[0]; i++) mb_free(bufs[i]);
  free(w->zbuf);
  free(w);
  return rc;
}
