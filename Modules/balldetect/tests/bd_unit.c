/* Unit tests of balldetect on synthetic label images (TAP). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "balldetect/balldetect.h"
#include "tap.h"

enum { W = 320, H = 240, GREEN = 8, WHITE = 16 };

int main(void) {
  static uint8_t L[W * H];
  static int16_t top[W];
  bd *w = bd_new(W, H);
  check(w != NULL, "workspace");
  /* the field below row 40, a robot standing at its edge (columns 100..130 non-field down to 90) */
  for (int y = 0; y < H; y++)
    for (int x = 0; x < W; x++) L[y * W + x] = y >= 40 && !(x >= 100 && x <= 130 && y < 90) ? GREEN : 0;
  /* a bit of green noise above the field: shorter than the run */
  L[10 * W + 50] = GREEN;
  L[11 * W + 50] = GREEN;
  int n = bd_field_boundary(w, L, W, H, GREEN, 4, top);
  check(n == W, "every column has field");
  int ok = 1;
  for (int x = 0; x < W; x++) ok &= top[x] == 40;
  check(ok, "boundary at row 40, the robot in front of the edge bridged, noise above it ignored");
  /* a sloped edge (convex from below) stays as it is */
  for (int y = 0; y < H; y++)
    for (int x = 0; x < W; x++) L[y * W + x] = y >= 40 + abs(x - 160) / 4 ? GREEN : 0;
  bd_field_boundary(w, L, W, H, GREEN, 4, top);
  check(top[0] == 80 && top[160] == 40 && top[319] == 79, "a corner of the field: the boundary follows it");

  /* camera looking straight down from 0.5 m: every ball of radius 0.07 m looks f r / 0.43 */
  bd_view view = {.f = 100, .cx = W / 2.0, .cy = H / 2.0, .R = {0, 0, 1, 0, 1, 0, -1, 0, 0}, .height = 0.5};
  const double rpx = bd_ball_radius_px(&view, 100, 100, 0.07);
  check(fabs(rpx - 100 * 0.07 / 0.43) < 1e-9, "expected radius looking down");
  /* field everywhere, a white disc of that radius at (200, 150), a line through x = 60 */
  for (int y = 0; y < H; y++)
    for (int x = 0; x < W; x++) {
      const double dx = x + 0.5 - 200, dy = y + 0.5 - 150;
      L[y * W + x] = dx * dx + dy * dy <= rpx * rpx || abs(x - 60) <= 2 ? WHITE : GREEN;
    }
  bd_field_boundary(w, L, W, H, GREEN, 4, top);
  bd_candidate c[8];
  n = bd_candidates(w, L, W, H, 1, GREEN, top, &view, 0.07, 2, 0.8, 0.5, 1.5, c, 8);
  check(n == 1, "one candidate: the disc (the thin line is no disc)");
  check(n >= 1 && fabs(c[0].u - 200) < 1 && fabs(c[0].v - 150) < 1, "its centre within 1 px");
  check(n >= 1 && c[0].inner > 0.95 && c[0].ring < 0.05, "inside not field, around it field");
  /* the disc smeared 24 px across by a turning camera (the view's blur): the smear's centre */
  for (int y = 0; y < H; y++)
    for (int x = 0; x < W; x++) {
      const double dx = x + 0.5 - 200, dy = y + 0.5 - 150, ex = fabs(dx) > 12 ? fabs(dx) - 12 : 0;
      L[y * W + x] = ex * ex + dy * dy <= rpx * rpx ? WHITE : GREEN;
    }
  bd_field_boundary(w, L, W, H, GREEN, 4, top);
  view.blur[0] = 24;
  n = bd_candidates(w, L, W, H, 1, GREEN, top, &view, 0.07, 2, 0.8, 0.5, 1.5, c, 8);
  if (n >= 1) bd_settle(L, W, H, 1, GREEN, top, &view, 0.07, &c[0]);
  view.blur[0] = 0;
  if (n >= 1) printf("# smeared: centre %.2f, %.2f\n", c[0].u, c[0].v);
  check(n >= 1 && fabs(c[0].u - 200) < 1 && fabs(c[0].v - 150) < 1, "a smeared ball: the smear's centre within 1 px");

  float f[BD_NFEAT];
  static uint8_t yuyv[W * H * 2];
  for (int i = 0; i < W * H; i++) {
    yuyv[2 * i] = L[i] == WHITE ? 230 : 90;
    yuyv[2 * i + 1] = L[i] == WHITE ? 128 : 100;
  }
  check(bd_features(yuyv, W, H, 200, 150, rpx, 1.3, f) == BD_NFEAT, "features");
  double mean = 0;
  for (int i = 0; i < BD_GRID * BD_GRID; i++) mean += f[i];
  check(fabs(mean) < 1e-3 && f[8 * BD_GRID + 8] > 0 && f[0] < 0, "luma normalised, ball bright, corner dark");

  /* a near ball (41 px) and a centre 30 px off it: settled onto it */
  bd_view near = view;
  near.f = 250;
  const double rn = bd_ball_radius_px(&near, 160, 120, 0.07);
  for (int y = 0; y < H; y++)
    for (int x = 0; x < W; x++) {
      const double dx = x + 0.5 - 160, dy = y + 0.5 - 120;
      L[y * W + x] = dx * dx + dy * dy <= rn * rn ? WHITE : GREEN;
    }
  bd_field_boundary(w, L, W, H, GREEN, 4, top);
  bd_candidate cn = {.u = 190, .v = 120, .radius = rn};
  const int passes = bd_settle(L, W, H, 1, GREEN, top, &near, 0.07, &cn);
  printf("# near ball: settled at %.2f, %.2f in %d passes\n", cn.u, cn.v, passes);
  check(passes > 2 && fabs(cn.u - 160) < 1 && fabs(cn.v - 120) < 1, "a near ball's centre 30 px off settles within 1 px");

  /* obstacles: sky above row 40, a robot (columns 100..120, rows 20..100), a line, a dark spot */
  enum { RED = 2 };
  for (int y = 0; y < H; y++)
    for (int x = 0; x < W; x++) {
      uint8_t l = y >= 40 ? GREEN : 0;
      if (x >= 100 && x <= 120 && y >= 20 && y <= 100) l = (y >= 50 && y < 60) ? RED : 0;
      if (abs(y - 2 * x + 200) <= 2 && y >= 40) l = WHITE;
      if (x >= 200 && x < 210 && y >= 150 && y < 160) l = 0;
      L[y * W + x] = l;
    }
  bd_field_boundary(w, L, W, H, GREEN, 4, top);
  bd_obstacle ob[8];
  n = bd_obstacles(w, L, W, H, top, GREEN | WHITE, RED, 4, 6, 2, 3, 0, 3, ob, 8);   /* the line: 3 rows bridged */
  check(n == 1, "one obstacle: the robot (not the sky, the line or the spot in the field)");
  check(n >= 1 && ob[0].x0 == 100 && ob[0].x1 == 120 && ob[0].foot == 100 && ob[0].foot_visible,
        "its columns and its foot");
  check(n >= 1 && ob[0].red == 21 * 10 && ob[0].blue == 0, "its team colour counted");
  check(n >= 1 && ob[0].fx0 == 100 && ob[0].fx1 == 120, "its feet as wide as its columns");

  /* a robot cut by the image's top edge, the field beyond it: one leg (columns 150..153) rises to
   * the edge, its foot (columns 140..165, rows 52..60) wider; another robot's legs (columns 167..172)
   * go on below the foot's rows: not the foot */
  for (int y = 0; y < H; y++)
    for (int x = 0; x < W; x++) {
      uint8_t l = GREEN;
      if (x >= 150 && x <= 153 && y <= 60) l = 0;
      if (x >= 140 && x <= 165 && y >= 52 && y <= 60) l = 0;
      if (x >= 167 && x <= 172 && y >= 40 && y <= 90) l = 0;
      L[y * W + x] = l;
    }
  bd_field_boundary(w, L, W, H, GREEN, 4, top);
  n = bd_obstacles(w, L, W, H, top, GREEN | WHITE, RED, 4, 6, 2, 3, 0, 3, ob, 8);
  check(n == 1 && ob[0].x0 == 150 && ob[0].x1 == 153 && ob[0].foot == 60, "the leg rising to the top edge");
  check(n == 1 && ob[0].fx0 == 140 && ob[0].fx1 == 165, "its foot's columns, not the other robot's legs");
  check(bd_column_count(L, W, H, 150, -5, 70, GREEN | WHITE) == 61 &&
        bd_column_count(L, W, H, W, 0, 10, GREEN) == BD_EARG, "non-field labels counted in a column");

  char err[256];
  check(bd_mlp_load("/nonexistent/model.txt", err, sizeof err) == NULL && strstr(err, "/nonexistent/model.txt"),
        "a missing model: an error naming the file");
  bd_free(w);
  return tap_done();
}
