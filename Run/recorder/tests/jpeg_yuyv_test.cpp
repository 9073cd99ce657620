// jpeg_yuyv_test: the recorder's YUYV -> JPEG encoder (jpeg_yuyv.c) against the OpenCV path it replaced
// (cvtColor YUV2BGR_YUYV + imencode), on one field-like frame with camera noise, in one run:
// the decoded JPEG must show the picture OpenCV's conversion shows (BT.601 video range stretched to
// JPEG's full range: no washed-out whites, no colour shift), and the time per frame of both is printed.
//   jpeg_yuyv_test [DIR]   also writes DIR/jpeg_{reference,opencv,yuyv}.png to look at
#include "../jpeg_yuyv.h"
#include "tap.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace {

const int W = 640, H = 480, Q = 85;

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// Sky, green carpet, white lines (Y 235: video-range white, as the sim renders it), an orange ball,
// Gaussian sensor noise.
std::vector<uint8_t> scene() {
  std::vector<uint8_t> f((size_t)W * H * 2);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 3.0);
  auto c8 = [](double v) { return (uint8_t)std::min(255.0, std::max(0.0, std::round(v))); };
  for (int y = 0; y < H; y++)
    for (int x = 0; x < W; x += 2) {
      double Y = 99, U = 95, V = 86;
      if (y < 120) { Y = 180 - y / 2.0; U = 150; V = 118; }
      if (std::abs(y - (240 + (x - 320) / 5)) < 5 || (std::abs(x - 500) < 6 && y >= 120)) { Y = 235; U = 128; V = 128; }
      const double dx = x - 260, dy = y - 330;
      if (dx * dx + dy * dy < 30 * 30) { Y = 147; U = 45; V = 205; }
      uint8_t *p = &f[((size_t)y * W + x) * 2];
      p[0] = c8(Y + noise(rng)); p[1] = c8(U + noise(rng)); p[2] = c8(Y + noise(rng)); p[3] = c8(V + noise(rng));
    }
  return f;
}

// Mean of channel c over the pixels where mask is set, and mean |a - b| over the image.
double mean_in(const cv::Mat &bgr, const cv::Mat &mask, int c) {
  return cv::mean(bgr, mask)[c];
}
double mad(const cv::Mat &a, const cv::Mat &b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  const cv::Scalar m = cv::mean(d);
  return (m[0] + m[1] + m[2]) / 3;
}

}  // namespace

