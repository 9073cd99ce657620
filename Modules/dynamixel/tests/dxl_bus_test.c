/* The instruction layer over a real serial port (a pseudo-terminal) against a scripted peer:
 * ping/read/write, sync write, bulk read (1.0), sync read (2.0); corrupt, misaddressed,
 * out-of-order and missing answers are counted and skipped; a lost port is reported. */
#include "dynamixel/dynamixel.h"
#include "tap.h"

#include <pthread.h>
#include <pty.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

/* ---- scripted peer: answers each instruction with the next scripted byte string */
#define MAXSCRIPT 16
static struct { uint8_t bytes[512]; int len; } script[MAXSCRIPT];
static int nscript, script_pos, peer_protocol = 1;
static uint8_t last_inst[DXL_MAX_PACKET];
static int last_inst_len;
static pthread_mutex_t mu = PTHREAD_MUTEX_INITIALIZER;
static int master_fd;

static void *peer(void *arg) {
  (void)arg;
  uint8_t buf[4096];
  size_t len = 0;
  static dxl_packet pk;
  for (;;) {
    ssize_t r = read(master_fd, buf + len, sizeof buf - len);
    if (r <= 0) return NULL;
    len += (size_t)r;
    for (;;) {
      size_t used;
      pthread_mutex_lock(&mu);
      int proto = peer_protocol;
      pthread_mutex_unlock(&mu);
      int p = dxl_parse(proto, 0, buf, len, 0, &pk, &used);
      if (p == 1) {
        pthread_mutex_lock(&mu);
        memcpy(last_inst, buf, used);
        last_inst_len = (int)used;
        int k = script_pos < nscript ? script_pos++ : -1;
        pthread_mutex_unlock(&mu);
        if (k >= 0 && script[k].len > 0 && write(master_fd, script[k].bytes, (size_t)script[k].len) < 0)
          return NULL;
      }
      if (used) { memmove(buf, buf + used, len - used); len -= used; }
      if (p != 1 && p >= 0) break;
    }
  }
}

/* script helpers: a step is the concatenation of status packets */
static void script_reset(int protocol) {
  pthread_mutex_lock(&mu);
  nscript = script_pos = 0;
  peer_protocol = protocol;
  pthread_mutex_unlock(&mu);
}
static int step(void) {
  pthread_mutex_lock(&mu);
  int k = nscript++;
  script[k].len = 0;
  pthread_mutex_unlock(&mu);
  return k;
}
static void add_status(int k, int protocol, uint8_t id, uint8_t err, const uint8_t *d, size_t n,
                       int corrupt) {
  pthread_mutex_lock(&mu);
  int len = dxl_build_status(protocol, id, err, d, n, script[k].bytes + script[k].len,
                             sizeof script[k].bytes - (size_t)script[k].len);
  if (corrupt) script[k].bytes[script[k].len + len - 2] ^= 0x5A;
  script[k].len += len;
  pthread_mutex_unlock(&mu);
}
static void add_raw(int k, const uint8_t *d, size_t n) {
  pthread_mutex_lock(&mu);
  memcpy(script[k].bytes + script[k].len, d, n);
  script[k].len += (int)n;
  pthread_mutex_unlock(&mu);
}

