/* camera: the interface shared by every driver (config, open/close, stats, shm publishing). */
#include "camera/cam_internal.h"

#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

void cam_note(cam_camera *cam, const char *fmt, ...) {
  char buf[sizeof cam->stats.last_error];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  CAM_STATS(cam, memcpy(cam->stats.last_error, buf, sizeof buf));
}

double cam_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void cam_config_default(cam_config *cfg) {
  memset(cfg, 0, sizeof *cfg);
  cfg->driver = "v4l2";
  cfg->device = "/dev/video0";
  cfg->width = 640;
  cfg->height = 480;
  cfg->fps = 30;
  cfg->nbuffers = 4;
  cfg->reopen_interval = 1.0;
  cfg->exposure = cfg->gain = cfg->white_balance = CAM_CTRL_UNSET;
  cfg->brightness = cfg->contrast = cfg->saturation = CAM_CTRL_UNSET;
  cfg->seed = 1;
  cfg->robot_id = 0;
  cfg->head_joint[0] = 0;
  cfg->head_joint[1] = 1;
}

static void shm_release(cam_camera *cam) {
  if (cam->image) shm_block_close(cam->image);
  if (cam->sensor) shm_block_close(cam->sensor);
  if (cam->schema) shm_schema_free(cam->schema);
  cam->image = cam->sensor = NULL;
  cam->schema = NULL;
}

/* Attaches camera.image (required) and dcm.sensor (for clock and head angles). */
static int shm_attach(cam_camera *cam, char *err, size_t errlen) {
  char e[512];
  if (shm_schema_load(NULL, &cam->schema, e, sizeof e) < 0) {
    hrp_err(err, errlen, "camera: shm schema: %s", e);
    return CAM_ESHM;
  }
  if (shm_block_open(cam->schema, "camera.image", cam->robot_id, SHM_OPEN_CREATE, &cam->image, e,
                     sizeof e) < 0) {
    hrp_err(err, errlen, "camera: %s", e);
    shm_release(cam);
    return CAM_ESHM;
  }
  shm_block *b = cam->image;
  int count = 0;
  cam->img_width = shm_field_require(b, "width", SHM_I32, 1, e, sizeof e);
  cam->img_height = cam->img_width ? shm_field_require(b, "height", SHM_I32, 1, e, sizeof e) : NULL;
  cam->img_frame = cam->img_height ? shm_field_require(b, "frame", SHM_U32, 1, e, sizeof e) : NULL;
  cam->img_time = cam->img_frame ? shm_field_require(b, "time", SHM_F64, 1, e, sizeof e) : NULL;
  cam->img_head = cam->img_time ? shm_field_require(b, "head", SHM_F64, 2, e, sizeof e) : NULL;
  cam->img_angle = cam->img_head ? shm_field_require(b, "angle", SHM_F64, 2, e, sizeof e) : NULL;
  cam->img_yuyv = cam->img_angle ? shm_field_require(b, "yuyv", SHM_U8, 2, e, sizeof e) : NULL;
  if (!cam->img_yuyv) {
    hrp_err(err, errlen, "camera: %s", e);
    shm_release(cam);
    return CAM_ESHM;
  }
  shm_field_ptr(b, "yuyv", NULL, &count);
  cam->img_capacity = count;
  if (shm_block_open(cam->schema, "dcm.sensor", cam->robot_id, SHM_OPEN_CREATE, &cam->sensor, e,
                     sizeof e) == 0) {
    int n = 0;
    cam->sensor_time = shm_field_ptr(cam->sensor, "time", NULL, NULL);
    cam->sensor_position = shm_field_ptr(cam->sensor, "position", NULL, &n);
    cam->sensor_pid = shm_field_ptr(cam->sensor, "dcm_pid", NULL, NULL);
    int na = 0;
    cam->sensor_angle = shm_field_ptr(cam->sensor, "angle", NULL, &na);
    if (na < 2) cam->sensor_angle = NULL;
    cam->sensor_njoint = n;
  }
  return 0;
}

