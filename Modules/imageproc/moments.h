/* Moments of a region built from horizontal runs: area, bounding box, centroid, second moments and
 * the equivalent ellipse. One implementation for img_regions and img_color_stats and for the
 * regions oracle of the unit test, which checks the labelling around it (tests/regions_oracle.h).
 * Internal to Modules/imageproc: not part of imageproc.h's interface. */
#ifndef HRP_IMG_MOMENTS_H
#define HRP_IMG_MOMENTS_H

#include "imageproc/imageproc.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

typedef struct img_acc {
  int64_t area, sx, sy, sxx, syy, sxy;
  int32_t xmin, xmax, ymin, ymax;
} img_acc;

static inline void img_acc_init(img_acc *a) {
  memset(a, 0, sizeof *a);
  a->xmin = a->ymin = INT32_MAX;
  a->xmax = a->ymax = -1;
}

/* Adds the horizontal run x0..x1 (inclusive) on row y. */
static inline void img_acc_run(img_acc *a, int64_t x0, int64_t x1, int64_t y) {
  int64_t n = x1 - x0 + 1;
  int64_t sx = (x0 + x1) * n / 2;
  /* sum of x^2 for x in [x0, x1] = S(x1) - S(x0 - 1), S(k) = k(k+1)(2k+1)/6 */
  int64_t s1 = x1 * (x1 + 1) * (2 * x1 + 1) / 6, s0 = (x0 - 1) * x0 * (2 * x0 - 1) / 6;
  a->area += n;
  a->sx += sx;
  a->sy += n * y;
  a->sxx += s1 - s0;
  a->syy += n * y * y;
  a->sxy += sx * y;
  if (x0 < a->xmin) a->xmin = (int32_t)x0;
  if (x1 > a->xmax) a->xmax = (int32_t)x1;
  if (y < a->ymin) a->ymin = (int32_t)y;
  if (y > a->ymax) a->ymax = (int32_t)y;
}

static inline void img_acc_finish(const img_acc *a, img_region *r) {
  memset(r, 0, sizeof *r);
  r->area = (int32_t)a->area;
  if (a->area == 0) return;
  r->xmin = a->xmin; r->xmax = a->xmax; r->ymin = a->ymin; r->ymax = a->ymax;
  double n = (double)a->area;
  r->cx = (double)a->sx / n;
  r->cy = (double)a->sy / n;
  r->cxx = (double)a->sxx / n - r->cx * r->cx + 1.0 / 12;   /* + pixel's own extent */
  r->cyy = (double)a->syy / n - r->cy * r->cy + 1.0 / 12;
  r->cxy = (double)a->sxy / n - r->cx * r->cy;
  double m = 0.5 * (r->cxx + r->cyy);
  double d = sqrt(0.25 * (r->cxx - r->cyy) * (r->cxx - r->cyy) + r->cxy * r->cxy);
  double l1 = m + d, l2 = m - d;
  r->axis_major = 4.0 * sqrt(l1 > 0 ? l1 : 0);
  r->axis_minor = 4.0 * sqrt(l2 > 0 ? l2 : 0);
  r->orientation = 0.5 * atan2(2.0 * r->cxy, r->cxx - r->cyy);
}

#endif
