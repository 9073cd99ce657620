/* camera: one interface, three drivers (libhrpcam.so).
 *
 *   "v4l2"  a UVC camera through Video4Linux2: YUYV, memory-mapped buffers, capture on its own
 *           thread, controls (exposure, gain, white balance, ...) set from the config. A camera
 *           that is absent, unplugged mid-run or delivers short frames is reported (cam_stats,
 *           the grab's error message) and reopened every reopen_interval seconds.
 *   "dummy" random frames (noise plus random solid blobs) at the configured rate: bring-up and
 *           soak tests without a camera.
 *   "sim"   frames rendered by the sim DCM into the shm block camera.image.
 *
 * The v4l2 and dummy drivers publish every frame they deliver into the robot's camera.image
 * block (unless robot_id < 0), stamped with the robot's clock and head angles from dcm.sensor,
 * so any tool can read the current frame; the sim driver reads that block.
 *
 * Lifecycle: cam_open (parse config, start capture), cam_grab per frame, cam_close.
 * Functions return 0 or a negative CAM_E* code with a message in the caller's buffer. No exit().
 */
#ifndef HRP_CAMERA_H
#define HRP_CAMERA_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum {
  CAM_EARG = -1,      /* invalid configuration or argument (not retried) */
  CAM_ETIMEOUT = -2,  /* no new frame within the timeout; the camera is connected */
  CAM_ENODEV = -3,    /* the camera is absent or was lost; it is being reopened */
  CAM_EFORMAT = -4,   /* the device cannot give the configured format (retried) */
  CAM_ESHM = -5,      /* shared memory unavailable */
  CAM_ENOMEM = -6
};

#define CAM_CTRL_UNSET (-1000000)   /* leave a control as the device has it */

typedef struct cam_config {
  const char *driver;          /* "v4l2", "dummy" or "sim" */
  const char *device;          /* v4l2: device path, e.g. "/dev/video0" */
  int width, height;           /* px (width even) */
  double fps;                  /* frames/s requested (v4l2), produced (dummy; 0 = unpaced) */
  int nbuffers;                /* v4l2: mmap buffers, 2..16 (0 = 4) */
  double reopen_interval;      /* s between attempts to open a missing camera (0 = 1 s) */
  /* v4l2 controls, CAM_CTRL_UNSET to leave as is. exposure/white_balance: -1 = automatic. */
  int exposure;                /* V4L2_CID_EXPOSURE_ABSOLUTE, 100 us units */
  int gain;                    /* V4L2_CID_GAIN */
  int white_balance;           /* V4L2_CID_WHITE_BALANCE_TEMPERATURE, K */
  int brightness, contrast, saturation;
  uint32_t seed;               /* dummy: random seed */
  int robot_id;                /* shm robot (0 = $ROBOT_ID), < 0: no shm at all */
  int head_joint[2];           /* indices of head pan and tilt in dcm.sensor position */
} cam_config;

/* Fills cfg with defaults: v4l2 /dev/video0 640x480 at 30 fps, 4 buffers, controls unset,
 * robot_id 0, head joints 0 and 1. */
void cam_config_default(cam_config *cfg);

typedef struct cam_frame {
  const uint8_t *yuyv;         /* width*height*2 bytes, valid until the next cam_grab/cam_close */
  int32_t width, height;       /* px */
  uint32_t seq;                /* frames delivered by this camera since open (sim: DCM's count) */
  double time;                 /* s, robot clock at capture (monotonic wall time without a DCM) */
  double head[2];              /* rad, head pan and tilt at capture */
  double angle[2];             /* rad, torso roll and pitch at capture (dcm.sensor angle; 0 without a DCM) */
} cam_frame;

typedef struct cam_stats {
  uint32_t frames;             /* frames delivered to cam_grab */
  uint32_t captured;           /* frames captured from the device (v4l2) */
  uint32_t short_frames;       /* frames refused because they were shorter than the format */
  uint32_t lost;               /* times the device disappeared or failed mid-run */
  uint32_t opens;              /* successful (re)opens of the device */
  uint32_t open_failures;      /* failed attempts to open or set up the device */
  uint32_t control_errors;     /* controls the device refused */
  int32_t connected;           /* 1 while the camera is streaming */
  char last_error[256];        /* most recent problem, "" if none */
} cam_stats;

typedef struct cam_camera cam_camera;

/* Opens the driver named in cfg (strings are copied). A missing v4l2 device is not an error
 * here: capture starts and keeps retrying; cam_grab reports it. */
int cam_open(const cam_config *cfg, cam_camera **out, char *err, size_t errlen);
/* Waits up to timeout_s for a frame newer than the last one returned. 0 and *frame filled,
 * or CAM_ETIMEOUT / CAM_ENODEV / CAM_EFORMAT with the reason in err. */
int cam_grab(cam_camera *cam, cam_frame *frame, double timeout_s, char *err, size_t errlen);
/* Counters and state (thread-safe snapshot). */
void cam_get_stats(cam_camera *cam, cam_stats *out);
/* Stops capture, releases the device and shm. NULL is ignored. */
void cam_close(cam_camera *cam);

#ifdef __cplusplus
}
#endif
#endif
