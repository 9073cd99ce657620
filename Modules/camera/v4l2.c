/* camera: the V4L2 (UVC) driver.
 *
 * A capture thread owns the device: open, negotiate YUYV at the configured size, set the
 * controls, map nbuffers buffers, stream. Each frame dequeued is checked (a short or flagged
 * frame is counted and dropped), copied into the "ready" buffer, stamped with the robot clock,
 * and its buffer queued again. When the device fails or disappears (ENODEV, POLLERR) the thread
 * unmaps and closes everything, counts it, and tries to reopen every reopen_interval seconds.
 * cam_grab waits for a frame newer than the last one it returned and copies it out.
 */
#include "camera/cam_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <linux/videodev2.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

#define MAX_BUFFERS 16

cam_sys cam_v4l2_sys = { open, close, ioctl, mmap, munmap, poll };

typedef struct v4l2cam {
  cam_camera *cam;
  pthread_t thread;
  int thread_started;

  pthread_mutex_t lock;         /* guards everything below "shared" */
  pthread_cond_t cond;          /* a frame arrived, the state changed, or stop */

  /* capture thread only */
  int fd;
  struct { void *start; size_t length; } bufs[MAX_BUFFERS];
  int nbufs;
  size_t bytesperline, sizeimage;

  /* shared */
  int running;
  int connected;
  int state_rc;                 /* CAM_ENODEV or CAM_EFORMAT while not connected */
  char reason[300];
  uint8_t *ready;               /* width*height*2 */
  uint32_t ready_seq;
  double ready_time, ready_head[2], ready_angle[2];

  /* consumer only */
  uint8_t *out;
  uint32_t taken_seq;
} v4l2cam;

static int xioctl(int fd, unsigned long req, void *arg) {
  int r;
  do { r = cam_v4l2_sys.ioctl(fd, req, arg); } while (r < 0 && errno == EINTR);
  return r;
}

static void abs_deadline(struct timespec *ts, double dt) {
  clock_gettime(CLOCK_MONOTONIC, ts);
  if (dt < 0) dt = 0;
  long sec = (long)dt;
  ts->tv_sec += sec;
  ts->tv_nsec += (long)((dt - (double)sec) * 1e9);
  if (ts->tv_nsec >= 1000000000L) { ts->tv_sec++; ts->tv_nsec -= 1000000000L; }
}

/* Sets one control; a refusal is counted and noted, never fatal. */
static void set_ctrl(v4l2cam *v, uint32_t id, int value, const char *name) {
  struct v4l2_control c = { .id = id, .value = value };
  if (xioctl(v->fd, VIDIOC_S_CTRL, &c) < 0) {
    cam_camera *cam = v->cam;
    CAM_STATS(cam, cam->stats.control_errors++);
    cam_note(cam, "camera %s: control %s=%d refused: %s", cam->device, name, value, strerror(errno));
  }
}

static void apply_controls(v4l2cam *v) {
  const cam_config *c = &v->cam->cfg;
  if (c->exposure != CAM_CTRL_UNSET) {
    if (c->exposure < 0) {
      set_ctrl(v, V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_APERTURE_PRIORITY, "exposure_auto");
    } else {
      set_ctrl(v, V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_MANUAL, "exposure_auto");
      set_ctrl(v, V4L2_CID_EXPOSURE_ABSOLUTE, c->exposure, "exposure");
    }
  }
  if (c->white_balance != CAM_CTRL_UNSET) {
    if (c->white_balance < 0) {
      set_ctrl(v, V4L2_CID_AUTO_WHITE_BALANCE, 1, "white_balance_auto");
    } else {
      set_ctrl(v, V4L2_CID_AUTO_WHITE_BALANCE, 0, "white_balance_auto");
      set_ctrl(v, V4L2_CID_WHITE_BALANCE_TEMPERATURE, c->white_balance, "white_balance");
    }
  }
  if (c->gain != CAM_CTRL_UNSET) set_ctrl(v, V4L2_CID_GAIN, c->gain, "gain");
  if (c->brightness != CAM_CTRL_UNSET) set_ctrl(v, V4L2_CID_BRIGHTNESS, c->brightness, "brightness");
  if (c->contrast != CAM_CTRL_UNSET) set_ctrl(v, V4L2_CID_CONTRAST, c->contrast, "contrast");
  if (c->saturation != CAM_CTRL_UNSET) set_ctrl(v, V4L2_CID_SATURATION, c->saturation, "saturation");
}

