/* Unit tests of libhrpimg: LUT files, labelling, block OR, regions, colour statistics.
 * Each function is checked against a slow, obvious reference on seeded random images. TAP. */
#include "imageproc/imageproc.h"
#include "tap.h"
#include "regions_oracle.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>


static uint32_t rng_state = 12345;
static uint32_t rnd(void) {
  rng_state ^= rng_state << 13;
  rng_state ^= rng_state >> 17;
  rng_state ^= rng_state << 5;
  return rng_state;
}

/* ---------------------------------------------------------------- references */

/* 8-connected flood fill: region id per pixel (-1 none), returns count */
static int ref_regions(const uint8_t *lab, int w, int h, uint8_t mask, int *id, img_region *regs) {
  int *stack = malloc(sizeof(int) * w * h);
  for (int i = 0; i < w * h; i++) id[i] = -1;
  int n = 0;
  for (int s = 0; s < w * h; s++) {
    if (!(lab[s] & mask) || id[s] >= 0) continue;
    int sp = 0;
    stack[sp++] = s;
    id[s] = n;
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    img_region r;
    memset(&r, 0, sizeof r);
    r.xmin = w; r.ymin = h; r.xmax = -1; r.ymax = -1;
    while (sp) {
      int p = stack[--sp];
      int x = p % w, y = p / w;
      r.area++;
      sx += x; sy += y; sxx += (double)x * x; syy += (double)y * y; sxy += (double)x * y;
      if (x < r.xmin) r.xmin = x;
      if (x > r.xmax) r.xmax = x;
      if (y < r.ymin) r.ymin = y;
      if (y > r.ymax) r.ymax = y;
      for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
          int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          int q = ny * w + nx;
          if ((lab[q] & mask) && id[q] < 0) { id[q] = n; stack[sp++] = q; }
        }
    }
    r.cx = sx / r.area; r.cy = sy / r.area;
    r.cxx = sxx / r.area - r.cx * r.cx + 1.0 / 12;
    r.cyy = syy / r.area - r.cy * r.cy + 1.0 / 12;
    r.cxy = sxy / r.area - r.cx * r.cy;
    regs[n++] = r;
  }
  free(stack);
  return n;
}

static int same_region(const img_region *a, const img_region *b) {
  return a->area == b->area && a->xmin == b->xmin && a->xmax == b->xmax && a->ymin == b->ymin &&
         a->ymax == b->ymax && fabs(a->cx - b->cx) < 1e-9 && fabs(a->cy - b->cy) < 1e-9 &&
         fabs(a->cxx - b->cxx) < 1e-6 && fabs(a->cyy - b->cyy) < 1e-6 && fabs(a->cxy - b->cxy) < 1e-6;
}

/* ---------------------------------------------------------------- tests */

static void test_lut_files(void) {
  static uint8_t lut[IMG_LUT_SIZE], back[IMG_LUT_SIZE];
  for (int i = 0; i < IMG_LUT_SIZE; i++) lut[i] = (uint8_t)rnd();
  char path[256], err[512];
  snprintf(path, sizeof path, "/tmp/img_unit_%d.lut", (int)getpid());
  check(img_lut_save(path, lut, err, sizeof err) == 0, "LUT saves");
  check(img_lut_load(path, back, err, sizeof err) == 0 && memcmp(lut, back, IMG_LUT_SIZE) == 0,
        "LUT loads back identical");

  /* one flipped byte in the table: checksum error naming the file */
  FILE *f = fopen(path, "r+b");
  fseek(f, 16 + 1000, SEEK_SET);
  fputc(lut[1000] ^ 0x40, f);
  fclose(f);
  int rc = img_lut_load(path, back, err, sizeof err);
  check(rc == IMG_EFORMAT && strstr(err, path) && strstr(err, "corrupt"), "corrupt LUT refused, file named");

  /* truncated */
  img_lut_save(path, lut, err, sizeof err);
  check(truncate(path, 16 + IMG_LUT_SIZE - 7) == 0, "truncate test file");
  rc = img_lut_load(path, back, err, sizeof err);
  check(rc == IMG_EFORMAT && strstr(err, path) && strstr(err, "size"), "truncated LUT refused, file named");

  /* trailing data */
  img_lut_save(path, lut, err, sizeof err);
  f = fopen(path, "ab");
  fputc(0, f);
  fclose(f);
  rc = img_lut_load(path, back, err, sizeof err);
  check(rc == IMG_EFORMAT && strstr(err, path), "oversized LUT refused");

  /* a raw table without header */
  f = fopen(path, "wb");
  fwrite(lut, 1, IMG_LUT_SIZE, f);
  fclose(f);
  rc = img_lut_load(path, back, err, sizeof err);
  check(rc == IMG_EFORMAT && strstr(err, path) && strstr(err, "magic"), "headerless file refused");
  unlink(path);

  rc = img_lut_load(path, back, err, sizeof err);
  check(rc == IMG_EIO && strstr(err, path), "missing LUT file reported with its name");
}

