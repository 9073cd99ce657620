// render: ground by per-pixel ray casting into a field texture; solids by convex polygon scan
// conversion in painter's order; the ball by exact ray-sphere tests; luma noise from a seeded table.
#include "render.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace sim {

constexpr uint8_t Renderer::kGreen[3];
constexpr uint8_t Renderer::kWhite[3];
constexpr uint8_t Renderer::kOrange[3];
constexpr uint8_t Renderer::kFloor[3];
constexpr uint8_t Renderer::kSky[3];
constexpr uint8_t Renderer::kBallWhite[3];
constexpr uint8_t Renderer::kBallPatch[3];

namespace {

const double kNear = 0.01;
const Vec3 kLight = Vec3(0.3, 0.2, 0.93).normalized();

// The white ball's pattern: a dark patch around each of the 12 vertices of an icosahedron (the
// pentagons of the classic truncated-icosahedron ball; 6 axes, a patch at each end). A patch's
// angular radius of 0.30 rad lies between the pentagon's inscribed (0.28) and circumscribed (0.35)
// angle on a truncated icosahedron: 27% of the surface dark, as on such a ball (28%).
const double kPhi = 1.6180339887498949;
const Vec3 kPatchAxes[6] = {Vec3(0, 1, kPhi).normalized(), Vec3(0, 1, -kPhi).normalized(),
                            Vec3(1, kPhi, 0).normalized(), Vec3(1, -kPhi, 0).normalized(),
                            Vec3(kPhi, 0, 1).normalized(), Vec3(kPhi, 0, -1).normalized()};
const double kPatchCos = std::cos(0.30);

// Writes pixels u0..u1 of a row: luma per pixel from ys (or y), chroma per YUYV pair; a pair only
// half covered gets the average of its old chroma and the new one.
inline uint8_t sat(int y) { return (uint8_t)(y < 0 ? 0 : (y > 255 ? 255 : y)); }

// Noise of pixel `index` (row-major) in a frame: a seeded table walked from a per-frame offset (no
// table: none, for the spans of solids and the ball; the ground's light path adds none either).
struct Noise {
  const int8_t *table;
  uint32_t offset;
  int at(uint32_t index) const { return table[(index + offset) & 0xffff]; }
};

inline void put_span(uint8_t *row, int u0, int u1, const uint8_t *ys, int y, int cu, int cv, const Noise &nz,
                     uint32_t row_index) {
  if (!nz.table) {   // no noise (realism: develop() adds it); y and ys are 0..255
    for (int u = u0; u <= u1; u++) row[2 * u] = ys ? ys[u - u0] : (uint8_t)y;
  } else {
    for (int u = u0; u <= u1; u++) row[2 * u] = sat((ys ? ys[u - u0] : y) + nz.at(row_index + u));
  }
  for (int pu = u0 & ~1; pu <= u1; pu += 2) {
    uint8_t *c = row + 2 * pu;
    const bool full = pu >= u0 && pu + 1 <= u1;
    c[1] = full ? (uint8_t)cu : (uint8_t)((c[1] + cu + 1) >> 1);
    c[3] = full ? (uint8_t)cv : (uint8_t)((c[3] + cv + 1) >> 1);
  }
}

// A row of the ground in the light (realism): each pixel's colour (class cls: floor, carpet, line,
// sky) times its light lt (x 256; the sky unlit), the pair's chroma the mean of its two pixels'.
void lit_row(const uint8_t *cls, const int16_t *lt, const uint8_t *const col[4], int W, uint8_t *row) {
  int u = 0;
#ifdef __SSE2__
  // 8 pixels at a time, the same integer arithmetic as the loop below (bit-identical output):
  // (A la) >> 8 as mulhi(A 256, la), the pair's sum halved toward zero as C's / 2
  const __m128i zero = _mm_setzero_si128(), even = _mm_set1_epi32(0x0000ffff), k128 = _mm_set1_epi16(128);
  const __m128i k255 = _mm_set1_epi16(255), k256 = _mm_set1_epi16(256);
  __m128i m[4];
  for (; u + 8 <= W; u += 8) {
    // 8 pixels of carpet (most of a frame): its colour in the light, else each pixel's by its class
    uint64_t c8;
    memcpy(&c8, cls + u, 8);
    const bool carpet = c8 == 0x0101010101010101ull;
    if (!carpet) {
      const __m128i cl = _mm_unpacklo_epi8(_mm_loadl_epi64((const __m128i *)(cls + u)), zero);
      for (int k = 0; k < 4; k++) m[k] = _mm_cmpeq_epi16(cl, _mm_set1_epi16((short)k));
    }
    auto pick = [&](int k) {
      if (carpet) return _mm_set1_epi16(col[1][k]);
      __m128i x = zero;
      for (int i = 0; i < 4; i++) x = _mm_or_si128(x, _mm_and_si128(m[i], _mm_set1_epi16(col[i][k])));
      return x;
    };
    __m128i l = _mm_loadu_si128((const __m128i *)(lt + u));
    if (!carpet) l = _mm_or_si128(_mm_and_si128(m[3], k256), _mm_andnot_si128(m[3], l));
    const __m128i y = _mm_min_epi16(_mm_mulhi_epu16(_mm_slli_epi16(pick(0), 8), l), k255);
    const __m128i cu = _mm_mulhi_epi16(_mm_slli_epi16(_mm_sub_epi16(pick(1), k128), 8), l);
    const __m128i cv = _mm_mulhi_epi16(_mm_slli_epi16(_mm_sub_epi16(pick(2), k128), 8), l);
    // U's pair sum in the even lanes, V's in the odd ones
    __m128i s = _mm_or_si128(_mm_and_si128(_mm_add_epi16(cu, _mm_srli_epi32(cu, 16)), even),
                             _mm_andnot_si128(even, _mm_add_epi16(cv, _mm_slli_epi32(cv, 16))));
    s = _mm_srai_epi16(_mm_add_epi16(s, _mm_srli_epi16(s, 15)), 1);
    const __m128i c = _mm_max_epi16(_mm_min_epi16(_mm_add_epi16(s, k128), k255), zero);
    _mm_storeu_si128((__m128i *)(row + 2 * u), _mm_or_si128(y, _mm_slli_epi16(c, 8)));
  }
#endif
  for (; u < W; u += 2) {
    const int ca = cls[u], cb = cls[u + 1];
    const int la = ca == 3 ? 256 : lt[u], lb = cb == 3 ? 256 : lt[u + 1];
    const uint8_t *A = col[ca], *B = col[cb];
    uint8_t *p = row + 2 * u;
    p[0] = sat((A[0] * la) >> 8);
    p[1] = sat(128 + ((((A[1] - 128) * la) >> 8) + (((B[1] - 128) * lb) >> 8)) / 2);
    p[2] = sat((B[0] * lb) >> 8);
    p[3] = sat(128 + ((((A[2] - 128) * la) >> 8) + (((B[2] - 128) * lb) >> 8)) / 2);
  }
}

}  // namespace

