/* msgdef: a block's ros2msg definition from its field table, the fields of a recorded definition, and
 * the difference between two. */
#include "shmlog.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *const TYPE_NAMES[] = { NULL, "float64", "float32", "int32", "uint32", "int64", "uint64",
                                          "uint8", "int16", "uint16" };
static const int TYPE_SIZES[] = { 0, 8, 4, 4, 4, 8, 8, 1, 2, 2 };

const char *shmlog_type_name(int type) { return type >= 1 && type <= 9 ? TYPE_NAMES[type] : NULL; }

/* "dcm.sensor" -> "DcmSensor" */
static void camel(const char *in, char *out, size_t outlen) {
  size_t k = 0;
  int up = 1;
  for (const char *p = in; *p && k + 1 < outlen; p++) {
    if (!isalnum((unsigned char)*p)) {
      up = 1;
      continue;
    }
    out[k++] = (char)(up ? toupper((unsigned char)*p) : *p);
    up = 0;
  }
  out[k] = 0;
}

/* CDR offsets (each value aligned to its size, from the start after the 4-byte header), the definition. */
static int finish(shmlog_block *b, char *err, size_t errlen) {
  char cname[96];
  camel(b->name, cname, sizeof cname);
  snprintf(b->type_name, sizeof b->type_name, "hrp/msg/%s", cname);
  snprintf(b->topic, sizeof b->topic, "/%s", b->name);
  size_t off = 0, used = 0;
  used += (size_t)snprintf(b->def, sizeof b->def, "# shm block %s (Config/shm.schema)\n", b->name);
  for (int i = 0; i < b->nfields; i++) {
    shmlog_field *f = &b->field[i];
    const size_t size = (size_t)TYPE_SIZES[f->type];
    off = (off + size - 1) / size * size;
    f->cdr_offset = off;
    off += size * (size_t)f->count;
    if (used < sizeof b->def) {
      if (f->count == 1) used += (size_t)snprintf(b->def + used, sizeof b->def - used, "%s %s\n", TYPE_NAMES[f->type], f->name);
      else used += (size_t)snprintf(b->def + used, sizeof b->def - used, "%s[%d] %s\n", TYPE_NAMES[f->type], f->count, f->name);
    }
  }
  if (used >= sizeof b->def) {
    snprintf(err, errlen, "block '%s': its message definition is longer than %d bytes", b->name, SHMLOG_DEF_MAX);
    return -EINVAL;
  }
  b->cdr_size = 4 + off;
  return 0;
}

int shmlog_from_block(shm_block *blk, const char *const *skip, int nskip, shmlog_block *out, char *err,
                      size_t errlen) {
  memset(out, 0, sizeof *out);
  snprintf(out->name, sizeof out->name, "%s", shm_block_name(blk));
  for (int i = 0; i < shm_block_nfields(blk); i++) {
    const shm_field *f = shm_block_field(blk, i);
    int skipped = 0;
    for (int k = 0; k < nskip; k++) skipped |= strcmp(skip[k], f->name) == 0;
    if (skipped) continue;
    if (out->nfields >= SHMLOG_FIELDS_MAX || !shmlog_type_name((int)f->type)) {
      snprintf(err, errlen, "block '%s': field '%s': %s", out->name, f->name,
               out->nfields >= SHMLOG_FIELDS_MAX ? "too many fields" : "unknown type");
      return -EINVAL;
    }
    shmlog_field *g = &out->field[out->nfields++];
    snprintf(g->name, sizeof g->name, "%s", f->name);
    g->type = (int)f->type;
    g->count = (int)f->count;
    g->shm_offset = f->offset;
  }
  return finish(out, err, errlen);
}

int shmlog_parse(const char *block, const char *def, size_t len, shmlog_block *out, char *err, size_t errlen) {
  memset(out, 0, sizeof *out);
  snprintf(out->name, sizeof out->name, "%s", block);
  size_t pos = 0;
  int lineno = 0;
  while (pos < len) {
    char line[256];
    size_t n = 0;
    while (pos < len && def[pos] != '\n') {
      if (n + 1 < sizeof line) line[n++] = def[pos];
      pos++;
    }
    pos++;
    line[n] = 0;
    lineno++;
    char *hash = strchr(line, '#');
    if (hash) *hash = 0;
    char type[32], name[SHM_NAME_MAX + 16];
    int count = 1;
    if (sscanf(line, " %31s %63s", type, name) != 2) continue;
    char *br = strchr(type, '[');
    if (br) {
      if (sscanf(br, "[%d]", &count) != 1 || count < 1) goto bad;
      *br = 0;
    }
    int t = 0;
    for (int k = 1; k <= 9; k++)
      if (strcmp(type, TYPE_NAMES[k]) == 0) t = k;
    if (!t || out->nfields >= SHMLOG_FIELDS_MAX || strlen(name) >= SHM_NAME_MAX) goto bad;
    shmlog_field *f = &out->field[out->nfields++];
    snprintf(f->name, sizeof f->name, "%s", name);
    f->type = t;
    f->count = count;
    continue;
  bad:
    snprintf(err, errlen, "block '%s': line %d of the recorded definition is not a shm field: '%s'", block, lineno,
             line);
    return -EINVAL;
  }
  return finish(out, err, errlen);
}

