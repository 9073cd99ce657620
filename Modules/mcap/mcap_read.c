/* mcap_read: walks an MCAP file's records in order (mapped), into chunks, up to the first damage. */
#include "mcap.h"

#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zstd.h>

#define MAX_IDS 1024

enum { OP_SCHEMA = 3, OP_CHANNEL = 4, OP_MESSAGE = 5, OP_CHUNK = 6, OP_ATTACHMENT = 9, OP_FOOTER = 2,
       OP_DATA_END = 15 };

struct mcap_reader {
  const uint8_t *map;
  size_t size;
  size_t pos;                       /* next record in the file */
  uint8_t *chunk;                   /* the current chunk's records, decompressed */
  size_t chunk_len, chunk_cap, chunk_pos;
  int in_chunk, done;
  mcap_schema_info *schema[MAX_IDS];
  mcap_channel_info *channel[MAX_IDS];
  char err[512];
};

static int fail(mcap_reader *r, int code, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(r->err, sizeof r->err, fmt, ap);
  va_end(ap);
  r->done = 1;
  return code;
}

static uint64_t le(const uint8_t *p, int n) {
  uint64_t v = 0;
  for (int i = n - 1; i >= 0; i--) v = v << 8 | p[i];
  return v;
}

/* A u32-prefixed string at *p within [*p, end) into out; 0, or -1 when it runs past end. */
static int get_str(const uint8_t **p, const uint8_t *end, char *out, size_t outlen) {
  if (end - *p < 4) return -1;
  const uint64_t n = le(*p, 4);
  if ((uint64_t)(end - *p - 4) < n) return -1;
  const size_t k = n < outlen - 1 ? (size_t)n : outlen - 1;
  memcpy(out, *p + 4, k);
  out[k] = 0;
  *p += 4 + n;
  return 0;
}

int mcap_reader_open(const char *path, mcap_reader **out, char *err, size_t errlen) {
  const int fd = open(path, O_RDONLY);
  if (fd < 0) {
    const int e = errno;
    snprintf(err, errlen, "%s: %s", path, strerror(e));
    return -e;
  }
  struct stat st;
  if (fstat(fd, &st) != 0 || st.st_size < 8) {
    close(fd);
    snprintf(err, errlen, "%s: not an MCAP file (%lld bytes)", path, (long long)st.st_size);
    return -EINVAL;
  }
  void *m = mmap(NULL, (size_t)st.st_size, PROT_READ, MAP_PRIVATE, fd, 0);
  close(fd);
  if (m == MAP_FAILED) {
    const int e = errno;
    snprintf(err, errlen, "%s: cannot map: %s", path, strerror(e));
    return -e;
  }
  if (memcmp(m, "\x89MCAP0\r\n", 8) != 0) {
    munmap(m, (size_t)st.st_size);
    snprintf(err, errlen, "%s: not an MCAP file (no magic at its start)", path);
    return -EINVAL;
  }
  mcap_reader *r = (mcap_reader *)calloc(1, sizeof *r);
  if (!r) {
    munmap(m, (size_t)st.st_size);
    snprintf(err, errlen, "mcap: out of memory");
    return -ENOMEM;
  }
  r->map = (const uint8_t *)m;
  r->size = (size_t)st.st_size;
  r->pos = 8;
  *out = r;
  return 0;
}

void mcap_reader_close(mcap_reader *r) {
  if (!r) return;
  for (int i = 0; i < MAX_IDS; i++) {
    free(r->schema[i]);
    free(r->channel[i]);
  }
  free(r->chunk);
  munmap((void *)r->map, r->size);
  free(r);
}

void mcap_reader_rewind(mcap_reader *r) {
  r->pos = 8;
  r->in_chunk = 0;
  r->done = 0;
  r->err[0] = 0;
}

const mcap_schema_info *mcap_reader_schema(const mcap_reader *r, int id) {
  return id >= 0 && id < MAX_IDS ? r->schema[id] : NULL;
}
const mcap_channel_info *mcap_reader_channel(const mcap_reader *r, int id) {
  return id >= 0 && id < MAX_IDS ? r->channel[id] : NULL;
}
const char *mcap_reader_error(const mcap_reader *r) { return r->err; }