// Noise and light of one frame: the clean camera's luma noise, or (realism) none here and the light
// over the field.
struct Renderer::Look {
  Noise nz;
  const Lighting *light;   // null: flat light (the clean camera)
};

Lens Camera::lens() const {
  Lens l;
  l.width = width;
  l.height = height;
  l.fx = fu();
  l.fy = fv();
  l.cx = pu();
  l.cy = pv();
  l.k1 = k1;
  l.k2 = k2;
  return l;
}

void Camera::calibrate(const Params &p) {
  width = p.cam_width;
  height = p.cam_height;
  fovy = p.cam_fovy;
  fx = p.cam_fx;
  fy = p.cam_fy;
  cx = p.cam_cx;
  cy = p.cam_cy;
  k1 = p.cam_k1;
  k2 = p.cam_k2;
}

bool camera_project(const Camera &c, const Vec3 &p, double *u, double *v) {
  Vec3 q = c.rot.transpose() * (p - c.pos);
  if (q.x() <= kNear) return false;
  double x = -q.y() / q.x(), y = -q.z() / q.x();
  if (c.distorted()) {
    const double k = c.lens().factor(x * x + y * y);
    x *= k;
    y *= k;
    *u = c.pu() + c.fu() * x;
    *v = c.pv() + c.fv() * y;
    return true;
  }
  // the pinhole, in the arithmetic the renderer's clean frames were checked with
  *u = c.pu() - c.fu() * q.y() / q.x();
  *v = c.pv() - c.fv() * q.z() / q.x();
  return true;
}

Shot shot_of(const World &w, const Camera &c, int self, const std::vector<int> *hide, uint32_t frame) {
  Shot s;
  s.cam = c;
  s.ball = w.ball_position();
  s.ball_rot = w.ball_rotation();
  s.ball_radius = w.ball_radius();
  s.self = self;
  s.hide = hide;
  s.frame = frame;
  return s;
}