int main(int argc, char **argv) {
  cv::setNumThreads(1);   // as the recorder's writer thread
  std::vector<uint8_t> yuyv = scene();
  cv::Mat src(H, W, CV_8UC2, yuyv.data()), ref;
  cv::cvtColor(src, ref, cv::COLOR_YUV2BGR_YUYV);   // what the camera saw, uncompressed

  // the SIMD plane split gives the tables' values: every luma value, every pair of chroma values of a
  // line pair (512 x 512), and sizes with a tail and an odd last line
  {
    bool same = true;
    const int sizes[][2] = { { 512, 512 }, { 18, 5 }, { 640, 481 }, { 2, 1 } };
    for (const auto &sz : sizes) {
      const int w = sz[0], h = sz[1], cw = w / 2, ch = (h + 1) / 2;
      std::vector<uint8_t> f((size_t)w * h * 2);
      for (int r = 0; r < h; r++)
        for (int i = 0; i < cw; i++) {
          uint8_t *p = &f[((size_t)r * w + 2 * i) * 2];
          const int k = r / 2;
          if (r % 2 == 0) { p[0] = (uint8_t)i; p[1] = (uint8_t)i; p[2] = (uint8_t)(255 - i); p[3] = (uint8_t)(255 - i); }
          else { p[0] = (uint8_t)(i + k); p[1] = (uint8_t)k; p[2] = (uint8_t)(i * 7 + k); p[3] = (uint8_t)k; }
        }
      std::vector<uint8_t> a((size_t)w * h + 2 * (size_t)cw * ch), b(a.size());
      rec_jpeg_planes(f.data(), w, h, a.data(), a.data() + (size_t)w * h, a.data() + (size_t)w * h + (size_t)cw * ch, 1);
      rec_jpeg_planes(f.data(), w, h, b.data(), b.data() + (size_t)w * h, b.data() + (size_t)w * h + (size_t)cw * ch, 0);
      same = same && a == b;
    }
    check(same, "the SIMD plane split equals the tables for every value and size");
  }

  rec_jpeg *j = rec_jpeg_new();
  check(j != nullptr, "an encoder is made");
  if (!j) return tap_done();
  const uint8_t *out = nullptr;
  size_t len = 0;
  check(rec_jpeg_encode(j, yuyv.data(), W - 1, H, Q, &out, &len) < 0 && strstr(rec_jpeg_error(j), "even width"),
        "an odd width is refused with a reason");

  // the two paths, interleaved, best of several (the machine is shared)
  std::vector<uchar> old_jpeg;
  cv::Mat bgr;
  double t_old = 1e9, t_new = 1e9;
  int rc = 0;
  for (int k = 0; k < 15; k++) {
    double t0 = now();
    cv::cvtColor(src, bgr, cv::COLOR_YUV2BGR_YUYV);
    cv::imencode(".jpg", bgr, old_jpeg, { cv::IMWRITE_JPEG_QUALITY, Q });
    double t1 = now();
    rc |= rec_jpeg_encode(j, yuyv.data(), W, H, Q, &out, &len);
    double t2 = now();
    t_old = std::min(t_old, t1 - t0);
    t_new = std::min(t_new, t2 - t1);
  }
  check(rc == 0, "frames encode");
  printf("# 640x480 quality %d, best of 15: OpenCV (YUYV->BGR, imencode) %.2f ms/frame %zu bytes; "
         "YUYV planes -> TurboJPEG %.2f ms/frame %zu bytes (%.2fx)\n",
         Q, 1e3 * t_old, old_jpeg.size(), 1e3 * t_new, len, len ? t_old / t_new : 0.0);

  const cv::Mat dec_new = cv::imdecode(cv::Mat(1, (int)len, CV_8UC1, const_cast<uint8_t *>(out)), cv::IMREAD_COLOR);
  const cv::Mat dec_old = cv::imdecode(old_jpeg, cv::IMREAD_COLOR);
  check(dec_new.cols == W && dec_new.rows == H, "the JPEG decodes to 640x480");
  if (dec_new.empty()) return tap_done();
  const double e_new = mad(dec_new, ref), e_old = mad(dec_old, ref);
  printf("# mean |decoded - uncompressed| per channel: new %.2f, OpenCV %.2f\n", e_new, e_old);
  check(e_new <= 1.05 * e_old, "the decoded frame is as close to the camera's picture as OpenCV's");

  // colour and range where it shows: the white line and the ball, per channel, within 3 levels
  cv::Mat white(H, W, CV_8UC1, cv::Scalar(0)), ball(H, W, CV_8UC1, cv::Scalar(0));
  cv::circle(ball, {260, 330}, 26, 255, -1);
  cv::rectangle(white, {496, 130}, {503, 470}, 255, -1);
  bool same = true;
  for (int c = 0; c < 3; c++) {
    const double w_new = mean_in(dec_new, white, c), w_ref = mean_in(ref, white, c);
    const double b_new = mean_in(dec_new, ball, c), b_ref = mean_in(ref, ball, c);
    printf("# channel %d: white %.1f (uncompressed %.1f), ball %.1f (uncompressed %.1f)\n", c, w_new, w_ref, b_new, b_ref);
    same = same && std::abs(w_new - w_ref) < 3 && std::abs(b_new - b_ref) < 3;
  }
  check(same, "white stays white (video range stretched) and the ball keeps its colour");
  check(mean_in(dec_new, white, 1) > 245, "the lines decode near full white");

  if (argc > 1) {
    const std::string d = argv[1];
    const bool ok = cv::imwrite(d + "/jpeg_reference.png", ref) && cv::imwrite(d + "/jpeg_opencv.png", dec_old) &&
                    cv::imwrite(d + "/jpeg_yuyv.png", dec_new);
    check(ok, "PNGs written to " + d);
  }
  rec_jpeg_free(j);
  return tap_done();
}