int main(void) {
  int slave;
  char name[256];
  if (openpty(&master_fd, &slave, name, NULL, NULL) != 0) { perror("openpty"); return 1; }
  struct termios t;
  tcgetattr(slave, &t); cfmakeraw(&t); tcsetattr(slave, TCSANOW, &t);
  pthread_t th;
  pthread_create(&th, NULL, peer, NULL);

  char err[256] = "";
  dxl_port *port = NULL;
  int rc = dxl_port_open(name, 1000000, &port, err, sizeof err);
  check(rc == 0, "open a pty at 1 Mbps");
  if (rc) { printf("# %s\n", err); return tap_done(); }
  check(dxl_port_set_baud(port, 4500000, err, sizeof err) == 0 && dxl_port_baud(port) == 4500000,
         "custom rate 4.5 Mbps accepted (termios2)");
  dxl_port_set_baud(port, 1000000, err, sizeof err);
  check(dxl_port_byte_time(port) > 9.9e-6 && dxl_port_byte_time(port) < 10.1e-6,
         "10 microseconds per byte at 1 Mbps");

  dxl_bus bus;
  dxl_bus_init(&bus, port, 1);
  bus.timeout_margin = 0.2;   /* a loaded test machine may be slow to schedule the peer */
  uint8_t err8 = 0;
  /* ---- ping (1.0: ping, then read of the model number) */
  script_reset(1);
  add_status(step(), 1, 7, 0, NULL, 0, 0);
  add_status(step(), 1, 7, 0, (const uint8_t[]){ 29, 0 }, 2, 0);
  uint16_t model = 0;
  rc = dxl_ping(&bus, 7, &model, NULL, &err8);
  check(rc == 0 && model == 29, "1.0 ping reads the model number (MX-28: 29)");

  /* ---- read with error bits */
  script_reset(1);
  add_status(step(), 1, 7, DXL1_ERR_OVERLOAD, (const uint8_t[]){ 0x34, 0x12 }, 2, 0);
  uint8_t d[8] = { 0 };
  rc = dxl_read(&bus, 7, 36, 2, d, &err8);
  check(rc == 0 && dxl_get16(d) == 0x1234 && err8 == DXL1_ERR_OVERLOAD &&
         bus.stats.status_errors == 1, "1.0 read returns data and error bits");
  check_bytes(last_inst, last_inst_len, (const uint8_t[]){ 0xFF, 0xFF, 7, 4, 2, 36, 2, 0xCC }, 8,
            "1.0 read instruction on the wire");

  /* ---- corrupt answer, then nothing: timeout */
  script_reset(1);
  add_status(step(), 1, 7, 0, (const uint8_t[]){ 1, 2 }, 2, 1);
  uint64_t c0 = bus.stats.corrupt, t0 = bus.stats.timeouts;
  rc = dxl_read(&bus, 7, 36, 2, d, &err8);
  check(rc == DXL_COMM_RX_TIMEOUT && bus.stats.corrupt == c0 + 1 && bus.stats.timeouts == t0 + 1,
         "corrupt answer counted and skipped, read times out");

  /* ---- no answer at all */
  script_reset(1);
  step();
  rc = dxl_read(&bus, 7, 36, 2, d, &err8);
  check(rc == DXL_COMM_RX_TIMEOUT, "missing servo times out");

  /* ---- write waits for the status */
  script_reset(1);
  add_status(step(), 1, 7, 0, NULL, 0, 0);
  rc = dxl_write(&bus, 7, 30, (const uint8_t[]){ 0x00, 0x08 }, 2, &err8);
  check(rc == 0, "1.0 write acknowledged");

  /* ---- sync write: one broadcast packet, no answer */
  script_reset(1);
  step();
  const uint8_t ids[3] = { 1, 2, 3 };
  const uint8_t gp[6] = { 0x00, 0x08, 0x10, 0x08, 0x20, 0x08 };
  rc = dxl_sync_write(&bus, 30, 2, ids, 3, gp);
  usleep(20000);
  check_bytes(last_inst, last_inst_len,
            (const uint8_t[]){ 0xFF, 0xFF, 0xFE, 0x0D, 0x83, 30, 2, 1, 0x00, 0x08, 2, 0x10, 0x08, 3,
                               0x20, 0x08, 0x03 }, 17, "1.0 sync write on the wire");

  /* ---- bulk read: 2 answers before 1 (1 counted missing), a misaddressed id 9,
   *      a corrupt copy of 3, then a good 3 */
  script_reset(1);
  int k = step();
  add_status(k, 1, 2, 0, (const uint8_t[]){ 0x22, 0x02 }, 2, 0);
  add_status(k, 1, 9, 0, (const uint8_t[]){ 0x99, 0x09 }, 2, 0);
  add_status(k, 1, 3, 0, (const uint8_t[]){ 0x33, 0x03, 0, 0 }, 4, 1);
  add_raw(k, (const uint8_t[]){ 0x00, 0x13, 0xFF }, 3);
  add_status(k, 1, 3, 0, (const uint8_t[]){ 0x33, 0x03, 0x44, 0x04 }, 4, 0);
  uint8_t o1[2] = { 0 }, o2[2] = { 0 }, o3[4] = { 0 };
  dxl_bulk_item items[3] = { { 1, 36, 2, o1, 0, 0 }, { 2, 36, 2, o2, 0, 0 }, { 3, 36, 4, o3, 0, 0 } };
  dxl_bus_stats s0 = bus.stats;
  rc = dxl_bulk_read(&bus, items, 3);
  check(rc == 2 && items[0].result == DXL_COMM_RX_TIMEOUT && items[1].result == 0 &&
         items[2].result == 0 && dxl_get16(o2) == 0x0222 && dxl_get32(o3) == 0x04440333,
         "1.0 bulk read: answers matched by id, a skipped id marked missing");
  check(bus.stats.misaddressed == s0.misaddressed + 1 && bus.stats.corrupt == s0.corrupt + 1 &&
         bus.stats.timeouts == s0.timeouts + 1, "misaddressed, corrupt and missing counted");

  /* ---- out of order: 1, 1 again, 3, 2 (late) */
  script_reset(1);
  k = step();
  add_status(k, 1, 1, 0, (const uint8_t[]){ 1, 0 }, 2, 0);
  add_status(k, 1, 1, 0, (const uint8_t[]){ 1, 0 }, 2, 0);
  add_status(k, 1, 3, 0, (const uint8_t[]){ 3, 0, 0, 0 }, 4, 0);
  add_status(k, 1, 2, 0, (const uint8_t[]){ 2, 0 }, 2, 0);
  s0 = bus.stats;
  rc = dxl_bulk_read(&bus, items, 3);
  check(rc == 2 && items[1].result == DXL_COMM_RX_TIMEOUT &&
         bus.stats.out_of_order == s0.out_of_order + 1,
         "duplicate answer counted as out of order and skipped");

  /* ---- protocol 2.0: ping, sync read with stuffed data and an alert bit */
  dxl_bus_init(&bus, port, 2);
  bus.timeout_margin = 0.2;
  script_reset(2);
  add_status(step(), 2, 1, 0, (const uint8_t[]){ 0xFC, 0x03, 45 }, 3, 0);
  uint8_t fw = 0;
  rc = dxl_ping(&bus, 1, &model, &fw, &err8);
  check(rc == 0 && model == 1020 && fw == 45, "2.0 ping: model 1020 (XM430-W350), firmware");
  script_reset(2);
  k = step();
  add_status(k, 2, 1, 0, (const uint8_t[]){ 0xFF, 0xFF, 0xFD, 0x01 }, 4, 0);
  add_status(k, 2, 2, DXL2_ERR_ALERT, (const uint8_t[]){ 0x00, 0x08, 0x00, 0x00 }, 4, 0);
  uint8_t p1[4], p2[4];
  dxl_bulk_item sr[2] = { { 1, 0, 0, p1, 0, 0 }, { 2, 0, 0, p2, 0, 0 } };
  rc = dxl_sync_read(&bus, 132, 4, sr, 2);
  check(rc == 2 && dxl_get32(p1) == 0x01FDFFFF && dxl_get32(p2) == 0x800 &&
         sr[1].error == DXL2_ERR_ALERT, "2.0 sync read: stuffed data and alert bit");
  check_bytes(last_inst, last_inst_len,
            (const uint8_t[]){ 0xFF, 0xFF, 0xFD, 0x00, 0xFE, 0x09, 0x00, 0x82, 0x84, 0x00, 0x04,
                               0x00, 0x01, 0x02, 0xCE, 0xFA }, 16,
            "2.0 sync read on the wire (e-Manual example)");
  script_reset(2);
  k = step();
  add_status(k, 2, 1, 0, (const uint8_t[]){ 1, 2 }, 2, 0);
  add_status(k, 2, 200, 0, (const uint8_t[]){ 1, 2, 3, 4, 5, 6 }, 6, 0);
  uint8_t b1[2], b2[6];
  dxl_bulk_item br[2] = { { 1, 132, 2, b1, 0, 0 }, { 200, 30, 6, b2, 0, 0 } };
  rc = dxl_bulk_read(&bus, br, 2);
  check(rc == 2 && b2[5] == 6, "2.0 bulk read of two lengths");
  dxl_bus_init(&bus, port, 1);
  check(dxl_sync_read(&bus, 132, 4, sr, 2) == DXL_COMM_NOT_AVAILABLE, "1.0 has no sync read");

  /* ---- the port disappears */
  dxl_bus_init(&bus, port, 1);
  pthread_cancel(th);
  pthread_join(th, NULL);
  close(master_fd);
  rc = dxl_read(&bus, 7, 36, 2, d, &err8);
  check(rc < 0 && !dxl_port_is_open(port) && bus.stats.port_errors >= 1,
         "a lost port is reported and closed");
  close(slave);
  check(dxl_port_reopen(port, err, sizeof err) < 0 && strlen(err) > 0,
         "reopening a vanished port fails with a message");
  dxl_port_close(port);

  /* ---- USB look-up works with or without devices */
  dxl_usb_info usb[4];
  int nu = dxl_usb_find(usb, 4, err, sizeof err);
  printf("# USB adapters found: %d\n", nu);
  check(nu >= 0, "USB adapter look-up returns cleanly");
  return tap_done();
}