Renderer::Renderer(const Params &p, uint64_t seed)
    : seed_(seed), white_ball_(p.ball_kind == "white"), real_(p.realism), dev_(seed) {
  const double hl = p.field_length / 2 + p.border, hw = p.field_width / 2 + p.border;
  half_diagonal_ = std::hypot(hl, hw);
  light_dir_ = (double)((seed * 0x9e3779b97f4a7c15ull) >> 11) / (double)(1ull << 53) * 2 * M_PI;
  // The markings are symmetric in |X| and |Y|: one quarter of the carpet at 1 cm, stored in
  // 8 x 8 texel tiles (one cache line each) so that rays walking in any direction stay cached.
  res_ = 0.01;
  const double L = p.field_length / 2, W = p.field_width / 2, b = p.border;
  x0_ = 0;
  y0_ = 0;
  tw_ = ((int)std::ceil((L + b) / res_) + 7) & ~7;
  th_ = ((int)std::ceil((W + b) / res_) + 7) & ~7;
  tex_.assign((size_t)(tw_ / 8) * (th_ / 8), 0);
  carpet_x_ = (float)((L + b) / res_);
  carpet_y_ = (float)((W + b) / res_);
  const double lw = p.line_width / 2;
  const double R = p.circle_diameter / 2;
  auto near_ = [lw](double a, double b_) { return std::fabs(a - b_) <= lw; };
  for (int j = 0; j < th_; j++) {
    const double ay = (j + 0.5) * res_;
    for (int i = 0; i < tw_; i++) {
      const double ax = (i + 0.5) * res_;
      bool line =
          (near_(ay, W) && ax <= L + lw) || (near_(ax, L) && ay <= W + lw) ||   // boundary
          (ax <= lw && ay <= W + lw) ||                                        // halfway line
          std::fabs(std::hypot(ax, ay) - R) <= lw ||                           // centre circle
          (near_(ax, L - p.goal_area_length) && ay <= p.goal_area_width / 2 + lw) ||
          (near_(ay, p.goal_area_width / 2) && ax >= L - p.goal_area_length - lw && ax <= L) ||
          (near_(ax, L - p.penalty_area_length) && ay <= p.penalty_area_width / 2 + lw) ||
          (near_(ay, p.penalty_area_width / 2) && ax >= L - p.penalty_area_length - lw && ax <= L);
      // penalty marks and the centre mark: crosses of penalty_mark_size
      const double m = p.penalty_mark_size / 2;
      const double mx = L - p.penalty_mark_distance;
      if ((std::fabs(ax - mx) <= m && ay <= lw) || (std::fabs(ax - mx) <= lw && ay <= m)) line = true;
      if ((ax <= m && ay <= lw) || (ax <= lw && ay <= m)) line = true;
      if (line) tex_[(size_t)(j >> 3) * (tw_ >> 3) + (i >> 3)] |= 1ull << (((j & 7) << 3) + (i & 7));
    }
  }
  // each tile's reach: how many tiles around it (in both axes) are plain carpet, with no line texel
  // and wholly inside the carpet (at most 255); the texture's far edges count as not carpet, its
  // near ones not at all (the quarter's mirror images lie there). The distance to the nearest tile
  // that is not, along its row, then the larger of that and the rows' distance.
  const int tiles_x = tw_ / 8, tiles_y = th_ / 8;
  std::vector<int> row_dist((size_t)tiles_x * tiles_y);
  for (int tj = 0; tj < tiles_y; tj++) {
    int last = -100000;   // leftward
    for (int ti = 0; ti < tiles_x; ti++) {
      const bool plain = tex_[(size_t)tj * tiles_x + ti] == 0 && (ti + 1) * 8 <= carpet_x_ && (tj + 1) * 8 <= carpet_y_;
      if (!plain) last = ti;
      row_dist[(size_t)tj * tiles_x + ti] = ti - last;
    }
    last = tiles_x;   // rightward, the far edge first
    for (int ti = tiles_x - 1; ti >= 0; ti--) {
      int &d = row_dist[(size_t)tj * tiles_x + ti];
      if (d == 0) last = ti;
      d = std::min(d, last - ti);
    }
  }
  reach_.assign((size_t)tiles_x * tiles_y, 0);
  for (int tj = 0; tj < tiles_y; tj++)
    for (int ti = 0; ti < tiles_x; ti++) {
      int d = tiles_y - tj;   // the far edge
      for (int j = 0; j < tiles_y; j++) d = std::min(d, std::max(row_dist[(size_t)j * tiles_x + ti], std::abs(j - tj)));
      reach_[(size_t)tj * tiles_x + ti] = (uint8_t)std::min(255, std::max(0, d - 1));
    }
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ull);
  std::normal_distribution<double> n(0, std::max(0.0, p.cam_noise));
  noise_.resize(65536);
  for (int8_t &x : noise_) x = (int8_t)std::max(-100.0, std::min(100.0, std::round(n(rng))));
  // the table's start repeated after its end: a row of up to kNoiseExtra pixels reads it unwrapped
  noise_.resize(65536 + kNoiseExtra);
  std::copy(noise_.begin(), noise_.begin() + kNoiseExtra, noise_.begin() + 65536);
}

