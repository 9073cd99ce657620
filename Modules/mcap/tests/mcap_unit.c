/* mcap_unit: a file written by the writer reads back whole through the reader; a truncated copy
 * reads up to the damage and says where; a flipped byte inside a chunk is reported as corrupt. */
#include "mcap/mcap.h"
#include "tap.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define NMSG 5000

static long file_size(const char *path) {
  FILE *f = fopen(path, "rb");
  if (!f) return -1;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fclose(f);
  return n;
}

static void copy_prefix(const char *from, const char *to, long n, long flip) {
  FILE *a = fopen(from, "rb"), *b = fopen(to, "wb");
  for (long i = 0; i < n; i++) {
    int c = fgetc(a);
    if (i == flip) c ^= 0x5a;
    fputc(c, b);
  }
  fclose(a);
  fclose(b);
}

/* Reads every message; returns how many had the payload written for their index; rc: last result. */
static int read_all(const char *path, int *rc, char *why, size_t whylen) {
  mcap_reader *r;
  char err[256];
  if (mcap_reader_open(path, &r, err, sizeof err) < 0) {
    snprintf(why, whylen, "%s", err);
    *rc = -1;
    return 0;
  }
  mcap_message m;
  int good = 0;
  while ((*rc = mcap_reader_next(r, &m)) > 0) {
    uint32_t v;
    memcpy(&v, m.data, 4);
    if (m.len == 64 && v == m.sequence && m.log_time == 1000ull * m.sequence && m.channel == (int)(m.sequence % 2))
      good++;
  }
  snprintf(why, whylen, "%s", mcap_reader_error(r));
  mcap_reader_close(r);
  return good;
}

int main(void) {
  char path[64], cut[64], err[256];
  snprintf(path, sizeof path, "/tmp/mcap_unit.%d.mcap", (int)getpid());
  snprintf(cut, sizeof cut, "/tmp/mcap_unit.%d.cut.mcap", (int)getpid());

  mcap_writer *w;
  check(mcap_writer_open(path, "", 1, 16384, &w, err, sizeof err) == 0, "writer opens");
  const char *schema = "uint32 v\nuint8[60] pad\n";
  const int s = mcap_writer_schema(w, "test/msg/Thing", "ros2msg", schema, strlen(schema));
  const char *meta[] = { "k", "v" };
  const int c0 = mcap_writer_channel(w, s, "/a", "cdr", meta, 1);
  const int c1 = mcap_writer_channel(w, s, "/b", "cdr", NULL, 0);
  check(s == 1 && c0 == 0 && c1 == 1, "ids: schema 1, channels 0 and 1");
  check(mcap_writer_attachment(w, "config/x.json", "application/json", 0, "{\"a\":1}", 7) == 0, "attachment");
  for (uint32_t i = 0; i < NMSG; i++) {
    uint8_t buf[64] = { 0 };
    memcpy(buf, &i, 4);
    mcap_writer_message(w, (int)(i % 2), i, 1000ull * i, 1000ull * i, buf, sizeof buf);
  }
  check(mcap_writer_close(w, err, sizeof err) == 0, "writer closes");

  int rc;
  char why[512];
  int good = read_all(path, &rc, why, sizeof why);
  tap_ok(good == NMSG && rc == 0, "every message reads back in order", why);

  mcap_reader *r;
  mcap_reader_open(path, &r, err, sizeof err);
  check(mcap_reader_scan_channels(r) == 2, "channels found before the first message");
  const mcap_channel_info *ci = mcap_reader_channel(r, 1);
  const mcap_schema_info *si = mcap_reader_schema(r, 1);
  check(ci && strcmp(ci->topic, "/b") == 0 && si && si->len == strlen(schema) && !memcmp(si->data, schema, si->len),
        "channel and schema records read back");
  size_t alen = 0;
  const uint8_t *a = mcap_reader_attachment(r, "config/x.json", &alen);
  check(a && alen == 7 && !memcmp(a, "{\"a\":1}", 7), "attachment found by name");
  mcap_reader_close(r);

  const long size = file_size(path);
  copy_prefix(path, cut, size * 2 / 3, -1);
  good = read_all(cut, &rc, why, sizeof why);
  tap_ok(rc < 0 && good > NMSG / 3 && good < NMSG && strstr(why, "truncated"),
         "a truncated file reads up to the damage, which is reported", why);

  copy_prefix(path, cut, size, size / 2);
  good = read_all(cut, &rc, why, sizeof why);
  tap_ok(rc < 0 && good > 0 && good < NMSG && strstr(why, "chunk"), "a corrupt chunk is reported", why);

  check(mcap_reader_open("/nonexistent/x.mcap", &r, err, sizeof err) < 0 && strstr(err, "/nonexistent/x.mcap"),
        "a missing file is an error naming it");
  unlink(path);
  unlink(cut);
  return tap_done();
}
