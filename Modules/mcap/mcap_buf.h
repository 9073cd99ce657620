/* mcap_buf: a growable byte buffer with MCAP's little-endian field encoders (writer only). */
#ifndef HRP_MCAP_BUF_H
#define HRP_MCAP_BUF_H

#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct mcap_buf {
  uint8_t *p;
  size_t len, cap;
  int oom;          /* an allocation failed: the content is incomplete */
} mcap_buf;

static inline void mb_reserve(mcap_buf *b, size_t n) {
  if (b->len + n <= b->cap) return;
  size_t cap = b->cap ? b->cap : 4096;
  while (cap < b->len + n) cap *= 2;
  uint8_t *p = (uint8_t *)realloc(b->p, cap);
  if (!p) { b->oom = 1; return; }
  b->p = p;
  b->cap = cap;
}
static inline void mb_put(mcap_buf *b, const void *data, size_t n) {
  mb_reserve(b, n);
  if (b->oom) return;
  if (n) memcpy(b->p + b->len, data, n);
  b->len += n;
}
static inline void mb_u8(mcap_buf *b, uint8_t v) { mb_put(b, &v, 1); }
static inline void mb_u16(mcap_buf *b, uint16_t v) { uint8_t x[2] = { (uint8_t)v, (uint8_t)(v >> 8) }; mb_put(b, x, 2); }
static inline void mb_u32(mcap_buf *b, uint32_t v) {
  uint8_t x[4];
  for (int i = 0; i < 4; i++) x[i] = (uint8_t)(v >> (8 * i));
  mb_put(b, x, 4);
}
static inline void mb_u64(mcap_buf *b, uint64_t v) {
  uint8_t x[8];
  for (int i = 0; i < 8; i++) x[i] = (uint8_t)(v >> (8 * i));
  mb_put(b, x, 8);
}
/* string / bytes with a u32 length prefix */
static inline void mb_str(mcap_buf *b, const char *s) {
  const size_t n = s ? strlen(s) : 0;
  mb_u32(b, (uint32_t)n);
  mb_put(b, s, n);
}
static inline void mb_bytes32(mcap_buf *b, const void *d, size_t n) {
  mb_u32(b, (uint32_t)n);
  mb_put(b, d, n);
}
/* Map<string,string> with its u32 byte length */
static inline void mb_map(mcap_buf *b, const char *const *kv, int n) {
  size_t bytes = 0;
  for (int i = 0; i < 2 * n; i++) bytes += 4 + strlen(kv[i]);
  mb_u32(b, (uint32_t)bytes);
  for (int i = 0; i < 2 * n; i++) mb_str(b, kv[i]);
}
static inline void mb_free(mcap_buf *b) {
  free(b->p);
  b->p = NULL;
  b->len = b->cap = 0;
}

#endif
