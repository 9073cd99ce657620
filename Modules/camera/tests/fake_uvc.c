/* fake_uvc: a UVC camera at one path for the v4l2 driver's system calls (open/close/ioctl/mmap/
 * munmap/poll), so the driver can be tested without hardware. A test installs it in the driver's
 * table (cam_v4l2_sys, camera/cam_internal.h) in its own process: the fake is compiled like the
 * test, so a sanitizer build instruments both. Calls on other paths and descriptors go to libc.
 *
 * The fake device: capture + streaming caps; YUYV only, at 640x480, 320x240 or 160x120 (S_FMT
 * substitutes the nearest like a real driver and always answers YUYV); frame rate from S_PARM;
 * controls exposure/gain/white balance/brightness/contrast accepted and recorded, saturation
 * refused (EINVAL); up to 8 mmap buffers (anonymous shared memory handed out by mmap on the fd).
 * Frame k's bytes: bytes 0..3 = k (little-endian), byte i >= 4 = (i*7 + k) & 255 in each line's
 * first width*2 bytes.
 *
 * The knobs for the test are in fake_uvc.h.
 */
#include "fake_uvc.h"

#include <stdint.h>
#include <errno.h>
#include <fcntl.h>
#include <linux/videodev2.h>
#include <poll.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

#define NBUF 8
#define NCTRL 16

static pthread_mutex_t L = PTHREAD_MUTEX_INITIALIZER;
static struct {
  char path[256];
  int present;
  int fd;                 /* placeholder fd of the open device, -1 */
  int dead;               /* unplugged while open */
  uint32_t width, height;
  int pad;
  double period;
  int streaming;
  int nbufs;
  size_t buflen;
  struct { void *addr; size_t len; int queued; } bufs[NBUF];
  int queue[NBUF], qn;
  double next_frame;
  uint32_t frame_no;
  int short_pending;
  struct { uint32_t id; int value; } ctrls[NCTRL];
  int nctrls;
  int opens, closes, streamon, streamoff, qbuf, dqbuf, live_maps, reqbufs;
} F;

void fake_uvc_install(const char *path, int present) {
  pthread_mutex_lock(&L);
  snprintf(F.path, sizeof F.path, "%s", path);
  F.present = present;
  F.fd = -1;
  F.width = 640;
  F.height = 480;
  F.period = 1.0 / 30;
  pthread_mutex_unlock(&L);
  cam_v4l2_sys = fake_uvc_sys;
}

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---------------------------------------------------------------- knobs */

void fake_uvc_set_present(int present) {
  pthread_mutex_lock(&L);
  F.present = present;
  if (!present && F.fd >= 0) F.dead = 1;
  pthread_mutex_unlock(&L);
}

void fake_uvc_short_frames(int n) {
  pthread_mutex_lock(&L);
  F.short_pending = n;
  pthread_mutex_unlock(&L);
}

void fake_uvc_set_pad(int pad) {
  pthread_mutex_lock(&L);
  F.pad = pad;
  pthread_mutex_unlock(&L);
}

int fake_uvc_get(const char *name) {
  pthread_mutex_lock(&L);
  int v = -1;
  if (!strcmp(name, "opens")) v = F.opens;
  else if (!strcmp(name, "closes")) v = F.closes;
  else if (!strcmp(name, "streamon")) v = F.streamon;
  else if (!strcmp(name, "streamoff")) v = F.streamoff;
  else if (!strcmp(name, "qbuf")) v = F.qbuf;
  else if (!strcmp(name, "dqbuf")) v = F.dqbuf;
  else if (!strcmp(name, "live_maps")) v = F.live_maps;
  else if (!strcmp(name, "reqbufs")) v = F.reqbufs;
  else if (!strcmp(name, "fmt_width")) v = (int)F.width;
  else if (!strcmp(name, "fmt_height")) v = (int)F.height;
  else if (!strcmp(name, "open")) v = F.fd >= 0;
  else if (!strncmp(name, "ctrl_", 5)) {
    uint32_t id = (uint32_t)strtoul(name + 5, NULL, 10);
    for (int i = 0; i < F.nctrls; i++)
      if (F.ctrls[i].id == id) v = F.ctrls[i].value;
  }
  pthread_mutex_unlock(&L);
  return v;
}

/* ---------------------------------------------------------------- the device */

static size_t sizeimage(void) { return ((size_t)F.width * 2 + (size_t)F.pad) * F.height; }

static void fill_frame(uint8_t *p, uint32_t k) {
  size_t stride = (size_t)F.width * 2 + (size_t)F.pad;
  for (uint32_t y = 0; y < F.height; y++) {
    uint8_t *row = p + y * stride;
    size_t base = (size_t)y * F.width * 2;
    for (size_t x = 0; x < (size_t)F.width * 2; x++) row[x] = (uint8_t)((base + x) * 7 + k);
    memset(row + F.width * 2, 0xEE, (size_t)F.pad);
  }
  memcpy(p, &k, 4);
}

