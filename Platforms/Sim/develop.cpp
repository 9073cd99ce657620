// develop: Developer::run (effects.h), the per-frame development of the renderer's scratch into the
// camera's frame: the lens's map and the motion blur's samples, then the gains, white balance and
// noise. Row by row through a row buffer that stays in the cache. SSE2 where the machine has it; the
// portable loops do the same integer arithmetic (the same pixels either way), so a seed's frames do
// not depend on the build.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>

#include "effects.h"
#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace sim {

namespace {

inline uint8_t sat(int y) { return (uint8_t)(y < 0 ? 0 : (y > 255 ? 255 : y)); }

// The light of a frame in fixed point (1 << kShift is 1): luma Y' = Y g; a gain g_r on red moves
// V - 128 = 0.713 (R - Y) to (V - 128) g_r + (g_r - 1) 0.713 Y (Y's own change, 0.30 and 0.11 of it,
// left to the exposure gain), U likewise with g_b and 0.564; then all times g. The noise: the
// table's N(0, 16^2) times sigma / 16, luma with shot noise (sigma ~ sqrt(Y / 128)).
// Each term rounded by itself, as the tables of before did.
constexpr int kShift = 13, kHalf = 1 << (kShift - 1);   // chroma (gains up to 2.25)
constexpr int kShiftY = 14, kHalfY = 1 << (kShiftY - 1);   // luma (gain up to 1.5)
struct Tone {
  int gy;                     // x (1 << kShiftY)
  int gu, gyu, gv, gyv;       // x (1 << kShift)
  float ky;                   // luma noise x 256 at Y = 128
  int kc;                     // chroma noise x 256
};

Tone tone_of(const Develop &d) {
  auto fix = [](double x, const char *what, int shift = kShift) {
    const long k = std::lround(x * (1 << shift));
    if (k < -32768 || k > 32767) {
      throw std::runtime_error(std::string("develop: the ") + what + " coefficient " + std::to_string(x) +
                               " is outside the range of its 16-bit fixed point");
    }
    return (int)k;
  };
  Tone t;
  t.gy = fix(d.gain, "gain", kShiftY);
  t.gu = fix(d.gain * d.wb_blue, "blue gain");
  t.gyu = fix(d.gain * (d.wb_blue - 1) * 0.564, "blue balance");
  t.gv = fix(d.gain * d.wb_red, "red gain");
  t.gyv = fix(d.gain * (d.wb_red - 1) * 0.713, "red balance");
  if (!(d.noise_luma >= 0 && d.noise_luma <= 60 && d.noise_chroma >= 0 && d.noise_chroma <= 60)) {
    throw std::runtime_error("develop: noise " + std::to_string(d.noise_luma) + " / " + std::to_string(d.noise_chroma) +
                             " outside 0..60 grey levels");
  }
  t.ky = (float)(256.0 * d.noise_luma / 16);
  t.kc = (int)std::lround(256.0 * d.noise_chroma / 16);
  return t;
}

// Luma noise scale (x 256) at the lit luma yy (0..255): float steps the SSE2 path repeats exactly
// (IEEE single, rounded to nearest even as cvtps does; no sum, so nothing to fuse).
inline int luma_k(const Tone &t, int yy) {
  return (int)std::lrintf(std::sqrt((float)std::max(yy, 8) * (1.0f / 128)) * t.ky);
}

// One row of W pixels (W even) through the light: in and out may be the same. nr: the noise bytes
// beside the row's bytes (luma under luma, chroma under chroma).
void light_row(const Tone &t, const uint8_t *in, uint8_t *out, int W, const int8_t *nr) {
  int u = 0;
#ifdef __SSE2__
  const __m128i low = _mm_set1_epi16(0x00ff), even = _mm_set1_epi32(0x0000ffff), zero = _mm_setzero_si128();
  const __m128i k128 = _mm_set1_epi16(128), k255 = _mm_set1_epi16(255);
  const __m128i cy = _mm_set1_epi16((short)t.gy);
  const __m128i cc = _mm_setr_epi16((short)t.gu, (short)t.gv, (short)t.gu, (short)t.gv, (short)t.gu, (short)t.gv,
                                    (short)t.gu, (short)t.gv);
  const __m128i cyc = _mm_setr_epi16((short)t.gyu, (short)t.gyv, (short)t.gyu, (short)t.gyv, (short)t.gyu,
                                     (short)t.gyv, (short)t.gyu, (short)t.gyv);
  const __m128i kc = _mm_set1_epi16((short)t.kc), hi8 = _mm_set1_epi16((short)0xff00);
  const __m128 inv128 = _mm_set1_ps(1.0f / 128), eight = _mm_set1_ps(8.0f), ky = _mm_set1_ps(t.ky);
  for (; u + 8 <= W; u += 8) {
    const __m128i px = _mm_loadu_si128((const __m128i *)(in + 2 * u));
    const __m128i Y = _mm_and_si128(px, low);           // 8 lumas
    const __m128i C = _mm_srli_epi16(px, 8);            // U V U V ...
    // the mean luma of each pair in both of its lanes
    __m128i ym = _mm_and_si128(_mm_srli_epi16(_mm_add_epi16(Y, _mm_srli_epi32(Y, 16)), 1), even);
    ym = _mm_or_si128(ym, _mm_slli_epi32(ym, 16));
    // (x g + 2^(shift - 1)) >> shift as (x 2^(16 - shift)) g, rounded by the low half's top bit
    auto term = [&](__m128i x, __m128i g, int shift) {
      const __m128i xs = _mm_slli_epi16(x, 16 - shift);
      return _mm_add_epi16(_mm_mulhi_epi16(xs, g), _mm_srli_epi16(_mm_mullo_epi16(xs, g), 15));
    };
    const __m128i c = _mm_add_epi16(term(_mm_sub_epi16(C, k128), cc, kShift), term(ym, cyc, kShift));
    const __m128i y = term(Y, cy, kShiftY);
    const __m128i yy = _mm_max_epi16(_mm_min_epi16(y, k255), zero);
    auto k4 = [&](__m128i y32) {
      const __m128 f = _mm_max_ps(_mm_cvtepi32_ps(y32), eight);
      return _mm_cvtps_epi32(_mm_mul_ps(_mm_sqrt_ps(_mm_mul_ps(f, inv128)), ky));
    };
    const __m128i kyv = _mm_packs_epi32(k4(_mm_unpacklo_epi16(yy, zero)), k4(_mm_unpackhi_epi16(yy, zero)));
    const __m128i nb = _mm_loadu_si128((const __m128i *)(nr + 2 * u));
    // noise n x 256 in each lane: mulhi gives (n 256 k) >> 16 = (n k) >> 8
    const __m128i yo = _mm_add_epi16(y, _mm_mulhi_epi16(_mm_slli_epi16(nb, 8), kyv));
    const __m128i co = _mm_add_epi16(_mm_add_epi16(c, k128), _mm_mulhi_epi16(_mm_and_si128(nb, hi8), kc));
    const __m128i ys = _mm_max_epi16(_mm_min_epi16(yo, k255), zero), cs = _mm_max_epi16(_mm_min_epi16(co, k255), zero);
    _mm_storeu_si128((__m128i *)(out + 2 * u), _mm_or_si128(ys, _mm_slli_epi16(cs, 8)));
  }
#endif
  for (; u < W; u += 2) {
    const uint8_t *p = in + 2 * u;
    uint8_t *q = out + 2 * u;
    const int8_t *n = nr + 2 * u;
    const int ym = (p[0] + p[2]) >> 1;
    const int y0 = (p[0] * t.gy + kHalfY) >> kShiftY, y1 = (p[2] * t.gy + kHalfY) >> kShiftY;
    const int cu = (((p[1] - 128) * t.gu + kHalf) >> kShift) + ((ym * t.gyu + kHalf) >> kShift);
    const int cv = (((p[3] - 128) * t.gv + kHalf) >> kShift) + ((ym * t.gyv + kHalf) >> kShift);
    q[0] = sat(y0 + ((n[0] * 256 * luma_k(t, sat(y0))) >> 16));
    q[1] = sat(128 + cu + ((n[1] * 256 * t.kc) >> 16));
    q[2] = sat(y1 + ((n[2] * 256 * luma_k(t, sat(y1))) >> 16));
    q[3] = sat(128 + cv + ((n[3] * 256 * t.kc) >> 16));
  }
}

// Bytes p[j ^ 1] for j < n (n even): each byte pair swapped.
void swap_copy(const uint8_t *p, int n, uint8_t *q) {
  int j = 0;
#ifdef __SSE2__
  for (; j + 16 <= n; j += 16) {
    const __m128i x = _mm_loadu_si128((const __m128i *)(p + j));
    _mm_storeu_si128((__m128i *)(q + j), _mm_or_si128(_mm_slli_epi16(x, 8), _mm_srli_epi16(x, 8)));
  }
#endif
  for (; j < n; j++) q[j] = p[j ^ 1];
}

// Row v through the lens's map alone (no blur): each pixel's luma from its scratch pixel, the pair's
// chroma from the first one's pair. A regular run (LensMap::Run) is a copy: of whole scratch pairs
// where it starts on an even scratch pixel, else of the bytes from the pair's U on, each byte pair
// swapped (Y0 U Y1 V of the frame are Y U' Y' V' of the scratch's U'' Y U' Y' V' from one pair on).
void lens_row(const uint8_t *src, const LensMap &m, int v, int W, uint8_t *row) {
  for (int k = m.row_runs[v]; k < m.row_runs[v + 1]; k++) {
    const LensMap::Run &r = m.runs[k];
    const int s = r.src;
    uint8_t *q = row + 2 * r.u;
    if (r.regular) {
      if ((s & 3) == 0) memcpy(q, src + s, (size_t)4 * r.pairs);
      else swap_copy(src + s - 1, 4 * r.pairs, q);
      continue;
    }
    const int32_t *o = m.other.data() + r.src;
    for (int i = 0; i < r.pairs; i++, q += 4) {
      const int sa = o[2 * i], sb = o[2 * i + 1];   // byte offsets of the lumas
      const uint8_t *c = src + (sa & ~3);         // the pair of the first (the scratch's width is even)
      q[0] = src[sa];
      q[1] = c[1];
      q[2] = src[sb];
      q[3] = c[3];
    }
  }
}

// One YUYV pixel pair of the blur: the rounded means of n samples' sums of Y0, U, Y1, V.
inline void put_mean(uint8_t *q, int y0, int us, int y1, int vs, int n) {
  q[0] = (uint8_t)((y0 + n / 2) / n);
  q[1] = (uint8_t)((us + n / 2) / n);
  q[2] = (uint8_t)((y1 + n / 2) / n);
  q[3] = (uint8_t)((vs + n / 2) / n);
}

#ifndef __SSE2__
// One row of the blur, sample by sample: each pixel the rounded mean of its samples through the map
// (clamped at the frame's edges), the pair's chroma that of its first pixel's samples.
void blur_row(const Develop &d, int n, const uint8_t *src, const int32_t *map, int W, int H, int v, uint8_t *row) {
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
    put_mean(row + 2 * u, y0, us, y1, vs, n);
  }
}
#else
// The blur on planes: the luma of every frame pixel through the map, and its chroma (its scratch
// pixel's pair's) as U | V << 8 with the even pixels in ce, the odd ones in co, each row padded with
// copies of its edge pixels on both sides (P lumas, Q chroma words), so that the samples (|dx| <= P)
// read whole rows without clamping: a pair's first pixel's sample at offset dx is ce or co (dx's
// parity) from dx >> 1 on. Then each output row sums its samples' rows 16 pixels at a time. The
// same pixels as the sample by sample loop.
// A lens map's regular runs are short (a few dozen pixels): each is copied in whole blocks of 16
// lumas and 8 chroma pairs, the last block running past the run's end. What it writes there lies
// where the row's next run, its padding or the next row writes afterwards (rows and runs are filled
// in order), or in the planes' slack; it reads past the run only while that stays inside the scratch.
struct Planes {
  static constexpr int kSlack = 32;   // lumas (and chroma words) written past a plane's last row
  int W = 0, H = 0, P = 0, stride = 0, Q = 0, cstride = 0;
  std::vector<uint8_t> y;
  std::vector<uint16_t> ce, co;
  void fill(const uint8_t *src, const LensMap *map, int W_, int H_, int P_) {
    W = W_;
    H = H_;
    P = P_;
    stride = W + 2 * P;
    Q = P / 2 + 1;
    cstride = W / 2 + 2 * Q;
    if (y.size() < (size_t)stride * H + kSlack) y.resize((size_t)stride * H + kSlack);
    if (ce.size() < (size_t)cstride * H + kSlack) {
      ce.resize((size_t)cstride * H + kSlack);
      co.resize(ce.size());
    }
    // the wide copies' reads end at most 4 * 8 + 2 bytes past a run's last pair
    const uint8_t *src_end = map ? src + (size_t)map->width * map->height * 2 : nullptr;
    for (int r = 0; r < H; r++) {
      uint8_t *py = &y[(size_t)r * stride + P];
      uint16_t *pe = &ce[(size_t)r * cstride + Q], *po = &co[(size_t)r * cstride + Q];
      if (!map) {
        const uint8_t *row = src + (size_t)r * W * 2;
        lumas(row, W, py);
        chromas(row, W / 2, pe);
        memcpy(po, pe, W);   // both pixels of a pair show its chroma
      } else {
        // a regular run from its first scratch pixel on: on an even one the frame's pairs are the
        // scratch's; on an odd one each frame pair's first pixel is a scratch pair's second (that
        // pair's chroma), its second pixel the next pair's first
        for (int k = map->row_runs[r]; k < map->row_runs[r + 1]; k++) {
          const LensMap::Run &run = map->runs[k];
          const int u = run.u, n = 2 * run.pairs;
          if (run.regular) {
            const uint8_t *s0 = src + run.src;
            const bool wide = s0 + 2 * n + 64 <= src_end;
            if (wide) lumas_wide(s0, n, py + u);
            else lumas(s0, n, py + u);
            if ((run.src & 3) == 0) {
              if (wide) chromas_wide(s0, run.pairs, pe + u / 2);
              else chromas(s0, run.pairs, pe + u / 2);
              memcpy(po + u / 2, pe + u / 2, (size_t)2 * run.pairs);
            } else if (wide) {
              chromas_wide(s0 - 2, run.pairs, pe + u / 2);
              chromas_wide(s0 + 2, run.pairs, po + u / 2);
            } else {
              chromas(s0 - 2, run.pairs, pe + u / 2);
              chromas(s0 + 2, run.pairs, po + u / 2);
            }
            continue;
          }
          const int32_t *os = map->other.data() + run.src;
          for (int i = 0; i < n; i++) {
            const int sa = os[i];
            const uint8_t *c = src + (sa & ~3);
            py[u + i] = src[sa];
            ((u + i) & 1 ? po : pe)[(u + i) / 2] = (uint16_t)(c[1] | c[3] << 8);
          }
        }
      }
      memset(py - P, py[0], P);
      memset(py + W, py[W - 1], P);
      const uint16_t first = pe[0], last = po[W / 2 - 1];
      for (int j = 1; j <= Q; j++) {
        pe[-j] = po[-j] = first;
        pe[W / 2 - 1 + j] = po[W / 2 - 1 + j] = last;
      }
    }
  }
  // the lumas of n pixels (even) of YUYV
  static void lumas(const uint8_t *p, int n, uint8_t *out) {
    const __m128i low = _mm_set1_epi16(0x00ff);
    int i = 0;
    for (; i + 16 <= n; i += 16) {
      const __m128i a = _mm_loadu_si128((const __m128i *)(p + 2 * i));
      const __m128i b = _mm_loadu_si128((const __m128i *)(p + 2 * i + 16));
      _mm_storeu_si128((__m128i *)(out + i), _mm_packus_epi16(_mm_and_si128(a, low), _mm_and_si128(b, low)));
    }
    for (; i < n; i++) out[i] = p[2 * i];
  }
  // the lumas of n pixels, in whole blocks of 16 (up to 15 read and written past the end)
  static void lumas_wide(const uint8_t *p, int n, uint8_t *out) {
    const __m128i low = _mm_set1_epi16(0x00ff);
    for (int i = 0; i < n; i += 16) {
      const __m128i a = _mm_loadu_si128((const __m128i *)(p + 2 * i));
      const __m128i b = _mm_loadu_si128((const __m128i *)(p + 2 * i + 16));
      _mm_storeu_si128((__m128i *)(out + i), _mm_packus_epi16(_mm_and_si128(a, low), _mm_and_si128(b, low)));
    }
  }
  // 8 pairs' chroma U | V << 8
  static __m128i chroma8(const uint8_t *p) {
    const __m128i lo = _mm_set1_epi32(0xff), hi = _mm_set1_epi32(0xff00);
    auto c4 = [&](__m128i w) {
      const __m128i c = _mm_or_si128(_mm_and_si128(_mm_srli_epi32(w, 8), lo), _mm_and_si128(_mm_srli_epi32(w, 16), hi));
      return _mm_srai_epi32(_mm_slli_epi32(c, 16), 16);   // sign-extended: packs keeps the 16 bits
    };
    return _mm_packs_epi32(c4(_mm_loadu_si128((const __m128i *)p)), c4(_mm_loadu_si128((const __m128i *)(p + 16))));
  }
  // the chroma U | V << 8 of n pairs of YUYV
  static void chromas(const uint8_t *p, int n, uint16_t *out) {
    int i = 0;
    for (; i + 8 <= n; i += 8) _mm_storeu_si128((__m128i *)(out + i), chroma8(p + 4 * i));
    for (; i < n; i++) out[i] = (uint16_t)(p[4 * i + 1] | p[4 * i + 3] << 8);
  }
  // the same in whole blocks of 8 pairs (up to 7 read and written past the end)
  static void chromas_wide(const uint8_t *p, int n, uint16_t *out) {
    for (int i = 0; i < n; i += 8) _mm_storeu_si128((__m128i *)(out + i), chroma8(p + 4 * i));
  }
};

