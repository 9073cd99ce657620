/* Parser of Config/shm.schema: constants and blocks of typed fields. */
#include "shm_internal.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const struct { const char *name; shm_type type; size_t size; } TYPES[] = {
  {"f64", SHM_F64, 8}, {"f32", SHM_F32, 4}, {"i32", SHM_I32, 4}, {"u32", SHM_U32, 4},
  {"i64", SHM_I64, 8}, {"u64", SHM_U64, 8}, {"u8", SHM_U8, 1},  {"i16", SHM_I16, 2},
  {"u16", SHM_U16, 2},
};

size_t shm_type_size(int type) {
  for (size_t i = 0; i < sizeof TYPES / sizeof TYPES[0]; i++)
    if ((int)TYPES[i].type == type) return TYPES[i].size;
  return 0;
}

const char *shm_type_name(int type) {
  for (size_t i = 0; i < sizeof TYPES / sizeof TYPES[0]; i++)
    if ((int)TYPES[i].type == type) return TYPES[i].name;
  return "?";
}

static int type_from_name(const char *s) {
  for (size_t i = 0; i < sizeof TYPES / sizeof TYPES[0]; i++)
    if (strcmp(TYPES[i].name, s) == 0) return TYPES[i].type;
  return 0;
}

/* Names were checked by valid_name (shorter than SHM_NAME_MAX); pad with zeros so field
 * tables compare byte for byte. */
static void copy_name(char dst[SHM_NAME_MAX], const char *src) {
  memset(dst, 0, SHM_NAME_MAX);
  memcpy(dst, src, strnlen(src, SHM_NAME_MAX - 1));
}

static int set_const(shm_schema *s, const char *name, long value) {
  for (int i = 0; i < s->nconsts; i++)
    if (strcmp(s->consts[i].name, name) == 0) {
      if (i >= s->nlocked) s->consts[i].value = value;   /* platform overrides stay */
      return 0;
    }
  if (s->nconsts == SHM_MAX_CONSTS) return -1;
  copy_name(s->consts[s->nconsts].name, name);
  s->consts[s->nconsts++].value = value;
  return 0;
}

long shm_schema_const(const shm_schema *s, const char *name) {
  for (int i = 0; i < s->nconsts; i++)
    if (strcmp(s->consts[i].name, name) == 0) return s->consts[i].value;
  return -1;
}

static int valid_name(const char *s) {
  if (!*s || strlen(s) >= SHM_NAME_MAX) return 0;
  for (; *s; s++)
    if (!isalnum((unsigned char)*s) && *s != '_' && *s != '.') return 0;
  return 1;
}

/* Parses one file into s. Only const lines when consts_only (platform overrides). */
static int parse_file(shm_schema *s, const char *path, int consts_only, char *err, size_t errlen) {
  FILE *f = fopen(path, "r");
  if (!f) {
    snprintf(err, errlen, "%s: cannot open shm schema: %s", path, strerror(errno));
    return -ENOENT;
  }
  char line[512];
  int lineno = 0;
  shm_block_decl *cur = NULL;
  int rc = 0;
  while (fgets(line, sizeof line, f)) {
    lineno++;
    char *hash = strchr(line, '#');
    if (hash) *hash = '\0';
    char w[3][128];
    int n = sscanf(line, "%127s %127s %127s", w[0], w[1], w[2]);
    if (n <= 0) continue;
    if (strcmp(w[0], "const") == 0) {
      char *end = NULL;
      long v = n == 3 ? strtol(w[2], &end, 10) : -1;
      if (n != 3 || *end || v < 0 || !valid_name(w[1])) {
        snprintf(err, errlen, "%s:%d: expected 'const NAME NUMBER'", path, lineno);
        rc = -EINVAL; break;
      }
      if (set_const(s, w[1], v) < 0) {
        snprintf(err, errlen, "%s:%d: too many constants", path, lineno);
        rc = -EINVAL; break;
      }
      continue;
    }
    if (consts_only) {
      snprintf(err, errlen, "%s:%d: only 'const' lines allowed here", path, lineno);
      rc = -EINVAL; break;
    }
    if (strcmp(w[0], "block") == 0) {
      if (n != 2 || !valid_name(w[1])) {
        snprintf(err, errlen, "%s:%d: expected 'block NAME'", path, lineno);
        rc = -EINVAL; break;
      }
      for (int i = 0; i < s->nblocks; i++)
        if (strcmp(s->blocks[i].name, w[1]) == 0) {
          snprintf(err, errlen, "%s:%d: block '%s' declared twice", path, lineno, w[1]);
          rc = -EINVAL; goto done;
        }
      if (s->nblocks == SHM_MAX_BLOCKS) {
        snprintf(err, errlen, "%s:%d: too many blocks", path, lineno);
        rc = -EINVAL; break;
      }
      cur = &s->blocks[s->nblocks++];
      memset(cur, 0, sizeof *cur);
      copy_name(cur->name, w[1]);
      continue;
    }
    int type = type_from_name(w[0]);
    if (!type || n != 3 || !valid_name(w[1])) {
      snprintf(err, errlen, "%s:%d: expected 'TYPE FIELD COUNT' or 'block NAME' or 'const NAME N'",
               path, lineno);
      rc = -EINVAL; break;
    }
    if (!cur) {
      snprintf(err, errlen, "%s:%d: field '%s' outside a block", path, lineno, w[1]);
      rc = -EINVAL; break;
    }
    long count;
    if (isdigit((unsigned char)w[2][0])) {
      char *end = NULL;
      count = strtol(w[2], &end, 10);
      if (*end) count = -1;
    } else {
      count = shm_schema_const(s, w[2]);
      if (count < 0) {
        snprintf(err, errlen, "%s:%d: unknown constant '%s'", path, lineno, w[2]);
        rc = -EINVAL; break;
      }
    }
    if (count <= 0 || count > (1L << 28)) {
      snprintf(err, errlen, "%s:%d: bad element count '%s'", path, lineno, w[2]);
      rc = -EINVAL; break;
    }
    for (int i = 0; i < cur->nfields; i++)
      if (strcmp(cur->fields[i].name, w[1]) == 0) {
        snprintf(err, errlen, "%s:%d: field '%s' declared twice in block '%s'", path, lineno, w[1],
                 cur->name);
        rc = -EINVAL; goto done;
      }
    if (cur->nfields == SHM_MAX_FIELDS) {
      snprintf(err, errlen, "%s:%d: too many fields in block '%s'", path, lineno, cur->name);
      rc = -EINVAL; break;
    }
    shm_field *fd = &cur->fields[cur->nfields++];
    memset(fd, 0, sizeof *fd);
    copy_name(fd->name, w[1]);
    fd->type = (uint32_t)type;
    fd->count = (uint32_t)count;
  }
done:
  fclose(f);
  return rc;
}

