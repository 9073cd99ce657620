/* fake_socketcan: SocketCAN raw sockets over a userspace bus, so the Hubo DCM and its emulator run on a
 * kernel without AF_CAN (this machine's). A program takes it through its system-call table
 * (fakecan_sys, in hio_sys.h's shape) in its own process: the test build of the DCM
 * (build/testbin/dcm_hubo_fakecan), the emulator with HUBO_FAKE_CAN=1, fakecan_test. It is compiled
 * like that program, so a sanitizer build instruments both. Calls on other descriptors go to libc.
 *
 * Served: socket(PF_CAN, SOCK_RAW, CAN_RAW) (SOCK_NONBLOCK / SOCK_CLOEXEC honoured), ioctl
 * SIOCGIFINDEX and FIONBIO, bind(struct sockaddr_can), setsockopt CAN_RAW_FILTER /
 * CAN_RAW_ERR_FILTER (CAN_RAW_LOOPBACK / CAN_RAW_RECV_OWN_MSGS accepted), read / write of struct
 * can_frame (16 bytes; anything else is EINVAL), ppoll, close. Not served: CAN FD.
 *
 * The bus: each bound socket is a named pipe $FAKECAN_DIR/<ifname>/<pid>.<fd> that its owner reads
 * (a pipe, not a unix datagram socket: those queue only net.unix.max_dgram_qlen = 10 datagrams,
 * fewer than one cycle's replies; a pipe holds 4096 frames, and 16-byte writes are atomic). A frame
 * written goes to every other socket bound to that interface (as SocketCAN's loopback delivers to
 * the host's other sockets, never to the sender), in this process or another. A receiver whose
 * queue is full loses the frame, as a socket's overflowing receive queue does. The fake ignores
 * SIGPIPE (a peer that died).
 * Filters apply on receipt, as the kernel's: a frame passes when (id & mask) == (filter id & mask)
 * for some filter (inverted with CAN_INV_FILTER); error frames (CAN_ERR_FLAG) pass only through the
 * error mask. ppoll drops frames no filter passes, so POLLIN means a frame read() will return.
 *
 * Environment: FAKECAN_DIR (default /tmp/fakecan.<uid>), FAKECAN_IFACES (default
 * "can0,can1,vcan0,vcan1": the interfaces that exist, index = position + 1). A file
 * $FAKECAN_DIR/<ifname>.down takes the interface down: writes fail with ENETDOWN, reads with
 * ENETDOWN, ppoll reports POLLERR (looked at every 20 ms), until the file is removed.
 * Single-threaded use (the DCM, the emulator).
 */
#include "fake_socketcan.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <linux/can.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define MAXFD 1024
#define MAXFILTER 64
#define MAXIF 16
#define MAXPEER 64
#define PATHMAX 300

typedef struct fake {
  int used, bound, nonblock;
  int ifindex;
  char path[PATHMAX];
  int nfilter;
  struct can_filter filter[MAXFILTER];
  can_err_mask_t err_mask;
  int held;                  /* a frame read ahead by poll, returned by the next read */
  struct can_frame hold;
  /* peers of the bound interface (their pipes open for writing), re-listed when the folder changes */
  struct timespec dir_mtime;
  int npeer;
  char peer[MAXPEER][PATHMAX];
  int peer_fd[MAXPEER];
  double down_checked;
  int down;
} fake;

static fake F[MAXFD];
static char dir[200];
static char ifname[MAXIF][IFNAMSIZ];
static int nif;
static int inited;

static void init(void) {
  if (inited) return;
  inited = 1;
  const char *d = getenv("FAKECAN_DIR");
  if (d && *d) snprintf(dir, sizeof dir, "%s", d);
  else snprintf(dir, sizeof dir, "/tmp/fakecan.%u", (unsigned)getuid());
  const char *l = getenv("FAKECAN_IFACES");
  char list[256];
  snprintf(list, sizeof list, "%s", l && *l ? l : "can0,can1,vcan0,vcan1");
  for (char *save = NULL, *t = strtok_r(list, ",", &save); t && nif < MAXIF; t = strtok_r(NULL, ",", &save))
    snprintf(ifname[nif++], IFNAMSIZ, "%s", t);
  struct sigaction sa;
  if (sigaction(SIGPIPE, NULL, &sa) == 0 && sa.sa_handler == SIG_DFL) signal(SIGPIPE, SIG_IGN);
}

