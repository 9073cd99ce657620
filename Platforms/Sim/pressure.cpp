// pressure: the load of a sole shared among its point pressure sensors (pressure.h says the model).
#include "pressure.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace sim {

namespace {

using V2 = Eigen::Vector2d;

double cross(const V2 &o, const V2 &a, const V2 &b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

std::vector<V2> points(const std::vector<double> &xy) {
  std::vector<V2> p;
  for (size_t k = 0; k + 1 < xy.size(); k += 2) p.emplace_back(xy[k], xy[k + 1]);
  return p;
}

// The convex hull, counter-clockwise (Andrew's monotone chain).
std::vector<V2> hull(std::vector<V2> p) {
  std::sort(p.begin(), p.end(), [](const V2 &a, const V2 &b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  if (p.size() < 3) return p;
  std::vector<V2> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); i++) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) k--;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) k--;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

double area(const std::vector<V2> &h) {
  double a = 0;
  for (size_t i = 0; i < h.size(); i++) {
    const V2 &p = h[i], &q = h[(i + 1) % h.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

// c itself when it lies in the hull h (counter-clockwise), else the nearest point of h's boundary.
V2 into_hull(const std::vector<V2> &h, const V2 &c) {
  bool inside = true;
  for (size_t i = 0; i < h.size(); i++)
    if (cross(h[i], h[(i + 1) % h.size()], c) < 0) inside = false;
  if (inside) return c;
  V2 best = h[0];
  for (size_t i = 0; i < h.size(); i++) {
    const V2 &a = h[i], d = h[(i + 1) % h.size()] - a;
    const double t = std::min(1.0, std::max(0.0, (c - a).dot(d) / d.squaredNorm()));
    const V2 q = a + t * d;
    if ((q - c).squaredNorm() < (best - c).squaredNorm()) best = q;
  }
  return best;
}

}  // namespace

bool pressure_layout_ok(const std::vector<double> &xy) {
  if (xy.size() < 6 || xy.size() % 2) return false;
  for (double v : xy)
    if (!std::isfinite(v)) return false;
  const std::vector<V2> h = hull(points(xy));
  if (h.size() < 3) return false;
  // a hull thinner than 1 mm: its area below 1 mm times its longest side
  double side = 0;
  for (size_t i = 0; i < h.size(); i++) side = std::max(side, (h[(i + 1) % h.size()] - h[i]).norm());
  return area(h) > 1e-3 * side;
}

std::vector<double> pressure_distribute(const std::vector<double> &xy, double fz, double cx, double cy) {
  const std::vector<V2> p = points(xy);
  const size_t n = p.size();
  std::vector<double> f(n, 0.0);
  if (!(fz > 0) || !std::isfinite(fz) || !std::isfinite(cx) || !std::isfinite(cy) || n == 0) return f;
  const V2 c = into_hull(hull(p), V2(cx, cy));
  // the plate's deflection w = s0 + s1 x + s2 y; the sensors in contact carry k w each (k folded into
  // s): their sum and moments are the sole's. A sensor the plate would pull on leaves the set; one
  // the plate would press into (w > 0 where it is out of the set) joins it (an active-set search for
  // the unilateral springs' solution; a few rounds for a handful of sensors).
  std::vector<char> on(n, 1);
  const Eigen::Vector3d b(fz, fz * c.x(), fz * c.y());
  const double tol = 1e-9 * fz;
  for (size_t round = 0; round < 4 * n; round++) {
    Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
    for (size_t i = 0; i < n; i++) {
      if (!on[i]) continue;
      const Eigen::Vector3d phi(1, p[i].x(), p[i].y());
      A += phi * phi.transpose();
    }
    const Eigen::Vector3d s = A.completeOrthogonalDecomposition().solve(b);
    size_t drop = n, add = n;
    double least = -tol, most = tol;
    for (size_t i = 0; i < n; i++) {
      const double wi = s.dot(Eigen::Vector3d(1, p[i].x(), p[i].y()));
      f[i] = on[i] ? wi : 0.0;
      if (on[i] && wi < least) {
        least = wi;
        drop = i;
      }
      if (!on[i] && wi > most) {
        most = wi;
        add = i;
      }
    }
    if (drop < n) {
      on[drop] = 0;
    } else if (add < n) {
      on[add] = 1;
    } else {
      break;
    }
  }
  // rounding's crumbs below 0 read 0; the rest carries fz
  double sum = 0;
  for (double &v : f) {
    v = std::max(v, 0.0);
    sum += v;
  }
  if (sum > 0)
    for (double &v : f) v *= fz / sum;
  return f;
}

}  // namespace sim
