// effects: what makes the sim camera as imperfect as a real one (sim.lua camera.realism): sensor
// noise (luma with shot noise, chroma), motion blur from the camera's motion during the exposure,
// the lens's radial distortion (the robot's calibration, camera.lua), exposure and white-balance
// drift over time, uneven light over the field and soft shadows under robots and the ball.
//
// The renderer draws a pinhole image (lit, no noise) into a scratch buffer; develop() turns it into
// the camera's frame: distortion (a per-pixel source map), blur, gains, white balance, noise.
// Everything is seeded: the same seed, frame and scene give the same pixels.
#ifndef HRP_SIM_EFFECTS_H
#define HRP_SIM_EFFECTS_H

#include <cstdint>
#include <vector>

#include "config.h"

namespace sim {

// A camera with the robot's calibration, OpenCV's convention: pixel centres at integer
// coordinates, u = cx + fx * xd, xd = x * (1 + k1 r^2 + k2 r^4) for the pinhole coordinates x, y
// (r^2 = x^2 + y^2).
struct Lens {
  int width = 0, height = 0;
  double fx = 0, fy = 0, cx = 0, cy = 0, k1 = 0, k2 = 0;
  bool distorted() const { return k1 != 0 || k2 != 0; }
  // distortion factor at pinhole radius^2 r2
  double factor(double r2) const { return 1 + r2 * (k1 + r2 * k2); }
  // pinhole coordinates of the distorted ones (fixed-point iteration, as OpenCV's undistortPoints)
  void undistort(double xd, double yd, double *x, double *y) const;
};

// The pinhole image the renderer draws before develop(): its size and principal point, and for each
// pixel of the camera's frame the scratch pixel that it shows (empty: the same pixel, no distortion).
struct LensMap {
  Lens lens;                 // whose map this is
  int width = 0, height = 0; // scratch size
  double cx = 0, cy = 0;     // principal point in the scratch
  std::vector<int32_t> src;  // per pixel of the frame: the byte offset of its scratch pixel's luma
  // The same map as runs of pixel pairs along each row: in a regular run the pixels show consecutive
  // scratch pixels from the run's first one on (the distortion moves a row's source by a pixel only
  // every few dozen), so that it is copied rather than looked up pixel by pixel; the others go
  // through src. Row v's runs: runs[row_runs[v]] up to runs[row_runs[v + 1]].
  // The runs and the others' offsets are in the order they are read (the map itself is 1.2 MB: a
  // look-up per run missed the cache).
  struct Run {
    int u, pairs;   // first pixel (even), length in pairs
    bool regular;
    int32_t src;    // regular: src of the first pixel; else the index of its pixels' src in `other`
  };
  std::vector<Run> runs;
  std::vector<int> row_runs;
  std::vector<int32_t> other;
};
void lens_map_build(const Lens &l, LensMap *m);

// The realism settings (sim.lua camera section), fixed for a run.
struct Realism {
  bool on = false;
  double exposure = 0.010;         // s
  double noise_luma = 3, noise_chroma = 2;   // grey levels (luma at mid-grey 128)
  double gain_drift = 0.06, wb_drift = 0.03, drift_period = 20;
  double light_gradient = 0.10;    // relative illumination change over the field's half-diagonal
  double shadow_robot = 0.35, shadow_ball = 0.5;   // darkening at a shadow's centre
  double shadow_robot_radius = 0.12;   // m, the shadow's standard deviation under a robot's torso
};
// Reads the camera section's realism keys of a sim config into r; throws naming the file and key.
void realism_load(const Config &sim, Realism *r);

// The light of one frame over the field: a linear gradient and soft round shadows.
struct Lighting {
  struct Caster {
    double x, y, inv_2s2, depth;
  };
  double g0 = 1, gx = 0, gy = 0;   // light = g0 + gx * x + gy * y (field frame, m), before shadows
  std::vector<Caster> casters;
  double at(double x, double y) const;          // with shadows, for the ground
  // lround(256 at(x[i], y[i])) for i < n: the same numbers, the casters sorted out per block of points
  void at256(const double *x, const double *y, int n, int *l) const;
  double ambient(double x, double y) const { return g0 + gx * x + gy * y; }   // for solids
};

// The per-frame development of a scratch image into the camera's frame.
struct Develop {
  const LensMap *map = nullptr;   // null: the scratch is the frame (same size, no distortion)
  static constexpr int kMaxTaps = 8;
  int taps = 1;                   // motion blur: samples along the flow
  int dx[kMaxTaps] = {0}, dy[kMaxTaps] = {0};   // each sample's pixel offset
  double gain = 1, wb_red = 1, wb_blue = 1;
  double noise_luma = 0, noise_chroma = 0;
  uint32_t noise_offset = 0;
};

class Developer {
 public:
  explicit Developer(uint64_t seed);
  // src: the scratch (map's size, or the frame's without a map); out: width x height YUYV (may be src
  // when there is neither a map nor a blur).
  void run(const Develop &d, const uint8_t *src, int width, int height, uint8_t *out) const;

 private:
  static constexpr int kExtra = 4096;
  std::vector<int8_t> noise_;   // N(0, 16^2), 65536 entries, then the first kExtra again
};

// The drift of exposure and white balance at time t for the camera of robot `self`: smooth, two
// sines per gain with seeded phases, so a run is the same for a seed.
void realism_drift(const Realism &r, uint64_t seed, int self, double t, double *gain, double *wb_red,
                   double *wb_blue);

}  // namespace sim
#endif
