/* balldetect: the chosen ball's centre from its outline (bd_fit, balldetect.h).
 *
 * A centroid takes in whatever not-field region touches the ball (a field line passing behind it, the
 * image's edge cutting it), and more passes climb into it. The outline does not: rays from the centre
 * find where the ball's region meets the field; a ray that runs on past 1.5 radii (into a line), out of
 * the image or beyond the field boundary (the backdrop is as not-field as the ball) gives no point.
 * The outline fitted is the sphere's, not a circle: the edge of the ball's tangent cone for a centre
 * on the plane of ball centres, an ellipse off the optical axis whose middle is not the centre's
 * pixel (swept along the view's blur, the smear's shape); its size follows from where the centre is
 * (the expected size at that ground distance), with a loose offset for the colour table's edge. The
 * weights leave out the points beyond it: a region touching the ball only takes its outline further
 * out. */
#include "balldetect.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { NRAY = 48, MIN_POINTS = NRAY / 4 };

typedef struct fit_state {
  double px[NRAY], py[NRAY];   /* edge points, labels (continuous: a label's centre is +0.5) */
  int n;
} fit_state;

/* field and nothing else: the colour table gives some labels two colours (the shaded side of a
 * white ball is also light green), and those are no edge */
static int is_field(const uint8_t *labels, int wl, int x, int y, uint8_t green) {
  const uint8_t l = labels[(size_t)y * wl + x];
  return (l & green) != 0 && (l & ~green) == 0;
}

/* the edge points seen from (cx, cy), rays up to rmax labels; returns their count */
static int cast(const uint8_t *labels, int wl, int hl, uint8_t green, const int16_t *top, double cx, double cy,
                double rmax, fit_state *s) {
  s->n = 0;
  for (int k = 0; k < NRAY; k++) {
    const double a = 2 * M_PI * k / NRAY, dx = cos(a), dy = sin(a);
    for (double t = 0; t <= rmax; t += 1) {
      const double x = cx + t * dx, y = cy + t * dy;
      if (x < 0 || y < 0 || x >= wl || y >= hl) break;   /* the image cuts the ball */
      const int ix = (int)x, iy = (int)y;
      if (iy < top[ix]) break;                           /* beyond the field: unknown */
      if (!is_field(labels, wl, ix, iy, green)) continue;
      /* field here and one and two labels further on (stray field labels inside the ball, sensor noise
       * in its shade, are no edge) */
      int more = 1;
      for (int j = 1; j <= 2 && more; j++) {
        const double x2 = x + j * dx, y2 = y + j * dy;
        more = !(x2 >= 0 && y2 >= 0 && x2 < wl && y2 < hl) || is_field(labels, wl, (int)x2, (int)y2, green);
      }
      if (!more) continue;
      /* the edge to half a label: between the last not-field sample and the first field one */
      const double xh = x - 0.5 * dx, yh = y - 0.5 * dy;
      const double te = t >= 0.5 && xh >= 0 && yh >= 0 && is_field(labels, wl, (int)xh, (int)yh, green) ? t - 0.75
                                                                                                   : t - 0.25;
      s->px[s->n] = cx + te * dx;
      s->py[s->n] = cy + te * dy;
      s->n++;
      break;
    }
  }
  return s->n;
}

/* The ball's outline at centre pixel (u, v) (labels): the angle (rad) from the ray through it to the
 * sphere's tangent cone's edge, the cone of half angle asin(r / distance) around the ray to the centre
 * on the plane of ball centres (an ellipse off the optical axis, and not centred on the centre's
 * pixel: a circle is neither). The point is first moved back along the blur by as much as the smear
 * moved it (the segment centre -+ h: its nearest point's offset). */
typedef struct sphere_model {
  const bd_view *view;
  double sc, r, hx, hy;
} sphere_model;

static int by_value(const void *a, const void *b) {
  const double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : (x > y ? 1 : 0);
}