static void test_ranges(void) {
  static uint8_t lut[IMG_LUT_SIZE];
  memset(lut, 0, sizeof lut);
  img_color_range r[2] = { { 1, 100, 200, 0, 60, 170, 255 }, { 8, 50, 150, 20, 100, 10, 110 } };
  check(img_lut_add_ranges(lut, r, 2) == 0, "ranges accepted");
  int bad = 0;
  for (int t = 0; t < 200000; t++) {
    uint8_t y = (uint8_t)rnd(), u = (uint8_t)rnd(), v = (uint8_t)rnd();
    uint8_t want = 0;
    for (int k = 0; k < 2; k++) {
      /* the cell of (y,u,v) overlaps the range iff the value's cell bounds intersect it */
      int yin = (y | 3) >= r[k].ymin && (y & ~3) <= r[k].ymax;
      int uin = (u | 3) >= r[k].umin && (u & ~3) <= r[k].umax;
      int vin = (v | 3) >= r[k].vmin && (v & ~3) <= r[k].vmax;
      if (yin && uin && vin) want |= r[k].bit;
    }
    if (lut[img_lut_index(y, u, v)] != want) bad++;
  }
  check(bad == 0, "LUT from ranges labels every YUV value as its cell's ranges say");
  img_color_range inv = { 1, 10, 5, 0, 255, 0, 255 };
  check(img_lut_add_ranges(lut, &inv, 1) == IMG_EARG, "inverted range refused");
}

static void test_label(void) {
  static uint8_t lut[IMG_LUT_SIZE];
  for (int i = 0; i < IMG_LUT_SIZE; i++) lut[i] = (uint8_t)rnd();
  const int W = 640, H = 480;
  uint8_t *yuyv = malloc(W * H * 2);
  for (int i = 0; i < W * H * 2; i++) yuyv[i] = (uint8_t)rnd();
  uint8_t *lab = malloc(W * H), *ref = malloc(W * H);
  for (int scale = 2; scale <= 8; scale += 2) {
    int wo = W / scale, ho = H / scale;
    int rc = img_label_yuyv(yuyv, W, H, lut, scale, lab);
    for (int j = 0; j < ho; j++)
      for (int i = 0; i < wo; i++) {
        int x = i * scale, y = j * scale;
        const uint8_t *pair = yuyv + (size_t)y * W * 2 + (x / 2) * 4;
        ref[j * wo + i] = lut[img_lut_index(pair[0], pair[1], pair[3])];
      }
    char name[64];
    snprintf(name, sizeof name, "label at scale %d matches reference", scale);
    check(rc == 0 && memcmp(lab, ref, wo * ho) == 0, name);
  }
  check(img_label_yuyv(yuyv, W, H, lut, 3, lab) == IMG_EARG, "odd scale refused");
  check(img_label_yuyv(yuyv, 641, H, lut, 2, lab) == IMG_EARG, "odd width refused");
  free(yuyv); free(lab); free(ref);
}

static void test_block_or(void) {
  int sizes[][3] = { { 160, 120, 4 }, { 161, 123, 4 }, { 7, 5, 3 }, { 320, 240, 1 } };
  for (int s = 0; s < 4; s++) {
    int w = sizes[s][0], h = sizes[s][1], bs = sizes[s][2];
    uint8_t *lab = malloc(w * h);
    for (int i = 0; i < w * h; i++) lab[i] = (rnd() % 10 == 0) ? (uint8_t)(1u << (rnd() % 8)) : 0;
    int wo = (w + bs - 1) / bs, ho = (h + bs - 1) / bs;
    uint8_t *out = malloc(wo * ho);
    int rc = img_block_or(lab, w, h, bs, out);
    int bad = 0;
    for (int jb = 0; jb < ho; jb++)
      for (int ib = 0; ib < wo; ib++) {
        uint8_t acc = 0;
        for (int y = jb * bs; y < jb * bs + bs && y < h; y++)
          for (int x = ib * bs; x < ib * bs + bs && x < w; x++) acc |= lab[y * w + x];
        bad += out[jb * wo + ib] != acc;
      }
    char name[80];
    snprintf(name, sizeof name, "block OR %dx%d by %d matches reference", w, h, bs);
    check(rc == 0 && bad == 0, name);
    free(lab); free(out);
  }
}

