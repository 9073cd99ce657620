/* blocks: binds the structs generated from the schema (dcm_blocks.h) to open shm blocks. */
#include "dcm.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

int dcm_blocks_bind(shm_block *b, const char *block, const dcm_blk_field *fields, int nfields, void *out,
                    shm_block **blk, char *err, size_t errlen) {
  char *base = (char *)out;
  if (strcmp(shm_block_name(b), block) != 0) {
    snprintf(err, errlen, "shm block '%s' bound as '%s'", shm_block_name(b), block);
    return -EINVAL;
  }
  for (int k = 0; k < nfields; k++) {
    const dcm_blk_field *f = &fields[k];
    int type = 0, count = 0;
    if (!shm_field_ptr(b, f->name, &type, &count)) count = 1;   /* absent: the error comes below */
    void *p = shm_field_require(b, f->name, f->type, count > 0 ? count : 1, err, errlen);
    if (!p) return -EPROTO;
    *(void **)(base + f->ptr) = p;
    *(int *)(base + f->count) = count;
  }
  *blk = b;
  return 0;
}

int dcm_blocks_open(const shm_schema *schema, int robot_id, const char *block, const dcm_blk_field *fields,
                    int nfields, void *out, shm_block **blk, char *err, size_t errlen) {
  shm_block *b = NULL;
  int rc = shm_block_open(schema, block, robot_id, SHM_OPEN_CREATE, &b, err, errlen);
  if (rc < 0) return rc;
  rc = dcm_blocks_bind(b, block, fields, nfields, out, blk, err, errlen);
  if (rc < 0) shm_block_close(b);
  return rc;
}

int dcm_robot_attach(int robot_id, shm_schema **schema, dcm_blk_dcm_sensor *sensor, dcm_blk_dcm_actuator *actuator,
                     char *err, size_t errlen) {
  int r = shm_schema_load(NULL, schema, err, errlen);
  if (r < 0) return r;
  if ((r = dcm_blocks_open(*schema, robot_id, DCM_BLK_dcm_sensor(sensor), err, errlen)) < 0 ||
      (r = dcm_blocks_open(*schema, robot_id, DCM_BLK_dcm_actuator(actuator), err, errlen)) < 0) {
    dcm_robot_detach(schema, sensor, actuator);
    return r;
  }
  return 0;
}

void dcm_robot_detach(shm_schema **schema, dcm_blk_dcm_sensor *sensor, dcm_blk_dcm_actuator *actuator) {
  if (sensor->blk) shm_block_close(sensor->blk);
  if (actuator->blk) shm_block_close(actuator->blk);
  if (*schema) shm_schema_free(*schema);
  sensor->blk = actuator->blk = NULL;
  *schema = NULL;
}
