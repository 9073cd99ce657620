/* history: the recent past of every block, for history('dcm.sensor.gyro', 2.0) in the REPL
 * (Lib/history.lua). A shared-memory object /hrp-history.<ROBOT_ID> the sampler appends each recorded
 * block to: per block a ring of history_s seconds at the DCM's rate, each slot the block's data region
 * and its robot time, and the block's field table, so a reader needs nothing compiled in.
 *
 * Layout (little endian, 8-aligned):
 *   0     header   "HRPHIST\1", u32 version 1, u32 nblocks, f64 seconds, u64 total size   (64 bytes)
 *   64    entries  per block (128 bytes): name[48], u32 slots, u32 slot_size, u64 data_bytes,
 *                  u64 ring_offset, u64 fields_offset, u32 nfields, u32 pad, u64 count (samples appended)
 *   ...   fields   per block nfields x 64 bytes: name[48], u32 type, u32 count, u64 offset in the data
 *   ...   rings    per block slots x slot_size: f64 time (s), u64 seq (= sample index + 1; 0 while written),
 *                  data
 * A reader takes the slots of samples count-1, count-2, ... whose seq matches. */
#include "record.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#define HIST_ENTRY 128
#define HIST_BIG (64 * 1024)   /* blocks with a larger data region (the camera image) are left out */

typedef struct hist_entry {
  char name[SHM_NAME_MAX];
  uint32_t slots, slot_size;
  uint64_t data_bytes, ring_offset, fields_offset;
  uint32_t nfields, pad;
  uint64_t count;
  uint8_t pad2[HIST_ENTRY - SHM_NAME_MAX - 48];
} hist_entry;
_Static_assert(sizeof(hist_entry) == HIST_ENTRY, "history entry is 128 bytes");

static uint64_t round8(uint64_t n) { return (n + 7) & ~(uint64_t)7; }

static void ring_name(int robot_id, char *buf, size_t len) { snprintf(buf, len, "/hrp-history.%d", robot_id); }

int rec_history_open(rec_history *h, const rec_blocks *bs, const rec_opts *o, double period, char *err, size_t errlen) {
  memset(h, 0, sizeof *h);
  if (!(o->history_s > 0) || !(period > 0)) return 0;
  const uint32_t slots = (uint32_t)(o->history_s / period + 1);
  uint64_t total = 64 + (uint64_t)bs->n * HIST_ENTRY, fields = 0, rings = 0;
  for (int i = 0; i < bs->n; i++) {
    const shm_header *sh = shm_block_header(bs->b[i].blk);
    const uint64_t data = sh->total_size - sh->data_offset;
    h->entry_of[i] = -1;
    if (data > HIST_BIG) continue;
    fields += (uint64_t)shm_block_nfields(bs->b[i].blk) * 64;
    rings += (uint64_t)slots * (16 + round8(data));
  }
  total += fields + rings;
  char name[64];
  ring_name(o->robot_id, name, sizeof name);
  const int fd = shm_open(name, O_CREAT | O_RDWR | O_TRUNC, 0600);
  if (fd < 0 || ftruncate(fd, (off_t)total) != 0) {
    snprintf(err, errlen, "recorder: history %s: %s", name, strerror(errno));
    if (fd >= 0) close(fd);
    return -errno;
  }
  void *m = mmap(NULL, total, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  close(fd);
  if (m == MAP_FAILED) {
    snprintf(err, errlen, "recorder: history %s: %s", name, strerror(errno));
    shm_unlink(name);
    return -errno;
  }
  uint8_t *base = (uint8_t *)m;
  uint64_t fpos = 64 + (uint64_t)bs->n * HIST_ENTRY, rpos = fpos + fields;
  int n = 0;
  for (int i = 0; i < bs->n; i++) {
    const shm_header *sh = shm_block_header(bs->b[i].blk);
    const uint64_t data = sh->total_size - sh->data_offset;
    if (data > HIST_BIG) continue;
    hist_entry *e = (hist_entry *)(base + 64 + (uint64_t)n * HIST_ENTRY);
    snprintf(e->name, sizeof e->name, "%s", shm_block_name(bs->b[i].blk));
    e->slots = slots;
    e->slot_size = (uint32_t)(16 + round8(data));
    e->data_bytes = data;
    e->ring_offset = rpos;
    e->fields_offset = fpos;
    e->nfields = (uint32_t)shm_block_nfields(bs->b[i].blk);
    for (uint32_t k = 0; k < e->nfields; k++) {
      const shm_field *f = shm_block_field(bs->b[i].blk, (int)k);
      shm_field *g = (shm_field *)(base + fpos + 64 * k);
      memcpy(g->name, f->name, sizeof g->name);
      g->type = f->type;
      g->count = f->count;
      g->offset = f->offset - sh->data_offset;
    }
    fpos += 64 * (uint64_t)e->nfields;
    rpos += (uint64_t)slots * e->slot_size;
    h->entry_of[i] = n++;
  }
  memcpy(base, "HRPHIST\x01", 8);
  const uint32_t version = 1, nb = (uint32_t)n;
  memcpy(base + 8, &version, 4);
  memcpy(base + 12, &nb, 4);
  memcpy(base + 16, &o->history_s, 8);
  memcpy(base + 24, &total, 8);
  h->base = base;
  h->size = total;
  snprintf(h->name, sizeof h->name, "%s", name);
  return 0;
}

void rec_history_append(rec_history *h, const rec_blocks *bs, int i, double t) {
  if (!h->base || h->entry_of[i] < 0) return;
  hist_entry *e = (hist_entry *)(h->base + 64 + (uint64_t)h->entry_of[i] * HIST_ENTRY);
  const uint64_t k = e->count;
  uint8_t *slot = h->base + e->ring_offset + (k % e->slots) * e->slot_size;
  const uint64_t busy = 0, seq = k + 1;
  __atomic_store(((uint64_t *)slot) + 1, &busy, __ATOMIC_RELEASE);
  memcpy(slot, &t, 8);
  memcpy(slot + 16, bs->b[i].now + shm_block_header(bs->b[i].blk)->data_offset, e->data_bytes);
  __atomic_store(((uint64_t *)slot) + 1, &seq, __ATOMIC_RELEASE);
  __atomic_store_n(&e->count, k + 1, __ATOMIC_RELEASE);
}

void rec_history_close(rec_history *h) {
  if (!h->base) return;
  munmap(h->base, h->size);
  shm_unlink(h->name);
  h->base = NULL;
}
