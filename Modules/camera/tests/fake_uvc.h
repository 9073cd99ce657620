/* fake_uvc: a fake UVC camera for the v4l2 driver's tests (fake_uvc.c says what it emulates). */
#ifndef HRP_FAKE_UVC_H
#define HRP_FAKE_UVC_H

#include "camera/cam_internal.h"

/* The fake's calls, in the driver's table's shape. */
extern const cam_sys fake_uvc_sys;
/* Makes `path` the fake device (present or not) and puts fake_uvc_sys into cam_v4l2_sys. */
void fake_uvc_install(const char *path, int present);
/* Unplugs (an open device dies: ENODEV, POLLERR) or plugs the device back in. */
void fake_uvc_set_present(int present);
/* The next n frames are delivered with half their bytes. */
void fake_uvc_short_frames(int n);
/* Extra bytes at the end of every line (bytesperline > width*2). */
void fake_uvc_set_pad(int bytes);
/* Counters: opens closes streamon streamoff qbuf dqbuf live_maps reqbufs fmt_width fmt_height
 * open ctrl_<id in decimal>; -1 for an unknown name. */
int fake_uvc_get(const char *name);

#endif
