/* balldetect: field boundary, ball candidates, patch features and the classifier (balldetect.h). */
#include "balldetect.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct bd {
  int max_w, max_h;
  int32_t *integral;   /* (max_w + 1) x (max_h + 1): non-field labels below the boundary, summed */
  int32_t *integral_all;   /* labels below the boundary, summed (the field part of a box) */
  int16_t *raw;        /* per column: first row of the field run, before the hull */
  int *hull;           /* column indices on the hull */
  bd_candidate *cand;  /* every position that passed, before the suppression */
  int ncand_max;
};

double bd_ball_radius_px(const bd_view *view, double u, double v, double r) {
  const double b = -(u - view->cx) / view->f, c = -(v - view->cy) / view->f;
  const double *R = view->R;
  const double dz = R[6] + R[7] * b + R[8] * c;   /* the ray (1, b, c) in the level frame */
  const double drop = view->height - r;
  if (dz >= -1e-6 || drop <= 0) return 0;
  const double depth = drop / -dz;                 /* along the optical axis (the ray's x is 1) */
  return view->f * r / depth;
}

bd *bd_new(int max_w, int max_h) {
  if (max_w <= 0 || max_h <= 0) return NULL;
  bd *w = calloc(1, sizeof(bd));
  if (!w) return NULL;
  w->max_w = max_w;
  w->max_h = max_h;
  w->ncand_max = 4096;
  w->integral = calloc((size_t)(max_w + 1) * (max_h + 1), sizeof(int32_t));
  w->integral_all = calloc((size_t)(max_w + 1) * (max_h + 1), sizeof(int32_t));
  w->raw = calloc((size_t)max_w, sizeof(int16_t));
  w->hull = calloc((size_t)max_w, sizeof(int));
  w->cand = calloc((size_t)w->ncand_max, sizeof(bd_candidate));
  if (!w->integral || !w->integral_all || !w->raw || !w->hull || !w->cand) {
    bd_free(w);
    return NULL;
  }
  return w;
}

void bd_free(bd *w) {
  if (!w) return;
  free(w->integral);
  free(w->integral_all);
  free(w->raw);
  free(w->hull);
  free(w->cand);
  free(w);
}

/* ---------------------------------------------------------------- field boundary */

/* z of (b - a) x (c - a): > 0 when a, b, c turn one way, < 0 the other */
static long cross(int ax, int ay, int bx, int by, int cx, int cy) {
  return (long)(bx - ax) * (cy - ay) - (long)(by - ay) * (cx - ax);
}

int bd_field_boundary(bd *w, const uint8_t *labels, int wl, int hl, uint8_t green, int min_run, int16_t *top) {
  if (!w || !labels || !top || wl > w->max_w || hl > w->max_h || wl <= 0 || hl <= 0) return BD_EARG;
  if (min_run < 1) min_run = 1;
  int16_t *raw = w->raw;
  int nfield = 0;
  for (int x = 0; x < wl; x++) {
    int run = 0, y = 0;
    raw[x] = (int16_t)hl;
    for (; y < hl; y++) {
      if (labels[(size_t)y * wl + x] & green) {
        if (++run >= min_run) break;
      } else {
        run = 0;
      }
    }
    /* a run cut by the image's bottom still counts: the field goes on below */
    if (run >= min_run || (run > 0 && y == hl)) {
      raw[x] = (int16_t)((y == hl ? hl : y + 1) - run);
      nfield++;
    }
  }
  /* lower hull (smallest rows: image v points down) of the columns with field, Andrew's chain */
  int *h = w->hull, n = 0;
  for (int x = 0; x < wl; x++) {
    if (raw[x] >= hl) continue;
    while (n >= 2 && cross(h[n - 2], raw[h[n - 2]], h[n - 1], raw[h[n - 1]], x, raw[x]) <= 0) n--;
    h[n++] = x;
  }
  for (int x = 0; x < wl; x++) top[x] = (int16_t)hl;
  if (n == 0) return 0;
  top[h[0]] = raw[h[0]];
  for (int k = 0; k + 1 < n; k++) {
    const int x0 = h[k], x1 = h[k + 1];
    for (int x = x0; x <= x1; x++) {
      const double t = (double)(x - x0) / (x1 - x0);
      top[x] = (int16_t)floor(raw[x0] + t * (raw[x1] - raw[x0]) + 0.5);
    }
  }
  return nfield;
}

