/* The connected-regions stage as it was before the branch-free rewrite (a branch per pixel for the
 * runs, moments of every region), kept as the oracle that img_regions' output is unchanged, bit for
 * bit, order of equal areas included (img_unit: test_regions_unchanged). The moments of a region
 * (moments.h) are shared with img_regions: what the oracle checks is the runs and their labelling. */
#ifndef HRP_IMG_REGIONS_ORACLE_H
#define HRP_IMG_REGIONS_ORACLE_H

#include "imageproc/imageproc.h"
#include "imageproc/moments.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static int32_t o_find(int32_t *p, int32_t i) {
  while (p[i] != i) { p[i] = p[p[i]]; i = p[i]; }
  return i;
}

static int oracle_regions(const uint8_t *labels, int w, int h, uint8_t mask, img_region *out, int maxn) {
  const size_t max_runs = (size_t)(w / 2 + 1) * h;
  int32_t *x0s = malloc(max_runs * 4), *x1s = malloc(max_runs * 4), *ys = malloc(max_runs * 4);
  int32_t *parent = malloc(max_runs * 4), *regid = malloc(max_runs * 4);
  img_acc *accs = malloc(max_runs * sizeof *accs);
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
      img_acc_init(&accs[nreg]);
      nreg++;
    } else {
      regid[i] = regid[r];
    }
    img_acc_run(&accs[regid[i]], x0s[i], x1s[i], ys[i]);
  }
  int nout = 0;
  for (int32_t g = 0; g < nreg; g++) {
    int64_t area = accs[g].area;
    if (nout == maxn && (maxn == 0 || area <= out[nout - 1].area)) continue;
    int pos = nout < maxn ? nout++ : maxn - 1;
    while (pos > 0 && out[pos - 1].area < area) { out[pos] = out[pos - 1]; pos--; }
    img_acc_finish(&accs[g], &out[pos]);
  }
  free(x0s); free(x1s); free(ys); free(parent); free(regid); free(accs);
  return nreg;
}

#endif
