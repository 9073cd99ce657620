/* The connected-regions stage as it was before the branch-free rewrite (a branch per pixel for the
 * runs, moments of every region), kept as the oracle that img_regions' output is unchanged, bit for
 * bit, order of equal areas included (img_unit: test_regions_unchanged). */
#ifndef HRP_IMG_REGIONS_ORACLE_H
#define HRP_IMG_REGIONS_ORACLE_H

#include "imageproc/imageproc.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct o_acc {
  int64_t area, sx, sy, sxx, syy, sxy;
  int32_t xmin, xmax, ymin, ymax;
} o_acc;

static void o_acc_run(o_acc *a, int64_t x0, int64_t x1, int64_t y) {
  int64_t n = x1 - x0 + 1, sx = (x0 + x1) * n / 2;
  int64_t s1 = x1 * (x1 + 1) * (2 * x1 + 1) / 6, s0 = (x0 - 1) * x0 * (2 * x0 - 1) / 6;
  a->area += n; a->sx += sx; a->sy += n * y; a->sxx += s1 - s0; a->syy += n * y * y; a->sxy += sx * y;
  if (x0 < a->xmin) a->xmin = (int32_t)x0;
  if (x1 > a->xmax) a->xmax = (int32_t)x1;
  if (y < a->ymin) a->ymin = (int32_t)y;
  if (y > a->ymax) a->ymax = (int32_t)y;
}

static void o_acc_finish(const o_acc *a, img_region *r) {
  memset(r, 0, sizeof *r);
  r->area = (int32_t)a->area;
  if (a->area == 0) return;
  r->xmin = a->xmin; r->xmax = a->xmax; r->ymin = a->ymin; r->ymax = a->ymax;
  double n = (double)a->area;
  r->cx = (double)a->sx / n;
  r->cy = (double)a->sy / n;
  r->cxx = (double)a->sxx / n - r->cx * r->cx + 1.0 / 12;
  r->cyy = (double)a->syy / n - r->cy * r->cy + 1.0 / 12;
  r->cxy = (double)a->sxy / n - r->cx * r->cy;
  double m = 0.5 * (r->cxx + r->cyy);
  double d = sqrt(0.25 * (r->cxx - r->cyy) * (r->cxx - r->cyy) + r->cxy * r->cxy);
  double l1 = m + d, l2 = m - d;
  r->axis_major = 4.0 * sqrt(l1 > 0 ? l1 : 0);
  r->axis_minor = 4.0 * sqrt(l2 > 0 ? l2 : 0);
  r->orientation = 0.5 * atan2(2.0 * r->cxy, r->cxx - r->cyy);
}

static int32_t o_find(int32_t *p, int32_t i) {
  while (p[i] != i) { p[i] = p[p[i]]; i = p[i]; }
  return i;
}

static int oracle_regions(const uint8_t *labels, int w, int h, uint8_t mask, img_region *out, int maxn) {
  const size_t max_runs = (size_t)(w / 2 + 1) * h;
  int32_t *x0s = malloc(max_runs * 4), *x1s = malloc(max_runs * 4), *ys = malloc(max_runs * 4);
  int32_t *parent = malloc(max_runs * 4), *regid = malloc(max_runs * 4);
  o_acc *accs = malloc(max_runs * sizeof *accs);
  int32_t nruns = 0, prev_start = 0, prev_end = 0;
  for (int y = 0; y < h; y++) {
    const uint8_t *row = labels + (size_t)y * w;
    int32_t cur_start = nruns;
    int x = 0;
    while (x < w) {
      while (x < w && !(row[x] & mask)) x++;
      if (x >= w) break;
      int s = x;
      while (x < w && (row[x] & mask)) x++;
      x0s[nruns] = s; x1s[nruns] = x - 1; ys[nruns] = y; parent[nruns] = nruns;
      nruns++;
    }
    int32_t j = prev_start;
    for (int32_t i = cur_start; i < nruns; i++) {
      while (j < prev_end && x1s[j] + 1 < x0s[i]) j++;
      for (int32_t k = j; k < prev_end && x0s[k] <= x1s[i] + 1; k++) {
        int32_t a = o_find(parent, i), b = o_find(parent, k);
        if (a < b) parent[b] = a;
        else if (b < a) parent[a] = b;
      }
    }
    prev_start = cur_start;
    prev_end = nruns;
  }
  int32_t nreg = 0;
  for (int32_t i = 0; i < nruns; i++) {
    int32_t r = o_find(parent, i);
    if (r == i) {
      regid[i] = nreg;
      memset(&accs[nreg], 0, sizeof accs[nreg]);
      accs[nreg].xmin = accs[nreg].ymin = INT32_MAX;
      accs[nreg].xmax = accs[nreg].ymax = -1;
      nreg++;
    } else {
      regid[i] = regid[r];
    }
    o_acc_run(&accs[regid[i]], x0s[i], x1s[i], ys[i]);
  }
  int nout = 0;
  for (int32_t g = 0; g < nreg; g++) {
    int64_t area = accs[g].area;
    if (nout == maxn && (maxn == 0 || area <= out[nout - 1].area)) continue;
    int pos = nout < maxn ? nout++ : maxn - 1;
    while (pos > 0 && out[pos - 1].area < area) { out[pos] = out[pos - 1]; pos--; }
    o_acc_finish(&accs[g], &out[pos]);
  }
  free(x0s); free(x1s); free(ys); free(parent); free(regid); free(accs);
  return nreg;
}

#endif