/* ---------------------------------------------------------------- candidates */

/* sum of the integral image over labels [x0, x1) x [y0, y1), clipped; *area gets the clipped area */
static int32_t box(const int32_t *S, int wl, int hl, int x0, int y0, int x1, int y1, int32_t *area) {
  if (x0 < 0) x0 = 0;
  if (y0 < 0) y0 = 0;
  if (x1 > wl) x1 = wl;
  if (y1 > hl) y1 = hl;
  if (x1 <= x0 || y1 <= y0) {
    *area = 0;
    return 0;
  }
  const int s = wl + 1;
  *area = (x1 - x0) * (y1 - y0);
  return S[y1 * s + x1] - S[y0 * s + x1] - S[y1 * s + x0] + S[y0 * s + x0];
}

/* The candidate's centre moved to the centroid of the non-field labels in its disc swept by half the
 * view's blur either way (the smear's shape: a disc alone would rest anywhere along a smear longer
 * than the ball), up to `passes` times, until it moves less than a quarter label; the radius
 * follows. At most ~400 labels a disc's area looked at per pass. Returns the passes made. */
static int centroid_passes(const uint8_t *labels, int wl, int hl, uint8_t green, const int16_t *top, int scale,
                           const bd_view *view, double ball_r, bd_candidate *c, int passes) {
  const double sc = scale;
  const double hbx = view->blur[0] / (2 * sc), hby = view->blur[1] / (2 * sc);   /* labels */
  const double hb2 = hbx * hbx + hby * hby, ex = fabs(hbx), ey = fabs(hby);
  int it = 0;
  while (it < passes) {
    it++;
    const double r = c->radius / sc, cx = c->u / sc - 0.5, cy = c->v / sc - 0.5;
    const int st = r > 20 ? (int)(r / 10) : 1;
    double sx = 0, sy = 0, m = 0;
    for (int yy = (int)(cy - r - ey); yy <= (int)(cy + r + ey) + 1; yy += st) {
      if (yy < 0 || yy >= hl) continue;
      for (int xx = (int)(cx - r - ex); xx <= (int)(cx + r + ex) + 1; xx += st) {
        if (xx < 0 || xx >= wl) continue;
        double dx = xx - cx, dy = yy - cy;
        if (hb2 > 0) {
          /* beyond the field boundary only within the disc itself: the sweep there would take in the
           * backdrop behind a ball smeared at the field's edge */
          if (yy < top[xx] && dx * dx + dy * dy > r * r) continue;
          /* from the nearest point of the segment centre -+ half the blur */
          double t = (dx * hbx + dy * hby) / hb2;
          t = t < -1 ? -1 : (t > 1 ? 1 : t);
          dx -= t * hbx;
          dy -= t * hby;
        }
        if (dx * dx + dy * dy > r * r || (labels[(size_t)yy * wl + xx] & green)) continue;
        sx += xx;
        sy += yy;
        m += 1;
      }
    }
    if (m == 0) break;
    const double nu = (sx / m + 0.5) * sc, nv = (sy / m + 0.5) * sc;
    const double moved = (nu - c->u) * (nu - c->u) + (nv - c->v) * (nv - c->v);
    c->u = nu;
    c->v = nv;
    const double rr = bd_ball_radius_px(view, c->u, c->v, ball_r);
    if (rr > 0) c->radius = rr;
    if (moved < 0.0625 * sc * sc) break;
  }
  return it;
}

int bd_settle(const uint8_t *labels, int wl, int hl, int scale, uint8_t green, const int16_t *top, const bd_view *view,
              double ball_r, bd_candidate *c) {
  if (!labels || !top || !view || !c || wl <= 0 || hl <= 0 || scale <= 0 || !(c->radius > 0)) return BD_EARG;
  /* not a ball whose disc reaches beyond the field boundary: there the backdrop is as not-field as
   * the ball, and more passes would climb into it */
  const double r = c->radius / scale, cx = c->u / scale - 0.5, cy = c->v / scale - 0.5;
  for (int x = (int)(cx - r); x <= (int)(cx + r) + 1; x++)
    if (x >= 0 && x < wl && cy - r < top[x]) return 0;
  return centroid_passes(labels, wl, hl, green, top, scale, view, ball_r, c, 6);
}

