/* jpeg_yuyv: a YUYV camera frame straight into a JPEG (TurboJPEG from Y, U, V planes). The camera's YUYV
 * is BT.601 video range (a UVC camera's default; the sim renders white at Y 235) and JPEG's YCbCr is
 * full range, so the planes are stretched on the way: the decoded JPEG shows what OpenCV's
 * YUV2BGR_YUYV showed, without converting to BGR and the encoder converting back (two thirds of the
 * old cost). */
#include "jpeg_yuyv.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <turbojpeg.h>

struct rec_jpeg {
  tjhandle tj;
  uint8_t *planes;         /* Y (w*h), then U and V (w/2 * (h+1)/2 each) */
  size_t planes_cap;
  unsigned char *out;      /* tjBufSize: the largest JPEG of this size, never reallocated */
  unsigned long out_cap;
  char err[200];
};

/* video range -> full range, rounded: Y 16..235 -> 0..255, U/V 16..240 around 128 -> 0..255 */
static uint8_t g_luma[256], g_chroma[256];

static uint8_t clamp8(double v) { return (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : lround(v)); }

static void tables(void) {
  for (int i = 0; i < 256; i++) {
    g_luma[i] = clamp8((i - 16) * 255.0 / 219.0);
    g_chroma[i] = clamp8(128 + (i - 128) * 255.0 / 224.0);
  }
}

#ifdef __SSE2__
#include <emmintrin.h>

/* The tables' values in 16-bit fixed point (the same numbers for every input, checked exhaustively by
 * jpeg_yuyv_test): luma floor((255 * max(y - 16, 0) + 109) / 219), chroma floor(max(255 a - 3856, 0) / 224)
 * with a the rounded mean of the line pair's two values; both clamped to 255 by the packing. */
static inline __m128i luma8(__m128i y) {
  const __m128i t = _mm_add_epi16(_mm_mullo_epi16(_mm_subs_epu16(y, _mm_set1_epi16(16)), _mm_set1_epi16(255)),
                                  _mm_set1_epi16(109));
  return _mm_srli_epi16(_mm_mulhi_epu16(t, _mm_set1_epi16(1197)), 2);
}
static inline __m128i chroma8(__m128i a) {
  const __m128i t = _mm_subs_epu16(_mm_mullo_epi16(a, _mm_set1_epi16(255)), _mm_set1_epi16(3856));
  return _mm_srli_epi16(_mm_mulhi_epu16(t, _mm_set1_epi16(18725)), 6);
}

/* 8 pixel pairs of two lines: 16 luma of each, 8 U and 8 V (the pair's mean) */
static int split_sse2(const uint8_t *a, const uint8_t *b, uint8_t *ya, uint8_t *yb, uint8_t *u, uint8_t *v, int cw) {
  const __m128i lo = _mm_set1_epi16(0x00FF), zero = _mm_setzero_si128();
  int i = 0;
  for (; i + 8 <= cw; i += 8) {
    const __m128i a0 = _mm_loadu_si128((const __m128i *)(a + 4 * i)), a1 = _mm_loadu_si128((const __m128i *)(a + 4 * i + 16));
    const __m128i b0 = _mm_loadu_si128((const __m128i *)(b + 4 * i)), b1 = _mm_loadu_si128((const __m128i *)(b + 4 * i + 16));
    _mm_storeu_si128((__m128i *)(ya + 2 * i), _mm_packus_epi16(luma8(_mm_and_si128(a0, lo)), luma8(_mm_and_si128(a1, lo))));
    _mm_storeu_si128((__m128i *)(yb + 2 * i), _mm_packus_epi16(luma8(_mm_and_si128(b0, lo)), luma8(_mm_and_si128(b1, lo))));
    const __m128i c0 = chroma8(_mm_avg_epu16(_mm_srli_epi16(a0, 8), _mm_srli_epi16(b0, 8)));
    const __m128i c1 = chroma8(_mm_avg_epu16(_mm_srli_epi16(a1, 8), _mm_srli_epi16(b1, 8)));
    const __m128i uv = _mm_packus_epi16(c0, c1);   /* U0 V0 U1 V1 ... U7 V7 */
    _mm_storel_epi64((__m128i *)(u + i), _mm_packus_epi16(_mm_and_si128(uv, lo), zero));
    _mm_storel_epi64((__m128i *)(v + i), _mm_packus_epi16(_mm_srli_epi16(uv, 8), zero));
  }
  return i;
}
#endif