static void test_regions(void) {
  const int W = 160, H = 120;
  img_cc *cc = img_cc_new(W, H);
  uint8_t *lab = malloc(W * H);
  int *id = malloc(sizeof(int) * W * H);
  img_region *ref = malloc(sizeof(img_region) * W * H);
  img_region *got = malloc(sizeof(img_region) * W * H);
  int densities[] = { 1, 10, 30, 50, 70, 95 };
  for (int d = 0; d < 6; d++) {
    int allok = 1;
    for (int trial = 0; trial < 5; trial++) {
      for (int i = 0; i < W * H; i++) {
        uint8_t l = 0;
        if ((int)(rnd() % 100) < densities[d]) l |= 1;
        if (rnd() % 4 == 0) l |= 2;
        lab[i] = l;
      }
      int nref = ref_regions(lab, W, H, 1, id, ref);
      int n = img_regions(cc, lab, W, H, 1, got, W * H);
      if (n != nref) { allok = 0; break; }
      /* every region found must be one of the reference's: match by bounding box and area */
      for (int i = 0; i < n && allok; i++) {
        int found = 0;
        for (int k = 0; k < nref && !found; k++) found = same_region(&got[i], &ref[k]);
        if (!found) allok = 0;
        if (i > 0 && got[i].area > got[i - 1].area) allok = 0;
      }
    }
    char name[80];
    snprintf(name, sizeof name, "regions at %d%% density match flood fill (count, bbox, moments)",
             densities[d]);
    check(allok, name);
  }
  /* top-k selection: only the largest maxn, sorted */
  for (int i = 0; i < W * H; i++) lab[i] = (rnd() % 100) < 40;
  int nref = ref_regions(lab, W, H, 1, id, ref);
  img_region top[5];
  int n = img_regions(cc, lab, W, H, 1, top, 5);
  int ok = n == nref;
  for (int k = 0; k < 5 && ok; k++) {
    int bigger = 0;   /* regions in ref strictly bigger than top[k] must be fewer than k+1 */
    for (int r = 0; r < nref; r++) bigger += ref[r].area > top[k].area;
    if (bigger > k) ok = 0;
  }
  check(ok, "largest 5 regions returned in order");

  /* a filled disc: centroid, area, axes */
  memset(lab, 0, W * H);
  double cx0 = 70.3, cy0 = 50.6, rad = 20;
  for (int y = 0; y < H; y++)
    for (int x = 0; x < W; x++)
      if ((x - cx0) * (x - cx0) + (y - cy0) * (y - cy0) <= rad * rad) lab[y * W + x] = 4;
  n = img_regions(cc, lab, W, H, 4, top, 1);
  check(n == 1 && fabs(top[0].cx - cx0) < 0.2 && fabs(top[0].cy - cy0) < 0.2 &&
            fabs(top[0].area - M_PI * rad * rad) < 0.03 * M_PI * rad * rad &&
            fabs(top[0].axis_major - 2 * rad) < 1.0 && fabs(top[0].axis_minor - 2 * rad) < 1.0,
        "disc: centroid, area and axes");
  /* an elongated bar at 0 rad */
  memset(lab, 0, W * H);
  for (int y = 40; y < 50; y++)
    for (int x = 10; x < 110; x++) lab[y * W + x] = 1;
  n = img_regions(cc, lab, W, H, 1, top, 1);
  check(n == 1 && top[0].area == 1000 && top[0].xmin == 10 && top[0].xmax == 109 &&
            fabs(top[0].orientation) < 1e-6 && fabs(top[0].axis_major / top[0].axis_minor - 10) < 0.2,
        "bar: bbox, orientation, axis ratio");
  check(img_regions(cc, lab, W + 1, H, 1, top, 1) == IMG_EARG, "image larger than workspace refused");
  memset(lab, 0, W * H);
  check(img_regions(cc, lab, W, H, 1, top, 1) == 0, "empty image: no regions");
  free(lab); free(id); free(ref); free(got);
  img_cc_free(cc);
}