static int device_ioctl(unsigned long req, void *arg) {
  if (F.dead) { errno = ENODEV; return -1; }
  switch (req) {
  case VIDIOC_QUERYCAP: {
    struct v4l2_capability *c = arg;
    memset(c, 0, sizeof *c);
    snprintf((char *)c->driver, sizeof c->driver, "uvcvideo");
    snprintf((char *)c->card, sizeof c->card, "Fake UVC Camera");
    c->device_caps = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING;
    c->capabilities = c->device_caps | V4L2_CAP_DEVICE_CAPS;
    return 0;
  }
  case VIDIOC_S_FMT:
  case VIDIOC_G_FMT: {
    struct v4l2_format *f = arg;
    if (f->type != V4L2_BUF_TYPE_VIDEO_CAPTURE) { errno = EINVAL; return -1; }
    if (req == VIDIOC_S_FMT) {
      if (F.nbufs > 0) { errno = EBUSY; return -1; }
      static const uint32_t sizes[3][2] = { { 640, 480 }, { 320, 240 }, { 160, 120 } };
      int pick = 2;
      for (int i = 0; i < 3; i++)
        if (sizes[i][0] <= f->fmt.pix.width && sizes[i][1] <= f->fmt.pix.height) { pick = i; break; }
      F.width = sizes[pick][0];
      F.height = sizes[pick][1];
    }
    f->fmt.pix.width = F.width;
    f->fmt.pix.height = F.height;
    f->fmt.pix.pixelformat = V4L2_PIX_FMT_YUYV;
    f->fmt.pix.field = V4L2_FIELD_NONE;
    f->fmt.pix.bytesperline = F.width * 2 + (uint32_t)F.pad;
    f->fmt.pix.sizeimage = (uint32_t)sizeimage();
    return 0;
  }
  case VIDIOC_S_PARM: {
    struct v4l2_streamparm *p = arg;
    struct v4l2_fract *t = &p->parm.capture.timeperframe;
    if (t->numerator && t->denominator) F.period = (double)t->numerator / t->denominator;
    return 0;
  }
  case VIDIOC_S_CTRL: {
    struct v4l2_control *c = arg;
    if (c->id == (uint32_t)V4L2_CID_SATURATION) { errno = EINVAL; return -1; }
    for (int i = 0; i < F.nctrls; i++)
      if (F.ctrls[i].id == c->id) { F.ctrls[i].value = c->value; return 0; }
    if (F.nctrls < NCTRL) {
      F.ctrls[F.nctrls].id = c->id;
      F.ctrls[F.nctrls++].value = c->value;
    }
    return 0;
  }
  case VIDIOC_REQBUFS: {
    struct v4l2_requestbuffers *r = arg;
    if (r->memory != V4L2_MEMORY_MMAP) { errno = EINVAL; return -1; }
    if (F.streaming) { errno = EBUSY; return -1; }
    F.reqbufs++;
    F.qn = 0;
    if (r->count == 0) { F.nbufs = 0; return 0; }
    if (r->count > NBUF) r->count = NBUF;
    F.nbufs = (int)r->count;
    long page = sysconf(_SC_PAGESIZE);
    F.buflen = (sizeimage() + (size_t)page - 1) / (size_t)page * (size_t)page;
    for (int i = 0; i < NBUF; i++) F.bufs[i].queued = 0;
    return 0;
  }
  case VIDIOC_QUERYBUF:
  case VIDIOC_QBUF: {
    struct v4l2_buffer *b = arg;
    if (b->index >= (uint32_t)F.nbufs || b->memory != V4L2_MEMORY_MMAP) { errno = EINVAL; return -1; }
    if (req == VIDIOC_QUERYBUF) {
      b->length = (uint32_t)F.buflen;
      b->m.offset = (uint32_t)(b->index * F.buflen);
      b->flags = F.bufs[b->index].queued ? V4L2_BUF_FLAG_QUEUED : 0;
      return 0;
    }
    if (F.bufs[b->index].queued) { errno = EINVAL; return -1; }
    F.bufs[b->index].queued = 1;
    F.queue[F.qn++] = (int)b->index;
    F.qbuf++;
    return 0;
  }
  case VIDIOC_DQBUF: {
    struct v4l2_buffer *b = arg;
    if (!F.streaming) { errno = EINVAL; return -1; }
    if (F.qn == 0 || now() < F.next_frame) { errno = EAGAIN; return -1; }
    int idx = F.queue[0];
    memmove(F.queue, F.queue + 1, sizeof(int) * (size_t)(--F.qn));
    F.bufs[idx].queued = 0;
    if (!F.bufs[idx].addr) { errno = EIO; return -1; }
    fill_frame(F.bufs[idx].addr, ++F.frame_no);
    memset(b, 0, sizeof *b);
    b->type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b->memory = V4L2_MEMORY_MMAP;
    b->index = (uint32_t)idx;
    b->bytesused = (uint32_t)sizeimage();
    b->sequence = F.frame_no;
    if (F.short_pending > 0) { F.short_pending--; b->bytesused /= 2; }
    double t = now();
    F.next_frame = F.next_frame + F.period > t ? F.next_frame + F.period : t + F.period;
    F.dqbuf++;
    return 0;
  }
  case VIDIOC_STREAMON:
    if (F.nbufs == 0) { errno = EINVAL; return -1; }
    F.streaming = 1;
    F.streamon++;
    F.next_frame = now() + F.period;
    return 0;
  case VIDIOC_STREAMOFF:
    F.streaming = 0;
    F.streamoff++;
    F.qn = 0;
    for (int i = 0; i < NBUF; i++) F.bufs[i].queued = 0;
    return 0;
  default:
    errno = ENOTTY;
    return -1;
  }
}

