// Vision pipeline benchmark: frames per second of the whole colour pipeline at 640x480 YUYV on
// one core, libhrpimg side by side with the same stages written with OpenCV calls, in one run.
//
// Stages (both versions):
//   1. classify: YUYV subsampled by 2 (320x240, Y0 U V of every other pair on every other line)
//      -> colour labels (hrp: the 2^18 LUT; OpenCV: cv::inRange per colour box, OR of the bits)
//   2. block image: 4x4 bit-OR (hrp: img_block_or; OpenCV: cv::resize INTER_AREA per colour, > 0)
//   3. regions: ball colour on the label image, white on the block image (hrp: img_regions;
//      OpenCV: cv::connectedComponentsWithStats), largest 8 kept
//   4. colour statistics: ball colour in the largest ball region's box and green in the band below
//      it (hrp: img_color_stats; OpenCV: cv::moments on the mask ROI)
// The LUT is built from the same colour boxes, aligned to its 4-level cells, so both label
// images are identical; the program checks that and that both find the same ball.
//
// The two versions are timed in alternating batches (a shared machine's changing load hits both alike).
// Usage: img_bench [seconds per version and frame, default 2]
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <random>
#include <vector>

extern "C" {
#include "imageproc/imageproc.h"
}

namespace {

const int W = 640, H = 480, WA = 320, HA = 240, BS = 4, WB = 80, HB = 60;
const int BALL = 1, GREEN = 8, WHITE = 16;

// Colour boxes, aligned to LUT cells (min multiple of 4, max = 4k+3).
const img_color_range kColors[] = {
    {BALL, 40, 235, 0, 111, 168, 255},
    {GREEN, 28, 191, 56, 123, 40, 123},
    {WHITE, 176, 255, 104, 151, 104, 151},
};
const int kNColors = 3;

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double cpu_now() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

// A field scene: noisy green carpet, white lines, a white post, an orange ball.
std::vector<uint8_t> make_scene(unsigned seed) {
  std::vector<uint8_t> f(W * H * 2);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 3.0);
  auto clamp = [](double v) { return (uint8_t)std::min(255.0, std::max(0.0, std::round(v))); };
  for (int y = 0; y < H; y++) {
    for (int x = 0; x < W; x += 2) {
      double Y = 99, U = 95, V = 86;                                    // green
      bool line = std::abs(y - (200 + (x - 320) / 6)) < 4 || std::abs(x - 500) < 5;
      bool post = x > 60 && x < 84 && y < 260;
      double dx = x - 300, dy = y - 330;
      bool ball = dx * dx + dy * dy < 28 * 28;
      if (y < 120 && !post) { Y = 150; U = 140; V = 120; }             // background, no class
      if (line || post) { Y = 235; U = 128; V = 128; }
      if (ball) { Y = 147; U = 45; V = 205; }
      uint8_t *p = &f[(y * W + x) * 2];
      p[0] = clamp(Y + noise(rng)); p[1] = clamp(U + noise(rng));
      p[2] = clamp(Y + noise(rng)); p[3] = clamp(V + noise(rng));
    }
  }
  return f;
}

std::vector<uint8_t> make_noise(unsigned seed) {
  std::vector<uint8_t> f(W * H * 2);
  std::mt19937 rng(seed);
  for (auto &b : f) b = (uint8_t)rng();
  return f;
}

struct Result {
  int ball_regions = 0, white_regions = 0;
  int ball_area = 0;
  double ball_cx = 0, ball_cy = 0;
  int ball_stats_area = 0, green_below = 0;
};

// ---------------------------------------------------------------- libhrpimg

struct Hrp {
  std::vector<uint8_t> lut = std::vector<uint8_t>(IMG_LUT_SIZE, 0);
  std::vector<uint8_t> labels = std::vector<uint8_t>(WA * HA), blocks = std::vector<uint8_t>(WB * HB);
  img_cc *cc = img_cc_new(WA, HA);
  img_region regs[8], st;
  Hrp() { img_lut_add_ranges(lut.data(), kColors, kNColors); }
  ~Hrp() { img_cc_free(cc); }

  Result run(const uint8_t *yuyv) {
    Result r;
    img_label_yuyv(yuyv, W, H, lut.data(), 2, labels.data());
    img_block_or(labels.data(), WA, HA, BS, blocks.data());
    r.white_regions = img_regions(cc, blocks.data(), WB, HB, WHITE, regs, 8);
    r.ball_regions = img_regions(cc, labels.data(), WA, HA, BALL, regs, 8);
    if (r.ball_regions > 0) {
      const img_region &b = regs[0];
      r.ball_area = b.area; r.ball_cx = b.cx; r.ball_cy = b.cy;
      img_color_stats(labels.data(), WA, HA, BALL, b.xmin, b.xmax, b.ymin, b.ymax, &st);
      r.ball_stats_area = st.area;
      int h = b.ymax - b.ymin + 1;
      img_color_stats(labels.data(), WA, HA, GREEN, b.xmin, b.xmax, b.ymax + 1, b.ymax + h / 2 + 1, &st);
      r.green_below = st.area;
    }
    return r;
  }
};

// ---------------------------------------------------------------- OpenCV

struct Cv {
  cv::Mat masks[kNColors], labels, bmask, blocks, cc, stats, cents;
  Cv() { labels.create(HA, WA, CV_8U); blocks.create(HB, WB, CV_8U); }

