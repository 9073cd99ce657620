/* The V4L2 driver's capture path against a fake UVC device (tests/fake_uvc.c, put into the
 * driver's system-call table in this process). Covers an absent camera and retry, format
 * negotiation, controls, buffer queueing and mapping, frames delivered intact (also with padded
 * lines), short frames, a device that disappears mid-run and comes back, and bad devices. TAP. */
#include "camera/camera.h"
#include "fake_uvc.h"
#include "tap.h"

#include <linux/videodev2.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define DEV "/dev/fakevideo-hrp-test"

static int ctrl(uint32_t id) {
  char name[32];
  snprintf(name, sizeof name, "ctrl_%u", id);
  return fake_uvc_get(name);
}

/* The fake device's frame k: bytes 0..3 = k, byte i = (i*7 + k) & 255 (unpadded index). */
static int frame_ok(const cam_frame *f) {
  uint32_t k;
  if (!f->yuyv) return 0;
  memcpy(&k, f->yuyv, 4);
  size_t n = (size_t)f->width * f->height * 2;
  for (size_t i = 4; i < n; i++)
    if (f->yuyv[i] != (uint8_t)(i * 7 + k)) return 0;
  return 1;
}

static uint32_t frame_k(const cam_frame *f) {
  uint32_t k = 0;
  if (f->yuyv) memcpy(&k, f->yuyv, 4);   /* no frame (an earlier check failed): no crash */
  return k;
}

/* Grabs until rc is returned or `seconds` pass; returns the last rc. */
static int grab_until(cam_camera *cam, cam_frame *f, int want, double seconds, char *err, size_t len) {
  int rc = -99;
  for (int i = 0; i < (int)(seconds / 0.1); i++) {
    rc = cam_grab(cam, f, 0.1, err, len);
    if (rc == want) break;
  }
  return rc;
}

static void base_config(cam_config *cfg) {
  cam_config_default(cfg);
  cfg->driver = "v4l2";
  cfg->device = DEV;
  cfg->fps = 200;
  cfg->robot_id = -1;   /* no shm: this test is about the device */
  cfg->reopen_interval = 0.05;
  cfg->exposure = 150;
  cfg->gain = 40;
  cfg->white_balance = 4000;
  cfg->saturation = 10;   /* the fake device refuses this one */
}

static void test_lifecycle(void) {
  cam_config cfg;
  base_config(&cfg);
  cam_camera *cam = NULL;
  char err[512] = "";
  cam_frame f;
  cam_stats st;

  fake_uvc_set_present(0);
  check(cam_open(&cfg, &cam, err, sizeof err) == 0, "open succeeds with the camera absent");
  int rc = cam_grab(cam, &f, 0.3, err, sizeof err);
  check(rc == CAM_ENODEV && strstr(err, DEV) && strstr(err, "No such file"),
        "absent camera reported with its path");
  cam_get_stats(cam, &st);
  check(st.open_failures >= 2 && !st.connected, "absent camera retried (open failures counted)");

  fake_uvc_set_present(1);
  rc = grab_until(cam, &f, 0, 3.0, err, sizeof err);
  check(rc == 0 && f.width == 640 && f.height == 480, "camera plugged in: a 640x480 frame arrives");
  check(rc == 0 && frame_ok(&f), "frame delivered intact through the mmap buffers");

  check(fake_uvc_get("fmt_width") == 640 && fake_uvc_get("fmt_height") == 480, "format negotiated 640x480");
  check(fake_uvc_get("reqbufs") >= 1 && fake_uvc_get("live_maps") == 4 && fake_uvc_get("streamon") == 1,
        "4 buffers requested, mapped and streaming");
  check(fake_uvc_get("qbuf") >= 4 + fake_uvc_get("dqbuf") - 1, "every dequeued buffer is queued again");
  check(ctrl(V4L2_CID_EXPOSURE_AUTO) == V4L2_EXPOSURE_MANUAL && ctrl(V4L2_CID_EXPOSURE_ABSOLUTE) == 150,
        "exposure set manual, 150");
  check(ctrl(V4L2_CID_GAIN) == 40, "gain set");
  check(ctrl(V4L2_CID_AUTO_WHITE_BALANCE) == 0 && ctrl(V4L2_CID_WHITE_BALANCE_TEMPERATURE) == 4000,
        "white balance manual, 4000 K");
  cam_get_stats(cam, &st);
  check(st.control_errors == 1, "a refused control is counted, not fatal");

  int ok = 1;
  uint32_t last_seq = f.seq, last_k = frame_k(&f);
  for (int i = 0; i < 30 && ok; i++) {
    rc = cam_grab(cam, &f, 1.0, err, sizeof err);
    ok = rc == 0 && f.seq > last_seq && frame_k(&f) > last_k && frame_ok(&f);
    last_seq = f.seq;
    last_k = frame_k(&f);
  }
  check(ok, "30 more frames, in order, each intact");

  fake_uvc_short_frames(3);
  int good_after = 0;
  for (int i = 0; i < 40; i++) {
    rc = cam_grab(cam, &f, 1.0, err, sizeof err);
    if (rc == 0 && frame_ok(&f)) good_after++;
  }
  cam_get_stats(cam, &st);
  check(st.short_frames == 3 && good_after == 40 && strstr(st.last_error, "short frame"),
        "3 short frames counted and dropped; capture goes on");

  fake_uvc_set_present(0);
  rc = grab_until(cam, &f, CAM_ENODEV, 3.0, err, sizeof err);
  check(rc == CAM_ENODEV && strstr(err, DEV), "unplugged mid-run: grab reports the device lost");
  cam_get_stats(cam, &st);
  check(st.lost == 1 && !st.connected, "loss counted");
  usleep(100000);
  check(fake_uvc_get("live_maps") == 0 && fake_uvc_get("open") == 0, "buffers unmapped and device closed");

  fake_uvc_set_present(1);
  rc = grab_until(cam, &f, 0, 3.0, err, sizeof err);
  cam_get_stats(cam, &st);
  check(rc == 0 && frame_ok(&f) && st.opens == 2 && st.connected, "plugged back: reopened, frames again");

  cam_close(cam);
  check(fake_uvc_get("live_maps") == 0 && fake_uvc_get("open") == 0, "close releases buffers and device");
}