static int take_schema(mcap_reader *r, const uint8_t *p, const uint8_t *end, size_t at) {
  if (end - p < 2) return fail(r, -EINVAL, "schema record at byte %zu is cut short", at);
  const int id = (int)le(p, 2);
  p += 2;
  mcap_schema_info s = { .id = id };
  if (id >= MAX_IDS || get_str(&p, end, s.name, sizeof s.name) || get_str(&p, end, s.encoding, sizeof s.encoding) ||
      end - p < 4 || (uint64_t)(end - p - 4) < le(p, 4))
    return fail(r, -EINVAL, "schema record at byte %zu is corrupt", at);
  s.len = (size_t)le(p, 4);
  s.data = p + 4;
  if (!r->schema[id] && !(r->schema[id] = (mcap_schema_info *)malloc(sizeof s)))
    return fail(r, -ENOMEM, "mcap: out of memory");
  *r->schema[id] = s;
  return 0;
}

static int take_channel(mcap_reader *r, const uint8_t *p, const uint8_t *end, size_t at) {
  if (end - p < 4) return fail(r, -EINVAL, "channel record at byte %zu is cut short", at);
  mcap_channel_info c = { .id = (int)le(p, 2), .schema_id = (int)le(p + 2, 2) };
  p += 4;
  if (c.id >= MAX_IDS || get_str(&p, end, c.topic, sizeof c.topic) || get_str(&p, end, c.encoding, sizeof c.encoding))
    return fail(r, -EINVAL, "channel record at byte %zu is corrupt", at);
  if (!r->channel[c.id] && !(r->channel[c.id] = (mcap_channel_info *)malloc(sizeof c)))
    return fail(r, -ENOMEM, "mcap: out of memory");
  *r->channel[c.id] = c;
  return 0;
}

/* Decompresses the chunk record (content p..end) at file byte `at` into r->chunk. */
static int open_chunk(mcap_reader *r, const uint8_t *p, const uint8_t *end, size_t at) {
  char compression[32];
  if (end - p < 28) return fail(r, -EINVAL, "chunk at byte %zu is cut short", at);
  const uint64_t usize = le(p + 16, 8);
  const uint32_t crc = (uint32_t)le(p + 24, 4);
  p += 28;
  if (get_str(&p, end, compression, sizeof compression) || end - p < 8 || (uint64_t)(end - p - 8) < le(p, 8))
    return fail(r, -EINVAL, "chunk at byte %zu is corrupt", at);
  const size_t clen = (size_t)le(p, 8);
  p += 8;
  if (usize > ((uint64_t)1 << 32)) return fail(r, -EINVAL, "chunk at byte %zu claims %llu bytes", at,
                                               (unsigned long long)usize);
  if (usize > r->chunk_cap) {
    uint8_t *b = (uint8_t *)realloc(r->chunk, (size_t)usize);
    if (!b) return fail(r, -ENOMEM, "mcap: out of memory");
    r->chunk = b;
    r->chunk_cap = (size_t)usize;
  }
  if (strcmp(compression, "zstd") == 0) {
    const size_t n = ZSTD_decompress(r->chunk, r->chunk_cap, p, clen);
    if (ZSTD_isError(n) || n != usize)
      return fail(r, -EINVAL, "chunk at byte %zu does not decompress: %s", at,
                  ZSTD_isError(n) ? ZSTD_getErrorName(n) : "wrong size");
  } else if (compression[0] == 0) {
    if (clen != usize) return fail(r, -EINVAL, "chunk at byte %zu: sizes disagree", at);
    memcpy(r->chunk, p, clen);
  } else {
    return fail(r, -ENOTSUP, "chunk at byte %zu: compression '%s' is not supported (zstd or none)", at, compression);
  }
  if (crc != 0 && mcap_crc32(0, r->chunk, (size_t)usize) != crc)
    return fail(r, -EINVAL, "chunk at byte %zu: CRC mismatch (corrupt data)", at);
  r->chunk_len = (size_t)usize;
  r->chunk_pos = 0;
  r->in_chunk = 1;
  return 0;
}

