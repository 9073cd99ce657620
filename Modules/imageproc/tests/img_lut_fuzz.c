/* libFuzzer target: the colour-table loader (img_lut_load) on any file content, and the vision
 * pipeline on any table it accepts. The input is written to a memfd that the loader opens by path
 * (/proc/self/fd/N), so the loader runs unchanged. Each input is loaded twice: as it is, and with
 * the header's checksum made right for its table, so the fuzzer also reaches tables the loader
 * accepts. Checks: a refusal has a message naming the file; an accepted table is the file's bytes;
 * labelling with it gives each pixel its LUT entry; regions and colour statistics of every bit
 * stay inside the image. */
#include "imageproc/imageproc.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#define HEADER 16
#define W 32
#define H 16
#define SCALE 2

static int fd = -1;
static char path[64];
static uint8_t lut[IMG_LUT_SIZE];
static uint8_t frame[W * H * 2], labels[(W / SCALE) * (H / SCALE)], blocks[16];
static img_region regs[8];
static img_cc *cc;

static void write_file(const uint8_t *data, size_t size) {
  if (ftruncate(fd, 0) != 0 || pwrite(fd, data, size, 0) != (ssize_t)size) abort();
}

static void check_pipeline(const uint8_t *seed, size_t n) {
  for (size_t i = 0; i < sizeof frame; i++) frame[i] = n ? seed[(i * 7919) % n] ^ (uint8_t)i : (uint8_t)i;
  const int wa = W / SCALE, ha = H / SCALE;
  if (img_label_yuyv(frame, W, H, lut, SCALE, labels) != 0) abort();
  for (int j = 0; j < ha; j++)
    for (int i = 0; i < wa; i++) {
      const uint8_t *px = frame + (j * SCALE * W + (i * SCALE & ~1)) * 2;   /* Y0 U Y1 V */
      if (labels[j * wa + i] != lut[img_lut_index(px[0], px[1], px[3])]) abort();
    }
  if (img_block_or(labels, wa, ha, 4, blocks) != 0) abort();
  for (int b = 0; b < 8; b++) {
    uint8_t mask = (uint8_t)(1u << b);
    int found = img_regions(cc, labels, wa, ha, mask, regs, 8);
    if (found < 0 || found > wa * ha) abort();
    int total = 0;
    for (int r = 0; r < found && r < 8; r++) {
      if (regs[r].area <= 0 || regs[r].xmin < 0 || regs[r].xmax >= wa || regs[r].ymin < 0 ||
          regs[r].ymax >= ha)
        abort();
      total += regs[r].area;
    }
    if (total > img_count(labels, wa, ha, mask)) abort();
    img_region st;
    img_color_stats(labels, wa, ha, mask, -3, wa + 3, -3, ha + 3, &st);
    if (st.area != img_count(labels, wa, ha, mask)) abort();
  }
}

static void load(const uint8_t *data, size_t size) {
  write_file(data, size);
  char err[512] = "";
  int rc = img_lut_load(path, lut, err, sizeof err);
  if (rc == 0) {
    if (size != HEADER + IMG_LUT_SIZE || memcmp(lut, data + HEADER, IMG_LUT_SIZE) != 0) abort();
    check_pipeline(data, size);
  } else if (rc != IMG_EFORMAT || !strstr(err, path)) {
    abort();   /* a refusal is a format error (the file is readable) naming the file */
  }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (fd < 0) {
    fd = memfd_create("lut_fuzz", 0);
    if (fd < 0) abort();
    snprintf(path, sizeof path, "/proc/self/fd/%d", fd);
    cc = img_cc_new(W, H);
    if (!cc) abort();
  }
  load(data, size);
  if (size >= HEADER) {
    uint8_t *fixed = malloc(size);
    if (!fixed) return 0;
    memcpy(fixed, data, size);
    size_t body = size - HEADER < IMG_LUT_SIZE ? size - HEADER : IMG_LUT_SIZE;
    uint32_t crc = img_crc32(fixed + HEADER, body);
    for (int k = 0; k < 4; k++) fixed[12 + k] = (uint8_t)(crc >> (8 * k));
    load(fixed, size);
    free(fixed);
  }
  return 0;
}
