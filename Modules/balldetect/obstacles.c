/* balldetect: obstacles (other robots) standing on the field, from label columns (balldetect.h). */
#include <stdlib.h>
#include <string.h>

#include "balldetect.h"

/* per column: the run found (or not), stored in the caller's workspace-sized arrays */
typedef struct col {
  int16_t ok, top, foot, red, blue;
} col;

static int by_width(const void *a, const void *b) {
  const bd_obstacle *x = a, *y = b;
  return (y->x1 - y->x0) - (x->x1 - x->x0);
}

/* The columns of the feet: the non-field labels on the foot's 3 lowest rows with field below them
 * (nothing goes on down: not another robot's legs), reached from the band's columns that stand on
 * that foot, up to max_gap columns bridged. A robot cut by the image's top edge shows one leg's
 * columns rising to it, and its feet, wider, below. */
static int foot_column(const uint8_t *labels, int wl, int hl, const int16_t *top, uint8_t field_mask, int foot,
                       int x) {
  int on = 0;
  if (foot < top[x] + 2) return 0;
  for (int y = foot; y >= 0 && y > foot - 3; y--) on |= !(labels[(size_t)y * wl + x] & field_mask);
  if (!on) return 0;
  for (int y = foot + 3; y < hl && y <= foot + 5; y++)
    if (!(labels[(size_t)y * wl + x] & field_mask)) return 0;
  return 1;
}

static void foot_extent(const uint8_t *labels, int wl, int hl, const int16_t *top, uint8_t field_mask, int max_gap,
                        bd_obstacle *o, const col *cols) {
  /* the band's first and last columns standing on its foot: the scans start there */
  int c0 = -1, c1 = -1;
  for (int c = o->x0; c <= o->x1; c++) {
    if (!cols[c].ok || cols[c].foot < o->foot - 2 || cols[c].foot > o->foot + 2) continue;
    if (c0 < 0) c0 = c;
    c1 = c;
  }
  o->fx0 = o->x0;
  o->fx1 = o->x1;
  if (c0 < 0) return;
  for (int x = c0 - 1, gap = 0; x >= 0 && gap <= max_gap; x--) {
    if (!foot_column(labels, wl, hl, top, field_mask, o->foot, x)) {
      gap++;
    } else {
      gap = 0;
      if (x < o->fx0) o->fx0 = x;
    }
  }
  for (int x = c1 + 1, gap = 0; x < wl && gap <= max_gap; x++) {
    if (!foot_column(labels, wl, hl, top, field_mask, o->foot, x)) {
      gap++;
    } else {
      gap = 0;
      if (x > o->fx1) o->fx1 = x;
    }
  }
}