static void test_padded_lines(void) {
  cam_config cfg;
  base_config(&cfg);
  cfg.width = 320;
  cfg.height = 240;
  fake_uvc_set_pad(64);
  cam_camera *cam = NULL;
  char err[512];
  cam_frame f;
  int rc = cam_open(&cfg, &cam, err, sizeof err);
  if (rc == 0) rc = grab_until(cam, &f, 0, 3.0, err, sizeof err);
  check(rc == 0 && f.width == 320 && f.height == 240 && frame_ok(&f),
        "padded lines (bytesperline > width*2): frame unpadded intact");
  cam_close(cam);
  fake_uvc_set_pad(0);
}

static void test_bad_devices(void) {
  cam_config cfg;
  base_config(&cfg);
  cfg.width = 800;
  cfg.height = 600;
  cam_camera *cam = NULL;
  char err[512];
  cam_frame f;
  int rc = cam_open(&cfg, &cam, err, sizeof err);
  if (rc == 0) rc = grab_until(cam, &f, CAM_EFORMAT, 2.0, err, sizeof err);
  check(rc == CAM_EFORMAT && strstr(err, "640x480") && strstr(err, "800x600"),
        "unsupported size: device's offer and config named");
  cam_close(cam);

  base_config(&cfg);
  cfg.device = "/dev/null";
  rc = cam_open(&cfg, &cam, err, sizeof err);
  if (rc == 0) rc = grab_until(cam, &f, CAM_EFORMAT, 2.0, err, sizeof err);
  check(rc == CAM_EFORMAT && strstr(err, "not a V4L2 device"), "a non-V4L2 file is reported");
  cam_close(cam);

  base_config(&cfg);
  cfg.driver = "firewire";
  rc = cam_open(&cfg, &cam, err, sizeof err);
  check(rc == CAM_EARG && strstr(err, "firewire"), "unknown driver refused at open");
  base_config(&cfg);
  cfg.width = 641;
  check(cam_open(&cfg, &cam, err, sizeof err) == CAM_EARG, "odd width refused at open");
}

int main(void) {
  const cam_sys libc_calls = cam_v4l2_sys;
  fake_uvc_install(DEV, 1);
  check(cam_v4l2_sys.open != libc_calls.open, "the fake UVC device is in the driver's table");
  test_lifecycle();
  test_padded_lines();
  test_bad_devices();
  cam_v4l2_sys = libc_calls;
  return tap_done();
}