void Renderer::ground(const Camera &c, const Look &look, uint8_t *img) const {
  const Noise &nz = look.nz;
  const int W = c.width, H = c.height;
  const double f = c.fu(), fv = c.fv();
  const double cu = c.pu(), cv = c.pv();
  const Mat3 &R = c.rot;
  const float cx = (float)c.pos.x(), cy = (float)c.pos.y(), cz = (float)c.pos.z();
  const Vec3 du = R * Vec3(0, -1.0 / f, 0);
  const float dux = (float)du.x(), duy = (float)du.y(), duz = (float)du.z();
  const float inv_res = (float)(1.0 / res_), tx0 = (float)x0_, ty0 = (float)y0_;
  const float fw = carpet_x_, fh = carpet_y_;
  const uint8_t *col[4] = {kFloor, kGreen, kWhite, kSky};
  const uint64_t *tex = tex_.data();
  const int tiles_x = tw_ >> 3;
  const uint8_t *reach = reach_.data();
  std::vector<uint8_t> cls(W);
  // realism: light x 256 per pixel of the row (16 bits: the light stays below 2), and at the samples
  std::vector<int16_t> lt(look.light ? W : 0);
  std::vector<double> lx(look.light ? W / 8 + 2 : 0), ly(lx.size());
  std::vector<int> sl(lx.size());
  for (int v = 0; v < H; v++) {
    uint8_t *row = img + (size_t)v * W * 2;
    const Vec3 d0 = R * Vec3(1, cu / f, -(v - cv) / fv);
    const float dx0 = (float)d0.x(), dy0 = (float)d0.y(), dz0 = (float)d0.z();
    // the ray hits the ground where dz(u) = dz0 + u * duz < 0: one interval of u per row
    int ua = 0, ub = W - 1;
    const float eps = -1e-4f;
    if (std::fabs(duz) < 1e-12f) {
      if (!(dz0 < eps)) ub = -1;
    } else {
      // dz(uz) = eps; clamped before the conversion to int (|uz| can be huge)
      const double uz = std::min(std::max((double)(eps - dz0) / duz, -2.0), W + 2.0);
      if (duz > 0) ub = std::min(W - 1, (int)std::ceil(uz) - 1);
      else ua = std::max(0, (int)std::floor(uz) + 1);
    }
    for (int u = 0; u < std::min(ua, W); u++) cls[u] = 3;
    for (int u = std::max(ub + 1, 0); u < W; u++) cls[u] = 3;
    // exact ground coordinates every 8 pixels, linear in between (the perspective error over 8
    // pixels is far below a texel except next to the horizon, where every pixel is exact)
    // by-value captures: the uint8_t stores into cls may alias anything captured by reference
    auto ground_xy = [=](int uu, float *gx, float *gy) {
      const float t = -cz / (dz0 + uu * duz);
      *gx = (cx + t * (dx0 + uu * dux) - tx0) * inv_res;
      *gy = (cy + t * (dy0 + uu * duy) - ty0) * inv_res;
    };
    auto lookup = [=](float gx, float gy) -> uint8_t {
      const float fx = std::fabs(gx), fy = std::fabs(gy);
      if (!(fx < fw && fy < fh)) return 0;
      const int i = (int)fx, j = (int)fy;
      return (uint8_t)(1 + ((tex[(size_t)(j >> 3) * tiles_x + (i >> 3)] >> (((j & 7) << 3) + (i & 7))) & 1));
    };
    int u = std::max(ua, 0);
    if (ub >= u) {
      // interpolated only while the blocks are short in texels: from the first one that jumps metres
      // (near the horizon) on, every pixel of the row is cast
      bool exact = false;
      float gx0, gy0;
      ground_xy(u, &gx0, &gy0);
      while (u + 8 <= ub) {
        float gx1, gy1;
        ground_xy(u + 8, &gx1, &gy1);
        if (std::fabs(gx1 - gx0) + std::fabs(gy1 - gy0) > 400.0f) exact = true;
        // plain carpet where the block's tiles are: along a row the ground point moves along a line,
        // monotonically between two pixels' (cast or interpolated), so the block's samples (on the
        // mirrored quarter) lie within max(|dx|, |dy|) texels of its first one, within that many
        // tiles, rounded up, plus one (a texel's slack for the rounding)
        const float ax0 = std::fabs(gx0), ay0 = std::fabs(gy0);
        const float span = std::max(std::fabs(gx1 - gx0), std::fabs(gy1 - gy0));
        const bool plain = ax0 < fw && ay0 < fh && span < 2000.0f &&
                           reach[(size_t)((int)ay0 >> 3) * tiles_x + ((int)ax0 >> 3)] >= ((int)(span + 1.0f) >> 3) + 1;
        if (plain) {
          memset(&cls[u], 1, 8);
        } else if (exact) {
          for (int k = 0; k < 8; k++) {
            float gx, gy;
            ground_xy(u + k, &gx, &gy);
            cls[u + k] = lookup(gx, gy);
          }
        } else {
          const float sx = (gx1 - gx0) * 0.125f, sy = (gy1 - gy0) * 0.125f;
          float gx = gx0, gy = gy0;
          for (int k = 0; k < 8; k++, gx += sx, gy += sy) cls[u + k] = lookup(gx, gy);
        }
        u += 8;
        gx0 = gx1;
        gy0 = gy1;
      }
    }
    for (; u <= ub; u++) {
      float gx, gy;
      ground_xy(u, &gx, &gy);
      cls[u] = lookup(gx, gy);
    }
    const uint32_t base = (uint32_t)(v * W);
    if (look.light) {
      // the light at the ground point every 16 pixels, linear in between (it changes over decimetres:
      // 16 pixels are 3 cm of ground 1 m away, 11 cm at 4 m, where the ball's shadow is a few pixels)
      const int a = std::max(ua, 0);
      if (ub >= a) {
        int ns = 0;
        for (int uu = a;; uu = std::min(uu + 16, ub)) {
          float gx, gy;
          ground_xy(uu, &gx, &gy);
          // beyond the carpet (rays near the horizon reach kilometres) the light is the carpet edge's
          lx[ns] = std::max(-(double)fw, std::min((double)fw, (double)gx)) * res_ + x0_;
          ly[ns] = std::max(-(double)fh, std::min((double)fh, (double)gy)) * res_ + y0_;
          ns++;
          if (uu == ub) break;
        }
        look.light->at256(lx.data(), ly.data(), ns, sl.data());
        int l0 = sl[0];
        lt[a] = (int16_t)l0;
        for (int j = 1, u0 = a; j < ns; j++, u0 += 16) {
          const int u1 = std::min(u0 + 16, ub), l1 = sl[j];
          if (u1 - u0 == 16) {
            // the 16.16 step (l1 - l0) 65536 / 16 below is exact here: the same values without a division
            const int dl = l1 - l0;
#ifdef __SSE2__
            const __m128i k18 = _mm_setr_epi16(1, 2, 3, 4, 5, 6, 7, 8), k8 = _mm_set1_epi16(8);
            const __m128i l0v = _mm_set1_epi16((short)l0), dlv = _mm_set1_epi16((short)dl);
            _mm_storeu_si128((__m128i *)&lt[u0 + 1], _mm_add_epi16(l0v, _mm_srai_epi16(_mm_mullo_epi16(dlv, k18), 4)));
            _mm_storeu_si128((__m128i *)&lt[u0 + 9],
                             _mm_add_epi16(l0v, _mm_srai_epi16(_mm_mullo_epi16(dlv, _mm_add_epi16(k18, k8)), 4)));
#else
            for (int k = 1; k <= 16; k++) lt[u0 + k] = (int16_t)(l0 + ((k * dl) >> 4));
#endif
          } else {
            const int step = (l1 - l0) * 65536 / (u1 - u0);   // 16.16 fixed point
            int l = l0 * 65536;
            for (int k = u0 + 1; k <= u1; k++) lt[k] = (int16_t)((l += step) >> 16);
          }
          l0 = l1;
        }
      }
      lit_row(cls.data(), lt.data(), col, W, row);
      continue;
    }
    u = 0;
#ifdef __SSE2__
    // 16 pixels at a time, the same integer arithmetic as the loop below (bit-identical output):
    // colours picked by class masks, luma + noise saturated, chroma the floor mean of each pair
    if (W <= kNoiseExtra) {
      const int8_t *nrow = noise_.data() + ((base + nz.offset) & 0xffff);   // no wrap within a row
      const __m128i zero = _mm_setzero_si128(), low = _mm_set1_epi16(0x00ff);
      const __m128i k1 = _mm_set1_epi8(1), k2 = _mm_set1_epi8(2), k3 = _mm_set1_epi8(3);
      const __m128i carpet_y = _mm_set1_epi8((char)kGreen[0]);
      const __m128i carpet_uv = _mm_set1_epi32((int)((uint32_t)kGreen[1] << 8 | (uint32_t)kGreen[2] << 24));
      for (; u + 16 <= W; u += 16) {
        const __m128i cl = _mm_loadu_si128((const __m128i *)&cls[u]);
        const __m128i m1 = _mm_cmpeq_epi8(cl, k1);
        const __m128i n = _mm_loadu_si128((const __m128i *)(nrow + u));
        const __m128i pos = _mm_and_si128(n, _mm_cmpgt_epi8(n, zero));
        const __m128i neg = _mm_and_si128(_mm_sub_epi8(zero, n), _mm_cmpgt_epi8(zero, n));
        if (_mm_movemask_epi8(m1) == 0xffff) {
          // 16 pixels of carpet (most of a frame): its luma with the noise, its chroma
          const __m128i y = _mm_subs_epu8(_mm_adds_epu8(carpet_y, pos), neg);
          _mm_storeu_si128((__m128i *)(row + 2 * u), _mm_or_si128(_mm_unpacklo_epi8(y, zero), carpet_uv));
          _mm_storeu_si128((__m128i *)(row + 2 * u + 16), _mm_or_si128(_mm_unpackhi_epi8(y, zero), carpet_uv));
          continue;
        }
        const __m128i m0 = _mm_cmpeq_epi8(cl, zero);
        const __m128i m2 = _mm_cmpeq_epi8(cl, k2), m3 = _mm_cmpeq_epi8(cl, k3);
        auto pick = [&](int k) {
          return _mm_or_si128(_mm_or_si128(_mm_and_si128(m0, _mm_set1_epi8((char)col[0][k])),
                                           _mm_and_si128(m1, _mm_set1_epi8((char)col[1][k]))),
                              _mm_or_si128(_mm_and_si128(m2, _mm_set1_epi8((char)col[2][k])),
                                           _mm_and_si128(m3, _mm_set1_epi8((char)col[3][k]))));
        };
        const __m128i y = _mm_subs_epu8(_mm_adds_epu8(pick(0), pos), neg);
        const __m128i cu8 = pick(1), cv8 = pick(2);
        const __m128i U = _mm_srli_epi16(_mm_add_epi16(_mm_and_si128(cu8, low), _mm_srli_epi16(cu8, 8)), 1);
        const __m128i V = _mm_srli_epi16(_mm_add_epi16(_mm_and_si128(cv8, low), _mm_srli_epi16(cv8, 8)), 1);
        const __m128i lo = _mm_or_si128(_mm_and_si128(y, low), _mm_slli_epi16(U, 8));   // Y0 U
        const __m128i hi = _mm_or_si128(_mm_srli_epi16(y, 8), _mm_slli_epi16(V, 8));    // Y1 V
        _mm_storeu_si128((__m128i *)(row + 2 * u), _mm_unpacklo_epi16(lo, hi));
        _mm_storeu_si128((__m128i *)(row + 2 * u + 16), _mm_unpackhi_epi16(lo, hi));
      }
    }
#endif
    for (; u < W; u += 2) {
      const uint8_t *a = col[cls[u]], *b = col[cls[u + 1]];
      uint8_t *p = row + 2 * u;
      p[0] = sat(a[0] + nz.at(base + u));
      p[1] = (uint8_t)((a[1] + b[1]) >> 1);
      p[2] = sat(b[0] + nz.at(base + u + 1));
      p[3] = (uint8_t)((a[2] + b[2]) >> 1);
    }
  }
}

