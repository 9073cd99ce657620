/* libFuzzer target: a shared-memory segment written by someone else is input. The first byte picks
 * how it is opened (as one of the schema's blocks, or as it describes itself: the tools' way), the
 * rest becomes the segment's bytes; every field the open block offers is then read in full. A
 * crash, a sanitizer report or a read outside the mapping is a bug. (Tests/foundation/shm_fuzz_test.sh) */
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "shm/shm.h"

static shm_schema *g_schema;
/* a robot id of this process's own: two fuzzers on one machine (two make test runs) must not write
 * and truncate each other's segment under their mappings (a SIGBUS that is no bug of the parser) */
static int g_robot;

int LLVMFuzzerInitialize(int *argc, char ***argv) {
  char err[256];
  g_robot = 1000000 + (int)(getpid() % 100000);
  if (shm_schema_load(NULL, &g_schema, err, sizeof err) < 0) {
    fprintf(stderr, "shm_segment_fuzz: %s\n", err);
    exit(1);
  }
  return 0;
}

static size_t type_size(uint32_t t) {
  switch (t) {
    case SHM_F64: case SHM_I64: case SHM_U64: return 8;
    case SHM_F32: case SHM_I32: case SHM_U32: return 4;
    case SHM_I16: case SHM_U16: return 2;
    case SHM_U8: return 1;
    default: return 0;
  }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size < 1 + sizeof(shm_header)) return 0;   /* a short segment only waits for its creator */
  const int nb = shm_schema_nblocks(g_schema);
  const int pick = data[0] % (nb + 1);            /* nb: no schema, the segment describes itself */
  const char *block = pick < nb ? shm_schema_block_name(g_schema, pick) : "fuzz.block";
  char seg[128];
  shm_segment_name(g_robot, block, seg, sizeof seg);
  int fd = shm_open(seg, O_CREAT | O_RDWR | O_TRUNC, 0600);
  if (fd < 0) return 0;
  uint8_t *copy = malloc(size - 1);
  memcpy(copy, data + 1, size - 1);
  /* a segment whose creator never finished is waited for (200 ms): not what this target explores */
  ((shm_header *)copy)->ready = 1;
  if (write(fd, copy, size - 1) != (ssize_t)(size - 1)) { close(fd); free(copy); return 0; }
  close(fd);
  free(copy);
  shm_block *b = NULL;
  char err[512];
  const int flags = pick < nb ? 0 : SHM_OPEN_NOSCHEMA;
  if (shm_block_open(pick < nb ? g_schema : NULL, block, g_robot, flags, &b, err, sizeof err) == 0) {
    volatile uint8_t sum = 0;
    for (int i = 0; i < shm_block_nfields(b); i++) {
      const shm_field *f = shm_block_field(b, i);
      char name[SHM_NAME_MAX + 1];
      memcpy(name, f->name, SHM_NAME_MAX);
      name[SHM_NAME_MAX] = 0;
      int type = 0, count = 0;
      const uint8_t *p = shm_field_ptr(b, name, &type, &count);
      if (!p) continue;
      const size_t n = type_size((uint32_t)type) * (size_t)count;
      for (size_t k = 0; k < n; k++) sum ^= p[k];
    }
    (void)sum;
    shm_block_close(b);
  }
  shm_unlink(seg);
  return 0;
}