static void dev_close(v4l2cam *v) {
  if (v->fd < 0) return;
  enum v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  xioctl(v->fd, VIDIOC_STREAMOFF, &type);   /* fails harmlessly on a vanished device */
  for (int i = 0; i < v->nbufs; i++)
    if (v->bufs[i].start && v->bufs[i].start != MAP_FAILED)
      cam_v4l2_sys.munmap(v->bufs[i].start, v->bufs[i].length);
  v->nbufs = 0;
  struct v4l2_requestbuffers req = { .count = 0, .type = V4L2_BUF_TYPE_VIDEO_CAPTURE,
                                     .memory = V4L2_MEMORY_MMAP };
  xioctl(v->fd, VIDIOC_REQBUFS, &req);
  cam_v4l2_sys.close(v->fd);
  v->fd = -1;
}

static int errno_rc(int e) { return (e == ENODEV || e == ENOENT || e == ENXIO || e == EIO) ? CAM_ENODEV : CAM_EFORMAT; }

/* Opens and starts the device. 0, or a CAM_E* code with the reason in msg. */
static int dev_open(v4l2cam *v, char *msg, size_t len) {
  cam_camera *cam = v->cam;
  const cam_config *c = &cam->cfg;
  const char *dev = cam->device;
  v->fd = cam_v4l2_sys.open(dev, O_RDWR | O_NONBLOCK);
  if (v->fd < 0) {
    int e = errno;
    hrp_err(msg, len, "camera %s: cannot open: %s", dev, strerror(e));
    return errno_rc(e);
  }
  int e = 0;
  struct v4l2_capability cap;
  memset(&cap, 0, sizeof cap);
  if (xioctl(v->fd, VIDIOC_QUERYCAP, &cap) < 0) {
    e = errno;
    hrp_err(msg, len, "camera %s: not a V4L2 device (VIDIOC_QUERYCAP: %s)", dev, strerror(e));
    goto fail;
  }
  uint32_t caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
  if (!(caps & V4L2_CAP_VIDEO_CAPTURE) || !(caps & V4L2_CAP_STREAMING)) {
    hrp_err(msg, len, "camera %s: not a streaming capture device (caps %08x)", dev, caps);
    dev_close(v);
    return CAM_EFORMAT;
  }
  struct v4l2_format fmt;
  memset(&fmt, 0, sizeof fmt);
  fmt.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  fmt.fmt.pix.width = (uint32_t)c->width;
  fmt.fmt.pix.height = (uint32_t)c->height;
  fmt.fmt.pix.pixelformat = V4L2_PIX_FMT_YUYV;
  fmt.fmt.pix.field = V4L2_FIELD_ANY;
  if (xioctl(v->fd, VIDIOC_S_FMT, &fmt) < 0) {
    e = errno;
    hrp_err(msg, len, "camera %s: VIDIOC_S_FMT: %s", dev, strerror(e));
    goto fail;
  }
  /* the driver may substitute another size or format: it must be exactly what we asked */
  if (fmt.fmt.pix.pixelformat != V4L2_PIX_FMT_YUYV || fmt.fmt.pix.width != (uint32_t)c->width ||
      fmt.fmt.pix.height != (uint32_t)c->height) {
    uint32_t pf = fmt.fmt.pix.pixelformat;
    hrp_err(msg, len, "camera %s: device offers %ux%u %c%c%c%c, config asks %dx%d YUYV", dev,
            fmt.fmt.pix.width, fmt.fmt.pix.height, (char)(pf & 0xff), (char)((pf >> 8) & 0xff),
            (char)((pf >> 16) & 0xff), (char)(pf >> 24), c->width, c->height);
    dev_close(v);
    return CAM_EFORMAT;
  }
  v->bytesperline = fmt.fmt.pix.bytesperline >= (uint32_t)c->width * 2 ? fmt.fmt.pix.bytesperline
                                                                       : (size_t)c->width * 2;
  v->sizeimage = v->bytesperline * (size_t)c->height;
  if (c->fps > 0) {   /* best effort: not every device lets the rate be chosen */
    struct v4l2_streamparm parm;
    memset(&parm, 0, sizeof parm);
    parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    parm.parm.capture.timeperframe.numerator = 1000;
    parm.parm.capture.timeperframe.denominator = (uint32_t)(c->fps * 1000 + 0.5);
    xioctl(v->fd, VIDIOC_S_PARM, &parm);
  }
  apply_controls(v);

  struct v4l2_requestbuffers req;
  memset(&req, 0, sizeof req);
  req.count = (uint32_t)(c->nbuffers < 2 ? 2 : c->nbuffers > MAX_BUFFERS ? MAX_BUFFERS : c->nbuffers);
  req.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  req.memory = V4L2_MEMORY_MMAP;
  if (xioctl(v->fd, VIDIOC_REQBUFS, &req) < 0) {
    e = errno;
    hrp_err(msg, len, "camera %s: VIDIOC_REQBUFS: %s", dev, strerror(e));
    goto fail;
  }
  if (req.count < 2 || req.count > MAX_BUFFERS) {
    hrp_err(msg, len, "camera %s: device granted %u buffers (need 2..%d)", dev, req.count, MAX_BUFFERS);
    dev_close(v);
    return CAM_EFORMAT;
  }
  for (uint32_t i = 0; i < req.count; i++) {
    struct v4l2_buffer buf;
    memset(&buf, 0, sizeof buf);
    buf.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    buf.memory = V4L2_MEMORY_MMAP;
    buf.index = i;
    if (xioctl(v->fd, VIDIOC_QUERYBUF, &buf) < 0) {
      e = errno;
      hrp_err(msg, len, "camera %s: VIDIOC_QUERYBUF %u: %s", dev, i, strerror(e));
      goto fail;
    }
    void *p = cam_v4l2_sys.mmap(NULL, buf.length, PROT_READ | PROT_WRITE, MAP_SHARED, v->fd, buf.m.offset);
    if (p == MAP_FAILED) {
      e = errno;
      hrp_err(msg, len, "camera %s: mmap of buffer %u: %s", dev, i, strerror(e));
      goto fail;
    }
    v->bufs[i].start = p;
    v->bufs[i].length = buf.length;
    v->nbufs = (int)i + 1;
    if (buf.length < v->sizeimage) {
      hrp_err(msg, len, "camera %s: buffer %u holds %u bytes, a frame needs %zu", dev, i, buf.length,
              v->sizeimage);
      dev_close(v);
      return CAM_EFORMAT;
    }
    if (xioctl(v->fd, VIDIOC_QBUF, &buf) < 0) {
      e = errno;
      hrp_err(msg, len, "camera %s: VIDIOC_QBUF %u: %s", dev, i, strerror(e));
      goto fail;
    }
  }
  enum v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (xioctl(v->fd, VIDIOC_STREAMON, &type) < 0) {
    e = errno;
    hrp_err(msg, len, "camera %s: VIDIOC_STREAMON: %s", dev, strerror(e));
    goto fail;
  }
  return 0;
fail:
  dev_close(v);
  return errno_rc(e);
}