int cam_open(const cam_config *cfg, cam_camera **out, char *err, size_t errlen) {
  if (!cfg || !out) { hrp_err(err, errlen, "cam_open: NULL argument"); return CAM_EARG; }
  *out = NULL;
  const cam_driver *drv = NULL;
  const char *name = cfg->driver ? cfg->driver : "(null)";
  if (strcmp(name, "v4l2") == 0) drv = &cam_driver_v4l2;
  else if (strcmp(name, "dummy") == 0) drv = &cam_driver_dummy;
  else if (strcmp(name, "sim") == 0) drv = &cam_driver_sim;
  if (!drv) {
    hrp_err(err, errlen, "camera: unknown driver '%s' (v4l2, dummy or sim)", name);
    return CAM_EARG;
  }
  if (cfg->width <= 0 || cfg->height <= 0 || (cfg->width & 1) || cfg->width > 8192 ||
      cfg->height > 8192) {
    hrp_err(err, errlen, "camera: invalid size %dx%d (width must be even)", cfg->width, cfg->height);
    return CAM_EARG;
  }
  if (cfg->fps < 0 || cfg->fps > 1000) {
    hrp_err(err, errlen, "camera: invalid fps %g", cfg->fps);
    return CAM_EARG;
  }
  cam_camera *cam = calloc(1, sizeof *cam);
  if (!cam) { hrp_err(err, errlen, "camera: out of memory"); return CAM_ENOMEM; }
  cam->cfg = *cfg;
  snprintf(cam->device, sizeof cam->device, "%s", cfg->device ? cfg->device : "/dev/video0");
  cam->cfg.device = cam->device;
  cam->cfg.driver = drv->name;
  if (cam->cfg.nbuffers == 0) cam->cfg.nbuffers = 4;
  if (cam->cfg.reopen_interval <= 0) cam->cfg.reopen_interval = 1.0;
  cam->drv = drv;
  pthread_mutex_init(&cam->stats_lock, NULL);
  cam->robot_id = cfg->robot_id == 0 ? shm_robot_id() : cfg->robot_id;
  if (cfg->robot_id >= 0 || drv == &cam_driver_sim) {
    if (cfg->robot_id < 0) {
      hrp_err(err, errlen, "camera: the sim driver needs shm (robot_id >= 0)");
      free(cam);
      return CAM_EARG;
    }
    int rc = shm_attach(cam, err, errlen);
    if (rc < 0) { free(cam); return rc; }
    if (drv != &cam_driver_sim && cfg->width * cfg->height * 2 > cam->img_capacity) {
      hrp_err(err, errlen, "camera: %dx%d frames do not fit camera.image (%d bytes; see cam_bytes in "
              "Config/shm.schema)", cfg->width, cfg->height, cam->img_capacity);
      shm_release(cam);
      free(cam);
      return CAM_EARG;
    }
  }
  int rc = drv->start(cam, err, errlen);
  if (rc < 0) {
    shm_release(cam);
    pthread_mutex_destroy(&cam->stats_lock);
    free(cam);
    return rc;
  }
  *out = cam;
  return 0;
}

int cam_grab(cam_camera *cam, cam_frame *frame, double timeout_s, char *err, size_t errlen) {
  if (!cam || !frame) { hrp_err(err, errlen, "cam_grab: NULL argument"); return CAM_EARG; }
  int rc = cam->drv->grab(cam, frame, timeout_s, err, errlen);
  if (rc == 0) CAM_STATS(cam, cam->stats.frames++);
  return rc;
}

void cam_get_stats(cam_camera *cam, cam_stats *out) {
  if (!cam || !out) return;
  CAM_STATS(cam, *out = cam->stats);
}

void cam_close(cam_camera *cam) {
  if (!cam) return;
  cam->drv->stop(cam);
  shm_release(cam);
  pthread_mutex_destroy(&cam->stats_lock);
  free(cam);
}

void cam_clock(cam_camera *cam, double *time, double head[2], double angle[2]) {
  head[0] = head[1] = 0;
  angle[0] = angle[1] = 0;
  if (cam->sensor && cam->sensor_time && cam->sensor_pid && *cam->sensor_pid > 0 &&
      shm_pid_alive(*cam->sensor_pid)) {
    uint32_t seq;
    int i0 = cam->cfg.head_joint[0], i1 = cam->cfg.head_joint[1];
    int ok = cam->sensor_position && i0 >= 0 && i1 >= 0 && i0 < cam->sensor_njoint &&
             i1 < cam->sensor_njoint;
    do {
      seq = shm_read_begin(cam->sensor);
      *time = *cam->sensor_time;
      if (ok) { head[0] = cam->sensor_position[i0]; head[1] = cam->sensor_position[i1]; }
      if (cam->sensor_angle) { angle[0] = cam->sensor_angle[0]; angle[1] = cam->sensor_angle[1]; }
    } while (shm_read_retry(cam->sensor, seq));
    return;
  }
  *time = cam_now();
}

void cam_publish(cam_camera *cam, const cam_frame *f) {
  if (!cam->image) return;
  size_t bytes = (size_t)f->width * f->height * 2;
  if (bytes > (size_t)cam->img_capacity) return;   /* checked at open */
  shm_write_begin(cam->image);
  *cam->img_width = f->width;
  *cam->img_height = f->height;
  *cam->img_time = f->time;
  cam->img_head[0] = f->head[0];
  cam->img_head[1] = f->head[1];
  cam->img_angle[0] = f->angle[0];
  cam->img_angle[1] = f->angle[1];
  memcpy(cam->img_yuyv, f->yuyv, bytes);
  *cam->img_frame = f->seq;
  shm_write_end(cam->image);
}