static int by_score(const void *a, const void *b) {
  const double sa = ((const bd_candidate *)a)->score, sb = ((const bd_candidate *)b)->score;
  return sa < sb ? 1 : (sa > sb ? -1 : 0);
}

int bd_candidates(bd *w, const uint8_t *labels, int wl, int hl, int scale, uint8_t green,
                  const int16_t *top, const bd_view *view, double ball_r, int step, double min_inner,
                  double max_ring, double min_radius_px, bd_candidate *out, int maxn) {
  if (!w || !labels || !top || !view || !out || wl > w->max_w || hl > w->max_h || wl <= 0 || hl <= 0 ||
      scale <= 0 || step <= 0 || maxn < 0)
    return BD_EARG;
  /* integral images of the labels below the boundary (A) and of those that are not field (S): the
   * disc and the ring are judged on their part on the field (a far ball at the field's edge rises
   * above the boundary; what lies beyond the field says nothing) */
  int32_t *S = w->integral, *A = w->integral_all;
  const int s = wl + 1;
  memset(S, 0, sizeof(int32_t) * (size_t)s);
  memset(A, 0, sizeof(int32_t) * (size_t)s);
  for (int y = 0; y < hl; y++) {
    const uint8_t *row = labels + (size_t)y * wl;
    int32_t acc = 0, acc_all = 0;
    int32_t *o = S + (size_t)(y + 1) * s, *p = S + (size_t)y * s;
    int32_t *oa = A + (size_t)(y + 1) * s, *pa = A + (size_t)y * s;
    o[0] = oa[0] = 0;
    for (int x = 0; x < wl; x++) {
      const int32_t in = y >= top[x];
      acc += in & ((row[x] & green) == 0);
      acc_all += in;
      o[x + 1] = p[x + 1] + acc;
      oa[x + 1] = pa[x + 1] + acc_all;
    }
  }
  int nc = 0;
  const double sc = scale;
  for (int y = step / 2; y < hl; y += step) {
    const uint8_t *row = labels + (size_t)y * wl;
    for (int x = step / 2; x < wl; x += step) {
      if (row[x] & green) continue;
      const double u = (x + 0.5) * sc, v = (y + 0.5) * sc;
      const double rpx = bd_ball_radius_px(view, u, v, ball_r);
      if (rpx < min_radius_px) continue;
      const double r = rpx / sc;   /* labels */
      if (y + r < top[x]) continue;   /* the ball's foot is on the field */
      /* the disc's inner box and a ring (box 1.6 r minus box 1.15 r), each on its part on the field;
       * at least a quarter of the inner box lies on the field */
      int32_t ai, dummy;
      const int a = (int)(0.7 * r + 0.5) > 0 ? (int)(0.7 * r + 0.5) : 1;
      const int32_t ni = box(S, wl, hl, x - a + 1, y - a + 1, x + a, y + a, &dummy);
      const int32_t fi = box(A, wl, hl, x - a + 1, y - a + 1, x + a, y + a, &ai);
      if (ai == 0 || fi * 4 < ai || ni < min_inner * fi) continue;
      const int bo = (int)(1.6 * r + 1), bm = (int)(1.15 * r + 1);
      const int32_t no = box(S, wl, hl, x - bo + 1, y - bo + 1, x + bo, y + bo, &dummy);
      const int32_t nm = box(S, wl, hl, x - bm + 1, y - bm + 1, x + bm, y + bm, &dummy);
      const int32_t fo = box(A, wl, hl, x - bo + 1, y - bo + 1, x + bo, y + bo, &dummy);
      const int32_t fm = box(A, wl, hl, x - bm + 1, y - bm + 1, x + bm, y + bm, &dummy);
      const double ring = fo > fm ? (double)(no - nm) / (fo - fm) : 0;
      if (ring > max_ring) continue;
      if (nc >= w->ncand_max) break;
      bd_candidate *c = &w->cand[nc++];
      c->u = u;
      c->v = v;
      c->radius = rpx;
      c->inner = (double)ni / fi;
      c->ring = ring;
      /* less the part of the inner box beyond the boundary: the blurred far edge of the field is a
       * row of not-field spots that would otherwise outrank a ball on the field */
      c->score = c->inner - ring - (1 - (double)fi / ai);
      c->prob = -1;
    }
  }
  qsort(w->cand, (size_t)nc, sizeof(bd_candidate), by_score);
  int n = 0;
  for (int i = 0; i < nc && n < maxn; i++) {
    const bd_candidate *c = &w->cand[i];
    int near = 0;
    for (int k = 0; k < n && !near; k++) {
      const double du = c->u - out[k].u, dv = c->v - out[k].v, rr = out[k].radius > c->radius ? out[k].radius : c->radius;
      near = du * du + dv * dv < rr * rr;
    }
    if (near) continue;
    out[n] = *c;
    /* the centre: the centroid of its region, twice (a disc on a spot's edge moves onto it) */
    centroid_passes(labels, wl, hl, green, top, scale, view, ball_r, &out[n], 2);
    n++;
  }
  return n;
}

