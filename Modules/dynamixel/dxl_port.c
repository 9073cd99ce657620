/* dxl_port.c: a serial port for a Dynamixel bus through termios (raw 8N1), any rate up to
 * 4.5 Mbps, low-latency mode, reads with absolute deadlines, reopen after loss. */
#include "dynamixel/dynamixel.h"

#include <errno.h>
#include <fcntl.h>
#include <linux/serial.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

/* dxl_baud.c: sets a rate with no Bxxx constant through termios2 (kept apart: its kernel
 * headers clash with <termios.h>). */
int dxl_port_set_custom_baud_(int fd, int baud);

struct dxl_port {
  int fd;
  int baud;
  char path[256];
};

double dxl_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static speed_t std_speed(int baud) {
  switch (baud) {
  case 9600: return B9600;
  case 19200: return B19200;
  case 38400: return B38400;
  case 57600: return B57600;
  case 115200: return B115200;
  case 230400: return B230400;
  case 460800: return B460800;
  case 500000: return B500000;
  case 576000: return B576000;
  case 921600: return B921600;
  case 1000000: return B1000000;
  case 1152000: return B1152000;
  case 1500000: return B1500000;
  case 2000000: return B2000000;
  case 2500000: return B2500000;
  case 3000000: return B3000000;
  case 3500000: return B3500000;
  case 4000000: return B4000000;
  default: return 0;
  }
}

static int configure(int fd, int baud, char *err, size_t errlen) {
  struct termios tio;
  if (tcgetattr(fd, &tio) != 0) {
    snprintf(err, errlen, "tcgetattr: %s", strerror(errno));
    return DXL_EPORT;
  }
  cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_cflag &= ~(CSTOPB | PARENB | CRTSCTS);
  tio.c_iflag &= ~(IXON | IXOFF | IXANY);
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  speed_t sp = std_speed(baud);
  if (sp) {
    cfsetispeed(&tio, sp);
    cfsetospeed(&tio, sp);
  }
  if (tcsetattr(fd, TCSANOW, &tio) != 0) {
    snprintf(err, errlen, "tcsetattr: %s", strerror(errno));
    return DXL_EPORT;
  }
  if (!sp && dxl_port_set_custom_baud_(fd, baud) != 0) {
    snprintf(err, errlen, "baud %d not accepted by the driver: %s", baud, strerror(errno));
    return DXL_EPORT;
  }
  /* Low latency (FTDI & co.); a pseudo-terminal has no serial_struct: fine. */
  struct serial_struct ss;
  if (ioctl(fd, TIOCGSERIAL, &ss) == 0) {
    ss.flags |= ASYNC_LOW_LATENCY;
    (void)ioctl(fd, TIOCSSERIAL, &ss);
  }
  tcflush(fd, TCIOFLUSH);
  return 0;
}

static int open_fd(dxl_port *p, char *err, size_t errlen) {
  int fd = open(p->path, O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    snprintf(err, errlen, "cannot open %s: %s", p->path, strerror(errno));
    return DXL_EPORT;
  }
  int rc = configure(fd, p->baud, err, errlen);
  if (rc) { close(fd); return rc; }
  p->fd = fd;
  return 0;
}

int dxl_port_open(const char *path, int baud, dxl_port **out, char *err, size_t errlen) {
  if (!path || !out || baud <= 0 || baud > 4500000) {
    snprintf(err, errlen, "dxl_port_open: bad arguments (baud %d, max 4500000)", baud);
    return DXL_EARG;
  }
  *out = NULL;
  dxl_port *p = calloc(1, sizeof *p);
  if (!p) { snprintf(err, errlen, "out of memory"); return DXL_EARG; }
  snprintf(p->path, sizeof p->path, "%s", path);
  p->baud = baud;
  p->fd = -1;
  int rc = open_fd(p, err, errlen);
  if (rc) { free(p); return rc; }
  *out = p;
  return 0;
}

void dxl_port_close(dxl_port *p) {
  if (!p) return;
  if (p->fd >= 0) close(p->fd);
  free(p);
}

int dxl_port_reopen(dxl_port *p, char *err, size_t errlen) {
  if (!p) return DXL_EARG;
  if (p->fd >= 0) { close(p->fd); p->fd = -1; }
  return open_fd(p, err, errlen);
}

int dxl_port_set_baud(dxl_port *p, int baud, char *err, size_t errlen) {
  if (!p || baud <= 0 || baud > 4500000) return DXL_EARG;
  p->baud = baud;
  if (p->fd < 0) return open_fd(p, err, errlen);
  return configure(p->fd, baud, err, errlen);
}

int dxl_port_baud(const dxl_port *p) { return p ? p->baud : 0; }
int dxl_port_fd(const dxl_port *p) { return p ? p->fd : -1; }
int dxl_port_is_open(const dxl_port *p) { return p && p->fd >= 0; }

double dxl_port_byte_time(const dxl_port *p) {
  return p && p->baud > 0 ? 10.0 / p->baud : 0.0;
}

static void lost(dxl_port *p) {
  if (p->fd >= 0) close(p->fd);
  p->fd = -1;
}

int dxl_port_write(dxl_port *p, const uint8_t *buf, size_t len) {
  if (!p || p->fd < 0) return DXL_COMM_TX_FAIL;
  size_t done = 0;
  double deadline = dxl_now() + 0.1 + len * dxl_port_byte_time(p) * 2;
  while (done < len) {
    ssize_t w = write(p->fd, buf + done, len - done);
    if (w > 0) { done += (size_t)w; continue; }
    if (w < 0 && errno == EINTR) continue;
    if (w < 0 && errno == EAGAIN) {
      double left = deadline - dxl_now();
      if (left <= 0) return DXL_COMM_TX_FAIL;
      struct pollfd pfd = { p->fd, POLLOUT, 0 };
      (void)poll(&pfd, 1, (int)(left * 1000) + 1);
      continue;
    }
    lost(p);
    return DXL_COMM_TX_FAIL;
  }
  return (int)len;
}

int dxl_port_read(dxl_port *p, uint8_t *buf, size_t len, double deadline) {
  if (!p || p->fd < 0) return DXL_COMM_RX_FAIL;
  for (;;) {
    ssize_t r = read(p->fd, buf, len);
    if (r > 0) return (int)r;
    if (r == 0) {
      /* no data (VMIN 0): a pty whose other end is gone also reads 0 -- see POLLHUP below */
    } else if (errno == EINTR) {
      continue;
    } else if (errno != EAGAIN) {
      lost(p);
      return DXL_COMM_RX_FAIL;
    }
    double left = deadline - dxl_now();
    if (left <= 0) return 0;
    struct pollfd pfd = { p->fd, POLLIN, 0 };
    /* poll has millisecond resolution: use ppoll for sub-millisecond deadlines */
    struct timespec ts = { (time_t)left, (long)((left - (double)(time_t)left) * 1e9) };
    int n = ppoll(&pfd, 1, &ts, NULL);
    if (n < 0 && errno != EINTR) { lost(p); return DXL_COMM_RX_FAIL; }
    if (n > 0 && (pfd.revents & (POLLERR | POLLNVAL))) { lost(p); return DXL_COMM_RX_FAIL; }
    if (n > 0 && (pfd.revents & POLLHUP) && !(pfd.revents & POLLIN)) {
      lost(p);   /* the device (or the emulator behind a pty) went away */
      return DXL_COMM_RX_FAIL;
    }
  }
}

void dxl_port_clear(dxl_port *p) {
  if (!p || p->fd < 0) return;
  tcflush(p->fd, TCIFLUSH);
}