void Renderer::solid(const Camera &c, const Solid &s, const Look &look, uint8_t *img) const {
  const Noise &nz = look.nz;
  const int W = c.width, H = c.height;
  const double f = c.fu(), fv = c.fv(), cu = c.pu(), cv = c.pv();
  Vec3 centre = Vec3::Zero();
  for (const Vec3 &p : s.v) centre += p;
  centre /= (double)s.v.size();
  std::vector<Vec3> poly, clipped;
  std::vector<double> pu, pv;
  // realism: the light where the solid stands (its chroma scaled with it)
  const double lit = look.light ? look.light->ambient(centre.x(), centre.y()) : 1.0;
  const int su = look.light ? sat(128 + (int)std::lround((s.yuv[1] - 128) * lit)) : s.yuv[1];
  const int sv = look.light ? sat(128 + (int)std::lround((s.yuv[2] - 128) * lit)) : s.yuv[2];
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
      pv.push_back(cv - fv * q.z() / q.x());
      vmin = std::min(vmin, pv.back());
      vmax = std::max(vmax, pv.back());
    }
    const double shade = (0.75 + 0.25 * std::max(0.0, n.dot(kLight))) * lit;
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
      if (u0 <= u1) put_span(img + (size_t)v * W * 2, u0, u1, nullptr, Y, su, sv, nz, (uint32_t)(v * W));
    }
  }
}