/* Next record of the chunk or the file: opcode, content, its position. 1, 0 at the end, < 0 on damage. */
static int next_record(mcap_reader *r, uint8_t *op, const uint8_t **p, const uint8_t **end, size_t *at) {
  for (;;) {
    if (r->done) return r->err[0] ? -EINVAL : 0;
    if (r->in_chunk) {
      if (r->chunk_pos >= r->chunk_len) {
        r->in_chunk = 0;
        continue;
      }
      if (r->chunk_len - r->chunk_pos < 9 || le(r->chunk + r->chunk_pos + 1, 8) > r->chunk_len - r->chunk_pos - 9)
        return fail(r, -EINVAL, "a record inside the chunk before byte %zu is cut short", r->pos);
      *op = r->chunk[r->chunk_pos];
      *p = r->chunk + r->chunk_pos + 9;
      *end = *p + le(r->chunk + r->chunk_pos + 1, 8);
      *at = r->pos;
      r->chunk_pos = (size_t)(*end - r->chunk);
      return 1;
    }
    if (r->pos == r->size) return fail(r, -EINVAL, "the file ends at byte %zu without a footer (truncated)", r->pos);
    if (r->size - r->pos < 9 || le(r->map + r->pos + 1, 8) > r->size - r->pos - 9)
      return fail(r, -EINVAL, "the record at byte %zu runs past the end of the file (%zu bytes): truncated", r->pos,
                  r->size);
    *op = r->map[r->pos];
    *p = r->map + r->pos + 9;
    *end = *p + le(r->map + r->pos + 1, 8);
    *at = r->pos;
    r->pos = (size_t)(*end - r->map);
    if (*op == OP_DATA_END || *op == OP_FOOTER) {
      r->done = 1;
      return 0;
    }
    if (*op == OP_CHUNK) {
      int rc = open_chunk(r, *p, *end, *at);
      if (rc < 0) return rc;
      continue;
    }
    return 1;
  }
}

int mcap_reader_next(mcap_reader *r, mcap_message *m) {
  uint8_t op;
  const uint8_t *p, *end;
  size_t at;
  int rc;
  while ((rc = next_record(r, &op, &p, &end, &at)) > 0) {
    if (op == OP_SCHEMA) {
      if ((rc = take_schema(r, p, end, at)) < 0) return rc;
    } else if (op == OP_CHANNEL) {
      if ((rc = take_channel(r, p, end, at)) < 0) return rc;
    } else if (op == OP_MESSAGE) {
      if (end - p < 22) return fail(r, -EINVAL, "message record near byte %zu is cut short", at);
      m->channel = (int)le(p, 2);
      m->sequence = (uint32_t)le(p + 2, 4);
      m->log_time = le(p + 6, 8);
      m->publish_time = le(p + 14, 8);
      m->data = p + 22;
      m->len = (size_t)(end - p - 22);
      if (!mcap_reader_channel(r, m->channel))
        return fail(r, -EINVAL, "message near byte %zu names channel %d, which no record declared", at, m->channel);
      return 1;
    }
  }
  return rc;
}

int mcap_reader_scan_channels(mcap_reader *r) {
  mcap_reader_rewind(r);
  uint8_t op;
  const uint8_t *p, *end;
  size_t at;
  /* schemas and channels precede the messages of their channels (inside chunks too, as some writers
   * put them): read up to the first message */
  while (next_record(r, &op, &p, &end, &at) > 0 && op != OP_MESSAGE) {
    if (op == OP_SCHEMA && take_schema(r, p, end, at) < 0) break;
    if (op == OP_CHANNEL && take_channel(r, p, end, at) < 0) break;
  }
  int n = 0;
  for (int i = 0; i < MAX_IDS; i++) n += r->channel[i] != NULL;
  if (!r->err[0]) mcap_reader_rewind(r);
  return n;
}

const uint8_t *mcap_reader_attachment(mcap_reader *r, const char *name, size_t *len) {
  size_t pos = 8;
  char have[MCAP_NAME_MAX], media[MCAP_NAME_MAX];
  while (r->size - pos >= 9 && le(r->map + pos + 1, 8) <= r->size - pos - 9) {
    const uint8_t op = r->map[pos];
    const uint8_t *p = r->map + pos + 9, *end = p + le(r->map + pos + 1, 8);
    pos = (size_t)(end - r->map);
    if (op == OP_FOOTER || op == OP_DATA_END) break;
    if (op != OP_ATTACHMENT || end - p < 16) continue;
    p += 16;
    if (get_str(&p, end, have, sizeof have) || get_str(&p, end, media, sizeof media) || end - p < 8 ||
        (uint64_t)(end - p - 8) < le(p, 8))
      break;
    if (strcmp(have, name) == 0) {
      *len = (size_t)le(p, 8);
      return p + 8;
    }
  }
  return NULL;
}