/* ---------------------------------------------------------------- the driver's calls */

static int fake_open_mode(const char *path, int flags, mode_t mode) {
  if (path && strcmp(path, F.path) == 0) {
    pthread_mutex_lock(&L);
    int fd = -1;
    if (!F.present) errno = ENOENT;
    else if (F.fd >= 0) errno = EBUSY;
    else {
      fd = open("/dev/null", O_RDWR);
      if (fd >= 0) {
        F.fd = fd;
        F.dead = 0;
        F.streaming = 0;
        F.nbufs = 0;
        F.qn = 0;
        F.nctrls = 0;
        F.opens++;
      }
    }
    pthread_mutex_unlock(&L);
    return fd;
  }
  return open(path, flags, mode);
}

static mode_t get_mode(int flags, va_list ap) {
  return (flags & (O_CREAT | O_TMPFILE)) ? (mode_t)va_arg(ap, int) : 0;
}

static int fake_open(const char *path, int flags, ...) {
  va_list ap;
  va_start(ap, flags);
  mode_t m = get_mode(flags, ap);
  va_end(ap);
  return fake_open_mode(path, flags, m);
}

static int fake_close(int fd) {
  pthread_mutex_lock(&L);
  if (fd >= 0 && fd == F.fd) {
    F.fd = -1;
    F.streaming = 0;
    F.closes++;
  }
  pthread_mutex_unlock(&L);
  return close(fd);
}

static int fake_ioctl(int fd, unsigned long req, ...) {
  va_list ap;
  va_start(ap, req);
  void *arg = va_arg(ap, void *);
  va_end(ap);
  pthread_mutex_lock(&L);
  if (fd >= 0 && fd == F.fd) {
    int r = device_ioctl(req, arg);
    pthread_mutex_unlock(&L);
    return r;
  }
  pthread_mutex_unlock(&L);
  return ioctl(fd, req, arg);
}

static void *fake_mmap(void *addr, size_t len, int prot, int flags, int fd, off_t off) {
  pthread_mutex_lock(&L);
  if (fd >= 0 && fd == F.fd) {
    void *p = MAP_FAILED;
    size_t idx = F.buflen ? (size_t)off / F.buflen : 0;
    if (F.dead) errno = ENODEV;
    else if (F.buflen == 0 || (size_t)off % F.buflen || idx >= (size_t)F.nbufs || len > F.buflen)
      errno = EINVAL;
    else {
      p = mmap(NULL, len, prot, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
      if (p != MAP_FAILED) {
        F.bufs[idx].addr = p;
        F.bufs[idx].len = len;
        F.live_maps++;
      }
    }
    pthread_mutex_unlock(&L);
    return p;
  }
  pthread_mutex_unlock(&L);
  return mmap(addr, len, prot, flags, fd, off);
}

static int fake_munmap(void *addr, size_t len) {
  pthread_mutex_lock(&L);
  for (int i = 0; i < NBUF; i++)
    if (addr && F.bufs[i].addr == addr) {
      F.bufs[i].addr = NULL;
      F.live_maps--;
    }
  pthread_mutex_unlock(&L);
  return munmap(addr, len);
}

static int fake_poll(struct pollfd *fds, nfds_t n, int timeout_ms) {
  pthread_mutex_lock(&L);
  int fake = n == 1 && fds[0].fd >= 0 && fds[0].fd == F.fd;
  if (!fake) {
    pthread_mutex_unlock(&L);
    return poll(fds, n, timeout_ms);
  }
  fds[0].revents = 0;
  if (F.dead) {
    fds[0].revents = POLLERR | POLLHUP;
    pthread_mutex_unlock(&L);
    return 1;
  }
  double wait = timeout_ms < 0 ? 1.0 : timeout_ms / 1000.0;
  int ready = 0;
  if (F.streaming && F.qn > 0) {
    double dt = F.next_frame - now();
    if (dt <= wait) { wait = dt > 0 ? dt : 0; ready = 1; }
  }
  pthread_mutex_unlock(&L);
  /* sleep in small steps so an unplug is seen promptly */
  double end = now() + wait;
  for (;;) {
    double left = end - now();
    if (left <= 0) break;
    struct timespec ts = { 0, (long)((left < 0.005 ? left : 0.005) * 1e9) };
    nanosleep(&ts, NULL);
    pthread_mutex_lock(&L);
    int dead = F.dead;
    pthread_mutex_unlock(&L);
    if (dead) {
      fds[0].revents = POLLERR | POLLHUP;
      return 1;
    }
  }
  if (ready) fds[0].revents = POLLIN;
  return ready;
}

const cam_sys fake_uvc_sys = { fake_open, fake_close, fake_ioctl, fake_mmap, fake_munmap, fake_poll };
