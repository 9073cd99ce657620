/* camera: the sim driver. The sim DCM renders the head camera's view into the shm block
 * camera.image; this driver waits for a frame newer than the last one and copies it out
 * consistently (the block's sequence lock). */
#include "camera/cam_internal.h"

#include <stdlib.h>
#include <string.h>

typedef struct simcam {
  uint8_t *buf;
  uint32_t last_frame;
  int have_last;
} simcam;

static int sim_start(cam_camera *cam, char *err, size_t errlen) {
  simcam *s = calloc(1, sizeof *s);
  if (!s || !(s->buf = malloc((size_t)cam->img_capacity))) {
    free(s);
    hrp_err(err, errlen, "camera sim: out of memory");
    return CAM_ENOMEM;
  }
  cam->priv = s;
  return 0;
}

static int sim_grab(cam_camera *cam, cam_frame *f, double timeout_s, char *err, size_t errlen) {
  simcam *s = cam->priv;
  shm_header *h = shm_block_header(cam->image);
  double deadline = cam_now() + (timeout_s > 0 ? timeout_s : 0);
  for (;;) {
    uint32_t writes = __atomic_load_n(&h->writes, __ATOMIC_ACQUIRE);
    uint32_t frame = __atomic_load_n(cam->img_frame, __ATOMIC_ACQUIRE);
    if (frame != 0 && (!s->have_last || frame != s->last_frame)) {
      for (int attempt = 0; attempt < 8; attempt++) {
        uint32_t seq = shm_read_begin(cam->image);
        int w = *cam->img_width, hh = *cam->img_height;
        f->seq = *cam->img_frame;
        f->time = *cam->img_time;
        f->head[0] = cam->img_head[0];
        f->head[1] = cam->img_head[1];
        f->angle[0] = cam->img_angle[0];
        f->angle[1] = cam->img_angle[1];
        long bytes = (long)w * hh * 2;
        int valid = w > 0 && hh > 0 && !(w & 1) && bytes <= cam->img_capacity;
        if (valid) memcpy(s->buf, cam->img_yuyv, (size_t)bytes);
        if (shm_read_retry(cam->image, seq)) continue;
        if (!valid) {
          cam_note(cam, "camera sim: camera.image holds an invalid size %dx%d", w, hh);
          hrp_err(err, errlen, "camera sim: camera.image holds an invalid size %dx%d", w, hh);
          s->last_frame = f->seq;
          s->have_last = 1;
          return CAM_EFORMAT;
        }
        f->width = w;
        f->height = hh;
        f->yuyv = s->buf;
        s->last_frame = f->seq;
        s->have_last = 1;
        CAM_STATS(cam, cam->stats.connected = 1; cam->stats.captured++);
        return 0;
      }
      /* torn 8 times in a row: the writer is busy; wait for its next write */
    }
    double left = deadline - cam_now();
    if (left <= 0) break;
    /* woken by the writer's shm_write_end; polled every 10 ms for writers that skip the lock */
    shm_wait_write(cam->image, writes, left < 0.01 ? left : 0.01);
  }
  int pid_known = cam->sensor_pid && *cam->sensor_pid > 0 && shm_pid_alive(*cam->sensor_pid);
  CAM_STATS(cam, cam->stats.connected = pid_known);
  if (!pid_known) {
    hrp_err(err, errlen, "camera sim: no frame within %.3f s and no sim DCM running (start ./run_dcm)",
            timeout_s);
    return CAM_ENODEV;
  }
  hrp_err(err, errlen, "camera sim: no new frame in camera.image within %.3f s", timeout_s);
  return CAM_ETIMEOUT;
}

static void sim_stop(cam_camera *cam) {
  simcam *s = cam->priv;
  if (!s) return;
  free(s->buf);
  free(s);
  cam->priv = NULL;
}

const cam_driver cam_driver_sim = { "sim", sim_start, sim_grab, sim_stop };
