/* balldetect: the chosen ball's centre from its outline (bd_fit, balldetect.h).
 *
 * A centroid takes in whatever not-field region touches the ball (a field line passing behind it, the
 * image's edge cutting it), and more passes climb into it. The outline does not: rays from the centre
 * find where the ball's region meets the field; a ray that runs on past 1.5 radii (into a line), out of
 * the image or beyond the field boundary (the backdrop is as not-field as the ball) gives no point; a
 * circle (swept along the view's blur, the smear's shape) is fitted to the points with weights that
 * leave out the few that ended on a line's far edge. */
#include "balldetect.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { NRAY = 48, MIN_POINTS = NRAY / 4 };

typedef struct fit_state {
  double px[NRAY], py[NRAY];   /* edge points, labels (continuous: a label's centre is +0.5) */
  int n;
} fit_state;

static int is_field(const uint8_t *labels, int wl, int x, int y, uint8_t green) {
  return (labels[(size_t)y * wl + x] & green) != 0;
}

/* the edge points seen from (cx, cy), rays up to rmax labels; returns their count */
static int cast(const uint8_t *labels, int wl, int hl, uint8_t green, const int16_t *top, double cx, double cy,
                double rmax, fit_state *s) {
  s->n = 0;
  for (int k = 0; k < NRAY; k++) {
    const double a = 2 * M_PI * k / NRAY, dx = cos(a), dy = sin(a);
    for (double t = 0; t <= rmax; t += 0.5) {
      const double x = cx + t * dx, y = cy + t * dy;
      if (x < 0 || y < 0 || x >= wl || y >= hl) break;   /* the image cuts the ball */
      const int ix = (int)x, iy = (int)y;
      if (iy < top[ix]) break;                           /* beyond the field: unknown */
      if (!is_field(labels, wl, ix, iy, green)) continue;
      /* field here and a label further on (one stray field label inside the ball is no edge) */
      const double x2 = x + dx, y2 = y + dy;
      if (x2 >= 0 && y2 >= 0 && x2 < wl && y2 < hl && !is_field(labels, wl, (int)x2, (int)y2, green)) continue;
      /* between the last not-field sample and this one */
      s->px[s->n] = cx + (t - 0.25) * dx;
      s->py[s->n] = cy + (t - 0.25) * dy;
      s->n++;
      break;
    }
  }
  return s->n;
}

/* distance from p to the segment c -+ h, and the unit vector from its nearest point to p */
static double seg_dist(double px, double py, double cx, double cy, double hx, double hy, double *ux, double *uy) {
  double dx = px - cx, dy = py - cy;
  const double h2 = hx * hx + hy * hy;
  if (h2 > 0) {
    double t = (dx * hx + dy * hy) / h2;
    t = t < -1 ? -1 : (t > 1 ? 1 : t);
    dx -= t * hx;
    dy -= t * hy;
  }
  const double d = sqrt(dx * dx + dy * dy);
  *ux = d > 1e-9 ? dx / d : 0;
  *uy = d > 1e-9 ? dy / d : 0;
  return d;
}

static int by_value(const void *a, const void *b) {
  const double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : (x > y ? 1 : 0);
}

/* Fits centre (x, y) and radius rho to the points: Gauss-Newton with Cauchy weights (scale from the
 * residuals' median), a weak pull of rho toward r0 (an arc alone leaves the radius loose). Returns
 * the points within the inlier band, and the largest angle (rad) between neighbouring inliers seen
 * from the centre in *gap. */