/* residuals (labels: the angles times f / scale, less the outline's offset d) at centre (u, v) */
static int residuals(const sphere_model *m, const fit_state *s, double u, double v, double d, double *e) {
  const bd_view *vw = m->view;
  const double b = -(u * m->sc - vw->cx) / vw->f, c = -(v * m->sc - vw->cy) / vw->f;
  const double *R = vw->R;
  const double dz = R[6] + R[7] * b + R[8] * c, drop = vw->height - m->r;
  if (dz >= -1e-6 || drop <= 0) return 0;
  const double n2 = 1 + b * b + c * c, dist = drop / -dz * sqrt(n2);
  if (dist <= m->r) return 0;
  const double cone = asin(m->r / dist), k = vw->f / m->sc;
  const double h2 = m->hx * m->hx + m->hy * m->hy;
  for (int i = 0; i < s->n; i++) {
    double px = s->px[i], py = s->py[i];
    if (h2 > 0) {
      double t = ((px - u) * m->hx + (py - v) * m->hy) / h2;
      t = t < -1 ? -1 : (t > 1 ? 1 : t);
      px -= t * m->hx;
      py -= t * m->hy;
    }
    const double pb = -(px * m->sc - vw->cx) / vw->f, pc = -(py * m->sc - vw->cy) / vw->f;
    const double cosang = (1 + b * pb + c * pc) / sqrt(n2 * (1 + pb * pb + pc * pc));
    e[i] = k * (acos(cosang > 1 ? 1 : cosang) - cone) - d;
  }
  return 1;
}

/* Fits the centre pixel (u, v) and the outline's offset d (labels: how much larger the region's
 * outline is than the sphere's; held loosely to 0, an arc alone leaves it loose) to the points:
 * Gauss-Newton with Cauchy weights (scale from the residuals' median). Returns the points within the
 * inlier band (0: no fit), and the largest angle (rad) between neighbouring inliers seen from the
 * centre in *gap. */
static int fit_sphere(const sphere_model *m, const fit_state *s, double r0, double *u, double *v, double *d,
                      double *gap, double *cond) {
  double e[NRAY], eu[NRAY], ev[NRAY], ju[NRAY], jv[NRAY], ae[NRAY];
  double scale = 1, A[3][3];
  const double eps = 0.01;
  for (int it = 0; it < 12; it++) {
    if (!residuals(m, s, *u, *v, *d, e)) return 0;
    /* the derivatives change little near the fit: taken anew on the first two iterations and every
     * fourth (each takes two more passes over the points) */
    if (it < 2 || it % 4 == 0) {
      if (!residuals(m, s, *u + eps, *v, *d, eu) || !residuals(m, s, *u, *v + eps, *d, ev)) return 0;
      for (int i = 0; i < s->n; i++) {
        ju[i] = (eu[i] - e[i]) / eps;
        jv[i] = (ev[i] - e[i]) / eps;
      }
    }
    for (int i = 0; i < s->n; i++) ae[i] = fabs(e[i]);
    qsort(ae, (size_t)s->n, sizeof(double), by_value);
    scale = 1.4826 * ae[s->n / 2];
    if (scale < 0.5) scale = 0.5;   /* labels: the outline's own quantisation */
    memset(A, 0, sizeof A);
    double b[3] = {0};
    const double wp = 1;   /* the pull of d toward 0: one point's worth */
    A[2][2] += wp;
    b[2] -= wp * *d;
    for (int i = 0; i < s->n; i++) {
      /* a region touching the ball only takes its outline further out, never nearer: a point beyond
       * the outline is three times as suspect as one inside it */
      const double q = (e[i] > 0 ? 3 : 1) * e[i] / (2.4 * scale), w = 1 / (1 + q * q);
      const double J[3] = {ju[i], jv[i], -1};
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
    double dl[3];
    for (int k = 0; k < 3; k++) {
      double M[3][3];
      memcpy(M, A, sizeof M);
      for (int r = 0; r < 3; r++) M[r][k] = b[r];
      dl[k] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
               M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) / det;
    }
    *u += dl[0];
    *v += dl[1];
    *d += dl[2];
    if (dl[0] * dl[0] + dl[1] * dl[1] + dl[2] * dl[2] < 1e-3) break;
  }
  /* the inliers and the widest gap between them around the centre */
  if (!residuals(m, s, *u, *v, *d, e)) return 0;
  double ang[NRAY];
  int n = 0;
  /* a fixed band (not the residuals' scale: a wrong fit's spread would widen it): the outline's
   * quantisation, and the region's edge a little off the sphere's on a large ball */
  const double band = 1.5 + 0.04 * r0;
  for (int i = 0; i < s->n; i++)
    if (fabs(e[i]) <= band) ang[n++] = atan2(s->py[i] - *v, s->px[i] - *u);
  *gap = 2 * M_PI;
  if (n >= 2) {
    qsort(ang, (size_t)n, sizeof(double), by_value);
    double g = ang[0] + 2 * M_PI - ang[n - 1];
    for (int i = 1; i < n; i++)
      if (ang[i] - ang[i - 1] > g) g = ang[i] - ang[i - 1];
    *gap = g;
  }
  /* how well the points hold the centre in its worst direction against its best: the centre's block
   * of the last iteration's normal equations with the offset d eliminated, its eigenvalues' ratio (1
   * for a whole outline, ~0.2 for half of it, ~0 for a smear's straight sides alone) */
  const double sxx = A[0][0] - A[0][2] * A[2][0] / A[2][2], syy = A[1][1] - A[1][2] * A[2][1] / A[2][2];
  const double sxy = A[0][1] - A[0][2] * A[2][1] / A[2][2];
  const double h = (sxx + syy) / 2, q = sqrt(((sxx - syy) / 2) * ((sxx - syy) / 2) + sxy * sxy);
  *cond = h + q > 0 ? (h - q) / (h + q) : 0;
  return n;
}

