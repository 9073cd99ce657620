// effects: the sim camera's imperfections (see effects.h).
#include "effects.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace sim {

void Lens::undistort(double xd, double yd, double *x, double *y) const {
  double u = xd, v = yd;
  for (int i = 0; i < 20; i++) {
    const double f = factor(u * u + v * v);
    const double nu = xd / f, nv = yd / f;
    const bool done = std::fabs(nu - u) + std::fabs(nv - v) < 1e-12;
    u = nu;
    v = nv;
    if (done) break;
  }
  *x = u;
  *y = v;
}

void lens_map_build(const Lens &l, LensMap *m) {
  m->lens = l;
  const int W = l.width, H = l.height;
  // pinhole position of every frame pixel; the scratch covers them all
  std::vector<float> px((size_t)W * H), py((size_t)W * H);
  double umin = 1e30, umax = -1e30, vmin = 1e30, vmax = -1e30;
  for (int v = 0; v < H; v++) {
    for (int u = 0; u < W; u++) {
      double x, y;
      l.undistort((u - l.cx) / l.fx, (v - l.cy) / l.fy, &x, &y);
      const double su = l.cx + l.fx * x, sv = l.cy + l.fy * y;
      px[(size_t)v * W + u] = (float)su;
      py[(size_t)v * W + u] = (float)sv;
      umin = std::min(umin, su);
      umax = std::max(umax, su);
      vmin = std::min(vmin, sv);
      vmax = std::max(vmax, sv);
    }
  }
  // a lens far outside a webcam's (a fisheye's) would need a huge pinhole image: refuse it
  if (!(umax - umin < 3.0 * W && vmax - vmin < 3.0 * H)) {
    throw std::runtime_error("camera distortion k1 = " + std::to_string(l.k1) + ", k2 = " + std::to_string(l.k2) +
                             " maps the image onto more than 3x its pinhole size: not a lens the sim can draw");
  }
  const int u0 = (int)std::floor(umin + 0.5), v0 = (int)std::floor(vmin + 0.5);
  m->width = (((int)std::floor(umax + 0.5) - u0 + 1) + 1) & ~1;   // YUYV: even
  m->height = (int)std::floor(vmax + 0.5) - v0 + 1;
  m->cx = l.cx - u0;
  m->cy = l.cy - v0;
  m->src.resize((size_t)W * H);
  for (size_t i = 0; i < m->src.size(); i++) {
    const int su = std::min(m->width - 1, std::max(0, (int)std::floor(px[i] + 0.5) - u0));
    const int sv = std::min(m->height - 1, std::max(0, (int)std::floor(py[i] + 0.5) - v0));
    m->src[i] = (sv * m->width + su) * 2;
  }
}

void realism_load(const Config &s, Realism *r) {
  const std::string f = s.file();
  auto num = [&](const char *key, double lo, double hi) {
    const double v = s.num(std::string("camera.") + key);
    if (!(v >= lo && v <= hi)) {
      throw std::runtime_error(f + ": 'camera." + key + "' is " + std::to_string(v) + ", must be in " +
                               std::to_string(lo) + ".." + std::to_string(hi));
    }
    return v;
  };
  r->on = s.flag("camera.realism");
  r->exposure = num("exposure", 0, 0.1);
  r->noise_luma = num("noise_luma", 0, 30);
  r->noise_chroma = num("noise_chroma", 0, 30);
  r->gain_drift = num("gain_drift", 0, 0.5);
  r->wb_drift = num("wb_drift", 0, 0.5);
  r->drift_period = num("drift_period", 0.1, 1e6);
  r->light_gradient = num("light_gradient", 0, 0.9);
  r->shadow_robot = num("shadow_robot", 0, 1);
  r->shadow_ball = num("shadow_ball", 0, 1);
  r->shadow_robot_radius = num("shadow_robot_radius", 0.01, 1);
}

double Lighting::at(double x, double y) const {
  double l = g0 + gx * x + gy * y;
  for (const Caster &c : casters) {
    const double dx = x - c.x, dy = y - c.y, e = (dx * dx + dy * dy) * c.inv_2s2;
    if (e < 9) l *= 1 - c.depth * std::exp(-e);   // beyond 3 standard deviations: no shadow
  }
  return l;
}

namespace {

// a per-run, per-camera phase in [0, 2 pi) from the seed
double phase(uint64_t seed, int self, int k) {
  uint64_t z = seed * 0x9e3779b97f4a7c15ull + (uint64_t)(self + 1) * 0xbf58476d1ce4e5b9ull + (uint64_t)k * 0x94d049bb133111ebull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return (double)(z >> 11) / (double)(1ull << 53) * 2 * M_PI;
}

inline uint8_t sat(int y) { return (uint8_t)(y < 0 ? 0 : (y > 255 ? 255 : y)); }

}  // namespace

