/* fake_socketcan: an LD_PRELOAD shim that serves SocketCAN raw sockets over a userspace bus, so the
 * Hubo DCM and its emulator run unchanged on a kernel without AF_CAN (this machine's).
 *
 * Served: socket(PF_CAN, SOCK_RAW, CAN_RAW) (SOCK_NONBLOCK / SOCK_CLOEXEC honoured), ioctl
 * SIOCGIFINDEX and FIONBIO, if_nametoindex, bind(struct sockaddr_can), setsockopt CAN_RAW_FILTER /
 * CAN_RAW_ERR_FILTER (CAN_RAW_LOOPBACK / CAN_RAW_RECV_OWN_MSGS accepted), read / recv / recvfrom /
 * write / send / sendto of struct can_frame (16 bytes; anything else is EINVAL), poll, ppoll, close.
 * Not served: recvmsg, select, epoll, CAN FD.
 *
 * The bus: each bound socket is a named pipe $FAKECAN_DIR/<ifname>/<pid>.<fd> that its owner reads
 * (a pipe, not a unix datagram socket: those queue only net.unix.max_dgram_qlen = 10 datagrams,
 * fewer than one cycle's replies; a pipe holds 4096 frames, and 16-byte writes are atomic). A frame
 * written goes to every other socket bound to that interface (as SocketCAN's loopback delivers to
 * the host's other sockets, never to the sender). A receiver whose queue is full loses the frame,
 * as a socket's overflowing receive queue does. The shim ignores SIGPIPE (a peer that died).
 * Filters apply on receipt, as the kernel's: a frame passes when (id & mask) == (filter id & mask)
 * for some filter (inverted with CAN_INV_FILTER); error frames (CAN_ERR_FLAG) pass only through the
 * error mask. poll drops frames no filter passes, so POLLIN means a frame read() will return.
 *
 * Environment: FAKECAN_DIR (default /tmp/fakecan.<uid>), FAKECAN_IFACES (default
 * "can0,can1,vcan0,vcan1": the interfaces that exist, index = position + 1). A file
 * $FAKECAN_DIR/<ifname>.down takes the interface down: writes fail with ENETDOWN, reads with
 * ENETDOWN, poll reports POLLERR (looked at every 20 ms), until the file is removed.
 * Single-threaded use (the DCM, the emulator).
 */
#include <dirent.h>
#include <dlfcn.h>
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

static int (*real_socket)(int, int, int);
static int (*real_ioctl)(int, unsigned long, ...);
static int (*real_bind)(int, const struct sockaddr *, socklen_t);
static int (*real_setsockopt)(int, int, int, const void *, socklen_t);
static ssize_t (*real_read)(int, void *, size_t);
static ssize_t (*real_write)(int, const void *, size_t);
static ssize_t (*real_recv)(int, void *, size_t, int);
static ssize_t (*real_recvfrom)(int, void *, size_t, int, struct sockaddr *, socklen_t *);
static ssize_t (*real_send)(int, const void *, size_t, int);
static ssize_t (*real_sendto)(int, const void *, size_t, int, const struct sockaddr *, socklen_t);
static int (*real_poll)(struct pollfd *, nfds_t, int);
static int (*real_ppoll)(struct pollfd *, nfds_t, const struct timespec *, const sigset_t *);
static int (*real_close)(int);
static unsigned (*real_if_nametoindex)(const char *);

static void init(void) {
  if (inited) return;
  inited = 1;
  real_socket = dlsym(RTLD_NEXT, "socket");
  real_ioctl = dlsym(RTLD_NEXT, "ioctl");
  real_bind = dlsym(RTLD_NEXT, "bind");
  real_setsockopt = dlsym(RTLD_NEXT, "setsockopt");
  real_read = dlsym(RTLD_NEXT, "read");
  real_write = dlsym(RTLD_NEXT, "write");
  real_recv = dlsym(RTLD_NEXT, "recv");
  real_recvfrom = dlsym(RTLD_NEXT, "recvfrom");
  real_send = dlsym(RTLD_NEXT, "send");
  real_sendto = dlsym(RTLD_NEXT, "sendto");
  real_poll = dlsym(RTLD_NEXT, "poll");
  real_ppoll = dlsym(RTLD_NEXT, "ppoll");
  real_close = dlsym(RTLD_NEXT, "close");
  real_if_nametoindex = dlsym(RTLD_NEXT, "if_nametoindex");
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
    if (f->peer_fd[k] >= 0) real_close(f->peer_fd[k]);
  f->npeer = 0;
}

/* ---------------------------------------------------------------- socket, ioctl, bind, options */