static fake *get(int fd) {
  init();
  return fd >= 0 && fd < MAXFD && F[fd].used ? &F[fd] : NULL;
}

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static int is_down(fake *f) {
  if (!f->bound) return 0;
  const double t = now();
  if (t - f->down_checked > 0.02) {
    char p[PATHMAX];
    snprintf(p, sizeof p, "%s/%s.down", dir, ifname[f->ifindex - 1]);
    f->down = access(p, F_OK) == 0;
    f->down_checked = t;
  }
  return f->down;
}

static void drop_peers(fake *f) {
  for (int k = 0; k < f->npeer; k++)
    if (f->peer_fd[k] >= 0) close(f->peer_fd[k]);
  f->npeer = 0;
}

/* ---------------------------------------------------------------- socket, ioctl, bind, options */

static int fake_socket(int domain, int type, int protocol) {
  init();
  if (domain != PF_CAN) return socket(domain, type, protocol);
  if ((type & 0xFF) != SOCK_RAW || protocol != CAN_RAW) {
    errno = EPROTONOSUPPORT;
    return -1;
  }
  /* a placeholder until bind() puts the interface's pipe on this descriptor */
  const int fd = open("/dev/null", O_RDONLY | ((type & SOCK_CLOEXEC) ? O_CLOEXEC : 0));
  if (fd < 0) return fd;
  if (fd >= MAXFD) {
    close(fd);
    errno = EMFILE;
    return -1;
  }
  memset(&F[fd], 0, sizeof F[fd]);
  F[fd].used = 1;
  F[fd].nonblock = (type & SOCK_NONBLOCK) != 0;
  F[fd].nfilter = 1;   /* the default filter passes every frame */
  return fd;
}

static int index_of(const char *name) {
  for (int k = 0; k < nif; k++)
    if (!strncmp(ifname[k], name, IFNAMSIZ)) return k + 1;
  return 0;
}

static int fake_ioctl(int fd, unsigned long req, ...) {
  va_list ap;
  va_start(ap, req);
  void *arg = va_arg(ap, void *);
  va_end(ap);
  if (!get(fd)) return ioctl(fd, req, arg);
  if (req == FIONBIO) {   /* Python's settimeout, and others */
    F[fd].nonblock = *(int *)arg != 0;
    return F[fd].bound ? ioctl(fd, req, arg) : 0;
  }
  if (req != SIOCGIFINDEX) {
    errno = EINVAL;
    return -1;
  }
  struct ifreq *ifr = (struct ifreq *)arg;
  const int idx = index_of(ifr->ifr_name);
  if (!idx) {
    errno = ENODEV;
    return -1;
  }
  ifr->ifr_ifindex = idx;
  return 0;
}

static int fake_bind(int fd, const struct sockaddr *addr, socklen_t len) {
  fake *f = get(fd);
  if (!f) return bind(fd, addr, len);
  const struct sockaddr_can *a = (const struct sockaddr_can *)addr;
  if (!a || len < (socklen_t)sizeof *a || a->can_family != AF_CAN) {
    errno = EINVAL;
    return -1;
  }
  if (a->can_ifindex < 1 || a->can_ifindex > nif) {
    errno = a->can_ifindex == 0 ? EOPNOTSUPP : ENODEV;   /* "any interface" is not served */
    return -1;
  }
  if (f->bound) {
    errno = EINVAL;
    return -1;
  }
  char d[PATHMAX];
  mkdir(dir, 0700);
  snprintf(d, sizeof d, "%s/%s", dir, ifname[a->can_ifindex - 1]);
  mkdir(d, 0700);
  if (snprintf(f->path, sizeof f->path, "%s/%d.%d", d, (int)getpid(), fd) >= (int)sizeof f->path) {
    errno = ENAMETOOLONG;
    return -1;
  }
  unlink(f->path);
  if (mkfifo(f->path, 0600) < 0) return -1;
  /* read-write: the open never blocks and the pipe never reads end-of-file */
  const int p = open(f->path, O_RDWR | O_NONBLOCK);
  if (p < 0) return -1;
  if (!f->nonblock) fcntl(p, F_SETFL, fcntl(p, F_GETFL) & ~O_NONBLOCK);
  const int fdflags = fcntl(fd, F_GETFD);
  dup2(p, fd);
  close(p);
  fcntl(fd, F_SETFD, fdflags);
  f->ifindex = a->can_ifindex;
  f->bound = 1;
  f->dir_mtime.tv_sec = -1;
  return 0;
}

