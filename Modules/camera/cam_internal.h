/* camera: what the drivers share (not installed; include camera.h instead). */
#ifndef HRP_CAM_INTERNAL_H
#define HRP_CAM_INTERNAL_H

#include <poll.h>
#include <pthread.h>
#include <sys/types.h>

#include "camera/camera.h"
#include "shm/shm.h"
#include "errmsg.h"

typedef struct cam_driver {
  const char *name;
  /* sets up the driver's private state; errors here are configuration errors */
  int (*start)(cam_camera *cam, char *err, size_t errlen);
  int (*grab)(cam_camera *cam, cam_frame *frame, double timeout_s, char *err, size_t errlen);
  void (*stop)(cam_camera *cam);
} cam_driver;

struct cam_camera {
  cam_config cfg;
  char device[256];
  const cam_driver *drv;
  void *priv;                 /* the driver's state */

  pthread_mutex_t stats_lock;
  cam_stats stats;

  /* shm (robot_id >= 0) */
  int robot_id;
  shm_schema *schema;
  shm_block *image;           /* camera.image */
  int32_t *img_width, *img_height;
  uint32_t *img_frame;
  double *img_time, *img_head, *img_angle;
  uint8_t *img_yuyv;
  int img_capacity;           /* bytes of img_yuyv */
  shm_block *sensor;          /* dcm.sensor: robot clock and head angles */
  double *sensor_time, *sensor_position, *sensor_angle;
  int32_t *sensor_pid;
  int sensor_njoint;
};

extern const cam_driver cam_driver_v4l2, cam_driver_dummy, cam_driver_sim;

/* The system calls the v4l2 driver makes on its device, through this table so a test can put a
 * fake device in their place in its own process (Modules/camera/tests/fake_uvc.c), where a
 * sanitizer sees both. By default the libc functions themselves: the driver's call costs one
 * indirect jump on top of the system call. A test replaces it before cam_open and restores it after
 * cam_close (the capture thread reads it). */
typedef struct cam_sys {
  int (*open)(const char *path, int flags, ...);
  int (*close)(int fd);
  int (*ioctl)(int fd, unsigned long req, ...);
  void *(*mmap)(void *addr, size_t len, int prot, int flags, int fd, off_t off);
  int (*munmap)(void *addr, size_t len);
  int (*poll)(struct pollfd *fds, nfds_t n, int timeout_ms);
} cam_sys;
extern cam_sys cam_v4l2_sys;

/* Records a problem in stats.last_error (thread-safe). */
void cam_note(cam_camera *cam, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Runs fn under the stats lock: use the macro below for counter updates. */
#define CAM_STATS(cam, stmt) do { pthread_mutex_lock(&(cam)->stats_lock); stmt; \
                                  pthread_mutex_unlock(&(cam)->stats_lock); } while (0)
/* Robot clock, head angles and torso roll and pitch now (dcm.sensor if a DCM is alive, else
 * monotonic time and zeros). */
void cam_clock(cam_camera *cam, double *time, double head[2], double angle[2]);
/* Copies a delivered frame into camera.image (no-op without shm). */
void cam_publish(cam_camera *cam, const cam_frame *frame);
/* Monotonic wall time, s. */
double cam_now(void);

#endif
