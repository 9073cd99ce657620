/* libFuzzer target: the schema parser (Config/shm.schema's format) on any text; a loaded schema is
 * walked block by block and field by field. (Tests/foundation/shm_fuzz_test.sh) */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "shm/shm.h"

static char g_path[64];

int LLVMFuzzerInitialize(int *argc, char ***argv) {
  snprintf(g_path, sizeof g_path, "/tmp/shm_schema_fuzz.%d", (int)getpid());
  return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  FILE *f = fopen(g_path, "wb");
  if (!f) return 0;
  fwrite(data, 1, size, f);
  fclose(f);
  shm_schema *s = NULL;
  char err[512];
  if (shm_schema_load(g_path, &s, err, sizeof err) == 0) {
    volatile long sum = 0;
    for (int i = 0; i < shm_schema_nblocks(s); i++) {
      sum += (long)shm_schema_block_name(s, i)[0];
      for (int k = 0; k < shm_schema_block_nfields(s, i); k++) {
        const shm_field *fd = shm_schema_block_field(s, i, k);
        sum += (long)fd->offset + fd->count + fd->type + fd->name[0];
      }
    }
    (void)sum;
    shm_schema_free(s);
  }
  remove(g_path);
  return 0;
}
