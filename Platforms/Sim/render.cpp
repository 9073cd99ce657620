// render: ground by per-pixel ray casting into a field texture; solids by convex polygon scan
// conversion in painter's order; the ball by exact ray-sphere tests; then luma noise.
#include "render.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace sim {

constexpr uint8_t Renderer::kGreen[3];
constexpr uint8_t Renderer::kWhite[3];
constexpr uint8_t Renderer::kOrange[3];
constexpr uint8_t Renderer::kFloor[3];
constexpr uint8_t Renderer::kSky[3];

namespace {

const double kNear = 0.01;
const Vec3 kLight = Vec3(0.3, 0.2, 0.93).normalized();

// Writes pixels u0..u1 of a row: luma per pixel from ys (or y), chroma per YUYV pair; a pair only
// half covered gets the average of its old chroma and the new one.
inline void put_span(uint8_t *row, int u0, int u1, const uint8_t *ys, int y, int cu, int cv) {
  for (int u = u0; u <= u1; u++) row[2 * u] = ys ? ys[u - u0] : (uint8_t)y;
  for (int pu = u0 & ~1; pu <= u1; pu += 2) {
    uint8_t *c = row + 2 * pu;
    const bool full = pu >= u0 && pu + 1 <= u1;
    c[1] = full ? (uint8_t)cu : (uint8_t)((c[1] + cu + 1) >> 1);
    c[3] = full ? (uint8_t)cv : (uint8_t)((c[3] + cv + 1) >> 1);
  }
}

}  // namespace

bool camera_project(const Camera &c, const Vec3 &p, double *u, double *v) {
  Vec3 q = c.rot.transpose() * (p - c.pos);
  if (q.x() <= kNear) return false;
  const double f = c.focal();
  *u = (c.width - 1) / 2.0 - f * q.y() / q.x();
  *v = (c.height - 1) / 2.0 - f * q.z() / q.x();
  return true;
}

Renderer::Renderer(const Params &p, uint64_t seed) : seed_(seed) {
  res_ = 0.01;
  const double L = p.field_length / 2, W = p.field_width / 2, b = p.border;
  x0_ = -L - b;
  y0_ = -W - b;
  tw_ = (int)std::ceil((2 * (L + b)) / res_);
  th_ = (int)std::ceil((2 * (W + b)) / res_);
  tex_.assign((size_t)tw_ * th_, 1);
  const double lw = p.line_width / 2;
  const double R = p.circle_diameter / 2;
  auto near_ = [lw](double a, double b_) { return std::fabs(a - b_) <= lw; };
  for (int j = 0; j < th_; j++) {
    const double Y = y0_ + (j + 0.5) * res_, ay = std::fabs(Y);
    for (int i = 0; i < tw_; i++) {
      const double X = x0_ + (i + 0.5) * res_, ax = std::fabs(X);
      bool line =
          (near_(ay, W) && ax <= L + lw) || (near_(ax, L) && ay <= W + lw) ||   // boundary
          (near_(X, 0) && ay <= W + lw) ||                                    // halfway line
          std::fabs(std::hypot(X, Y) - R) <= lw ||                            // centre circle
          (near_(ax, L - p.goal_area_length) && ay <= p.goal_area_width / 2 + lw) ||
          (near_(ay, p.goal_area_width / 2) && ax >= L - p.goal_area_length - lw && ax <= L) ||
          (near_(ax, L - p.penalty_area_length) && ay <= p.penalty_area_width / 2 + lw) ||
          (near_(ay, p.penalty_area_width / 2) && ax >= L - p.penalty_area_length - lw && ax <= L);
      // penalty marks and the centre mark: crosses of penalty_mark_size
      const double m = p.penalty_mark_size / 2;
      const double mx = L - p.penalty_mark_distance;
      if ((std::fabs(ax - mx) <= m && ay <= lw) || (std::fabs(ax - mx) <= lw && ay <= m)) line = true;
      if ((ax <= m && ay <= lw) || (ax <= lw && ay <= m)) line = true;
      tex_[(size_t)j * tw_ + i] = line ? 2 : 1;
    }
  }
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ull);
  std::normal_distribution<double> n(0, std::max(0.0, p.cam_noise));
  noise_.resize(65536);
  for (int8_t &x : noise_) x = (int8_t)std::max(-100.0, std::min(100.0, std::round(n(rng))));
}