static int fit_circle(const fit_state *s, double hx, double hy, double r0, double *x, double *y, double *rho,
                      double *gap) {
  double e[NRAY], ae[NRAY];
  double scale = 1;
  for (int it = 0; it < 12; it++) {
    for (int i = 0; i < s->n; i++) {
      double ux, uy;
      e[i] = seg_dist(s->px[i], s->py[i], *x, *y, hx, hy, &ux, &uy) - *rho;
      ae[i] = fabs(e[i]);
    }
    qsort(ae, (size_t)s->n, sizeof(double), by_value);
    scale = 1.4826 * ae[s->n / 2];
    if (scale < 0.5) scale = 0.5;   /* labels: the outline's own quantisation */
    double A[3][3] = {{0}}, b[3] = {0};
    const double wp = 1;   /* the pull toward r0: one point's worth */
    A[2][2] += wp;
    b[2] -= wp * (*rho - r0);
    for (int i = 0; i < s->n; i++) {
      double ux, uy;
      seg_dist(s->px[i], s->py[i], *x, *y, hx, hy, &ux, &uy);
      /* a region touching the ball only takes its outline further out, never nearer: a point beyond
       * the circle is three times as suspect as one inside it */
      const double q = (e[i] > 0 ? 3 : 1) * e[i] / (2.4 * scale), w = 1 / (1 + q * q);
      const double J[3] = {-ux, -uy, -1};
      for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++) A[r][c] += w * J[r] * J[c];
        b[r] -= w * J[r] * e[i];
      }
    }
    /* 3 x 3 solve (Cramer) */
    const double det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
                       A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                       A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
    if (fabs(det) < 1e-12) return 0;
    double d[3];
    for (int k = 0; k < 3; k++) {
      double M[3][3];
      memcpy(M, A, sizeof M);
      for (int r = 0; r < 3; r++) M[r][k] = b[r];
      d[k] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
              M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) / det;
    }
    *x += d[0];
    *y += d[1];
    *rho += d[2];
    if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < 1e-4) break;
  }
  /* the inliers and the widest gap between them around the centre */
  double ang[NRAY];
  int n = 0;
  const double band = 3 * scale > 1.5 ? 3 * scale : 1.5;
  for (int i = 0; i < s->n; i++) {
    double ux, uy;
    if (fabs(seg_dist(s->px[i], s->py[i], *x, *y, hx, hy, &ux, &uy) - *rho) <= band)
      ang[n++] = atan2(s->py[i] - *y, s->px[i] - *x);
  }
  *gap = 2 * M_PI;
  if (n >= 2) {
    qsort(ang, (size_t)n, sizeof(double), by_value);
    double g = ang[0] + 2 * M_PI - ang[n - 1];
    for (int i = 1; i < n; i++)
      if (ang[i] - ang[i - 1] > g) g = ang[i] - ang[i - 1];
    *gap = g;
  }
  return n;
}

/* One fit from (u, v) px: the rays cast again from the fitted centre until it stays. Returns the
 * inliers (0: no fit that passes), the centre in *fu, *fv (px). */
static int fit_from(const uint8_t *labels, int wl, int hl, int scale, uint8_t green, const int16_t *top,
                    const bd_view *view, double ball_r, double u, double v, double *fu, double *fv) {
  const double sc = scale, hx = view->blur[0] / (2 * sc), hy = view->blur[1] / (2 * sc);
  fit_state s;
  int inliers = 0;
  for (int pass = 0; pass < 4; pass++) {
    const double rpx = bd_ball_radius_px(view, u, v, ball_r);
    const double r0 = rpx / sc;
    if (!(r0 >= 3)) return 0;   /* too few labels across for an outline */
    const double cx = u / sc, cy = v / sc;
    if (cast(labels, wl, hl, green, top, cx, cy, 1.5 * r0 + sqrt(hx * hx + hy * hy), &s) < MIN_POINTS) return 0;
    double x = cx, y = cy, rho = r0, gap;
    inliers = fit_circle(&s, hx, hy, r0, &x, &y, &rho, &gap);
    /* enough of the outline around it, a radius near the expected one (its region is the ball's) */
    if (inliers < MIN_POINTS || gap > M_PI || fabs(rho - r0) > 0.25 * r0 + 1) return 0;
    const double moved = (x - cx) * (x - cx) + (y - cy) * (y - cy);
    u = x * sc;
    v = y * sc;
    if (moved < 0.0625) break;
  }
  *fu = u;
  *fv = v;
  return inliers;
}

int bd_fit(const uint8_t *labels, int wl, int hl, int scale, uint8_t green, const int16_t *top, const bd_view *view,
           double ball_r, double u0, double v0, bd_candidate *c) {
  if (!labels || !top || !view || !c || wl <= 0 || hl <= 0 || scale <= 0 || !(ball_r > 0)) return BD_EARG;
  double ua = 0, va = 0, ub = 0, vb = 0;
  const int na = fit_from(labels, wl, hl, scale, green, top, view, ball_r, c->u, c->v, &ua, &va);
  const int nb = fit_from(labels, wl, hl, scale, green, top, view, ball_r, u0, v0, &ub, &vb);
  if (na == 0 && nb == 0) return 0;
  c->u = na >= nb ? ua : ub;
  c->v = na >= nb ? va : vb;
  const double r = bd_ball_radius_px(view, c->u, c->v, ball_r);
  if (r > 0) c->radius = r;
  return na >= nb ? na : nb;
}
