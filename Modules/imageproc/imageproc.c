/* imageproc: lookup-table labelling, block OR, connected regions, colour statistics. */
#include "imageproc/imageproc.h"
#include "imageproc/moments.h"
#include "errmsg.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* ---------------------------------------------------------------- LUT files */

#define LUT_HEADER 16

uint32_t img_crc32(const uint8_t *data, size_t n) {
  static uint32_t table[256];
  static int ready = 0;
  if (!ready) {   /* idempotent: racing threads compute the same values */
    for (uint32_t i = 0; i < 256; i++) {
      uint32_t c = i;
      for (int k = 0; k < 8; k++) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      table[i] = c;
    }
    ready = 1;
  }
  uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < n; i++) c = table[(c ^ data[i]) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

static uint32_t rd32(const uint8_t *p) {
  return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}
static void wr32(uint8_t *p, uint32_t v) {
  p[0] = (uint8_t)v; p[1] = (uint8_t)(v >> 8); p[2] = (uint8_t)(v >> 16); p[3] = (uint8_t)(v >> 24);
}

int img_lut_load(const char *path, uint8_t *lut, char *err, size_t errlen) {
  if (!path || !lut) { hrp_err(err, errlen, "img_lut_load: NULL argument"); return IMG_EARG; }
  FILE *f = fopen(path, "rb");
  if (!f) { hrp_err(err, errlen, "LUT '%s': cannot open: %s", path, strerror(errno)); return IMG_EIO; }
  uint8_t header[LUT_HEADER];
  size_t n = fread(header, 1, LUT_HEADER, f);
  if (n != LUT_HEADER || memcmp(header, IMG_LUT_MAGIC, 8) != 0) {
    fclose(f);
    hrp_err(err, errlen, "LUT '%s': not a lookup table (bad magic; expected \"%s\" header)", path,
            IMG_LUT_MAGIC);
    return IMG_EFORMAT;
  }
  uint32_t count = rd32(header + 8), crc = rd32(header + 12);
  if (count != IMG_LUT_SIZE) {
    fclose(f);
    hrp_err(err, errlen, "LUT '%s': has %u entries, expected %d", path, count, IMG_LUT_SIZE);
    return IMG_EFORMAT;
  }
  n = fread(lut, 1, IMG_LUT_SIZE, f);
  int extra = fgetc(f);
  int rerr = ferror(f);
  fclose(f);
  if (rerr) { hrp_err(err, errlen, "LUT '%s': read error", path); return IMG_EIO; }
  if (n != IMG_LUT_SIZE || extra != EOF) {
    hrp_err(err, errlen, "LUT '%s': wrong size (%s; expected %d bytes)", path,
            n != IMG_LUT_SIZE ? "truncated" : "trailing data", LUT_HEADER + IMG_LUT_SIZE);
    return IMG_EFORMAT;
  }
  uint32_t got = img_crc32(lut, IMG_LUT_SIZE);
  if (got != crc) {
    hrp_err(err, errlen, "LUT '%s': corrupt (checksum %08x, header says %08x)", path, got, crc);
    return IMG_EFORMAT;
  }
  return 0;
}

int img_lut_save(const char *path, const uint8_t *lut, char *err, size_t errlen) {
  if (!path || !lut) { hrp_err(err, errlen, "img_lut_save: NULL argument"); return IMG_EARG; }
  char tmp[4096];
  snprintf(tmp, sizeof tmp, "%s.tmp.%d", path, (int)getpid());
  FILE *f = fopen(tmp, "wb");
  if (!f) { hrp_err(err, errlen, "LUT '%s': cannot write: %s", path, strerror(errno)); return IMG_EIO; }
  uint8_t header[LUT_HEADER];
  memcpy(header, IMG_LUT_MAGIC, 8);
  wr32(header + 8, IMG_LUT_SIZE);
  wr32(header + 12, img_crc32(lut, IMG_LUT_SIZE));
  int ok = fwrite(header, 1, LUT_HEADER, f) == LUT_HEADER &&
           fwrite(lut, 1, IMG_LUT_SIZE, f) == IMG_LUT_SIZE;
  ok = (fclose(f) == 0) && ok;
  if (!ok || rename(tmp, path) != 0) {
    hrp_err(err, errlen, "LUT '%s': write failed: %s", path, strerror(errno));
    unlink(tmp);
    return IMG_EIO;
  }
  return 0;
}

int img_lut_add_ranges(uint8_t *lut, const img_color_range *ranges, int nranges) {
  if (!lut || (nranges > 0 && !ranges) || nranges < 0) return IMG_EARG;
  for (int r = 0; r < nranges; r++) {
    const img_color_range *c = &ranges[r];
    if (c->ymin > c->ymax || c->umin > c->umax || c->vmin > c->vmax) return IMG_EARG;
    /* cell k covers values [4k, 4k+3]: it overlaps [lo, hi] for k in [lo/4, hi/4] */
    for (int y = c->ymin >> 2; y <= c->ymax >> 2; y++)
      for (int u = c->umin >> 2; u <= c->umax >> 2; u++)
        for (int v = c->vmin >> 2; v <= c->vmax >> 2; v++)
          lut[(y << 12) | (u << 6) | v] |= c->bit;
  }
  return 0;
}

/* ---------------------------------------------------------------- labelling */

int img_label_yuyv(const uint8_t *yuyv, int width, int height, const uint8_t *lut, int scale,
                   uint8_t *labels) {
  if (!yuyv || !lut || !labels || width <= 0 || height <= 0 || (width & 1) || scale < 2 ||
      (scale & 1))
    return IMG_EARG;
  const int wo = width / scale, ho = height / scale;
  const size_t stride = (size_t)width * 2;
  const int step = 2 * scale;   /* bytes between consecutive output pixels */
  for (int j = 0; j < ho; j++) {
    const uint8_t *p = yuyv + (size_t)j * scale * stride;
    uint8_t *out = labels + (size_t)j * wo;
    int i = 0;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    /* a pair as one word (Y0 | U << 8 | Y1 << 16 | V << 24), four outputs stored at once: fewer loads
     * and stores around the LUT reads, which are what is left (random on a noisy image) */
#define PAIR_INDEX(v) ((((v) & 0xFCu) << 10) | (((v) >> 4) & 0xFC0u) | ((v) >> 26))
    for (; i + 4 <= wo; i += 4, p += 4 * step) {
      uint32_t v0, v1, v2, v3;
      memcpy(&v0, p, 4);
      memcpy(&v1, p + step, 4);
      memcpy(&v2, p + 2 * step, 4);
      memcpy(&v3, p + 3 * step, 4);
      const uint32_t r = (uint32_t)lut[PAIR_INDEX(v0)] | (uint32_t)lut[PAIR_INDEX(v1)] << 8 |
                         (uint32_t)lut[PAIR_INDEX(v2)] << 16 | (uint32_t)lut[PAIR_INDEX(v3)] << 24;
      memcpy(out + i, &r, 4);
    }
#undef PAIR_INDEX
#endif
    for (; i < wo; i++, p += step) {
      out[i] = lut[((uint32_t)(p[0] >> 2) << 12) | ((uint32_t)(p[1] >> 2) << 6) | (p[3] >> 2)];
    }
  }
  return 0;
}

int img_block_or(const uint8_t *labels, int w, int h, int bs, uint8_t *out) {
  if (!labels || !out || w <= 0 || h <= 0 || bs <= 0) return IMG_EARG;
  const int wo = (w + bs - 1) / bs, ho = (h + bs - 1) / bs;
  if (bs == 4 && w % 4 == 0 && w <= 4096) {
    /* the usual 4 x 4: OR the block row's lines into one (whole words, vectorised), then each 4 bytes */
    uint32_t line[1024];
    for (int jb = 0; jb < ho; jb++) {
      const int y0 = jb * 4, y1 = y0 + 4 < h ? y0 + 4 : h;
      memcpy(line, labels + (size_t)y0 * w, (size_t)w);
      for (int y = y0 + 1; y < y1; y++) {
        const uint8_t *row = labels + (size_t)y * w;
        for (int i = 0; i < wo; i++) {
          uint32_t v;
          memcpy(&v, row + 4 * i, 4);
          line[i] |= v;
        }
      }
      uint8_t *o = out + (size_t)jb * wo;
      for (int i = 0; i < wo; i++) {
        const uint32_t v = line[i];
        o[i] = (uint8_t)(v | v >> 8 | v >> 16 | v >> 24);
      }
    }
    return 0;
  }
  for (int jb = 0; jb < ho; jb++) {
    uint8_t *o = out + (size_t)jb * wo;
    memset(o, 0, (size_t)wo);
    int y1 = (jb + 1) * bs < h ? (jb + 1) * bs : h;
    for (int y = jb * bs; y < y1; y++) {
      const uint8_t *row = labels + (size_t)y * w;
      int x = 0;
      for (int ib = 0; ib < wo; ib++) {
        int x1 = x + bs < w ? x + bs : w;
        uint8_t acc = o[ib];
        for (; x < x1; x++) acc |= row[x];
        o[ib] = acc;
      }
    }
  }
  return 0;
}

int img_count(const uint8_t *labels, int w, int h, uint8_t mask) {
  if (!labels || w <= 0 || h <= 0) return IMG_EARG;
  int n = 0;
  size_t total = (size_t)w * h;
  for (size_t i = 0; i < total; i++) n += (labels[i] & mask) != 0;
  return n;
}

int img_color_stats(const uint8_t *labels, int w, int h, uint8_t mask,
                    int x0, int x1, int y0, int y1, img_region *out) {
  if (!labels || !out || w <= 0 || h <= 0) return IMG_EARG;
  if (x0 < 0) x0 = 0;
  if (y0 < 0) y0 = 0;
  if (x1 > w - 1) x1 = w - 1;
  if (y1 > h - 1) y1 = h - 1;
  img_acc a;
  img_acc_init(&a);
  for (int y = y0; y <= y1; y++) {
    const uint8_t *row = labels + (size_t)y * w;
    int x = x0;
    while (x <= x1) {
      while (x <= x1 && !(row[x] & mask)) x++;
      if (x > x1) break;
      int s = x;
      while (x <= x1 && (row[x] & mask)) x++;
      img_acc_run(&a, s, x - 1, y);
    }
  }
  img_acc_finish(&a, out);
  return 0;
}

/* ---------------------------------------------------------------- connected regions */

typedef struct run {
  int16_t x0, x1;
  int32_t y;
} run;

struct img_cc {
  int max_w, max_h;
  size_t max_runs;
  uint64_t *bits;    /* one row: bit x set when pixel x has the colour (words + 1, the last 0) */
  run *runs;
  int32_t *parent;   /* union-find over runs */
  int32_t *regid;    /* compact region id of each run */
  int32_t *area;     /* per region: pixels */
  int32_t *slot;     /* per region: its place among the regions returned, -1 none */
  int32_t *sel;      /* the regions returned, largest first */
  img_acc *accs;         /* per region returned */
};

img_cc *img_cc_new(int max_w, int max_h) {
  if (max_w <= 0 || max_h <= 0 || max_w > 32767) return NULL;
  img_cc *cc = calloc(1, sizeof *cc);
  if (!cc) return NULL;
  cc->max_w = max_w;
  cc->max_h = max_h;
  cc->max_runs = (size_t)(max_w / 2 + 1) * max_h;
  cc->bits = calloc((size_t)max_w / 64 + 2, sizeof *cc->bits);
  cc->runs = malloc(cc->max_runs * sizeof *cc->runs);
  cc->parent = malloc(cc->max_runs * sizeof *cc->parent);
  cc->regid = malloc(cc->max_runs * sizeof *cc->regid);
  cc->area = malloc(cc->max_runs * sizeof *cc->area);
  cc->slot = malloc(cc->max_runs * sizeof *cc->slot);
  cc->sel = malloc(cc->max_runs * sizeof *cc->sel);
  cc->accs = malloc(cc->max_runs * sizeof *cc->accs);
  if (!cc->bits || !cc->runs || !cc->parent || !cc->regid || !cc->area || !cc->slot || !cc->sel || !cc->accs) {
    img_cc_free(cc);
    return NULL;
  }
  return cc;
}

void img_cc_free(img_cc *cc) {
  if (!cc) return;
  free(cc->bits);
  free(cc->runs);
  free(cc->parent);
  free(cc->regid);
  free(cc->area);
  free(cc->slot);
  free(cc->sel);
  free(cc->accs);
  free(cc);
}

static inline int32_t uf_find(int32_t *parent, int32_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

static inline void uf_union(int32_t *parent, int32_t a, int32_t b) {
  a = uf_find(parent, a);
  b = uf_find(parent, b);
  if (a < b) parent[b] = a;
  else if (b < a) parent[a] = b;
}

/* The row's pixels with any bit of mask as a bit string (bit x of word x / 64), 8 pixels at a time
 * without a branch: a noisy image has a run every few pixels, and a branch per pixel mispredicts at each
 * run's start and end (it was most of the time of img_regions on a random-noise frame). */
static void row_bits(const uint8_t *row, int w, uint8_t mask, uint64_t *bits) {
  const uint64_t m8 = 0x0101010101010101ull * mask, low7 = 0x7F7F7F7F7F7F7F7Full, high = 0x8080808080808080ull;
  const int nw = (w + 63) / 64;
  for (int k = 0; k < nw; k++) {
    uint64_t word = 0;
    for (int g = 0; g < 8; g++) {
      const int x = k * 64 + g * 8;
      uint64_t v = 0;
      if (x + 8 <= w) memcpy(&v, row + x, 8);
      else if (x < w) memcpy(&v, row + x, (size_t)(w - x));
      const uint64_t t = v & m8;
      const uint64_t nz = (((t & low7) + low7) | t) & high;   /* 0x80 in each byte that is not 0 */
      /* byte i's high bit -> bit i (little endian: byte i is pixel x + i) */
      word |= (((nz >> 7) * 0x0102040810204080ull) >> 56) << (g * 8);
    }
    bits[k] = word;
  }
  bits[nw] = 0;
}

int img_regions(img_cc *cc, const uint8_t *labels, int w, int h, uint8_t mask,
                img_region *out, int maxn) {
  if (!cc || !labels || w <= 0 || h <= 0 || w > cc->max_w || h > cc->max_h || maxn < 0 ||
      (maxn > 0 && !out))
    return IMG_EARG;
  run *runs = cc->runs;
  int32_t *parent = cc->parent;
  int32_t nruns = 0, prev_start = 0, prev_end = 0;
  uint64_t *bits = cc->bits;
  const int nw = (w + 63) / 64;
  for (int y = 0; y < h; y++) {
    int32_t cur_start = nruns;
    row_bits(labels + (size_t)y * w, w, mask, bits);
    /* runs from the bit string: a start is a set bit after a clear one, an end a set bit before a
     * clear one (across word boundaries: the neighbouring words' edge bits) */
    int32_t ns = nruns, ne = nruns;
    for (int k = 0; k < nw; k++) {
      const uint64_t b = bits[k], before = k ? bits[k - 1] >> 63 : 0, after = bits[k + 1] & 1;
      uint64_t starts = b & ~(b << 1 | before), ends = b & ~(b >> 1 | after << 63);
      for (; starts; starts &= starts - 1) {
        runs[ns].x0 = (int16_t)(k * 64 + __builtin_ctzll(starts));
        runs[ns].y = y;
        parent[ns] = ns;
        ns++;
      }
      for (; ends; ends &= ends - 1) runs[ne++].x1 = (int16_t)(k * 64 + __builtin_ctzll(ends));
    }
    nruns = ns;
    /* join with the previous row's runs that touch (8-connectivity) */
    int32_t j = prev_start;
    for (int32_t i = cur_start; i < nruns; i++) {
      while (j < prev_end && runs[j].x1 + 1 < runs[i].x0) j++;
      for (int32_t k = j; k < prev_end && runs[k].x0 <= runs[i].x1 + 1; k++) uf_union(parent, i, k);
    }
    prev_start = cur_start;
    prev_end = nruns;
  }
  /* compact region ids (a root has the smallest index of its set, so it comes first) and areas */
  int32_t nreg = 0;
  int32_t *regid = cc->regid, *area = cc->area;
  for (int32_t i = 0; i < nruns; i++) {
    int32_t r = uf_find(parent, i);
    if (r == i) {
      regid[i] = nreg;
      area[nreg++] = 0;
    } else {
      regid[i] = regid[r];
    }
    area[regid[i]] += runs[i].x1 - runs[i].x0 + 1;
  }
  /* pick the largest maxn by area (ties: the first found first) */
  int32_t *sel = cc->sel, *slot = cc->slot;
  int nout = 0;
  for (int32_t g = 0; g < nreg; g++) {
    slot[g] = -1;
    const int32_t a = area[g];
    if (nout == maxn && (maxn == 0 || a <= area[sel[nout - 1]])) continue;
    int pos = nout < maxn ? nout++ : maxn - 1;
    while (pos > 0 && area[sel[pos - 1]] < a) {
      sel[pos] = sel[pos - 1];
      pos--;
    }
    sel[pos] = g;
  }
  /* moments only of the regions returned: a noisy image has thousands of specks nobody asked about */
  img_acc *accs = cc->accs;
  for (int k = 0; k < nout; k++) {
    slot[sel[k]] = k;
    img_acc_init(&accs[k]);
  }
  if (nout > 0)
    for (int32_t i = 0; i < nruns; i++) {
      const int32_t k = slot[regid[i]];
      if (k >= 0) img_acc_run(&accs[k], runs[i].x0, runs[i].x1, runs[i].y);
    }
  for (int k = 0; k < nout; k++) img_acc_finish(&accs[k], &out[k]);
  return nreg;
}
