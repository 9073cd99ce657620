/* Creating, attaching and validating shared-memory blocks. */
#include "shm_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

_Static_assert(sizeof(shm_header) == 256, "shm_header must be 256 bytes");
_Static_assert(sizeof(shm_field) == 64, "shm_field must be 64 bytes");
_Static_assert(offsetof(shm_header, seq) == 128, "seq must start its own cache line");

struct shm_block {
  char name[SHM_NAME_MAX];
  char segname[128];
  dev_t dev;                /* the object mapped: a name that now leads elsewhere was replaced */
  ino_t ino;
  uint8_t *base;
  size_t size;
  shm_header *hdr;
  shm_field *fields;
};

int shm_robot_id(void) {
  const char *s = getenv("ROBOT_ID");
  if (!s || !*s) return 1;
  long v = strtol(s, NULL, 10);
  return v > 0 ? (int)v : 1;
}

void shm_segment_name(int robot_id, const char *block, char *buf, size_t len) {
  snprintf(buf, len, "/hrp.%d.%s", robot_id, block);
}

int shm_pid_alive(int pid) {
  if (pid <= 0) return 0;
  return kill(pid, 0) == 0 || errno == EPERM;
}

static void sleep_ms(int ms) {
  struct timespec ts = {ms / 1000, (long)(ms % 1000) * 1000000L};
  nanosleep(&ts, NULL);
}

/* Describes how a segment's field table differs from the schema's, into msg. */
static void describe_difference(const shm_block_decl *d, const shm_field *seg, int nseg,
                                char *msg, size_t len) {
  for (int i = 0; i < d->nfields; i++) {
    const shm_field *want = &d->fields[i];
    const shm_field *have = NULL;
    for (int j = 0; j < nseg; j++)
      if (strncmp(seg[j].name, want->name, SHM_NAME_MAX) == 0) have = &seg[j];
    if (!have) {
      snprintf(msg, len, "field '%s' is in the schema but not in the segment", want->name);
      return;
    }
    if (have->type != want->type || have->count != want->count) {
      snprintf(msg, len, "field '%s' is %s[%u] in the segment but %s[%u] in the schema", want->name,
               shm_type_name((int)have->type), have->count, shm_type_name((int)want->type),
               want->count);
      return;
    }
    if (have->offset != want->offset) {
      snprintf(msg, len, "field '%s' is at offset %lu in the segment but %lu in the schema",
               want->name, (unsigned long)have->offset, (unsigned long)want->offset);
      return;
    }
  }
  for (int j = 0; j < nseg; j++) {
    int found = 0;
    for (int i = 0; i < d->nfields; i++)
      if (strncmp(seg[j].name, d->fields[i].name, SHM_NAME_MAX) == 0) found = 1;
    if (!found) {
      snprintf(msg, len, "field '%.*s' is in the segment but not in the schema", SHM_NAME_MAX - 1,
               seg[j].name);
      return;
    }
  }
  snprintf(msg, len, "field order differs");
}