static void set_state(v4l2cam *v, int connected, int rc, const char *reason) {
  pthread_mutex_lock(&v->lock);
  v->connected = connected;
  v->state_rc = rc;
  snprintf(v->reason, sizeof v->reason, "%s", reason);
  pthread_cond_broadcast(&v->cond);
  pthread_mutex_unlock(&v->lock);
  cam_camera *cam = v->cam;
  CAM_STATS(cam, cam->stats.connected = connected);
  if (!connected) cam_note(cam, "%s", reason);
}

static void lost(v4l2cam *v, const char *what, int e) {
  char msg[256];
  hrp_err(msg, sizeof msg, "camera %s: lost (%s: %s); reopening", v->cam->device, what, strerror(e));
  dev_close(v);
  cam_camera *cam = v->cam;
  CAM_STATS(cam, cam->stats.lost++);
  set_state(v, 0, CAM_ENODEV, msg);
}

/* One dequeued buffer: check, publish to the consumer, requeue. */
static void deliver(v4l2cam *v, struct v4l2_buffer *buf) {
  cam_camera *cam = v->cam;
  const int w = cam->cfg.width, h = cam->cfg.height;
  if (buf->index >= (uint32_t)v->nbufs) {
    lost(v, "VIDIOC_DQBUF returned an unknown buffer", EINVAL);
    return;
  }
  if ((buf->flags & V4L2_BUF_FLAG_ERROR) || buf->bytesused < v->sizeimage) {
    CAM_STATS(cam, cam->stats.short_frames++);
    cam_note(cam, "camera %s: short frame dropped (%u of %zu bytes%s)", cam->device, buf->bytesused,
             v->sizeimage, (buf->flags & V4L2_BUF_FLAG_ERROR) ? ", error flag" : "");
  } else {
    double t, head[2], angle[2];
    cam_clock(cam, &t, head, angle);
    const uint8_t *src = v->bufs[buf->index].start;
    pthread_mutex_lock(&v->lock);
    if (v->bytesperline == (size_t)w * 2) {
      memcpy(v->ready, src, (size_t)w * h * 2);
    } else {
      for (int y = 0; y < h; y++)
        memcpy(v->ready + (size_t)y * w * 2, src + (size_t)y * v->bytesperline, (size_t)w * 2);
    }
    v->ready_seq++;
    v->ready_time = t;
    v->ready_head[0] = head[0];
    v->ready_head[1] = head[1];
    v->ready_angle[0] = angle[0];
    v->ready_angle[1] = angle[1];
    pthread_cond_broadcast(&v->cond);
    pthread_mutex_unlock(&v->lock);
    CAM_STATS(cam, cam->stats.captured++);
  }
  if (xioctl(v->fd, VIDIOC_QBUF, buf) < 0) lost(v, "VIDIOC_QBUF", errno);
}

