/* dxl_usb.c: find Dynamixel USB adapters with libusb and set the FTDI latency timer. */
#include "dynamixel/dynamixel.h"

#include <libusb.h>
#include <stdio.h>
#include <string.h>

typedef struct known_adapter { uint16_t vendor, product; const char *name; int ftdi; } known_adapter;

static const known_adapter KNOWN[] = {
  { 0x0403, 0x6014, "U2D2 (FTDI FT232H)", 1 },
  { 0x0403, 0x6001, "USB2Dynamixel / CM-730 (FTDI FT232R)", 1 },
  { 0x0403, 0x6010, "FTDI FT2232", 1 },
  { 0x0483, 0x5740, "OpenCR (STM32 CDC)", 0 },
};
#define NKNOWN (int)(sizeof KNOWN / sizeof KNOWN[0])

static const known_adapter *lookup(uint16_t v, uint16_t p) {
  for (int i = 0; i < NKNOWN; i++)
    if (KNOWN[i].vendor == v && KNOWN[i].product == p) return &KNOWN[i];
  return NULL;
}

/* Calls fn on every known adapter; returns how many were seen or a negative code. */
static int each_adapter(int (*fn)(libusb_device *, const known_adapter *, void *), void *ctx,
                        char *err, size_t errlen) {
  libusb_context *usb = NULL;
  if (libusb_init(&usb) != 0) {
    snprintf(err, errlen, "libusb unavailable (no USB on this machine)");
    return 0;   /* not an error: nothing to find */
  }
  libusb_device **list = NULL;
  ssize_t n = libusb_get_device_list(usb, &list);
  int found = 0;
  for (ssize_t i = 0; i < n; i++) {
    struct libusb_device_descriptor d;
    if (libusb_get_device_descriptor(list[i], &d) != 0) continue;
    const known_adapter *k = lookup(d.idVendor, d.idProduct);
    if (!k) continue;
    if (fn(list[i], k, ctx) == 0) found++;
  }
  if (list) libusb_free_device_list(list, 1);
  libusb_exit(usb);
  return found;
}

typedef struct find_ctx { dxl_usb_info *out; int max, n; } find_ctx;

static int add_info(libusb_device *dev, const known_adapter *k, void *vctx) {
  find_ctx *c = vctx;
  if (c->n >= c->max) return -1;
  dxl_usb_info *u = &c->out[c->n++];
  u->vendor = k->vendor;
  u->product = k->product;
  u->bus = libusb_get_bus_number(dev);
  u->address = libusb_get_device_address(dev);
  snprintf(u->name, sizeof u->name, "%s", k->name);
  return 0;
}

int dxl_usb_find(dxl_usb_info *out, int max, char *err, size_t errlen) {
  if (!out || max <= 0) return DXL_EARG;
  find_ctx c = { out, max, 0 };
  int r = each_adapter(add_info, &c, err, errlen);
  return r < 0 ? r : c.n;
}

static int set_ftdi_latency(libusb_device *dev, const known_adapter *k, void *vctx) {
  int ms = *(int *)vctx;
  if (!k->ftdi) return -1;
  libusb_device_handle *h = NULL;
  if (libusb_open(dev, &h) != 0) return -1;   /* no permission: the sysfs path may still work */
  /* FTDI vendor request SIO_SET_LATENCY_TIMER (9), value = ms, index = interface A (1) */
  int r = libusb_control_transfer(h, LIBUSB_REQUEST_TYPE_VENDOR | LIBUSB_RECIPIENT_DEVICE |
                                  LIBUSB_ENDPOINT_OUT, 9, (uint16_t)ms, 1, NULL, 0, 500);
  libusb_close(h);
  return r < 0 ? -1 : 0;
}

int dxl_usb_set_latency(const char *tty, int ms, char *err, size_t errlen) {
  if (ms < 1 || ms > 255) return DXL_EARG;
  int set = 0;
  /* The kernel's ftdi_sio re-applies its own value on every open: set it there first. */
  if (tty && *tty) {
    const char *base = strrchr(tty, '/');
    base = base ? base + 1 : tty;
    char path[256];
    snprintf(path, sizeof path, "/sys/bus/usb-serial/devices/%s/latency_timer", base);
    FILE *f = fopen(path, "w");
    if (f) {
      if (fprintf(f, "%d\n", ms) > 0) set++;
      fclose(f);
    }
  }
  int r = each_adapter(set_ftdi_latency, &ms, err, errlen);
  if (r > 0) set += r;
  return set;
}