void Renderer::ball(const Camera &c, const Vec3 &centre, const Mat3 &brot, double r, const Look &look,
                    uint8_t *img) const {
  const Noise &nz = look.nz;
  const int W = c.width, H = c.height;
  const double f = c.fu(), fv = c.fv(), cu = c.pu(), cv = c.pv();
  const Vec3 s = c.rot.transpose() * (centre - c.pos);
  if (s.x() + r <= kNear) return;
  int u0 = 0, u1 = W - 1, v0 = 0, v1 = H - 1;
  if (s.x() - r * std::sqrt(3.0) > kNear) {
    // the sphere projects inside the projection of its bounding cube
    double umin = 1e30, umax = -1e30, vmin = 1e30, vmax = -1e30;
    for (int k = 0; k < 8; k++) {
      const Vec3 q = s + r * Vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
      const double pu = cu - f * q.y() / q.x(), pv = cv - fv * q.z() / q.x();
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
  const Vec3 lc = c.rot.transpose() * kLight;   // light direction in camera coordinates
  const double sx = s.x(), sy = s.y(), sz = s.z(), inv_f = 1.0 / f, inv_fv = 1.0 / fv, inv_r = 1.0 / r;
  // camera-frame normal -> ball frame, for the pattern
  const Mat3 to_ball = brot.transpose() * c.rot;
  const uint8_t *col = white_ball_ ? kBallWhite : kOrange;
  // realism: the light where the ball is (its chroma scaled with it)
  const double lit = look.light ? look.light->ambient(centre.x(), centre.y()) : 1.0;
  const int bu = look.light ? sat(128 + (int)std::lround((col[1] - 128) * lit)) : col[1];
  const int bv = look.light ? sat(128 + (int)std::lround((col[2] - 128) * lit)) : col[2];
  std::vector<uint8_t> ys(W);
  for (int v = v0; v <= v1; v++) {
    int first = -1, last = -2;
    const double dz = -(v - cv) * inv_fv;
    for (int u = u0; u <= u1; u++) {
      const double dy = -(u - cu) * inv_f;   // ray (1, dy, dz)
      const double dd = 1 + dy * dy + dz * dz, sd = sx + sy * dy + sz * dz;
      if (sd <= 0) continue;
      const double disc = sd * sd - dd * (ss - r2);
      if (disc < 0) continue;
      const double t = (sd - std::sqrt(disc)) / dd;
      if (t < kNear) continue;
      const double nx = (t - sx) * inv_r, ny = (t * dy - sy) * inv_r, nzz = (t * dz - sz) * inv_r;
      const double shade = (0.45 + 0.55 * std::max(0.0, nx * lc.x() + ny * lc.y() + nzz * lc.z())) * lit;
      if (first < 0) first = u;
      last = u;
      int base = col[0];
      if (white_ball_) {
        const Vec3 nb = to_ball * Vec3(nx, ny, nzz);
        for (const Vec3 &a : kPatchAxes) {
          if (std::fabs(nb.dot(a)) > kPatchCos) {
            base = kBallPatch[0];
            break;
          }
        }
      }
      ys[u - first] = (uint8_t)std::min(255, (int)(base * shade + 0.5));
    }
    // the silhouette of a sphere is convex: one span per row (the patches are neutral grey: the
    // chroma stays the ball's)
    if (first >= 0) {
      put_span(img + (size_t)v * W * 2, first, last, ys.data(), 0, bu, bv, nz, (uint32_t)(v * W));
    }
  }
}

uint32_t Renderer::noise_offset(uint32_t frame) const {
  return (uint32_t)((frame * 2654435761u) ^ (uint32_t)seed_);
}

const LensMap &Renderer::lens_map(const Lens &l) const {
  std::lock_guard<std::mutex> g(maps_mu_);
  for (const auto &m : maps_) {
    const Lens &k = m->lens;
    if (k.width == l.width && k.height == l.height && k.fx == l.fx && k.fy == l.fy && k.cx == l.cx &&
        k.cy == l.cy && k.k1 == l.k1 && k.k2 == l.k2)
      return *m;
  }
  maps_.emplace_back(new LensMap);
  lens_map_build(l, maps_.back().get());
  return *maps_.back();
}

// The blur, gains and noise of a frame (realism).
void Renderer::develop_settings(const Shot &sh, Develop *d) const {
  realism_drift(real_, seed_, sh.self, sh.time, &d->gain, &d->wb_red, &d->wb_blue);
  d->noise_luma = real_.noise_luma;
  d->noise_chroma = real_.noise_chroma;
  d->noise_offset = noise_offset(sh.frame) * 2;
  d->taps = 1;
  if (!sh.has_start || !sh.cam_start.pos.allFinite() || !sh.cam_start.rot.allFinite()) return;
  // motion blur: where the point seen at the image centre at the end of the exposure was seen at
  // its start (the ground point there, or one 5 m away above the horizon); the image moves along
  // that flow during the exposure (rotation about the optical axis is left out: uniform blur)
  const Camera &c = sh.cam;
  const Vec3 dir = c.rot.col(0);
  const double t = dir.z() < -1e-3 ? std::min(5.0, -c.pos.z() / dir.z()) : 5.0;
  double u, v;
  if (!camera_project(sh.cam_start, c.pos + t * dir, &u, &v)) return;
  const double fu = u - c.pu(), fv = v - c.pv(), len = std::hypot(fu, fv);
  if (!(len >= 0.5)) return;
  // samples 1 px apart along the flow, at most 8 (a longer smear is sampled more sparsely: a fast
  // head turn's 20 px smear every 2.5 px, which the eye and a detector hardly tell from a continuous one)
  const int n = std::min(Develop::kMaxTaps, (int)std::ceil(len));
  d->taps = n;
  for (int k = 0; k < n; k++) {
    // the frame at time s of the exposure, seen back from its end: what lies at p at the end was at
    // p + s * flow then, so the frame's pixel p takes the end image's p - s * flow (the smear runs
    // from where things were at the start to where they are at the end)
    const double s = (k + 0.5) / n;
    d->dx[k] = -(int)std::lround(s * fu);
    d->dy[k] = -(int)std::lround(s * fv);
  }
}

void Renderer::draw(const Shot &sh, const Camera &c, const std::vector<Solid> &solids, const Look &look,
                    uint8_t *img) const {
  ground(c, look, img);
  // painter's order: farthest first; index -1 is the ball
  std::vector<std::pair<double, int>> order;
  for (size_t i = 0; i < solids.size(); i++) {
    const Solid &s = solids[i];
    if (s.robot == sh.self && sh.hide && std::find(sh.hide->begin(), sh.hide->end(), s.link) != sh.hide->end())
      continue;
    Vec3 centre = Vec3::Zero();
    for (const Vec3 &p : s.v) centre += p;
    centre /= (double)s.v.size();
    order.push_back({(centre - c.pos).norm(), (int)i});
  }
  order.push_back({(sh.ball - c.pos).norm(), -1});
  std::sort(order.begin(), order.end(), [](const std::pair<double, int> &a, const std::pair<double, int> &b) {
    return a.first > b.first || (a.first == b.first && a.second < b.second);
  });
  for (const auto &o : order) {
    if (o.second < 0) ball(c, sh.ball, sh.ball_rot, sh.ball_radius, look, img);
    else solid(c, solids[o.second], look, img);
  }
}

void Renderer::render(const Shot &sh, const std::vector<Solid> &solids, uint8_t *img) const {
  const Camera &c = sh.cam;
  if (!c.pos.allFinite() || !c.rot.allFinite()) {
    memset(img, 0, (size_t)c.width * c.height * 2);   // a broken pose: a black frame, never a crash
    return;
  }
  if (!real_.on && !c.distorted()) {
    // the clean camera: drawn in place, its luma noise as it goes
    draw(sh, c, solids, Look{Noise{noise_.data(), noise_offset(sh.frame)}, nullptr}, img);
    return;
  }
  // a pinhole image into a scratch (larger than the frame where the lens shows more), then developed
  Develop d;
  Camera pin = c;
  if (c.distorted()) {
    d.map = &lens_map(c.lens());
    pin.width = d.map->width;
    pin.height = d.map->height;
    pin.fx = c.fu();
    pin.fy = c.fv();
    pin.cx = d.map->cx;
    pin.cy = d.map->cy;
    pin.k1 = pin.k2 = 0;
  }
  if (real_.on) develop_settings(sh, &d);
  // without a lens map and a blur the pinhole image is the frame: drawn and developed in place
  thread_local std::vector<uint8_t> scratch_buf;
  uint8_t *scratch = img;
  if (d.map || d.taps > 1) {
    scratch_buf.resize((size_t)pin.width * pin.height * 2);
    scratch = scratch_buf.data();
  }
  if (!real_.on) {
    draw(sh, pin, solids, Look{Noise{noise_.data(), noise_offset(sh.frame)}, nullptr}, scratch);
  } else {
    // the light over the field: a gradient across the carpet, soft shadows under each robot's torso
    // and under the ball
    Lighting light;
    const double a = real_.light_gradient / half_diagonal_;
    light.gx = a * std::cos(light_dir_);
    light.gy = a * std::sin(light_dir_);
    int last_robot = -1;
    for (const Solid &s : solids) {
      if (s.robot < 0 || s.link != 0 || s.robot == last_robot || real_.shadow_robot <= 0) continue;
      last_robot = s.robot;
      Vec3 m = Vec3::Zero();
      for (const Vec3 &p : s.v) m += p;
      m /= (double)s.v.size();
      const double sg = real_.shadow_robot_radius;
      light.casters.push_back({m.x(), m.y(), 1 / (2 * sg * sg), real_.shadow_robot});
    }
    if (real_.shadow_ball > 0) {
      const double sg = 0.7 * sh.ball_radius;   // a contact shadow, darkest where the ball touches
      light.casters.push_back({sh.ball.x(), sh.ball.y(), 1 / (2 * sg * sg), real_.shadow_ball});
    }
    draw(sh, pin, solids, Look{Noise{nullptr, 0}, &light}, scratch);
  }
  dev_.run(d, scratch, c.width, c.height, img);
}

}  // namespace sim