void realism_drift(const Realism &r, uint64_t seed, int self, double t, double *gain, double *wb_red,
                   double *wb_blue) {
  // two incommensurate periods: the change never repeats exactly within a game
  const double w1 = 2 * M_PI / r.drift_period, w2 = w1 * 2.71;
  auto drift = [&](int k, double amp) {
    return 1 + amp * (0.7 * std::sin(w1 * t + phase(seed, self, k)) + 0.3 * std::sin(w2 * t + phase(seed, self, k + 1)));
  };
  *gain = drift(0, r.gain_drift);
  *wb_red = drift(2, r.wb_drift);
  *wb_blue = drift(4, r.wb_drift);
}

Developer::Developer(uint64_t seed) {
  std::mt19937_64 rng(seed ^ 0x5851f42d4c957f2dull);
  std::normal_distribution<double> n(0, 16);
  noise_.resize(65536);
  for (int8_t &x : noise_) x = (int8_t)std::max(-127.0, std::min(127.0, std::round(n(rng))));
  noise_.resize(65536 + kExtra);
  std::copy(noise_.begin(), noise_.begin() + kExtra, noise_.begin() + 65536);
}

void Developer::run(const Develop &d, const uint8_t *src, int W, int H, uint8_t *out) const {
  const int32_t *map = d.map ? d.map->src.data() : nullptr;
  const int n = std::max(1, std::min(16, d.taps));
  // fixed point (x 2^12): the exposure gain over the taps' sum. White balance: a gain g_r on red
  // moves V by (g_r - 1) (R - Y) 0.713 = (g_r - 1) (V - 128 + 0.713 Y) (BT.601: V - 128 = 0.713 (R - Y)),
  // a gain g_b on blue moves U by (g_b - 1) (U - 128 + 0.564 Y); Y's own change (0.30 and 0.11 of
  // them) is left to the exposure gain.
  const int gy = (int)std::lround(4096.0 * d.gain / n);
  const int gc = (int)std::lround(4096.0 * d.gain);
  const int wr = (int)std::lround(4096.0 * (d.wb_red - 1)), wb = (int)std::lround(4096.0 * (d.wb_blue - 1));
  // noise: the table's N(0, 16^2) times sigma / 16; luma with shot noise, sigma ~ sqrt(Y / 128)
  int ky[256];
  for (int y = 0; y < 256; y++) ky[y] = (int)std::lround(256.0 * d.noise_luma * std::sqrt(std::max(y, 8) / 128.0) / 16);
  const int kc = (int)std::lround(256.0 * d.noise_chroma / 16);
  const int8_t *nt = noise_.data();
  for (int v = 0; v < H; v++) {
    uint8_t *row = out + (size_t)v * W * 2;
    const int8_t *nrow = W * 2 <= kExtra ? nt + (((uint32_t)v * W * 2 + d.noise_offset) & 0xffff) : nullptr;
    for (int u = 0; u < W; u += 2) {
      int y0 = 0, y1 = 0, us = 0, vs = 0;
      for (int k = 0; k < n; k++) {
        const int vv = std::min(H - 1, std::max(0, v + d.dy[k]));
        const int ua = std::min(W - 1, std::max(0, u + d.dx[k])), ub = std::min(W - 1, std::max(0, u + 1 + d.dx[k]));
        const int oa = (vv * W + ua) * 2, ob = (vv * W + ub) * 2;
        const int sa = map ? map[oa >> 1] : oa, sb = map ? map[ob >> 1] : ob;   // byte offsets of the lumas
        y0 += src[sa];
        y1 += src[sb];
        const uint8_t *c = src + (sa & ~3);   // its YUYV pair (the scratch's width is even)
        us += c[1];
        vs += c[3];
      }
      const int ym = (y0 + y1) / (2 * n);
      y0 = (y0 * gy) >> 12;
      y1 = (y1 * gy) >> 12;
      int cu = us / n - 128, cv = vs / n - 128;
      cu += (wb * ((577 * ym >> 10) + cu)) >> 12;   // 0.564 Y
      cv += (wr * ((730 * ym >> 10) + cv)) >> 12;   // 0.713 Y
      cu = (cu * gc) >> 12;
      cv = (cv * gc) >> 12;
      int ny0 = 0, ny1 = 0, nu = 0, nv = 0;
      if (nrow) {
        ny0 = (nrow[2 * u] * ky[sat(y0)]) >> 8;
        nu = (nrow[2 * u + 1] * kc) >> 8;
        ny1 = (nrow[2 * u + 2] * ky[sat(y1)]) >> 8;
        nv = (nrow[2 * u + 3] * kc) >> 8;
      }
      uint8_t *q = row + 2 * u;
      q[0] = sat(y0 + ny0);
      q[1] = sat(128 + cu + nu);
      q[2] = sat(y1 + ny1);
      q[3] = sat(128 + cv + nv);
    }
  }
}

}  // namespace sim