int bd_obstacles(bd *w, const uint8_t *labels, int wl, int hl, const int16_t *top, uint8_t field_mask,
                 uint8_t red, uint8_t blue, int min_run, int min_below, int max_gap, int leg_gap,
                 int min_width, bd_obstacle *out, int maxn) {
  (void)w;
  if (!labels || !top || !out || wl <= 0 || hl <= 0 || wl > 4096 || maxn < 0 || leg_gap < 0) return BD_EARG;
  col cols[4096];
  for (int x = 0; x < wl; x++) {
    col *c = &cols[x];
    c->ok = 0;
    /* from the bottom up: the first obstacle label starts a run; bridged field-mask labels up to
     * max_gap; the run ends at a longer gap. Kept when long enough and up to the boundary. */
    int y = hl - 1;
    /* foot and top of the runs below when they chain up to this one, and their labels below the boundary */
    int chain = -1, chain_top = -1, chain_below = 0;
    while (y >= 0) {
      while (y >= 0 && (labels[(size_t)y * wl + x] & field_mask)) y--;
      if (y < 0) break;
      /* a run starting within leg_gap rows above the last one continues it: thin legs smeared by
       * motion blur take the field's colour, and the feet below them are the robot's foot */
      if (chain < 0 || chain_top - y > leg_gap) {
        chain = y;
        chain_below = 0;
      }
      const int foot = chain;
      int gap = 0, yt = y, nred = 0, nblue = 0, n = 0;
      for (; y >= 0; y--) {
        const uint8_t l = labels[(size_t)y * wl + x];
        if (l & field_mask) {
          if (++gap > max_gap) break;
        } else {
          gap = 0;
          yt = y;
          n++;
          chain_below += y > top[x];
          nred += (l & red) != 0;
          nblue += (l & blue) != 0;
        }
      }
      /* the foot stands on the field, below its boundary, with min_below labels of the run (and
       * of the runs chained to it) below the boundary: what rises from the boundary itself is the
       * world beyond the field, and so is a strip between the boundary's hull and a field edge
       * that the lens bent */
      if (n >= min_run && yt <= top[x] && foot >= top[x] + 2 && chain_below >= min_below) {
        c->ok = 1;
        c->top = (int16_t)yt;
        c->foot = (int16_t)foot;
        c->red = (int16_t)nred;
        c->blue = (int16_t)nblue;
        break;
      }
      /* too short or inside the field (a ball, a mark): look further up, above what was seen */
      if (yt <= top[x]) break;
      chain_top = yt;
      y = yt - 1;
    }
  }
  /* bands of neighbouring columns whose feet agree */
  int n = 0, nall = 0;
  bd_obstacle tmp[64];
  for (int x = 0; x < wl;) {
    if (!cols[x].ok) {
      x++;
      continue;
    }
    /* the next column of the band: ok, within min_width columns (the field seen between the legs);
     * feet may differ (legs, arms and body above them) */
    int x1 = x;
    for (;;) {
      int nx = x1 + 1;
      while (nx < wl && nx <= x1 + min_width && !cols[nx].ok) nx++;
      if (nx >= wl || nx > x1 + min_width) break;
      x1 = nx;
    }
    if (x1 - x + 1 >= min_width && nall < 64) {
      bd_obstacle *o = &tmp[nall++];
      int16_t feet[4096];
      int k = 0;
      feet[0] = (int16_t)x;   /* set: the band's first column is ok, but the compiler cannot see it */
      o->x0 = x;
      o->x1 = x1;
      o->top = hl;
      o->red = o->blue = 0;
      o->foot_visible = 1;
      for (int c = x; c <= x1; c++) {
        if (!cols[c].ok) continue;
        feet[k++] = cols[c].foot;
        if (cols[c].top < o->top) o->top = cols[c].top;
        o->red += cols[c].red;
        o->blue += cols[c].blue;
      }
      /* the foot: the lowest rows are the feet, arms and body end higher; the 95th percentile, so
       * that one stray column does not decide (insertion sort: bands are narrow) */
      for (int i = 1; i < k; i++)
        for (int j = i; j > 0 && feet[j] < feet[j - 1]; j--) {
          const int16_t t = feet[j];
          feet[j] = feet[j - 1];
          feet[j - 1] = t;
        }
      o->foot = feet[(k - 1) * 19 / 20];
      if (o->foot >= hl - 1) o->foot_visible = 0;
      foot_extent(labels, wl, hl, top, field_mask, max_gap, o, cols);
    }
    x = x1 + 1;
  }
  qsort(tmp, (size_t)nall, sizeof(bd_obstacle), by_width);
  for (int i = 0; i < nall && n < maxn; i++) out[n++] = tmp[i];
  return n;
}

int bd_column_count(const uint8_t *labels, int wl, int hl, int x, int y0, int y1, uint8_t mask) {
  if (!labels || x < 0 || x >= wl) return BD_EARG;
  if (y0 < 0) y0 = 0;
  if (y1 > hl - 1) y1 = hl - 1;
  int n = 0;
  for (int y = y0; y <= y1; y++) n += !(labels[(size_t)y * wl + x] & mask);
  return n;
}
