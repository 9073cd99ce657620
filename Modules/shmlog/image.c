/* image: the camera's compressed frame as sensor_msgs/msg/CompressedImage in CDR. */
#include "shmlog.h"

#include <errno.h>
#include <string.h>

const char SHMLOG_IMAGE_TYPE[] = "sensor_msgs/msg/CompressedImage";
const char SHMLOG_IMAGE_DEF[] =
    "std_msgs/Header header\n"
    "string format\n"
    "uint8[] data\n"
    "================================================================================\n"
    "MSG: std_msgs/Header\n"
    "builtin_interfaces/Time stamp\n"
    "string frame_id\n"
    "================================================================================\n"
    "MSG: builtin_interfaces/Time\n"
    "int32 sec\n"
    "uint32 nanosec\n";

static size_t align4(size_t n) { return (n + 3) & ~(size_t)3; }

static void put32(uint8_t *p, uint32_t v) { memcpy(p, &v, 4); }   /* little-endian hosts only */

/* a CDR string: u32 length with the NUL, the bytes, the NUL */
static size_t put_str(uint8_t *out, size_t at, const char *s) {
  at = align4(at);
  const size_t n = strlen(s) + 1;
  put32(out + at, (uint32_t)n);
  memcpy(out + at + 4, s, n);
  return at + 4 + n;
}

size_t shmlog_image_encode(uint64_t stamp_ns, const char *frame_id, const char *format, const uint8_t *data,
                           size_t len, uint8_t *out, size_t cap) {
  const size_t need = 4 + 8 + 4 + strlen(frame_id) + 1 + 3 + 4 + strlen(format) + 1 + 3 + 4 + len;
  if (need > cap) return 0;
  static const uint8_t header[4] = { 0x00, 0x01, 0x00, 0x00 };
  memcpy(out, header, 4);
  uint8_t *b = out + 4;   /* alignment counts from here */
  put32(b, (uint32_t)(stamp_ns / 1000000000u));
  put32(b + 4, (uint32_t)(stamp_ns % 1000000000u));
  size_t at = put_str(b, 8, frame_id);
  memset(b + at, 0, align4(at) - at);
  at = put_str(b, at, format);
  memset(b + at, 0, align4(at) - at);
  at = align4(at);
  put32(b + at, (uint32_t)len);
  memcpy(b + at + 4, data, len);
  return 4 + at + 4 + len;
}

/* a CDR string at *at of b (n bytes) */
static int get_str(const uint8_t *b, size_t n, size_t *at, char *out, size_t outlen) {
  *at = align4(*at);
  if (*at + 4 > n) return -EINVAL;
  uint32_t len;
  memcpy(&len, b + *at, 4);
  if (len < 1 || *at + 4 + len > n) return -EINVAL;
  if (out) {
    const size_t k = len - 1 < outlen - 1 ? len - 1 : outlen - 1;
    memcpy(out, b + *at + 4, k);
    out[k] = 0;
  }
  *at += 4 + len;
  return 0;
}

int shmlog_image_decode(const uint8_t *msg, size_t len, char *format, size_t formatlen, const uint8_t **data,
                        size_t *datalen) {
  if (len < 12 || msg[1] != 0x01) return -EINVAL;
  const uint8_t *b = msg + 4;
  const size_t n = len - 4;
  size_t at = 8;
  if (get_str(b, n, &at, NULL, 0) < 0 || get_str(b, n, &at, format, formatlen) < 0) return -EINVAL;
  at = align4(at);
  if (at + 4 > n) return -EINVAL;
  uint32_t dlen;
  memcpy(&dlen, b + at, 4);
  if (at + 4 + dlen > n) return -EINVAL;
  *data = b + at + 4;
  *datalen = dlen;
  return 0;
}
