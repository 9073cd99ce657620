/* hubo_io: SocketCAN raw sockets of the Hubo buses. */
#include "hubo_io.h"

#include <errno.h>
#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

hio_sys hio_sys_calls = HIO_SYS_LIBC;

double hio_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + ts.tv_nsec * 1e-9;
}

void hio_init(hio_bus *b, const char *iface) {
  memset(b, 0, sizeof *b);
  snprintf(b->iface, sizeof b->iface, "%s", iface);
  b->fd = -1;
  hcan_net_init(&b->net);
}

int hio_open(hio_bus *b, char *err, size_t n) {
  if (strlen(b->iface) >= IFNAMSIZ) {
    snprintf(err, n, "%s: an interface name has at most %d characters", b->iface, IFNAMSIZ - 1);
    return -EINVAL;
  }
  const int s = hio_sys_calls.socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
  if (s < 0) {
    const int e = errno;
    snprintf(err, n, "%s: socket(PF_CAN, SOCK_RAW, CAN_RAW): %s", b->iface, strerror(e));
    return -e;
  }
  struct ifreq ifr;
  memset(&ifr, 0, sizeof ifr);
  memcpy(ifr.ifr_name, b->iface, strlen(b->iface) + 1);
  struct sockaddr_can a = { .can_family = AF_CAN };
  int e = 0;
  if (hio_sys_calls.ioctl(s, SIOCGIFINDEX, &ifr) < 0) e = errno;
  if (!e) {
    a.can_ifindex = ifr.ifr_ifindex;
    if (hio_sys_calls.bind(s, (struct sockaddr *)&a, sizeof a) < 0) e = errno;
  }
  /* only the boards' replies: sensor replies 0x040..0x05F, encoders 0x060..0x08F (power 0x06E),
   * status 0x150..0x17F, current 0x1C0..0x1EF; standard frames only */
  const canid_t x = CAN_EFF_FLAG | CAN_RTR_FLAG;
  struct can_filter flt[] = {
    { 0x040, 0x7E0 | x }, { 0x060, 0x7E0 | x }, { 0x080, 0x7F0 | x },
    { 0x150, 0x7F0 | x }, { 0x160, 0x7E0 | x }, { 0x1C0, 0x7E0 | x }, { 0x1E0, 0x7F0 | x },
  };
  if (!e && hio_sys_calls.setsockopt(s, SOL_CAN_RAW, CAN_RAW_FILTER, flt, sizeof flt) < 0) e = errno;
  /* the controller's error frames: bus errors are counted, bus-off / restarts noticed */
  const can_err_mask_t em = CAN_ERR_TX_TIMEOUT | CAN_ERR_CRTL | CAN_ERR_PROT | CAN_ERR_BUSOFF | CAN_ERR_BUSERROR |
                            CAN_ERR_RESTARTED;
  if (!e && hio_sys_calls.setsockopt(s, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &em, sizeof em) < 0) e = errno;
  if (e) {
    snprintf(err, n, "%s: %s", b->iface, strerror(e));
    hio_sys_calls.close(s);
    return -e;
  }
  b->fd = s;
  b->txn = b->txhead = 0;
  return 0;
}

void hio_close(hio_bus *b) {
  if (b->fd >= 0) hio_sys_calls.close(b->fd);
  b->fd = -1;
  b->txn = b->txhead = 0;
}

void hio_queue(hio_bus *b, const hcan_frame *f) {
  if (b->fd < 0) return;
  if (b->txn >= HIO_TXQ) {
    b->tx_dropped++;
    return;
  }
  b->txq[(b->txhead + b->txn) % HIO_TXQ] = *f;
  b->txn++;
}

static int gone(int e) { return e == ENETDOWN || e == ENODEV || e == ENXIO || e == EBADF || e == ENETUNREACH; }

int hio_flush(hio_bus *b) {
  while (b->fd >= 0 && b->txn > 0) {
    const hcan_frame *f = &b->txq[b->txhead];
    struct can_frame c;
    memset(&c, 0, sizeof c);
    c.can_id = f->id;
    c.can_dlc = f->dlc;
    memcpy(c.data, f->data, 8);
    if (hio_sys_calls.write(b->fd, &c, sizeof c) != (ssize_t)sizeof c) {
      const int e = errno;
      if (e == ENOBUFS || e == EAGAIN || e == EINTR) return 0;   /* the kernel's queue is full: later */
      if (gone(e)) return -e;
      b->tx_dropped++;   /* a frame the driver refuses: skipped, the others go on */
    } else {
      b->tx_frames++;
      b->tx_bits += (uint64_t)hcan_frame_bits(f);
    }
    b->txhead = (b->txhead + 1) % HIO_TXQ;
    b->txn--;
  }
  return 0;
}

int hio_receive(hio_bus *b) {
  int got = 0;
  struct can_frame c;
  while (b->fd >= 0) {
    const ssize_t r = hio_sys_calls.read(b->fd, &c, sizeof c);
    if (r < 0) {
      const int e = errno;
      if (e == EAGAIN || e == EINTR) break;
      return gone(e) ? -e : got;
    }
    hcan_frame f = { .id = c.can_id, .dlc = c.can_dlc };
    memcpy(f.data, c.data, 8);
    b->rx_frames++;
    if (!(f.id & HCAN_ERR)) b->rx_bits += (uint64_t)hcan_frame_bits(&f);
    hcan_net_rx(&b->net, &f);
    got++;
  }
  return got;
}

static int owed(const hio_bus *b) {
  for (int i = 0; i < b->net.n; i++)
    if (b->net.b[i].owed) return 1;
  return 0;
}

int hio_settle(hio_bus *buses, int n, double deadline) {
  int failed = 0;
  for (;;) {
    struct pollfd pf[8];
    int np = 0, busy = 0;
    for (int k = 0; k < n && k < 8; k++) {
      hio_bus *b = &buses[k];
      if (b->fd < 0) continue;
      if (hio_flush(b) < 0 || hio_receive(b) < 0) {
        hio_close(b);
        b->downs++;
        failed++;
        continue;
      }
      const int want_out = b->txn > 0, want_in = owed(b);
      busy |= want_out || want_in;
      pf[np++] = (struct pollfd){ .fd = b->fd, .events = (short)((want_in || want_out ? POLLIN : 0) | (want_out ? POLLOUT : 0)) };
    }
    const double left = deadline - hio_now();
    if (!busy || left <= 0) return failed;
    struct timespec ts = { (time_t)left, (long)((left - (double)(time_t)left) * 1e9) };
    if (hio_sys_calls.ppoll(pf, (nfds_t)np, &ts, NULL) < 0 && errno != EINTR) return failed;
  }
}
