/* Internal declarations of the shm module (schema representation). */
#ifndef HRP_SHM_INTERNAL_H
#define HRP_SHM_INTERNAL_H

#include "shm.h"

#define SHM_MAX_CONSTS 64
#define SHM_MAX_BLOCKS 64
#define SHM_MAX_FIELDS 64

typedef struct shm_block_decl {
  char name[SHM_NAME_MAX];
  int nfields;
  shm_field fields[SHM_MAX_FIELDS];   /* offsets filled by the layout */
  uint32_t data_offset;
  uint64_t total_size;
  uint64_t layout_hash;
} shm_block_decl;

struct shm_schema {
  char path[1024];
  int nconsts, nlocked;               /* the first nlocked constants came from the platform */
  struct { char name[SHM_NAME_MAX]; long value; } consts[SHM_MAX_CONSTS];
  int nblocks;
  shm_block_decl blocks[SHM_MAX_BLOCKS];
};

size_t shm_type_size(int type);
const char *shm_type_name(int type);
uint64_t shm_layout_hash(const char *block, const shm_field *fields, int nfields);
const shm_block_decl *shm_schema_find(const shm_schema *s, const char *block);
const char *shm_root(void);

#endif
