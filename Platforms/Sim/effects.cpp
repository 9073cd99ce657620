// effects: the sim camera's imperfections (see effects.h).
#include "effects.h"

#include <algorithm>
#include <cmath>
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

namespace {

// Lens::undistort's answers as a function of the distorted radius^2 q: the ratio s of the pinhole
// radius to the distorted one solves s f(s^2 q) = 1. A table over q, linear in between, then one
// Newton step: the same map as Lens::undistort pixel by pixel in a tenth of the time (the ratio's
// curvature leaves the table ~1e-10 off, the step squares that). None where a step does not converge
// (a lens beyond a webcam's): the caller then iterates as Lens::undistort.
struct RadialInverse {
  const Lens &l;
  double q_max, scale;
  std::vector<double> s;
  bool ok = true;
  RadialInverse(const Lens &lens, double qmax) : l(lens), q_max(qmax) {
    const int n = 4096;
    scale = n / q_max;
    s.resize(n + 2);
    double x = 1;
    for (int i = 0; i <= n + 1 && ok; i++) {
      const double q = i / scale;
      int k = 0;
      for (; k < 50; k++) {
        const double step = newton(x, q);
        x -= step;
        if (!std::isfinite(x) || !(h_slope(x, q) > 0.1)) ok = false;
        if (std::fabs(step) < 1e-15 || !ok) break;
      }
      if (k == 50) ok = false;
      s[i] = x;
    }
  }
  double h_slope(double x, double q) const {
    const double x2q = x * x * q;
    return 1 + x2q * (3 * l.k1 + 5 * l.k2 * x2q);
  }
  double newton(double x, double q) const { return (x * l.factor(x * x * q) - 1) / h_slope(x, q); }
  // the ratio at q (0 <= q <= q_max)
  double at(double q) const {
    const double t = q * scale;
    const int i = (int)t;
    const double x = s[i] + (t - i) * (s[i + 1] - s[i]);
    return x - newton(x, q);
  }
};

}  // namespace

void lens_map_build(const Lens &l, LensMap *m) {
  m->lens = l;
  const int W = l.width, H = l.height;
  // pinhole position of every frame pixel; the scratch covers them all
  std::vector<float> px((size_t)W * H), py((size_t)W * H);
  double umin = 1e30, umax = -1e30, vmin = 1e30, vmax = -1e30;
  double q_max = 0;   // the largest distorted radius^2: at a corner
  for (int v : {0, H - 1})
    for (int u : {0, W - 1}) q_max = std::max(q_max, std::pow((u - l.cx) / l.fx, 2) + std::pow((v - l.cy) / l.fy, 2));
  const RadialInverse inv(l, q_max * 1.001);
  for (int v = 0; v < H; v++) {
    for (int u = 0; u < W; u++) {
      const double xd = (u - l.cx) / l.fx, yd = (v - l.cy) / l.fy;
      double x, y;
      if (inv.ok) {
        const double s = inv.at(xd * xd + yd * yd);
        x = xd * s;
        y = yd * s;
      } else {
        l.undistort(xd, yd, &x, &y);
      }
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
  m->runs.clear();
  m->other.clear();
  m->row_runs.assign(1, 0);
  for (int v = 0; v < H; v++) {
    const int32_t *r = m->src.data() + (size_t)v * W;
    for (int u = 0; u + 1 < W; u += 2) {
      const bool regular = r[u + 1] == r[u] + 2;
      LensMap::Run *last = (int)m->runs.size() > m->row_runs.back() ? &m->runs.back() : nullptr;
      if (last && last->regular == regular && (!regular || r[u] == r[u - 2] + 4)) {
        last->pairs++;
      } else {
        m->runs.push_back({u, 1, regular, regular ? r[u] : (int32_t)m->other.size()});
      }
      if (!regular) {
        m->other.push_back(r[u]);
        m->other.push_back(r[u + 1]);
      }
    }
    m->row_runs.push_back((int)m->runs.size());
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

namespace {

// exp(-e) for 0 <= e < 9 (a shadow within 3 standard deviations): exp(-k / 64) from a table times
// exp(-r), r = e - k / 64 < 1 / 64, by its Taylor polynomial to r^5 (the next term is below
// 2e-14 of it). Within a few units in the last place of std::exp's double, far from changing the
// light's rounding to 1 / 256 (that takes 256 light within 1e-11 of a half level).
struct ShadowExp {
  double t[9 * 64 + 2];
  ShadowExp() {
    for (int k = 0; k < 9 * 64 + 2; k++) t[k] = std::exp(-k / 64.0);
  }
  double operator()(double e) const {
    const int k = (int)(e * 64);
    const double r = e - k * (1.0 / 64);
    return t[k] * (1 - r * (1 - r * (0.5 - r * (1.0 / 6 - r * (1.0 / 24 - r * (1.0 / 120))))));
  }
};
const ShadowExp shadow_exp;

}  // namespace

double Lighting::at(double x, double y) const {
  double l = g0 + gx * x + gy * y;
  for (const Caster &c : casters) {
    const double dx = x - c.x, dy = y - c.y, e = (dx * dx + dy * dy) * c.inv_2s2;
    if (e < 9) l *= 1 - c.depth * shadow_exp(e);   // beyond 3 standard deviations: no shadow
  }
  return l;
}

void Lighting::at256(const double *x, const double *y, int n, int *l) const {
  // a caster farther than 3 standard deviations from a block's bounding box is so from each of its
  // points (the rounded differences, squares and sums only grow with the exact ones): at()'s test
  // skips it for all of them, so the block leaves it out from the start
  constexpr int kBlock = 8, kMaxActive = 64;
  const bool cull = casters.size() <= (size_t)kMaxActive;
  const Caster *active[kMaxActive];
  for (int b = 0; b < n; b += kBlock) {
    const int e = std::min(n, b + kBlock);
    int na = 0;
    if (cull) {
      double x0 = x[b], x1 = x[b], y0 = y[b], y1 = y[b];
      for (int i = b + 1; i < e; i++) {
        x0 = std::min(x0, x[i]);
        x1 = std::max(x1, x[i]);
        y0 = std::min(y0, y[i]);
        y1 = std::max(y1, y[i]);
      }
      for (const Caster &c : casters) {
        const double dx = c.x < x0 ? x0 - c.x : (c.x > x1 ? c.x - x1 : 0);
        const double dy = c.y < y0 ? y0 - c.y : (c.y > y1 ? c.y - y1 : 0);
        if ((dx * dx + dy * dy) * c.inv_2s2 < 9) active[na++] = &c;
      }
    }
    for (int i = b; i < e; i++) {
      double v = g0 + gx * x[i] + gy * y[i];
      if (!cull) {
        v = at(x[i], y[i]);
      } else {
        for (int k = 0; k < na; k++) {
          const Caster &c = *active[k];
          const double dx = x[i] - c.x, dy = y[i] - c.y, ee = (dx * dx + dy * dy) * c.inv_2s2;
          if (ee < 9) v *= 1 - c.depth * shadow_exp(ee);
        }
      }
      // lround without the library call: exact for 0 <= v < 2^31 (w - t is exact)
      const double w = 256 * v;
      const int t = (int)w;
      l[i] = w >= 0 && w < 2e9 ? t + (w - t >= 0.5) : (int)std::lround(w);
    }
  }
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

}  // namespace sim