static int still_running(v4l2cam *v) {
  pthread_mutex_lock(&v->lock);
  int r = v->running;
  pthread_mutex_unlock(&v->lock);
  return r;
}

static void *capture_thread(void *arg) {
  v4l2cam *v = arg;
  cam_camera *cam = v->cam;
  while (still_running(v)) {
    if (v->fd < 0) {
      char msg[256];
      int rc = dev_open(v, msg, sizeof msg);
      if (rc < 0) {
        CAM_STATS(cam, cam->stats.open_failures++);
        set_state(v, 0, rc, msg);
        struct timespec ts;
        abs_deadline(&ts, cam->cfg.reopen_interval);
        pthread_mutex_lock(&v->lock);
        while (v->running && pthread_cond_timedwait(&v->cond, &v->lock, &ts) != ETIMEDOUT) {}
        pthread_mutex_unlock(&v->lock);
        continue;
      }
      CAM_STATS(cam, cam->stats.opens++);
      set_state(v, 1, 0, "");
    }
    struct pollfd pfd = { .fd = v->fd, .events = POLLIN };
    int r = cam_v4l2_sys.poll(&pfd, 1, 100);
    if (r < 0) {
      if (errno == EINTR) continue;
      lost(v, "poll", errno);
      continue;
    }
    if (r == 0) continue;
    if (pfd.revents & (POLLERR | POLLHUP | POLLNVAL)) {
      lost(v, "poll reports the device gone", ENODEV);
      continue;
    }
    struct v4l2_buffer buf;
    memset(&buf, 0, sizeof buf);
    buf.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    buf.memory = V4L2_MEMORY_MMAP;
    if (xioctl(v->fd, VIDIOC_DQBUF, &buf) < 0) {
      if (errno == EAGAIN) continue;
      lost(v, "VIDIOC_DQBUF", errno);
      continue;
    }
    deliver(v, &buf);
  }
  dev_close(v);
  return NULL;
}