/* One fit from (u, v) px: the rays cast again from the fitted centre until it stays. Returns the
 * inliers (0: no fit that passes), the centre in *fu, *fv (px). */
static int fit_from(const uint8_t *labels, int wl, int hl, int scale, uint8_t green, const int16_t *top,
                    const bd_view *view, double ball_r, double u, double v, double *fu, double *fv) {
  const double sc = scale;
  const sphere_model m = {view, sc, ball_r, view->blur[0] / (2 * sc), view->blur[1] / (2 * sc)};
  fit_state s;
  int inliers = 0;
  for (int pass = 0; pass < 4; pass++) {
    const double r0 = bd_ball_radius_px(view, u, v, ball_r) / sc;
    /* a ball of 10 labels in radius or more (the OP3's camera: 2.1 m and nearer): on a smaller one a
     * line pulls the centroid by few pixels, while a smear longer than the view's blur says (a still
     * frame without rates, the head sped up) leaves its few outline points a choice of either end
     * (Tests/vision/ball_frames_test.sh's frame 65: 7.7% by the centroid, 11.5% fitted) */
    if (!(r0 >= 10)) return 0;
    const double cx = u / sc, cy = v / sc;
    /* not a ball whose disc reaches beyond the field boundary (as bd_settle): half its outline is
     * unknown there, and a smear longer than the view's blur says (the head turning faster than
     * since the last frame) then fits anywhere along it. A boundary at row 0 is the image's edge: the
     * field goes on above it */
    for (int x = (int)(cx - r0); x <= (int)(cx + r0); x++)
      if (x >= 0 && x < wl && top[x] > 0 && cy - r0 < top[x]) return 0;
    if (cast(labels, wl, hl, green, top, cx, cy, 1.5 * r0 + sqrt(m.hx * m.hx + m.hy * m.hy), &s) < MIN_POINTS)
      return 0;
    double x = cx, y = cy, d = 0, gap = 0, cond = 0;
    inliers = fit_sphere(&m, &s, r0, &x, &y, &d, &gap, &cond);
    /* enough of the outline around it, near the expected size (its region is the ball's), and the
     * points hold the centre in every direction (the spec's outlines cut by a line or an edge: 0.38
     * and more; a smear longer than the view's blur, cut at one end, leaves the centre free to slide
     * along it) */
    if (inliers < MIN_POINTS || gap > M_PI || fabs(d) > 0.25 * r0 + 1 || cond < 0.25) return 0;
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
  /* the second start only when it is more than a label from the first */
  const double du = (u0 - c->u) / scale, dv = (v0 - c->v) / scale;
  const int nb = du * du + dv * dv > 1 ? fit_from(labels, wl, hl, scale, green, top, view, ball_r, u0, v0, &ub, &vb) : 0;
  if (na == 0 && nb == 0) return 0;
  c->u = na >= nb ? ua : ub;
  c->v = na >= nb ? va : vb;
  const double r = bd_ball_radius_px(view, c->u, c->v, ball_r);
  if (r > 0) c->radius = r;
  return na >= nb ? na : nb;
}
