// effects: the sim camera's imperfections (see effects.h).
#include "effects.h"

#include <algorithm>
#include <cmath>
#include <cstring>
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
  const int n = std::max(1, std::min(Develop::kMaxTaps, d.taps));
  // 1. geometry: each pixel from its scratch pixel (the lens's map) averaged over the blur's taps
  if (n == 1 && !map) {
    if (out != src) memcpy(out, src, (size_t)W * H * 2);
  } else if (n == 1) {
    for (int v = 0; v < H; v++) {
      uint8_t *row = out + (size_t)v * W * 2;
      const int32_t *mrow = map + (size_t)v * W;
      for (int u = 0; u < W; u += 2) {
        const int sa = mrow[u], sb = mrow[u + 1];   // byte offsets of the lumas
        const uint8_t *c = src + (sa & ~3);         // the pair of the first (the scratch's width is even)
        uint8_t *q = row + 2 * u;
        q[0] = src[sa];
        q[1] = c[1];
        q[2] = src[sb];
        q[3] = c[3];
      }
    }
  } else {
    for (int v = 0; v < H; v++) {
      uint8_t *row = out + (size_t)v * W * 2;
      // the taps' rows and, for the pixels whose taps all stay inside the row, no clamping
      int vrow[Develop::kMaxTaps], lo = 0, hi = W - 2;
      for (int k = 0; k < n; k++) {
        vrow[k] = std::min(H - 1, std::max(0, v + d.dy[k])) * W;
        lo = std::max(lo, -d.dx[k]);
        hi = std::min(hi, W - 2 - d.dx[k]);
      }
      for (int u = 0; u < W; u += 2) {
        int y0 = 0, y1 = 0, us = 0, vs = 0;
        const bool inside = u >= lo && u <= hi;
        for (int k = 0; k < n; k++) {
          int oa = vrow[k] + u + d.dx[k], ob = oa + 1;   // pixel indices
          if (!inside) {
            oa = vrow[k] + std::min(W - 1, std::max(0, u + d.dx[k]));
            ob = vrow[k] + std::min(W - 1, std::max(0, u + 1 + d.dx[k]));
          }
          const int sa = map ? map[oa] : 2 * oa, sb = map ? map[ob] : 2 * ob;
          y0 += src[sa];
          y1 += src[sb];
          const uint8_t *c = src + (sa & ~3);
          us += c[1];
          vs += c[3];
        }
        uint8_t *q = row + 2 * u;
        q[0] = (uint8_t)((y0 + n / 2) / n);
        q[1] = (uint8_t)((us + n / 2) / n);
        q[2] = (uint8_t)((y1 + n / 2) / n);
        q[3] = (uint8_t)((vs + n / 2) / n);
      }
    }
  }
  // 2. light: exposure gain, white balance, noise, in place, through tables. A gain g_r on red moves
  // V - 128 = 0.713 (R - Y) to (V - 128) (1 + (g_r - 1)) + (g_r - 1) 0.713 Y (Y's own change, 0.30
  // and 0.11 of it, left to the exposure gain); U likewise with g_b and 0.564; then all times g.
  const bool plain = d.gain == 1 && d.wb_red == 1 && d.wb_blue == 1 && d.noise_luma == 0 && d.noise_chroma == 0;
  if (plain) return;
  int ty[256], tu[256], tv[256], tyu[256], tyv[256], ky[256];
  for (int x = 0; x < 256; x++) {
    ty[x] = (int)std::lround(x * d.gain);
    tu[x] = (int)std::lround((x - 128) * d.gain * d.wb_blue);
    tv[x] = (int)std::lround((x - 128) * d.gain * d.wb_red);
    tyu[x] = (int)std::lround(x * d.gain * (d.wb_blue - 1) * 0.564);
    tyv[x] = (int)std::lround(x * d.gain * (d.wb_red - 1) * 0.713);
    // noise: the table's N(0, 16^2) times sigma / 16 (x 256); luma with shot noise, sigma ~ sqrt(Y / 128)
    ky[x] = (int)std::lround(256.0 * d.noise_luma * std::sqrt(std::max(x, 8) / 128.0) / 16);
  }
  const int kc = (int)std::lround(256.0 * d.noise_chroma / 16);
  const int8_t *nt = noise_.data();
  static const int8_t zero_row[kExtra] = {0};
  for (int v = 0; v < H; v++) {
    uint8_t *q = out + (size_t)v * W * 2;
    const int8_t *nr = W * 2 <= kExtra ? nt + (((uint32_t)v * W * 2 + d.noise_offset) & 0xffff) : zero_row;
    for (int u = 0; u < 2 * W; u += 4, q += 4) {
      const int y0 = ty[q[0]], y1 = ty[q[2]], ym = (q[0] + q[2]) >> 1;
      const int cu = tu[q[1]] + tyu[ym], cv = tv[q[3]] + tyv[ym];
      q[0] = sat(y0 + ((nr[u] * ky[sat(y0)]) >> 8));
      q[1] = sat(128 + cu + ((nr[u + 1] * kc) >> 8));
      q[2] = sat(y1 + ((nr[u + 2] * ky[sat(y1)]) >> 8));
      q[3] = sat(128 + cv + ((nr[u + 3] * kc) >> 8));
    }
  }
}

}  // namespace sim