static void v4l2_free(v4l2cam *v) {
  pthread_mutex_destroy(&v->lock);
  pthread_cond_destroy(&v->cond);
  free(v->ready);
  free(v->out);
  free(v);
}

static int v4l2_start(cam_camera *cam, char *err, size_t errlen) {
  v4l2cam *v = calloc(1, sizeof *v);
  if (!v) { hrp_err(err, errlen, "camera v4l2: out of memory"); return CAM_ENOMEM; }
  v->cam = cam;
  v->fd = -1;
  v->running = 1;
  v->state_rc = CAM_ENODEV;
  snprintf(v->reason, sizeof v->reason, "camera %s: not opened yet", cam->device);
  pthread_mutex_init(&v->lock, NULL);
  pthread_condattr_t ca;
  pthread_condattr_init(&ca);
  pthread_condattr_setclock(&ca, CLOCK_MONOTONIC);
  pthread_cond_init(&v->cond, &ca);
  pthread_condattr_destroy(&ca);
  size_t bytes = (size_t)cam->cfg.width * cam->cfg.height * 2;
  v->ready = malloc(bytes);
  v->out = malloc(bytes);
  if (!v->ready || !v->out) {
    v4l2_free(v);
    hrp_err(err, errlen, "camera v4l2: out of memory");
    return CAM_ENOMEM;
  }
  cam->priv = v;
  if (pthread_create(&v->thread, NULL, capture_thread, v) != 0) {
    cam->priv = NULL;
    v4l2_free(v);
    hrp_err(err, errlen, "camera v4l2: cannot start the capture thread");
    return CAM_ENOMEM;
  }
  v->thread_started = 1;
  return 0;
}

static int v4l2_grab(cam_camera *cam, cam_frame *f, double timeout_s, char *err, size_t errlen) {
  v4l2cam *v = cam->priv;
  struct timespec ts;
  abs_deadline(&ts, timeout_s);
  pthread_mutex_lock(&v->lock);
  while (v->ready_seq == v->taken_seq) {
    if (pthread_cond_timedwait(&v->cond, &v->lock, &ts) == ETIMEDOUT) break;
  }
  if (v->ready_seq == v->taken_seq) {
    int rc = v->connected ? CAM_ETIMEOUT : v->state_rc;
    if (v->connected)
      hrp_err(err, errlen, "camera %s: no frame within %.3f s", cam->device, timeout_s);
    else
      hrp_err(err, errlen, "%s", v->reason);
    pthread_mutex_unlock(&v->lock);
    return rc;
  }
  memcpy(v->out, v->ready, (size_t)cam->cfg.width * cam->cfg.height * 2);
  v->taken_seq = v->ready_seq;
  f->seq = v->ready_seq;
  f->time = v->ready_time;
  f->head[0] = v->ready_head[0];
  f->head[1] = v->ready_head[1];
  f->angle[0] = v->ready_angle[0];
  f->angle[1] = v->ready_angle[1];
  pthread_mutex_unlock(&v->lock);
  f->yuyv = v->out;
  f->width = cam->cfg.width;
  f->height = cam->cfg.height;
  cam_publish(cam, f);
  return 0;
}

static void v4l2_stop(cam_camera *cam) {
  v4l2cam *v = cam->priv;
  if (!v) return;
  pthread_mutex_lock(&v->lock);
  v->running = 0;
  pthread_cond_broadcast(&v->cond);
  pthread_mutex_unlock(&v->lock);
  if (v->thread_started) pthread_join(v->thread, NULL);
  v4l2_free(v);
  cam->priv = NULL;
}

const cam_driver cam_driver_v4l2 = { "v4l2", v4l2_start, v4l2_grab, v4l2_stop };