void blur_row(const Develop &d, int n, const Planes &pl, int v, uint8_t *row) {
  const uint8_t *ry[Develop::kMaxTaps];
  const uint16_t *rc[Develop::kMaxTaps];   // pair j's chroma sample k: rc[k][j]
  for (int k = 0; k < n; k++) {
    const size_t r = (size_t)std::min(pl.H - 1, std::max(0, v + d.dy[k]));
    ry[k] = pl.y.data() + r * pl.stride + pl.P + d.dx[k];
    rc[k] = (d.dx[k] & 1 ? pl.co : pl.ce).data() + r * pl.cstride + pl.Q + (d.dx[k] >> 1);
  }
  // (s + n / 2) / n as ((s + n / 2) M) >> 16, M = 65536 / n + 1: exact for every s <= 8 * 255 + 4
  // (checked for every such s and n = 2..8)
  const __m128i m = _mm_set1_epi16((short)(uint16_t)(65536 / n + 1)), h = _mm_set1_epi16((short)(n / 2));
  const __m128i zero = _mm_setzero_si128(), low = _mm_set1_epi16(0x00ff);
  const int W = pl.W;
  int u = 0;
  for (; u + 16 <= W; u += 16) {
    __m128i y0 = zero, y1 = zero, us = zero, vs = zero;
    for (int k = 0; k < n; k++) {
      const __m128i a = _mm_loadu_si128((const __m128i *)(ry[k] + u));
      const __m128i c = _mm_loadu_si128((const __m128i *)(rc[k] + u / 2));   // 8 pairs' U | V << 8
      y0 = _mm_add_epi16(y0, _mm_unpacklo_epi8(a, zero));
      y1 = _mm_add_epi16(y1, _mm_unpackhi_epi8(a, zero));
      us = _mm_add_epi16(us, _mm_and_si128(c, low));
      vs = _mm_add_epi16(vs, _mm_srli_epi16(c, 8));
    }
    auto mean = [&](__m128i s) { return _mm_mulhi_epu16(_mm_add_epi16(s, h), m); };
    const __m128i mu = mean(us), mv = mean(vs);
    _mm_storeu_si128((__m128i *)(row + 2 * u), _mm_or_si128(mean(y0), _mm_slli_epi16(_mm_unpacklo_epi16(mu, mv), 8)));
    _mm_storeu_si128((__m128i *)(row + 2 * u + 16),
                     _mm_or_si128(mean(y1), _mm_slli_epi16(_mm_unpackhi_epi16(mu, mv), 8)));
  }
  for (; u < W; u += 2) {
    int y0 = 0, y1 = 0, us = 0, vs = 0;
    for (int k = 0; k < n; k++) {
      y0 += ry[k][u];
      y1 += ry[k][u + 1];
      us += rc[k][u / 2] & 0xff;
      vs += rc[k][u / 2] >> 8;
    }
    put_mean(row + 2 * u, y0, us, y1, vs, n);
  }
}
#endif

}  // namespace

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
  const bool plain = d.gain == 1 && d.wb_red == 1 && d.wb_blue == 1 && d.noise_luma == 0 && d.noise_chroma == 0;
  if (plain && n == 1 && !map) {
    if (out != src) memcpy(out, src, (size_t)W * H * 2);
    return;
  }
  Tone t{};
  if (!plain) t = tone_of(d);
  static const int8_t zero_row[kExtra] = {0};
  thread_local std::vector<uint8_t> row_buf;
  row_buf.resize((size_t)W * 2);