void Renderer::ground(const Camera &c, uint8_t *img) const {
  const int W = c.width, H = c.height;
  const float f = (float)c.focal();
  const float cu = (W - 1) / 2.0f, cv = (H - 1) / 2.0f;
  const Mat3 &R = c.rot;
  const float cx = (float)c.pos.x(), cy = (float)c.pos.y(), cz = (float)c.pos.z();
  const Vec3 du = R * Vec3(0, -1.0 / f, 0);
  const float dux = (float)du.x(), duy = (float)du.y(), duz = (float)du.z();
  const float inv_res = (float)(1.0 / res_), tx0 = (float)x0_, ty0 = (float)y0_;
  const uint8_t *col[3] = {kFloor, kGreen, kWhite};
  for (int v = 0; v < H; v++) {
    uint8_t *row = img + (size_t)v * W * 2;
    const Vec3 d0 = R * Vec3(1, cu / f, -(v - cv) / f);
    float dx = (float)d0.x(), dy = (float)d0.y(), dz = (float)d0.z();
    for (int u = 0; u < W; u += 2) {
      int cls[2];
      for (int k = 0; k < 2; k++) {
        int cl = 3;   // sky
        if (dz < -1e-4f) {
          const float t = -cz / dz;
          if (t < 200.0f) {
            const float X = cx + t * dx, Y = cy + t * dy;
            const int i = (int)std::floor((X - tx0) * inv_res), j = (int)std::floor((Y - ty0) * inv_res);
            cl = (i >= 0 && j >= 0 && i < tw_ && j < th_) ? tex_[(size_t)j * tw_ + i] : 0;
          }
        }
        cls[k] = cl;
        dx += dux;
        dy += duy;
        dz += duz;
      }
      const uint8_t *a = cls[0] == 3 ? kSky : col[cls[0]];
      const uint8_t *b = cls[1] == 3 ? kSky : col[cls[1]];
      uint8_t *p = row + 2 * u;
      p[0] = a[0];
      p[1] = (uint8_t)((a[1] + b[1]) >> 1);
      p[2] = b[0];
      p[3] = (uint8_t)((a[2] + b[2]) >> 1);
    }
  }
}

void Renderer::solid(const Camera &c, const Solid &s, uint8_t *img) const {
  const int W = c.width, H = c.height;
  const double f = c.focal(), cu = (W - 1) / 2.0, cv = (H - 1) / 2.0;
  Vec3 centre = Vec3::Zero();
  for (const Vec3 &p : s.v) centre += p;
  centre /= (double)s.v.size();
  std::vector<Vec3> poly, clipped;
  std::vector<double> pu, pv;
  for (const std::vector<int> &face : s.faces) {
    if (face.size() < 3) continue;
    // outward normal (whatever the winding) and back-face culling
    Vec3 fc = Vec3::Zero();
    for (int i : face) fc += s.v[i];
    fc /= (double)face.size();
    Vec3 n = (s.v[face[1]] - s.v[face[0]]).cross(s.v[face[2]] - s.v[face[0]]);
    if (n.norm() < 1e-12) continue;
    n.normalize();
    if (n.dot(fc - centre) < 0) n = -n;
    if (n.dot(fc - c.pos) >= 0) continue;
    // to camera coordinates, clip at the near plane
    poly.clear();
    for (int i : face) poly.push_back(c.rot.transpose() * (s.v[i] - c.pos));
    clipped.clear();
    for (size_t i = 0; i < poly.size(); i++) {
      const Vec3 &a = poly[i], &b = poly[(i + 1) % poly.size()];
      const bool ia = a.x() >= kNear, ib = b.x() >= kNear;
      if (ia) clipped.push_back(a);
      if (ia != ib) clipped.push_back(a + (b - a) * ((kNear - a.x()) / (b.x() - a.x())));
    }
    if (clipped.size() < 3) continue;
    pu.clear();
    pv.clear();
    double vmin = 1e30, vmax = -1e30;
    for (const Vec3 &q : clipped) {
      pu.push_back(cu - f * q.y() / q.x());
      pv.push_back(cv - f * q.z() / q.x());
      vmin = std::min(vmin, pv.back());
      vmax = std::max(vmax, pv.back());
    }
    const double shade = 0.75 + 0.25 * std::max(0.0, n.dot(kLight));
    const int Y = std::min(255, (int)std::lround(s.yuv[0] * shade));
    const int v0 = std::max(0, (int)std::ceil(vmin)), v1 = std::min(H - 1, (int)std::floor(vmax));
    const size_t m = pu.size();
    for (int v = v0; v <= v1; v++) {
      double xl = 1e30, xr = -1e30;
      for (size_t i = 0; i < m; i++) {
        const size_t k = (i + 1) % m;
        const double va = pv[i], vb = pv[k];
        if ((va <= v && v <= vb) || (vb <= v && v <= va)) {
          const double x = va == vb ? pu[i] : pu[i] + (v - va) * (pu[k] - pu[i]) / (vb - va);
          if (va == vb) {
            xl = std::min(xl, std::min(pu[i], pu[k]));
            xr = std::max(xr, std::max(pu[i], pu[k]));
          } else {
            xl = std::min(xl, x);
            xr = std::max(xr, x);
          }
        }
      }
      const int u0 = std::max(0, (int)std::ceil(xl)), u1 = std::min(W - 1, (int)std::floor(xr));
      if (u0 <= u1) put_span(img + (size_t)v * W * 2, u0, u1, nullptr, Y, s.yuv[1], s.yuv[2]);
    }
  }
}