static int fake_setsockopt(int fd, int level, int name, const void *val, socklen_t len) {
  fake *f = get(fd);
  if (!f) return setsockopt(fd, level, name, val, len);
  if (level == SOL_SOCKET) return 0;   /* buffer sizes, timestamps: accepted */
  if (level != SOL_CAN_RAW) {
    errno = ENOPROTOOPT;
    return -1;
  }
  switch (name) {
  case CAN_RAW_FILTER:
    if (len % sizeof(struct can_filter) || len / sizeof(struct can_filter) > MAXFILTER) {
      errno = EINVAL;
      return -1;
    }
    f->nfilter = (int)(len / sizeof(struct can_filter));
    if (f->nfilter) memcpy(f->filter, val, len);
    return 0;
  case CAN_RAW_ERR_FILTER:
    if (len != sizeof(can_err_mask_t)) {
      errno = EINVAL;
      return -1;
    }
    memcpy(&f->err_mask, val, sizeof f->err_mask);
    return 0;
  case CAN_RAW_LOOPBACK:
  case CAN_RAW_RECV_OWN_MSGS:
    return 0;
  default:
    errno = ENOPROTOOPT;
    return -1;
  }
}

/* ---------------------------------------------------------------- frames */

static int passes(const fake *f, const struct can_frame *c) {
  if (c->can_id & CAN_ERR_FLAG) return (c->can_id & f->err_mask & CAN_ERR_MASK) != 0;
  for (int k = 0; k < f->nfilter; k++) {
    const canid_t m = f->filter[k].can_mask;
    const int inv = (f->filter[k].can_id & CAN_INV_FILTER) != 0;
    const int match = (c->can_id & m) == (f->filter[k].can_id & ~CAN_INV_FILTER & m);
    if (match != inv) return 1;
  }
  return 0;
}

static void list_peers(fake *f) {
  char d[PATHMAX];
  snprintf(d, sizeof d, "%s/%s", dir, ifname[f->ifindex - 1]);
  struct stat st;
  if (stat(d, &st) != 0) {
    drop_peers(f);
    return;
  }
  if (st.st_mtim.tv_sec == f->dir_mtime.tv_sec && st.st_mtim.tv_nsec == f->dir_mtime.tv_nsec) return;
  f->dir_mtime = st.st_mtim;
  drop_peers(f);
  DIR *dp = opendir(d);
  if (!dp) return;
  struct dirent *e;
  while ((e = readdir(dp)) && f->npeer < MAXPEER) {
    if (e->d_name[0] == '.') continue;
    char p[PATHMAX];
    if (snprintf(p, sizeof p, "%s/%s", d, e->d_name) >= (int)sizeof p || !strcmp(p, f->path)) continue;
    const int fd = open(p, O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
      if (errno == ENXIO) unlink(p);   /* nobody reads it: its owner died without closing */
      continue;
    }
    memcpy(f->peer[f->npeer], p, sizeof p);
    f->peer_fd[f->npeer++] = fd;
  }
  closedir(dp);
}

static ssize_t can_send(fake *f, const void *buf, size_t len) {
  if (!f->bound) {
    errno = EDESTADDRREQ;
    return -1;
  }
  if (len != sizeof(struct can_frame) || ((const struct can_frame *)buf)->can_dlc > 8) {
    errno = EINVAL;
    return -1;
  }
  if (is_down(f)) {
    errno = ENETDOWN;
    return -1;
  }
  list_peers(f);
  for (int k = 0; k < f->npeer; k++) {
    if (write(f->peer_fd[k], buf, len) < 0 && errno == EPIPE) {
      unlink(f->peer[k]);   /* its reader is gone */
      f->dir_mtime.tv_sec = -1;
    }
    /* EAGAIN: that receiver's queue is full; it loses the frame */
  }
  return (ssize_t)len;
}