/* ---------------------------------------------------------------- features */

int bd_features(const uint8_t *yuyv, int width, int height, double u, double v, double radius,
                double margin, float *out) {
  if (!yuyv || !out || width <= 1 || height <= 0 || radius <= 0 || margin <= 0) return BD_EARG;
  const double side = 2 * margin * radius, cell = side / BD_GRID;
  const double x0 = u - side / 2, y0 = v - side / 2;
  /* up to 3 x 3 samples a cell: enough to average the pattern, bounded for near balls */
  const int ns = cell >= 3 ? 3 : (cell >= 1.5 ? 2 : 1);
  float *Y = out;
  float *U = out + BD_GRID * BD_GRID, *V = U + BD_CGRID * BD_CGRID;
  for (int k = 0; k < BD_CGRID * BD_CGRID; k++) U[k] = V[k] = 0;
  const int per = BD_GRID / BD_CGRID;
  double sum = 0, sum2 = 0, mid = 0;
  for (int j = 0; j < BD_GRID; j++) {
    for (int i = 0; i < BD_GRID; i++) {
      double ay = 0, au = 0, av = 0;
      for (int sj = 0; sj < ns; sj++) {
        int py = (int)(y0 + (j + (sj + 0.5) / ns) * cell);
        py = py < 0 ? 0 : (py >= height ? height - 1 : py);
        const uint8_t *row = yuyv + (size_t)py * width * 2;
        for (int si = 0; si < ns; si++) {
          int px = (int)(x0 + (i + (si + 0.5) / ns) * cell);
          px = px < 0 ? 0 : (px >= width ? width - 1 : px);
          const uint8_t *pair = row + (size_t)(px & ~1) * 2;
          ay += row[(size_t)px * 2];
          au += pair[1];
          av += pair[3];
        }
      }
      const double inv = 1.0 / (ns * ns);
      Y[j * BD_GRID + i] = (float)(ay * inv);
      sum += ay * inv;
      if (j >= BD_GRID / 4 && j < 3 * BD_GRID / 4 && i >= BD_GRID / 4 && i < 3 * BD_GRID / 4) mid += ay * inv;
      sum2 += ay * inv * ay * inv;
      const int c = (j / per) * BD_CGRID + i / per;
      U[c] += (float)(au * inv);
      V[c] += (float)(av * inv);
    }
  }
  const double n = BD_GRID * BD_GRID, mean = sum / n;
  const double var = sum2 / n - mean * mean;
  const double sd = sqrt(var > 0 ? var : 0) + 4;   /* + 4: a flat patch stays flat, not amplified noise */
  for (int k = 0; k < BD_GRID * BD_GRID; k++) Y[k] = (float)((Y[k] - mean) / sd);
  const double cn = per * per;
  for (int k = 0; k < BD_CGRID * BD_CGRID; k++) {
    U[k] = (float)((U[k] / cn - 128) / 32);
    V[k] = (float)((V[k] / cn - 128) / 32);
  }
  float *L = V + BD_CGRID * BD_CGRID;
  L[0] = (float)((mean - 128) / 64);
  L[1] = (float)((mid / (n / 4) - 128) / 64);
  L[2] = (float)((sd - 4) / 64);
  return BD_NFEAT;
}