#ifdef __SSE2__
  thread_local Planes planes;
  if (n > 1) {
    // a sample farther than the frame's width reads its edge, as one at the width does
    int P = 0;
    for (int k = 0; k < n; k++) P = std::max(P, std::min(W - 1, std::abs(d.dx[k])));
    Develop dc = d;
    for (int k = 0; k < n; k++) dc.dx[k] = std::max(-P, std::min(P, d.dx[k]));
    planes.fill(src, d.map, W, H, P);
    for (int v = 0; v < H; v++) {
      uint8_t *row = out + (size_t)v * W * 2;
      blur_row(dc, n, planes, v, plain ? row : row_buf.data());
      if (!plain) {
        const int8_t *nr = W * 2 <= kExtra ? noise_.data() + (((uint32_t)v * W * 2 + d.noise_offset) & 0xffff) : zero_row;
        light_row(t, row_buf.data(), row, W, nr);
      }
    }
    return;
  }
#endif
  for (int v = 0; v < H; v++) {
    uint8_t *row = out + (size_t)v * W * 2;
    // 1. geometry: the scratch's pixels through the lens's map and the blur's samples
    const uint8_t *g = src + (size_t)v * W * 2;   // no map, no blur: the scratch is the frame
    uint8_t *geo = plain ? row : row_buf.data();
#ifndef __SSE2__
    if (n > 1) {
      blur_row(d, n, src, map, W, H, v, geo);
      g = geo;
    } else
#endif
    if (map) {
      lens_row(src, *d.map, v, W, geo);
      g = geo;
    }
    // 2. light: exposure gain, white balance, noise
    if (!plain) {
      const int8_t *nr = W * 2 <= kExtra ? noise_.data() + (((uint32_t)v * W * 2 + d.noise_offset) & 0xffff) : zero_row;
      light_row(t, g, row, W, nr);
    }
  }
}

}  // namespace sim