static void test_stats(void) {
  const int W = 80, H = 60;
  uint8_t *lab = malloc(W * H);
  for (int i = 0; i < W * H; i++) lab[i] = (uint8_t)(rnd() & 0x0F);
  int ok = 1;
  for (int t = 0; t < 50 && ok; t++) {
    int x0 = (int)(rnd() % W) - 5, y0 = (int)(rnd() % H) - 5;
    int x1 = x0 + (int)(rnd() % 40), y1 = y0 + (int)(rnd() % 40);
    uint8_t mask = (uint8_t)(1u << (rnd() % 4));
    img_region got;
    img_color_stats(lab, W, H, mask, x0, x1, y0, y1, &got);
    double n = 0, sx = 0, sy = 0, sxx = 0;
    for (int y = y0 < 0 ? 0 : y0; y <= y1 && y < H; y++)
      for (int x = x0 < 0 ? 0 : x0; x <= x1 && x < W; x++)
        if (lab[y * W + x] & mask) { n++; sx += x; sy += y; sxx += (double)x * x; }
    if (got.area != n) ok = 0;
    if (n > 0 && (fabs(got.cx - sx / n) > 1e-9 || fabs(got.cy - sy / n) > 1e-9 ||
                  fabs(got.cxx - (sxx / n - (sx / n) * (sx / n) + 1.0 / 12)) > 1e-6))
      ok = 0;
  }
  check(ok, "colour statistics in random rectangles match reference");
  check(img_count(lab, W, H, 0) == 0, "count with empty mask is 0");
  free(lab);
}

/* img_regions gives what the previous version gave, bit for bit (regions_oracle.h), on seeded random
 * label images of widths around the 8- and 64-pixel words it now works in, many densities and masks */
static void test_regions_unchanged(void) {
  const int sizes[][2] = { { 320, 240 }, { 80, 60 }, { 161, 77 }, { 63, 5 }, { 64, 3 }, { 65, 9 }, { 1, 10 },
                           { 129, 31 }, { 7, 1 } };
  const int densities[] = { 1, 10, 30, 50, 70, 95, 100 };
  img_cc *cc = img_cc_new(320, 240);
  img_region *a = malloc(sizeof(img_region) * 320 * 240), *b = malloc(sizeof(img_region) * 320 * 240);
  uint8_t *lab = malloc(320 * 240);
  int cases = 0, same = 0;
  for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
    for (size_t d = 0; d < sizeof densities / sizeof densities[0]; d++)
      for (int trial = 0; trial < 3; trial++) {
        const int w = sizes[s][0], h = sizes[s][1];
        for (int i = 0; i < w * h; i++) {
          const uint8_t any = (uint8_t)(1u << (rnd() % 8));
          lab[i] = (int)(rnd() % 100) < densities[d] ? (uint8_t)(any | 1) : (uint8_t)(any & ~1u);
        }
        const uint8_t mask = trial == 2 ? 0x81 : 1;
        for (int maxn = 0; maxn <= 8; maxn += 8) {
          memset(a, 0x5a, sizeof(img_region) * 8);
          memset(b, 0x5a, sizeof(img_region) * 8);
          const int na = img_regions(cc, lab, w, h, mask, a, maxn), nb = oracle_regions(lab, w, h, mask, b, maxn);
          cases++;
          same += na == nb && memcmp(a, b, sizeof(img_region) * (size_t)(maxn < na ? maxn : na)) == 0;
        }
        /* all of them: the whole list in the same order */
        const int na = img_regions(cc, lab, w, h, mask, a, w * h), nb = oracle_regions(lab, w, h, mask, b, w * h);
        cases++;
        same += na == nb && memcmp(a, b, sizeof(img_region) * (size_t)na) == 0;
      }
  char name[120];
  snprintf(name, sizeof name, "regions are the previous version's, bit for bit (%d of %d cases)", same, cases);
  check(same == cases, name);
  free(a); free(b); free(lab);
  img_cc_free(cc);
}

int main(void) {
  test_lut_files();
  test_ranges();
  test_label();
  test_block_or();
  test_regions();
  test_regions_unchanged();
  test_stats();
  return tap_done();
}