static int create_segment(const char *segname, const shm_block_decl *d, shm_block *b, char *err,
                          size_t errlen) {
  int fd = shm_open(segname, O_RDWR | O_CREAT | O_EXCL, 0600);
  if (fd < 0) return -errno;
  struct stat st;
  if (ftruncate(fd, (off_t)d->total_size) < 0 || fstat(fd, &st) < 0) {
    int e = errno;
    snprintf(err, errlen, "shm %s: ftruncate: %s", segname, strerror(e));
    close(fd);
    shm_unlink(segname);
    return -e;
  }
  b->dev = st.st_dev;
  b->ino = st.st_ino;
  void *p = mmap(NULL, d->total_size, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  close(fd);
  if (p == MAP_FAILED) {
    int e = errno;
    snprintf(err, errlen, "shm %s: mmap: %s", segname, strerror(e));
    shm_unlink(segname);
    return -e;
  }
  shm_header *h = p;
  memcpy(h->magic, SHM_MAGIC, 8);
  h->version = SHM_FORMAT_VERSION;
  h->header_size = sizeof(shm_header);
  h->layout_hash = d->layout_hash;
  h->total_size = d->total_size;
  h->nfields = (uint32_t)d->nfields;
  h->field_size = sizeof(shm_field);
  h->data_offset = d->data_offset;
  h->creator_pid = getpid();
  struct timespec ts;
  clock_gettime(CLOCK_REALTIME, &ts);
  h->created_ns = (uint64_t)ts.tv_sec * 1000000000ULL + (uint64_t)ts.tv_nsec;
  snprintf(h->block, SHM_NAME_MAX, "%s", d->name);
  memcpy((uint8_t *)p + sizeof(shm_header), d->fields, (size_t)d->nfields * sizeof(shm_field));
  __atomic_store_n(&h->ready, 1u, __ATOMIC_RELEASE);
  b->base = p;
  b->size = d->total_size;
  return 0;
}

/* Result of looking at an existing segment. */
enum { SEG_OK = 0, SEG_STALE = 1, SEG_ERROR = 2, SEG_GONE = 3 };

/* A field table read from a segment somebody else wrote: every field named (NUL inside its
 * name), of a known type, 8-byte aligned and inside the segment. 0, or -1 with the field named. */
static int check_fields(const shm_field *f, uint32_t n, uint64_t total, char *err, size_t errlen) {
  for (uint32_t i = 0; i < n; i++) {
    const size_t tsize = shm_type_size((int)f[i].type);
    char name[SHM_NAME_MAX + 1];
    memcpy(name, f[i].name, SHM_NAME_MAX);
    name[SHM_NAME_MAX] = 0;
    const char *why = NULL;
    if (memchr(f[i].name, 0, SHM_NAME_MAX) == NULL) why = "its name has no end";
    else if (tsize == 0) why = "unknown type";
    else if (f[i].offset % 8 != 0) why = "offset not aligned to 8";
    else if (f[i].offset > total || (uint64_t)f[i].count > (total - f[i].offset) / tsize)
      why = "lies outside the segment";
    if (why) {
      snprintf(err, errlen, "field %u ('%.*s'): %s", i, 24, name, why);
      return -1;
    }
  }
  return 0;
}

static int attach_segment(const char *segname, const shm_block_decl *d, int writable, shm_block *b,
                          char *err, size_t errlen) {
  int fd = shm_open(segname, writable ? O_RDWR : O_RDONLY, 0);
  if (fd < 0) {
    if (errno == ENOENT) return SEG_GONE;
    snprintf(err, errlen, "shm %s: open: %s", segname, strerror(errno));
    return SEG_ERROR;
  }
  struct stat st;
  /* A creator may be between shm_open and ftruncate: give it a moment. */
  for (int i = 0; i < 50; i++) {
    if (fstat(fd, &st) == 0 && (size_t)st.st_size >= sizeof(shm_header)) break;
    sleep_ms(2);
  }
  if ((size_t)st.st_size < sizeof(shm_header)) {
    close(fd);
    snprintf(err, errlen, "shm %s: segment too small (%ld bytes)", segname, (long)st.st_size);
    return SEG_STALE;
  }
  int prot = writable ? PROT_READ | PROT_WRITE : PROT_READ;
  uint8_t *p = mmap(NULL, (size_t)st.st_size, prot, MAP_SHARED, fd, 0);
  close(fd);
  if (p == MAP_FAILED) {
    snprintf(err, errlen, "shm %s: mmap: %s", segname, strerror(errno));
    return SEG_ERROR;
  }
  shm_header *h = (shm_header *)p;
  for (int i = 0; i < 100 && !__atomic_load_n(&h->ready, __ATOMIC_ACQUIRE); i++) sleep_ms(2);
  int verdict = SEG_OK;
  if (memcmp(h->magic, SHM_MAGIC, 8) != 0 || h->version != SHM_FORMAT_VERSION ||
      h->header_size != sizeof(shm_header) || h->field_size != sizeof(shm_field)) {
    snprintf(err, errlen, "shm %s: not a format-%d hrp segment (bad magic or version)", segname,
             SHM_FORMAT_VERSION);
    verdict = SEG_STALE;
  } else if (!h->ready) {
    snprintf(err, errlen, "shm %s: creator (pid %d) never finished initialising it", segname,
             h->creator_pid);
    verdict = SEG_STALE;
  } else if (h->total_size > (uint64_t)st.st_size ||
             sizeof(shm_header) + (uint64_t)h->nfields * sizeof(shm_field) > h->total_size) {
    snprintf(err, errlen, "shm %s: segment truncated", segname);
    verdict = SEG_STALE;
  } else if (!d) {
    /* no schema to compare with: the segment's own description must hold together */
    char why[160];
    if (check_fields((const shm_field *)(p + sizeof(shm_header)), h->nfields, h->total_size, why, sizeof why) < 0) {
      snprintf(err, errlen, "shm %s: broken field table: %s", segname, why);
      verdict = SEG_ERROR;
    }
  } else {
    const shm_field *seg = (const shm_field *)(p + sizeof(shm_header));
    if (h->layout_hash != d->layout_hash || h->nfields != (uint32_t)d->nfields ||
        h->total_size != d->total_size ||
        memcmp(seg, d->fields, (size_t)d->nfields * sizeof(shm_field)) != 0) {
      char diff[256];
      describe_difference(d, seg, (int)h->nfields, diff, sizeof diff);
      snprintf(err, errlen, "shm block '%s' (%s): layout differs from the schema: %s", d->name,
               segname, diff);
      verdict = shm_pid_alive(h->creator_pid) ? SEG_ERROR : SEG_STALE;
    }
  }
  if (verdict != SEG_OK) {
    munmap(p, (size_t)st.st_size);
    return verdict;
  }
  b->base = p;
  b->size = (size_t)st.st_size;
  b->dev = st.st_dev;
  b->ino = st.st_ino;
  return SEG_OK;
}

int shm_block_open(const shm_schema *schema, const char *block, int robot_id, int flags,
                   shm_block **out, char *err, size_t errlen) {
  shm_schema *own = NULL;
  const shm_block_decl *d = NULL;
  if (!(flags & SHM_OPEN_NOSCHEMA)) {
    if (!schema) {
      int rc = shm_schema_load(NULL, &own, err, errlen);
      if (rc < 0) return rc;
      schema = own;
    }
    d = shm_schema_find(schema, block);
    if (!d) {
      snprintf(err, errlen, "shm: unknown block '%s' (not declared in %s)", block, schema->path);
      shm_schema_free(own);
      return -EINVAL;
    }
  }
  shm_block *b = calloc(1, sizeof *b);
  if (!b) { shm_schema_free(own); snprintf(err, errlen, "out of memory"); return -ENOMEM; }
  snprintf(b->name, sizeof b->name, "%s", block);
  char *segname = b->segname;
  shm_segment_name(robot_id, block, segname, sizeof b->segname);
  int create = (flags & SHM_OPEN_CREATE) && d;
  int rc = -EAGAIN;
  for (int attempt = 0; attempt < 5; attempt++) {
    if (create) {
      rc = create_segment(segname, d, b, err, errlen);
      if (rc == 0) break;
      if (rc != -EEXIST) break;
    }
    int v = attach_segment(segname, d, 1, b, err, errlen);
    if (v == SEG_OK) { rc = 0; break; }
    if (v == SEG_GONE) {
      rc = -ENOENT;
      if (!create) { snprintf(err, errlen, "shm block '%s' (%s) does not exist", block, segname); break; }
      continue;   /* removed between our create and attach: try again */
    }
    if (v == SEG_STALE && create) {
      fprintf(stderr, "shm: recreating stale segment: %s\n", err);
      shm_unlink(segname);
      continue;
    }
    rc = v == SEG_STALE ? -ESTALE : -EINVAL;
    break;
  }
  shm_schema_free(own);
  if (rc < 0) { free(b); return rc; }
  b->hdr = (shm_header *)b->base;
  b->fields = (shm_field *)(b->base + sizeof(shm_header));
  *out = b;
  return 0;
}

void shm_block_close(shm_block *b) {
  if (!b) return;
  munmap(b->base, b->size);
  free(b);
}

int shm_block_replaced(const shm_block *b) {
  int fd = shm_open(b->segname, O_RDONLY, 0);
  if (fd < 0) return errno == ENOENT ? 1 : -errno;
  struct stat st;
  int rc = fstat(fd, &st) == 0 ? (st.st_dev != b->dev || st.st_ino != b->ino) : -errno;
  close(fd);
  return rc;
}

int shm_block_unlink(const char *block, int robot_id) {
  char segname[128];
  shm_segment_name(robot_id, block, segname, sizeof segname);
  return shm_unlink(segname) == 0 ? 0 : -errno;
}

shm_header *shm_block_header(shm_block *b) { return b->hdr; }
const char *shm_block_name(const shm_block *b) { return b->name; }
int shm_block_nfields(const shm_block *b) { return (int)b->hdr->nfields; }

const shm_field *shm_block_field(const shm_block *b, int i) {
  return (i >= 0 && i < (int)b->hdr->nfields) ? &b->fields[i] : NULL;
}

void *shm_field_ptr(shm_block *b, const char *field, int *type, int *count) {
  for (uint32_t i = 0; i < b->hdr->nfields; i++) {
    const shm_field *f = &b->fields[i];
    if (strncmp(f->name, field, SHM_NAME_MAX) == 0) {
      if (type) *type = (int)f->type;
      if (count) *count = (int)f->count;
      return b->base + f->offset;
    }
  }
  return NULL;
}

void *shm_field_require(shm_block *b, const char *field, int type, int min_count, char *err,
                        size_t errlen) {
  int t = 0, n = 0;
  void *p = shm_field_ptr(b, field, &t, &n);
  if (!p) {
    snprintf(err, errlen, "shm block '%s' has no field '%s'", b->name, field);
    return NULL;
  }
  if (t != type || n < min_count) {
    snprintf(err, errlen, "shm block '%s' field '%s' is %s[%d], expected %s[>=%d]", b->name, field,
             shm_type_name(t), n, shm_type_name(type), min_count);
    return NULL;
  }
  return p;
}