void Renderer::ball(const Camera &c, const Vec3 &centre, double r, uint8_t *img) const {
  const int W = c.width, H = c.height;
  const double f = c.focal(), cu = (W - 1) / 2.0, cv = (H - 1) / 2.0;
  const Vec3 s = c.rot.transpose() * (centre - c.pos);
  if (s.x() + r <= kNear) return;
  int u0 = 0, u1 = W - 1, v0 = 0, v1 = H - 1;
  if (s.x() - r * std::sqrt(3.0) > kNear) {
    // the sphere projects inside the projection of its bounding cube
    double umin = 1e30, umax = -1e30, vmin = 1e30, vmax = -1e30;
    for (int k = 0; k < 8; k++) {
      const Vec3 q = s + r * Vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
      const double pu = cu - f * q.y() / q.x(), pv = cv - f * q.z() / q.x();
      umin = std::min(umin, pu);
      umax = std::max(umax, pu);
      vmin = std::min(vmin, pv);
      vmax = std::max(vmax, pv);
    }
    if (umax < 0 || vmax < 0 || umin > W - 1 || vmin > H - 1) return;
    u0 = std::max(0, (int)std::floor(umin));
    u1 = std::min(W - 1, (int)std::ceil(umax));
    v0 = std::max(0, (int)std::floor(vmin));
    v1 = std::min(H - 1, (int)std::ceil(vmax));
  }
  const double r2 = r * r, ss = s.squaredNorm();
  std::vector<uint8_t> ys(W);
  for (int v = v0; v <= v1; v++) {
    int first = -1, last = -2;
    for (int u = u0; u <= u1; u++) {
      const Vec3 d(1, -(u - cu) / f, -(v - cv) / f);
      const double dd = d.squaredNorm(), sd = s.dot(d);
      if (sd <= 0) continue;
      const double disc = sd * sd - dd * (ss - r2);
      if (disc < 0) continue;
      const double t = (sd - std::sqrt(disc)) / dd;
      if (t * std::sqrt(dd) < kNear) continue;
      const Vec3 n = c.rot * ((t * d - s) / r);
      const double shade = 0.45 + 0.55 * std::max(0.0, n.dot(kLight));
      if (first < 0) first = u;
      last = u;
      ys[u - first] = (uint8_t)std::min(255, (int)std::lround(kOrange[0] * shade));
    }
    // the silhouette of a sphere is convex: one span per row
    if (first >= 0) put_span(img + (size_t)v * W * 2, first, last, ys.data(), 0, kOrange[1], kOrange[2]);
  }
}

void Renderer::noise(const Camera &c, uint32_t frame, uint8_t *img) const {
  const size_t n = (size_t)c.width * c.height;
  uint32_t off = (uint32_t)((frame * 2654435761u) ^ (uint32_t)seed_);
  for (size_t i = 0; i < n; i++) {
    const int y = img[2 * i] + noise_[(i + off) & 0xffff];
    img[2 * i] = (uint8_t)(y < 0 ? 0 : (y > 255 ? 255 : y));
  }
}

void Renderer::render(const Camera &c, const std::vector<Solid> &solids, int self,
                      const std::vector<int> &hide, const Vec3 &ball_centre, double ball_radius,
                      uint32_t frame, uint8_t *img) const {
  ground(c, img);
  // painter's order: farthest first; index -1 is the ball
  std::vector<std::pair<double, int>> order;
  for (size_t i = 0; i < solids.size(); i++) {
    const Solid &s = solids[i];
    if (s.robot == self && std::find(hide.begin(), hide.end(), s.link) != hide.end()) continue;
    Vec3 centre = Vec3::Zero();
    for (const Vec3 &p : s.v) centre += p;
    centre /= (double)s.v.size();
    order.push_back({(centre - c.pos).norm(), (int)i});
  }
  order.push_back({(ball_centre - c.pos).norm(), -1});
  std::sort(order.begin(), order.end(), [](const std::pair<double, int> &a, const std::pair<double, int> &b) {
    return a.first > b.first || (a.first == b.first && a.second < b.second);
  });
  for (const auto &o : order) {
    if (o.second < 0) ball(c, ball_centre, ball_radius, img);
    else solid(c, solids[o.second], img);
  }
  noise(c, frame, img);
}

}  // namespace sim