  Result run(const uint8_t *yuyv) {
    Result r;
    // every other line, every other YUYV pair: a 240x320 view of 4-channel pixels (Y0 U Y1 V)
    cv::Mat pairs(HA, WA, CV_8UC4, const_cast<uint8_t *>(yuyv), (size_t)W * 2 * 2);
    labels.setTo(0);
    blocks.setTo(0);
    for (int c = 0; c < kNColors; c++) {
      const img_color_range &k = kColors[c];
      cv::inRange(pairs, cv::Scalar(k.ymin, k.umin, 0, k.vmin), cv::Scalar(k.ymax, k.umax, 255, k.vmax),
                  masks[c]);
      cv::bitwise_or(labels, cv::Scalar(k.bit), labels, masks[c]);
      cv::resize(masks[c], bmask, cv::Size(WB, HB), 0, 0, cv::INTER_AREA);
      cv::bitwise_or(blocks, cv::Scalar(k.bit), blocks, bmask);
    }
    auto top = [&](int n) {   // largest component (label 0 is the background)
      int best = -1;
      for (int i = 1; i < n; i++)
        if (best < 0 || stats.at<int>(i, cv::CC_STAT_AREA) > stats.at<int>(best, cv::CC_STAT_AREA)) best = i;
      return best;
    };
    cv::Mat white = blocks & WHITE;
    r.white_regions = cv::connectedComponentsWithStats(white, cc, stats, cents, 8, CV_32S) - 1;
    r.ball_regions = cv::connectedComponentsWithStats(masks[0], cc, stats, cents, 8, CV_32S) - 1;
    int b = top(r.ball_regions + 1);
    if (b > 0) {
      int x0 = stats.at<int>(b, cv::CC_STAT_LEFT), y0 = stats.at<int>(b, cv::CC_STAT_TOP);
      int w = stats.at<int>(b, cv::CC_STAT_WIDTH), h = stats.at<int>(b, cv::CC_STAT_HEIGHT);
      r.ball_area = stats.at<int>(b, cv::CC_STAT_AREA);
      r.ball_cx = cents.at<double>(b, 0);
      r.ball_cy = cents.at<double>(b, 1);
      cv::Moments m = cv::moments(masks[0](cv::Rect(x0, y0, w, h)), true);
      r.ball_stats_area = (int)m.m00;
      int by = y0 + h, bh = std::min(h / 2 + 1, HA - by);
      if (bh > 0) r.green_below = (int)cv::moments(masks[1](cv::Rect(x0, by, w, bh)), true).m00;
    }
    return r;
  }
};

// Both versions timed in alternating batches of 20 frames until `seconds` passed, each side's time summed:
// on a shared machine whose load changes during the run, both see the same load. The time is this
// thread's CPU time: the wall clock would count the time other processes had the core.
void measure(Hrp &hrp, Cv &ocv, const std::vector<uint8_t> &frame, double seconds, double *fh, double *fc, long *nh,
             long *nc) {
  volatile int sink = 0;
  double th = 0, tc = 0;
  long n = 0;
  const double start = now();
  do {
    double t0 = cpu_now();
    for (int i = 0; i < 20; i++) sink += hrp.run(frame.data()).ball_area;
    double t1 = cpu_now();
    for (int i = 0; i < 20; i++) sink += ocv.run(frame.data()).ball_area;
    double t2 = cpu_now();
    th += t1 - t0;
    tc += t2 - t1;
    n += 20;
  } while (now() - start < seconds);
  (void)sink;
  *nh = *nc = n;
  *fh = n / th;
  *fc = n / tc;
}

void bench(const char *name, const std::vector<uint8_t> &frame, double seconds) {
  Hrp hrp;
  Cv ocv;
  Result a = hrp.run(frame.data()), b = ocv.run(frame.data());
  bool same_labels = std::memcmp(hrp.labels.data(), ocv.labels.data, WA * HA) == 0;
  bool same_blocks = std::memcmp(hrp.blocks.data(), ocv.blocks.data, WB * HB) == 0;
  bool same_ball = a.ball_regions == b.ball_regions && a.ball_area == b.ball_area &&
                   std::fabs(a.ball_cx - b.ball_cx) < 1e-6 && std::fabs(a.ball_cy - b.ball_cy) < 1e-6 &&
                   a.ball_stats_area == b.ball_stats_area && a.green_below == b.green_below &&
                   a.white_regions == b.white_regions;
  long nh, nc;
  double fh, fc;
  measure(hrp, ocv, frame, 2 * seconds, &fh, &fc, &nh, &nc);
  std::printf("%-12s hrp %9.0f fps (%6.3f ms/frame, %ld frames)   opencv %8.0f fps (%6.3f ms/frame)   "
              "ratio %.2fx\n", name, fh, 1e3 / fh, nh, fc, 1e3 / fc, fh / fc);
  std::printf("%-12s same labels: %s, same blocks: %s, same regions/stats: %s "
              "(ball regions %d, area %d at %.1f,%.1f; white block regions %d)\n", "",
              same_labels ? "yes" : "NO", same_blocks ? "yes" : "NO", same_ball ? "yes" : "NO",
              a.ball_regions, a.ball_area, a.ball_cx, a.ball_cy, a.white_regions);
}

}  // namespace

int main(int argc, char **argv) {
  double seconds = argc > 1 ? std::atof(argv[1]) : 2.0;
  cv::setNumThreads(1);   // one core for both
  std::printf("vision pipeline, 640x480 YUYV -> 320x240 labels -> 80x60 blocks -> regions -> stats, "
              "one thread (OpenCV %s, setNumThreads(1)), thread CPU time\n", CV_VERSION);
  bench("field scene", make_scene(1), seconds);
  bench("noise frame", make_noise(2), seconds);
  return 0;
}
