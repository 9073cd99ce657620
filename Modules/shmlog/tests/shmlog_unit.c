/* shmlog_unit: a block's generated definition parses back to the same fields, CDR round-trips every
 * value bit for bit, a changed layout is named, and a compressed frame round-trips. */
#include "shmlog/shmlog.h"
#include "tap.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *SCHEMA =
    "const n 3\n"
    "block t.rec\n"
    "  f64 time 1\n"
    "  u32 tick 1\n"
    "  f64 position n\n"
    "  u8 name 5\n"
    "  i16 small 3\n"
    "  f32 gain 2\n"
    "  u8 big 100\n";

int main(void) {
  char path[64], err[256], msg[256];
  snprintf(path, sizeof path, "/tmp/shmlog_unit.%d.schema", (int)getpid());
  FILE *f = fopen(path, "w");
  fputs(SCHEMA, f);
  fclose(f);
  shm_schema *s;
  shm_block *b;
  const int id = shm_robot_id();
  check(shm_schema_load(path, &s, err, sizeof err) == 0, "schema loads");
  check(shm_block_open(s, "t.rec", id, SHM_OPEN_CREATE, &b, err, sizeof err) == 0, "block opens");

  const char *skip[] = { "big" };
  static shmlog_block lb, parsed, other;
  check(shmlog_from_block(b, skip, 1, &lb, err, sizeof err) == 0, "message of the block");
  tap_ok(strcmp(lb.type_name, "hrp/msg/TRec") == 0 && strcmp(lb.topic, "/t.rec") == 0, "type and topic names",
         lb.type_name);
  tap_ok(strstr(lb.def, "float64[3] position\n") && strstr(lb.def, "uint32 tick\n") && !strstr(lb.def, "big"),
         "definition lists the fields, the skipped one left out", NULL);
  /* CDR: time 0..8, tick 8..12, position 16..40, name 40..45, small 46..52, gain 52..60 */
  tap_ok(lb.cdr_size == 4 + 60, "CDR size with alignment", NULL);

  double *time = (double *)shm_field_ptr(b, "time", NULL, NULL);
  double *pos = (double *)shm_field_ptr(b, "position", NULL, NULL);
  uint32_t *tick = (uint32_t *)shm_field_ptr(b, "tick", NULL, NULL);
  uint8_t *name = (uint8_t *)shm_field_ptr(b, "name", NULL, NULL);
  int16_t *small = (int16_t *)shm_field_ptr(b, "small", NULL, NULL);
  float *gain = (float *)shm_field_ptr(b, "gain", NULL, NULL);
  *time = 12.345678901234567;
  *tick = 4000000001u;
  pos[0] = -1.5; pos[1] = NAN; pos[2] = 1e-300;
  memcpy(name, "hello", 5);
  small[0] = -7; small[1] = 300; small[2] = -32768;
  gain[0] = 0.1f; gain[1] = -INFINITY;

  const shm_header *h = shm_block_header(b);
  uint8_t *copy = calloc(1, h->total_size), *enc = malloc(lb.cdr_size);
  shmlog_encode(&lb, (const uint8_t *)h, enc);
  check(shmlog_decode(&lb, enc, lb.cdr_size, copy) == 0, "decodes");
  int same = 1;
  for (int i = 0; i < lb.nfields; i++) {
    const shmlog_field *g = &lb.field[i];
    size_t n = (size_t)g->count * (g->type == 1 ? 8 : g->type == 7 ? 1 : g->type == 8 ? 2 : 4);
    same &= memcmp(copy + g->shm_offset, (const uint8_t *)h + g->shm_offset, n) == 0;
  }
  check(same, "every value round-trips bit for bit (NaN, -inf, 1e-300, a u32 above 2^31)");
  check(shmlog_decode(&lb, enc, lb.cdr_size - 1, copy) < 0, "a message of the wrong size is refused");
  /* NaN payloads from a log (signalling, with bits set) come out as the one quiet NaN */
  {
    const uint64_t snan64 = 0x7ff0000000000001ull;
    const uint32_t snan32 = 0xff900001u;
    memcpy(enc + 4 + 16 + 8, &snan64, 8); /* position[1] */
    memcpy(enc + 4 + 52 + 4, &snan32, 4); /* gain[1] */
    check(shmlog_decode(&lb, enc, lb.cdr_size, copy) == 0, "decodes a message with NaN payloads");
    double quiet64 = NAN, got64;
    float quiet32 = NAN, got32;
    memcpy(&got64, copy + lb.field[2].shm_offset + 8, 8);
    memcpy(&got32, copy + lb.field[5].shm_offset + 4, 4);
    check(memcmp(&got64, &quiet64, 8) == 0 && memcmp(&got32, &quiet32, 4) == 0,
          "NaN payloads in float64 and float32 fields become the quiet NaN");
  }

  check(shmlog_parse("t.rec", lb.def, strlen(lb.def), &parsed, err, sizeof err) == 0, "definition parses back");
  check(shmlog_diff(&parsed, &lb, msg, sizeof msg) == 0 && parsed.cdr_size == lb.cdr_size, "no difference");
  const char *changed = "float64 time\nuint32 tick\nfloat64[2] position\nuint8[5] name\nint16[3] small\nfloat32[2] gain\n";
  shmlog_parse("t.rec", changed, strlen(changed), &other, err, sizeof err);
  tap_ok(shmlog_diff(&other, &lb, msg, sizeof msg) == 1 && strstr(msg, "'position' is float64[2] in the log but float64[3]"),
         "a changed count is named", msg);
  const char *missing = "float64 time\nuint32 tick\nfloat64[3] position\nuint8[5] name\nint16[3] small\n";
  shmlog_parse("t.rec", missing, strlen(missing), &other, err, sizeof err);
  tap_ok(shmlog_diff(&other, &lb, msg, sizeof msg) == 1 && strstr(msg, "'gain'") && strstr(msg, "not in the log"),
         "a field the log lacks is named", msg);
  const char *bad = "float64 time\nquaternion q\n";
  tap_ok(shmlog_parse("t.rec", bad, strlen(bad), &other, err, sizeof err) < 0 && strstr(err, "line 2"),
         "a definition that is not of shm fields is refused naming the line", err);

  uint8_t frame[256], out[64];
  const uint8_t jpeg[5] = { 0xff, 0xd8, 1, 2, 3 };
  const size_t n = shmlog_image_encode(1500000000ull, "camera", "jpeg", jpeg, 5, frame, sizeof frame);
  const uint8_t *data;
  size_t dlen;
  char format[16];
  check(n > 0 && shmlog_image_decode(frame, n, format, sizeof format, &data, &dlen) == 0 &&
        strcmp(format, "jpeg") == 0 && dlen == 5 && memcmp(data, jpeg, 5) == 0, "compressed frame round-trips");
  check(shmlog_image_encode(0, "camera", "jpeg", jpeg, 5, out, 20) == 0, "a frame too large for the buffer: 0");

  free(copy);
  free(enc);
  shm_block_close(b);
  shm_block_unlink("t.rec", id);
  shm_schema_free(s);
  unlink(path);
  return tap_done();
}