void rec_jpeg_planes(const uint8_t *yuyv, int w, int h, uint8_t *Y, uint8_t *U, uint8_t *V, int simd) {
  if (!g_luma[255]) tables();
  /* 4:2:0 as OpenCV wrote them: each line pair's chroma averaged (a third less to encode than 4:2:2) */
  const int cw = w / 2;
  for (int r = 0; r < h; r += 2) {
    const uint8_t *a = yuyv + (size_t)r * (size_t)w * 2, *b = r + 1 < h ? a + (size_t)w * 2 : a;
    uint8_t *ya = Y + (size_t)r * (size_t)w, *yb = r + 1 < h ? ya + w : ya;
    uint8_t *u = U + (size_t)(r / 2) * (size_t)cw, *v = V + (size_t)(r / 2) * (size_t)cw;
    int i = 0;
#ifdef __SSE2__
    /* the same values 16 pixels at a time (the tables' loop was a sixth of the recorder's time) */
    if (simd && yb != ya) i = split_sse2(a, b, ya, yb, u, v, cw);
#else
    (void)simd;
#endif
    for (; i < cw; i++) {
      const uint8_t *p = a + 4 * i, *q = b + 4 * i;
      ya[2 * i] = g_luma[p[0]];
      ya[2 * i + 1] = g_luma[p[2]];
      yb[2 * i] = g_luma[q[0]];
      yb[2 * i + 1] = g_luma[q[2]];
      u[i] = g_chroma[(p[1] + q[1] + 1) >> 1];
      v[i] = g_chroma[(p[3] + q[3] + 1) >> 1];
    }
  }
}

rec_jpeg *rec_jpeg_new(void) {
  rec_jpeg *j = (rec_jpeg *)calloc(1, sizeof *j);
  if (!j) return NULL;
  if (!(j->tj = tjInitCompress())) {
    free(j);
    return NULL;
  }
  if (!g_luma[255]) tables();
  return j;
}

void rec_jpeg_free(rec_jpeg *j) {
  if (!j) return;
  tjDestroy(j->tj);
  free(j->planes);
  tjFree(j->out);
  free(j);
}

const char *rec_jpeg_error(const rec_jpeg *j) { return j->err; }

int rec_jpeg_encode(rec_jpeg *j, const uint8_t *yuyv, int w, int h, int quality, const uint8_t **jpeg, size_t *len) {
  if (w <= 0 || h <= 0 || (w & 1)) {
    strcpy(j->err, "a YUYV frame needs an even width and a height > 0");
    return -1;
  }
  const size_t n = (size_t)w * (size_t)h;
  if (j->planes_cap < 2 * n) {
    free(j->planes);
    j->planes_cap = 0;
    if (!(j->planes = (uint8_t *)malloc(2 * n))) {
      strcpy(j->err, "out of memory");
      return -1;
    }
    j->planes_cap = 2 * n;
  }
  const unsigned long cap = tjBufSize(w, h, TJSAMP_420);
  if (j->out_cap < cap) {
    tjFree(j->out);
    j->out_cap = 0;
    if (!(j->out = tjAlloc((int)cap))) {
      strcpy(j->err, "out of memory");
      return -1;
    }
    j->out_cap = cap;
  }
  const int cw = w / 2, ch = (h + 1) / 2;
  uint8_t *Y = j->planes, *U = Y + n, *V = U + (size_t)cw * (size_t)ch;
  rec_jpeg_planes(yuyv, w, h, Y, U, V, 1);
  const unsigned char *planes[3] = { Y, U, V };
  const int strides[3] = { w, cw, cw };
  unsigned long size = j->out_cap;
  if (tjCompressFromYUVPlanes(j->tj, planes, w, strides, h, TJSAMP_420, &j->out, &size, quality, TJFLAG_NOREALLOC) < 0) {
    snprintf(j->err, sizeof j->err, "TurboJPEG: %s", tjGetErrorStr2(j->tj));
    return -1;
  }
  *jpeg = j->out;
  *len = size;
  return 0;
}