/* ---------------------------------------------------------------- classifier */

struct bd_mlp {
  int nin, nhid;
  double margin;
  float *w1, *b1, *w2, b2;
  float *h;   /* hidden activations */
};

void bd_mlp_free(bd_mlp *m) {
  if (!m) return;
  free(m->w1);
  free(m->b1);
  free(m->w2);
  free(m->h);
  free(m);
}

static int read_floats(FILE *f, float *dst, int n, const char *path, const char *what, char *err, size_t errlen) {
  for (int i = 0; i < n; i++) {
    if (fscanf(f, "%f", &dst[i]) != 1 || !isfinite(dst[i])) {
      snprintf(err, errlen, "%s: %s element %d of %d missing or not a finite number", path, what, i + 1, n);
      return -1;
    }
  }
  return 0;
}

bd_mlp *bd_mlp_load(const char *path, char *err, size_t errlen) {
  FILE *f = fopen(path, "r");
  if (!f) {
    snprintf(err, errlen, "%s: cannot open the ball classifier", path);
    return NULL;
  }
  char magic[32] = {0};
  int version = 0, nin = 0, nhid = 0;
  double margin = 0;
  if (fscanf(f, "%31s %d %d %d %lf", magic, &version, &nin, &nhid, &margin) != 5 ||
      strcmp(magic, "hrp-ball-mlp") != 0 || version != 1) {
    snprintf(err, errlen, "%s: not a ball classifier (want a first line 'hrp-ball-mlp 1 NIN NHID MARGIN')", path);
    fclose(f);
    return NULL;
  }
  if (nin != BD_NFEAT || nhid < 1 || nhid > 1024 || !(margin > 0 && margin < 10)) {
    snprintf(err, errlen, "%s: header NIN %d (this build's features: %d), NHID %d (1..1024), MARGIN %g (0..10)",
             path, nin, BD_NFEAT, nhid, margin);
    fclose(f);
    return NULL;
  }
  bd_mlp *m = calloc(1, sizeof(bd_mlp));
  if (!m) {
    fclose(f);
    snprintf(err, errlen, "%s: out of memory", path);
    return NULL;
  }
  m->nin = nin;
  m->nhid = nhid;
  m->margin = margin;
  m->w1 = malloc(sizeof(float) * (size_t)nin * nhid);
  m->b1 = malloc(sizeof(float) * (size_t)nhid);
  m->w2 = malloc(sizeof(float) * (size_t)nhid);
  m->h = malloc(sizeof(float) * (size_t)nhid);
  if (!m->w1 || !m->b1 || !m->w2 || !m->h || read_floats(f, m->w1, nin * nhid, path, "W1", err, errlen) ||
      read_floats(f, m->b1, nhid, path, "b1", err, errlen) || read_floats(f, m->w2, nhid, path, "w2", err, errlen) ||
      read_floats(f, &m->b2, 1, path, "b2", err, errlen)) {
    if (!m->h) snprintf(err, errlen, "%s: out of memory", path);
    bd_mlp_free(m);
    fclose(f);
    return NULL;
  }
  float extra;
  if (fscanf(f, "%f", &extra) == 1) {
    snprintf(err, errlen, "%s: more numbers than the header's NIN %d and NHID %d take", path, nin, nhid);
    bd_mlp_free(m);
    fclose(f);
    return NULL;
  }
  fclose(f);
  return m;
}

int bd_mlp_nin(const bd_mlp *m) { return m->nin; }
double bd_mlp_margin(const bd_mlp *m) { return m->margin; }

double bd_mlp_eval(const bd_mlp *m, const float *x) {
  double z = m->b2;
  for (int j = 0; j < m->nhid; j++) {
    const float *wr = m->w1 + (size_t)j * m->nin;
    float a = m->b1[j];
    for (int i = 0; i < m->nin; i++) a += wr[i] * x[i];
    if (a > 0) z += a * m->w2[j];
  }
  return 1 / (1 + exp(-z));
}