static const shmlog_field *find(const shmlog_block *b, const char *name) {
  for (int i = 0; i < b->nfields; i++)
    if (strcmp(b->field[i].name, name) == 0) return &b->field[i];
  return NULL;
}

int shmlog_diff(const shmlog_block *log, const shmlog_block *now, char *msg, size_t msglen) {
  for (int i = 0; i < log->nfields; i++) {
    const shmlog_field *a = &log->field[i], *b = find(now, a->name);
    if (!b) {
      snprintf(msg, msglen, "block '%s': field '%s' is in the log but not in Config/shm.schema", log->name, a->name);
      return 1;
    }
    if (a->type != b->type || a->count != b->count) {
      snprintf(msg, msglen, "block '%s': field '%s' is %s[%d] in the log but %s[%d] in Config/shm.schema", log->name,
               a->name, TYPE_NAMES[a->type], a->count, TYPE_NAMES[b->type], b->count);
      return 1;
    }
  }
  for (int i = 0; i < now->nfields; i++) {
    if (!find(log, now->field[i].name)) {
      snprintf(msg, msglen, "block '%s': field '%s' of Config/shm.schema is not in the log", now->name,
               now->field[i].name);
      return 1;
    }
  }
  for (int i = 0; i < log->nfields; i++) {
    if (strcmp(log->field[i].name, now->field[i].name) != 0) {
      snprintf(msg, msglen, "block '%s': the fields are in another order in the log (field %d is '%s', here '%s')",
               log->name, i + 1, log->field[i].name, now->field[i].name);
      return 1;
    }
  }
  return 0;
}

void shmlog_encode(const shmlog_block *b, const uint8_t *seg, uint8_t *out) {
  static const uint8_t header[4] = { 0x00, 0x01, 0x00, 0x00 };   /* CDR, little endian */
  memcpy(out, header, 4);
  size_t end = 4;
  for (int i = 0; i < b->nfields; i++) {
    const shmlog_field *f = &b->field[i];
    const size_t n = (size_t)TYPE_SIZES[f->type] * (size_t)f->count;
    memset(out + end, 0, 4 + f->cdr_offset - end);   /* alignment padding */
    memcpy(out + 4 + f->cdr_offset, seg + f->shm_offset, n);
    end = 4 + f->cdr_offset + n;
  }
}

/* Every NaN of a float field becomes the one quiet NaN: a recording is input from outside, and this
   LuaJIT reads some NaN payloads (e.g. the float bits ff900001) through the FFI as a wild object that
   crashes the reader (found by fuzzing the team messages). */
static void canonical_nans(uint8_t *p, int type, int count) {
  for (int k = 0; k < count; k++) {
    if (type == SHM_F64) {
      double v;
      memcpy(&v, p + 8 * k, 8);
      if (v != v) { v = NAN; memcpy(p + 8 * k, &v, 8); }
    } else {
      float v;
      memcpy(&v, p + 4 * k, 4);
      if (v != v) { v = NAN; memcpy(p + 4 * k, &v, 4); }
    }
  }
}

int shmlog_decode(const shmlog_block *b, const uint8_t *msg, size_t len, uint8_t *seg) {
  if (len != b->cdr_size || len < 4 || msg[1] != 0x01) return -EINVAL;
  for (int i = 0; i < b->nfields; i++) {
    const shmlog_field *f = &b->field[i];
    memcpy(seg + f->shm_offset, msg + 4 + f->cdr_offset, (size_t)TYPE_SIZES[f->type] * (size_t)f->count);
    if (f->type == SHM_F64 || f->type == SHM_F32) canonical_nans(seg + f->shm_offset, f->type, f->count);
  }
  return 0;
}
