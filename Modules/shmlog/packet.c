/* packet: one UDP datagram a robot process read (a GameController packet, a team message) as the
 * message hrp/msg/Packet in CDR, the bytes untouched: a log keeps what arrived, not what was made of it. */
#include "shmlog.h"

#include <string.h>

const char SHMLOG_PACKET_TYPE[] = "hrp/msg/Packet";
const char SHMLOG_PACKET_DEF[] =
    "float64 time\n"     /* s, robot clock when the process read it */
    "string source\n"    /* "gamecontroller", "team" */
    "string host\n"      /* the sender, dotted quad */
    "uint16 port\n"      /* the sender's port */
    "uint8[] data\n";

static size_t align(size_t n, size_t a) { return (n + a - 1) & ~(a - 1); }

/* a CDR string: u32 length with the NUL, the bytes, the NUL */
static size_t put_str(uint8_t *b, size_t at, const char *s) {
  const size_t a = align(at, 4);
  memset(b + at, 0, a - at);
  const uint32_t n = (uint32_t)strlen(s) + 1;
  memcpy(b + a, &n, 4);
  memcpy(b + a + 4, s, n);
  return a + 4 + n;
}

size_t shmlog_packet_encode(double time, const char *source, const char *host, uint16_t port, const uint8_t *data,
                            size_t len, uint8_t *out, size_t cap) {
  const size_t need = 4 + 8 + 3 + 4 + strlen(source) + 1 + 3 + 4 + strlen(host) + 1 + 1 + 2 + 3 + 4 + len;
  if (need > cap) return 0;
  static const uint8_t header[4] = { 0x00, 0x01, 0x00, 0x00 };   /* CDR, little endian */
  memcpy(out, header, 4);
  uint8_t *b = out + 4;   /* alignment counts from here */
  memcpy(b, &time, 8);
  size_t at = put_str(b, 8, source);
  at = put_str(b, at, host);
  size_t a = align(at, 2);
  memset(b + at, 0, a - at);
  memcpy(b + a, &port, 2);
  at = a + 2;
  a = align(at, 4);
  memset(b + at, 0, a - at);
  const uint32_t n = (uint32_t)len;
  memcpy(b + a, &n, 4);
  memcpy(b + a + 4, data, len);
  return 4 + a + 4 + len;
}
