// render: a small software rasterizer for the head camera -- field (carpet, lines), goals, ball
// and robots into a YUYV image. No GPU, no display; deterministic for a given seed and scene.
//
// Image coordinates: u to the right, v down, in pixels; the centre of pixel (i, k) is (i, k).
// Pinhole camera with square pixels: f = (height / 2) / tan(fovy / 2), principal point at the
// image centre ((width - 1) / 2, (height - 1) / 2). Camera frame: x optical axis, y image-left,
// z image-up.
#ifndef HRP_SIM_RENDER_H
#define HRP_SIM_RENDER_H

#include <cstdint>
#include <vector>

#include "world.h"

namespace sim {

struct Camera {
  Vec3 pos = Vec3::Zero();  // field frame
  Mat3 rot = Mat3::Identity();   // columns: optical axis, image-left, image-up (field frame)
  int width = 640, height = 480;
  double fovy = 43.3 * M_PI / 180;
  double focal() const { return (height / 2.0) / std::tan(fovy / 2); }
};

// Pixel position (u, v) of a field-frame point; false if it is behind the camera.
bool camera_project(const Camera &c, const Vec3 &p, double *u, double *v);

// What one frame shows: the camera and the moving things besides the solids.
struct Shot {
  Camera cam;
  Vec3 ball = Vec3::Zero();               // centre, field frame
  Mat3 ball_rot = Mat3::Identity();       // the ball's orientation (its pattern turns with it)
  double ball_radius = 0.07;
  int self = -1;                          // the robot whose camera it is
  const std::vector<int> *hide = nullptr; // links of `self` its camera does not see (its head)
  uint32_t frame = 0;                     // varies the sensor noise
};

// The shot of robot `self`'s camera `c` in the world as it is now.
Shot shot_of(const World &w, const Camera &c, int self, const std::vector<int> *hide, uint32_t frame);

class Renderer {
 public:
  Renderer(const Params &p, uint64_t seed);
  // Renders into yuyv (width * height * 2 bytes). Solids of robot `self` on links in `hide`
  // (the camera's own head) are skipped.
  void render(const Shot &s, const std::vector<Solid> &solids, uint8_t *yuyv) const;

  // colours (Y, U, V)
  static constexpr uint8_t kGreen[3] = {93, 98, 90};
  static constexpr uint8_t kWhite[3] = {230, 128, 128};
  static constexpr uint8_t kOrange[3] = {135, 52, 214};
  static constexpr uint8_t kFloor[3] = {102, 122, 133};
  static constexpr uint8_t kSky[3] = {160, 139, 121};
  // the white ball (sim.lua ball.kind = 'white'): white panels, dark patches
  static constexpr uint8_t kBallWhite[3] = {232, 128, 128};
  static constexpr uint8_t kBallPatch[3] = {40, 128, 128};

 private:
  void ground(const Camera &c, uint32_t frame, uint8_t *yuyv) const;
  void solid(const Camera &c, const Solid &s, uint32_t frame, uint8_t *yuyv) const;
  void ball(const Camera &c, const Vec3 &center, const Mat3 &rot, double r, uint32_t frame, uint8_t *yuyv) const;
  uint32_t noise_offset(uint32_t frame) const;

  double x0_, y0_, res_;         // field texture origin (m) and resolution (m per texel)
  int tw_, th_;                  // texture size (multiples of 8)
  // line bits of one quarter of the carpet (|X|, |Y| from the centre) at 1 cm, 8 x 8 texels per
  // 64-bit word: 28 KB, so the ray casts stay in the L1 cache
  std::vector<uint64_t> tex_;
  float carpet_x_, carpet_y_;    // carpet half-size in texels
  std::vector<uint8_t> cells_;   // 1 where a 64 x 64 texel cell holds any line texel
  int cells_x_;
  static constexpr int kNoiseExtra = 4096;
  std::vector<int8_t> noise_;    // luma noise table (65536 entries, then the first kNoiseExtra again)
  uint64_t seed_;
  bool white_ball_;              // sim.lua ball.kind: 'white' (patterned) or 'orange'
};

}  // namespace sim
#endif