int socket(int domain, int type, int protocol) {
  init();
  if (domain != PF_CAN) return real_socket(domain, type, protocol);
  if ((type & 0xFF) != SOCK_RAW || protocol != CAN_RAW) {
    errno = EPROTONOSUPPORT;
    return -1;
  }
  /* a placeholder until bind() puts the interface's pipe on this descriptor */
  const int fd = open("/dev/null", O_RDONLY | ((type & SOCK_CLOEXEC) ? O_CLOEXEC : 0));
  if (fd < 0) return fd;
  if (fd >= MAXFD) {
    real_close(fd);
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

int ioctl(int fd, unsigned long req, ...) {
  va_list ap;
  va_start(ap, req);
  void *arg = va_arg(ap, void *);
  va_end(ap);
  if (!get(fd)) return real_ioctl(fd, req, arg);
  if (req == FIONBIO) {   /* Python's settimeout, and others */
    F[fd].nonblock = *(int *)arg != 0;
    return F[fd].bound ? real_ioctl(fd, req, arg) : 0;
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

unsigned if_nametoindex(const char *name) {
  init();
  const int idx = index_of(name);
  return idx ? (unsigned)idx : real_if_nametoindex(name);
}

int bind(int fd, const struct sockaddr *addr, socklen_t len) {
  fake *f = get(fd);
  if (!f) return real_bind(fd, addr, len);
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
  real_close(p);
  fcntl(fd, F_SETFD, fdflags);
  f->ifindex = a->can_ifindex;
  f->bound = 1;
  f->dir_mtime.tv_sec = -1;
  return 0;
}

int setsockopt(int fd, int level, int name, const void *val, socklen_t len) {
  fake *f = get(fd);
  if (!f) return real_setsockopt(fd, level, name, val, len);
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
    if (real_write(f->peer_fd[k], buf, len) < 0 && errno == EPIPE) {
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
      if (real_poll(&p, 1, 0) <= 0 || !(p.revents & POLLIN)) return 0;
    }
    const ssize_t n = real_read((int)(f - F), c, sizeof *c);
    if (n < 0) return errno == EAGAIN ? 0 : -1;
    if (n == (ssize_t)sizeof *c && passes(f, c)) return 1;
  }
}

static ssize_t can_recv(fake *f, void *buf, size_t len, int flags) {
  if (len < sizeof(struct can_frame) || !f->bound) {
    errno = EINVAL;
    return -1;
  }
  if (is_down(f)) {
    errno = ENETDOWN;
    return -1;
  }
  struct can_frame c;
  const int r = take(f, &c, (flags & MSG_DONTWAIT) != 0);
  if (r < 0) return -1;
  if (r == 0) {
    errno = EAGAIN;
    return -1;
  }
  if (flags & MSG_PEEK) {
    f->hold = c;
    f->held = 1;
  }
  memcpy(buf, &c, sizeof c);
  return (ssize_t)sizeof c;
}

ssize_t read(int fd, void *buf, size_t len) {
  fake *f = get(fd);
  return f ? can_recv(f, buf, len, 0) : real_read(fd, buf, len);
}
ssize_t recv(int fd, void *buf, size_t len, int flags) {
  fake *f = get(fd);
  return f ? can_recv(f, buf, len, flags) : real_recv(fd, buf, len, flags);
}
ssize_t recvfrom(int fd, void *buf, size_t len, int flags, struct sockaddr *src, socklen_t *slen) {
  fake *f = get(fd);
  if (!f) return real_recvfrom(fd, buf, len, flags, src, slen);
  const ssize_t n = can_recv(f, buf, len, flags);
  if (n >= 0 && src && slen && *slen >= sizeof(struct sockaddr_can)) {
    struct sockaddr_can a = { .can_family = AF_CAN, .can_ifindex = f->ifindex };
    memcpy(src, &a, sizeof a);
    *slen = sizeof a;
  }
  return n;
}
ssize_t write(int fd, const void *buf, size_t len) {
  fake *f = get(fd);
  return f ? can_send(f, buf, len) : real_write(fd, buf, len);
}
ssize_t send(int fd, const void *buf, size_t len, int flags) {
  fake *f = get(fd);
  return f ? can_send(f, buf, len) : real_send(fd, buf, len, flags);
}
ssize_t sendto(int fd, const void *buf, size_t len, int flags, const struct sockaddr *to, socklen_t tolen) {
  fake *f = get(fd);
  return f ? can_send(f, buf, len) : real_sendto(fd, buf, len, flags, to, tolen);
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

/* poll and ppoll on fake sockets: timeout in s (< 0: none), waits in slices of at most 20 ms */
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
    int r = real_ppoll(fds, n, &ts, mask);
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

int poll(struct pollfd *fds, nfds_t n, int timeout) {
  if (!any_fake(fds, n)) return real_poll(fds, n, timeout);
  return wait_fds(fds, n, timeout < 0 ? -1 : timeout / 1000.0, NULL);
}

int ppoll(struct pollfd *fds, nfds_t n, const struct timespec *tmo, const sigset_t *mask) {
  if (!any_fake(fds, n)) return real_ppoll(fds, n, tmo, mask);
  return wait_fds(fds, n, tmo ? tmo->tv_sec + tmo->tv_nsec * 1e-9 : -1, mask);
}

int close(int fd) {
  fake *f = get(fd);
  if (f) {
    if (f->bound) unlink(f->path);
    drop_peers(f);
    memset(f, 0, sizeof *f);
  }
  return real_close(fd);
}