/* One frame that passes the filters into c: 1, 0 when none is there (non-blocking), -1 error. */
static int take(fake *f, struct can_frame *c, int dontwait) {
  if (f->held) {
    *c = f->hold;
    f->held = 0;
    return 1;
  }
  for (;;) {
    if (dontwait || f->nonblock) {
      struct pollfd p = { .fd = (int)(f - F), .events = POLLIN };
      if (poll(&p, 1, 0) <= 0 || !(p.revents & POLLIN)) return 0;
    }
    const ssize_t n = read((int)(f - F), c, sizeof *c);
    if (n < 0) return errno == EAGAIN ? 0 : -1;
    if (n == (ssize_t)sizeof *c && passes(f, c)) return 1;
  }
}

static ssize_t can_recv(fake *f, void *buf, size_t len) {
  if (len < sizeof(struct can_frame) || !f->bound) {
    errno = EINVAL;
    return -1;
  }
  if (is_down(f)) {
    errno = ENETDOWN;
    return -1;
  }
  struct can_frame c;
  const int r = take(f, &c, 0);
  if (r < 0) return -1;
  if (r == 0) {
    errno = EAGAIN;
    return -1;
  }
  memcpy(buf, &c, sizeof c);
  return (ssize_t)sizeof c;
}

static ssize_t fake_read(int fd, void *buf, size_t len) {
  fake *f = get(fd);
  return f ? can_recv(f, buf, len) : read(fd, buf, len);
}
static ssize_t fake_write(int fd, const void *buf, size_t len) {
  fake *f = get(fd);
  return f ? can_send(f, buf, len) : write(fd, buf, len);
}

/* A frame that passes the filters is ready (read ahead into the hold; others are dropped). */
static int readable(fake *f) {
  if (f->held) return 1;
  struct can_frame c;
  if (take(f, &c, 1) != 1) return 0;
  f->hold = c;
  f->held = 1;
  return 1;
}

/* ppoll on fake sockets: timeout in s (< 0: none), waits in slices of at most 20 ms */
static int wait_fds(struct pollfd *fds, nfds_t n, double timeout, const sigset_t *mask) {
  const double end = timeout < 0 ? -1 : now() + timeout;
  for (;;) {
    int ready = 0;   /* frames read ahead answer at once */
    for (nfds_t k = 0; k < n; k++) {
      fake *f = get(fds[k].fd);
      ready |= f && f->held && (fds[k].events & POLLIN);
    }
    double w = timeout < 0 ? 0.02 : end - now();
    if (w > 0.02) w = 0.02;   /* a taken-down interface is noticed while waiting */
    if (w < 0 || ready) w = 0;
    struct timespec ts = { (time_t)w, (long)((w - (double)(time_t)w) * 1e9) };
    int r = ppoll(fds, n, &ts, mask);
    if (r < 0) return r;
    r = 0;
    for (nfds_t k = 0; k < n; k++) {
      fake *f = get(fds[k].fd);
      if (f && is_down(f)) {
        fds[k].revents = (short)(POLLERR | (fds[k].events & POLLIN));
      } else if (f) {
        fds[k].revents &= (short)~POLLIN;
        if ((fds[k].events & POLLIN) && readable(f)) fds[k].revents |= POLLIN;
      }
      if (fds[k].revents) r++;
    }
    if (r > 0 || (timeout >= 0 && now() >= end)) return r;
  }
}

static int any_fake(const struct pollfd *fds, nfds_t n) {
  init();
  for (nfds_t k = 0; k < n; k++)
    if (get(fds[k].fd)) return 1;
  return 0;
}

static int fake_ppoll(struct pollfd *fds, nfds_t n, const struct timespec *tmo, const sigset_t *mask) {
  if (!any_fake(fds, n)) return ppoll(fds, n, tmo, mask);
  return wait_fds(fds, n, tmo ? tmo->tv_sec + tmo->tv_nsec * 1e-9 : -1, mask);
}

static int fake_close(int fd) {
  fake *f = get(fd);
  if (f) {
    if (f->bound) unlink(f->path);
    drop_peers(f);
    memset(f, 0, sizeof *f);
  }
  return close(fd);
}

const hio_sys fakecan_sys = { fake_socket, fake_ioctl, fake_bind, fake_setsockopt,
                              fake_read, fake_write, fake_ppoll, fake_close };
