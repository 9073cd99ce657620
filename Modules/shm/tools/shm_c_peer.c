/* A C process on the other side of a block, for the cross-language tests:
 *   shm_c_peer write BLOCK FIELD V1 [V2 ...]   write values (f64 or integer fields) under the lock
 *   shm_c_peer read BLOCK FIELD                print the values, one line, space separated
 *   shm_c_peer stream BLOCK N                  N locked updates of gyro[0..2] = k, 2k, 3k and tick = k
 *   shm_c_check BLOCK SECONDS                  (check) read gyro/tick for SECONDS, count torn reads
 * ROBOT_ID selects the robot. Exit status 0 on success. */
#include "shm/shm.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static shm_block *open_block(const char *name) {
  char err[512];
  shm_block *b = NULL;
  if (shm_block_open(NULL, name, shm_robot_id(), SHM_OPEN_CREATE, &b, err, sizeof err) < 0) {
    fprintf(stderr, "shm_c_peer: %s\n", err);
    exit(2);
  }
  return b;
}

static double get(void *p, int type, int i) {
  switch (type) {
    case SHM_F64: return ((double *)p)[i];
    case SHM_F32: return ((float *)p)[i];
    case SHM_I32: return ((int32_t *)p)[i];
    case SHM_U32: return ((uint32_t *)p)[i];
    case SHM_U8: return ((uint8_t *)p)[i];
    default: return 0.0 / 0.0;
  }
}

static void put(void *p, int type, int i, double v) {
  switch (type) {
    case SHM_F64: ((double *)p)[i] = v; break;
    case SHM_F32: ((float *)p)[i] = (float)v; break;
    case SHM_I32: ((int32_t *)p)[i] = (int32_t)v; break;
    case SHM_U32: ((uint32_t *)p)[i] = (uint32_t)v; break;
    case SHM_U8: ((uint8_t *)p)[i] = (uint8_t)v; break;
    default: break;
  }
}

int main(int argc, char **argv) {
  if (argc < 3) {
    fprintf(stderr, "usage: shm_c_peer write|read|stream|check BLOCK ...\n");
    return 2;
  }
  shm_block *b = open_block(argv[2]);
  if (strcmp(argv[1], "write") == 0 || strcmp(argv[1], "read") == 0) {
    if (argc < 4) return 2;
    int type = 0, count = 0;
    void *p = shm_field_ptr(b, argv[3], &type, &count);
    if (!p) { fprintf(stderr, "shm_c_peer: block '%s' has no field '%s'\n", argv[2], argv[3]); return 2; }
    if (argv[1][0] == 'w') {
      shm_write_begin(b);
      for (int i = 0; i + 4 < argc && i < count; i++) put(p, type, i, strtod(argv[i + 4], NULL));
      shm_write_end(b);
    } else {
      uint32_t seq;
      double v[4096];
      int n = count < 4096 ? count : 4096;
      do {
        seq = shm_read_begin(b);
        for (int i = 0; i < n; i++) v[i] = get(p, type, i);
      } while (shm_read_retry(b, seq));
      for (int i = 0; i < n; i++) printf(i ? " %.17g" : "%.17g", v[i]);
      printf("\n");
    }
    return 0;
  }
  char err[512];
  double *gyro = shm_field_require(b, "gyro", SHM_F64, 3, err, sizeof err);
  uint32_t *tick = shm_field_require(b, "tick", SHM_U32, 1, err, sizeof err);
  if (!gyro || !tick) { fprintf(stderr, "shm_c_peer: %s\n", err); return 2; }
  if (strcmp(argv[1], "stream") == 0) {
    long n = argc > 3 ? atol(argv[3]) : 100000;
    for (long k = 1; k <= n; k++) {
      shm_write_begin(b);
      gyro[0] = (double)k; gyro[1] = 2.0 * (double)k; gyro[2] = 3.0 * (double)k;
      *tick = (uint32_t)k;
      shm_write_end(b);
    }
    return 0;
  }
  if (strcmp(argv[1], "check") == 0) {
    double until = shm_now() + (argc > 3 ? atof(argv[3]) : 1.0);
    long reads = 0, torn = 0;
    while (shm_now() < until) {
      double g[3]; uint32_t t; uint32_t seq;
      do {
        seq = shm_read_begin(b);
        g[0] = gyro[0]; g[1] = gyro[1]; g[2] = gyro[2]; t = *tick;
      } while (shm_read_retry(b, seq));
      reads++;
      if (g[1] != 2.0 * g[0] || g[2] != 3.0 * g[0] || (double)t != g[0]) torn++;
    }
    printf("reads %ld torn %ld\n", reads, torn);
    return torn ? 1 : 0;
  }
  fprintf(stderr, "shm_c_peer: unknown mode '%s'\n", argv[1]);
  return 2;
}
