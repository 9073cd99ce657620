/* camera: the dummy driver. Random frames (noise with random solid discs and bars of random
 * colour), paced at cfg.fps (unpaced at 0). For bring-up and soak tests without a camera. */
#include "camera/cam_internal.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct dummy {
  uint8_t *buf;
  uint64_t rng;
  uint32_t seq;
  double next;      /* s, monotonic time of the next frame */
} dummy;

static uint64_t next_rand(uint64_t *s) {   /* xorshift64* */
  uint64_t x = *s;
  x ^= x >> 12;
  x ^= x << 25;
  x ^= x >> 27;
  *s = x;
  return x * 0x2545F4914F6CDD1DULL;
}

static int dummy_start(cam_camera *cam, char *err, size_t errlen) {
  dummy *d = calloc(1, sizeof *d);
  if (!d) { hrp_err(err, errlen, "camera dummy: out of memory"); return CAM_ENOMEM; }
  d->buf = malloc((size_t)cam->cfg.width * cam->cfg.height * 2);
  if (!d->buf) { free(d); hrp_err(err, errlen, "camera dummy: out of memory"); return CAM_ENOMEM; }
  d->rng = 0x9E3779B97F4A7C15ULL ^ ((uint64_t)cam->cfg.seed << 1 | 1);
  d->next = cam_now();
  cam->priv = d;
  CAM_STATS(cam, cam->stats.connected = 1; cam->stats.opens = 1);
  return 0;
}

static void sleep_until(double t) {
  double dt = t - cam_now();
  if (dt <= 0) return;
  struct timespec ts = { (time_t)dt, (long)((dt - (double)(time_t)dt) * 1e9) };
  while (nanosleep(&ts, &ts) != 0 && errno == EINTR) {}
}

/* Fills a w x h YUYV frame: uniform noise, then a few solid blobs. */
static void render(dummy *d, int w, int h) {
  size_t n = (size_t)w * h * 2;
  size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    uint64_t r = next_rand(&d->rng);
    memcpy(d->buf + i, &r, 8);
  }
  for (; i < n; i++) d->buf[i] = (uint8_t)next_rand(&d->rng);
  int nblobs = (int)(next_rand(&d->rng) % 6);
  for (int b = 0; b < nblobs; b++) {
    uint64_t r = next_rand(&d->rng);
    int cx = (int)(r % (uint64_t)w), cy = (int)((r >> 16) % (uint64_t)h);
    int rad = 2 + (int)((r >> 32) % (uint64_t)(h / 4));
    int bar = (int)((r >> 48) & 1);
    uint64_t c = next_rand(&d->rng);
    uint8_t y = (uint8_t)c, u = (uint8_t)(c >> 8), v = (uint8_t)(c >> 16);
    for (int yy = cy - rad; yy <= cy + rad; yy++) {
      if (yy < 0 || yy >= h) continue;
      uint8_t *row = d->buf + (size_t)yy * w * 2;
      for (int xx = (cx - rad) & ~1; xx <= cx + rad; xx += 2) {
        if (xx < 0 || xx + 1 >= w) continue;
        int dx = xx - cx, dy = yy - cy;
        if (!bar && dx * dx + dy * dy > rad * rad) continue;
        if (bar && abs(dx) > rad / 4) continue;
        uint8_t *p = row + (size_t)xx * 2;
        p[0] = y; p[1] = u; p[2] = y; p[3] = v;
      }
    }
  }
}

static int dummy_grab(cam_camera *cam, cam_frame *f, double timeout_s, char *err, size_t errlen) {
  dummy *d = cam->priv;
  if (cam->cfg.fps > 0) {
    double now = cam_now();
    if (d->next > now + timeout_s) {
      sleep_until(now + timeout_s);
      hrp_err(err, errlen, "camera dummy: no frame within %.3f s", timeout_s);
      return CAM_ETIMEOUT;
    }
    sleep_until(d->next);
    d->next += 1.0 / cam->cfg.fps;
    if (d->next < cam_now()) d->next = cam_now();   /* fell behind: do not burst */
  }
  render(d, cam->cfg.width, cam->cfg.height);
  f->yuyv = d->buf;
  f->width = cam->cfg.width;
  f->height = cam->cfg.height;
  f->seq = ++d->seq;
  cam_clock(cam, &f->time, f->head, f->angle);
  cam_publish(cam, f);
  return 0;
}

static void dummy_stop(cam_camera *cam) {
  dummy *d = cam->priv;
  if (!d) return;
  free(d->buf);
  free(d);
  cam->priv = NULL;
}

const cam_driver cam_driver_dummy = { "dummy", dummy_start, dummy_grab, dummy_stop };