/* Lays out the fields after the header and field table; computes the layout hash. */
static void layout_block(shm_block_decl *b) {
  uint64_t off = sizeof(shm_header) + (uint64_t)b->nfields * sizeof(shm_field);
  off = (off + 63) & ~(uint64_t)63;
  b->data_offset = (uint32_t)off;
  for (int i = 0; i < b->nfields; i++) {
    shm_field *fd = &b->fields[i];
    off = (off + 7) & ~(uint64_t)7;
    fd->offset = off;
    off += (uint64_t)fd->count * shm_type_size((int)fd->type);
  }
  b->total_size = (off + 4095) & ~(uint64_t)4095;
  b->layout_hash = shm_layout_hash(b->name, b->fields, b->nfields);
}

uint64_t shm_layout_hash(const char *block, const shm_field *fields, int nfields) {
  uint64_t h = 1469598103934665603ULL;
  char buf[128];
  int n = snprintf(buf, sizeof buf, "%s|", block);
  for (int k = 0; k < n; k++) { h ^= (uint8_t)buf[k]; h *= 1099511628211ULL; }
  for (int i = 0; i < nfields; i++) {
    n = snprintf(buf, sizeof buf, "%s:%u:%u;", fields[i].name, fields[i].type, fields[i].count);
    for (int k = 0; k < n; k++) { h ^= (uint8_t)buf[k]; h *= 1099511628211ULL; }
  }
  return h;
}

const char *shm_root(void) {
  const char *root = getenv("HRP_ROOT");
  return (root && *root) ? root : HRP_ROOT_DEFAULT;
}

int shm_schema_load(const char *path, shm_schema **out, char *err, size_t errlen) {
  char buf[1024];
  if (!path) path = getenv("HRP_SCHEMA");
  if (!path || !*path) {
    snprintf(buf, sizeof buf, "%s/Config/shm.schema", shm_root());
    path = buf;
  }
  shm_schema *s = calloc(1, sizeof *s);
  if (!s) { snprintf(err, errlen, "out of memory"); return -ENOMEM; }
  /* The body's constants are read first and locked: the schema's own values are defaults. */
  const char *robot = getenv("ROBOT");
  char over[1024];
  snprintf(over, sizeof over, "%s/Config/robots/%s/shm.consts", shm_root(),
           (robot && *robot) ? robot : "op3");
  int rc = 0;
  FILE *probe = fopen(over, "r");
  if (probe) {
    fclose(probe);
    rc = parse_file(s, over, 1, err, errlen);
    s->nlocked = s->nconsts;
  }
  if (rc == 0) rc = parse_file(s, path, 0, err, errlen);
  if (rc < 0) { free(s); return rc; }
  snprintf(s->path, sizeof s->path, "%s", path);
  for (int i = 0; i < s->nblocks; i++) layout_block(&s->blocks[i]);
  *out = s;
  return 0;
}

void shm_schema_free(shm_schema *s) { free(s); }

int shm_schema_nblocks(const shm_schema *s) { return s->nblocks; }

const char *shm_schema_block_name(const shm_schema *s, int i) {
  return (i >= 0 && i < s->nblocks) ? s->blocks[i].name : NULL;
}

int shm_schema_block_nfields(const shm_schema *s, int i) {
  return (i >= 0 && i < s->nblocks) ? s->blocks[i].nfields : -1;
}

const shm_field *shm_schema_block_field(const shm_schema *s, int i, int k) {
  if (i < 0 || i >= s->nblocks || k < 0 || k >= s->blocks[i].nfields) return NULL;
  return &s->blocks[i].fields[k];
}

const shm_block_decl *shm_schema_find(const shm_schema *s, const char *block) {
  for (int i = 0; i < s->nblocks; i++)
    if (strcmp(s->blocks[i].name, block) == 0) return &s->blocks[i];
  return NULL;
}
