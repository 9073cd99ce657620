// render: a small software rasterizer for the head camera -- field (carpet, lines), goals, ball
// and robots into a YUYV image. No GPU, no display; deterministic for a given seed and scene.
//
// Image coordinates: u to the right, v down, in pixels; the centre of pixel (i, k) is (i, k).
// The camera is the robot's calibration (camera.lua: fx, fy, cx, cy, radial k1, k2; effects.h's
// Lens); without one a pinhole with square pixels: f = (height / 2) / tan(fovy / 2), principal point
// at the image centre ((width - 1) / 2, (height - 1) / 2). Camera frame: x optical axis, y image-left,
// z image-up. With camera.realism (sim.lua) the frame goes through effects.h's imperfections.
#ifndef HRP_SIM_RENDER_H
#define HRP_SIM_RENDER_H

#include <cstdint>
#include <vector>

#include <memory>
#include <mutex>

#include "effects.h"
#include "world.h"

namespace sim {

struct Camera {
  Vec3 pos = Vec3::Zero();  // field frame
  Mat3 rot = Mat3::Identity();   // columns: optical axis, image-left, image-up (field frame)
  int width = 640, height = 480;
  double fovy = 43.3 * M_PI / 180;
  // calibration (fx > 0; else the pinhole from fovy), as Lens
  double fx = 0, fy = 0, cx = 0, cy = 0, k1 = 0, k2 = 0;
  double focal() const { return (height / 2.0) / std::tan(fovy / 2); }
  double fu() const { return fx > 0 ? fx : focal(); }
  double fv() const { return fx > 0 ? fy : focal(); }
  double pu() const { return fx > 0 ? cx : (width - 1) / 2.0; }
  double pv() const { return fx > 0 ? cy : (height - 1) / 2.0; }
  bool distorted() const { return k1 != 0 || k2 != 0; }
  Lens lens() const;
  // the calibration of camera.lua (Params' cam_*)
  void calibrate(const Params &p);
};

// Pixel position (u, v) of a field-frame point (through the lens's distortion); false if it is
// behind the camera.
bool camera_project(const Camera &c, const Vec3 &p, double *u, double *v);

// What one frame shows: the camera and the moving things besides the solids.
struct Shot {
  Camera cam;                             // at the end of the exposure
  Camera cam_start;                       // at its start (motion blur), if has_start
  bool has_start = false;
  double time = 0;                        // s, exposure (exposure and white-balance drift)
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
  // (the camera's own head) are skipped. Not reentrant across threads (a scratch per renderer).
  void render(const Shot &s, const std::vector<Solid> &solids, uint8_t *yuyv) const;
  const Realism &realism() const { return real_; }

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
  struct Look;   // noise and light of one frame (render.cpp)
  void draw(const Shot &sh, const Camera &c, const std::vector<Solid> &solids, const Look &look, uint8_t *img) const;
  void ground(const Camera &c, const Look &look, uint8_t *yuyv) const;
  void solid(const Camera &c, const Solid &s, const Look &look, uint8_t *yuyv) const;
  void ball(const Camera &c, const Vec3 &center, const Mat3 &rot, double r, const Look &look, uint8_t *yuyv) const;
  uint32_t noise_offset(uint32_t frame) const;
  const LensMap &lens_map(const Lens &l) const;
  void develop_settings(const Shot &sh, Develop *d) const;

  double x0_, y0_, res_;         // field texture origin (m) and resolution (m per texel)
  int tw_, th_;                  // texture size (multiples of 8)
  // line bits of one quarter of the carpet (|X|, |Y| from the centre) at 1 cm, 8 x 8 texels per
  // 64-bit word: 28 KB, so the ray casts stay in the L1 cache
  std::vector<uint64_t> tex_;
  float carpet_x_, carpet_y_;    // carpet half-size in texels
  // per tile: how many tiles around it are plain carpet (a block of 8 pixels whose samples stay
  // within them is carpet without a look-up per pixel)
  std::vector<uint8_t> reach_;
  static constexpr int kNoiseExtra = 4096;
  std::vector<int8_t> noise_;    // luma noise table (65536 entries, then the first kNoiseExtra again)
  uint64_t seed_;
  bool white_ball_;              // sim.lua ball.kind: 'white' (patterned) or 'orange'
  Realism real_;
  double half_diagonal_;         // m, of the carpet: the light gradient's scale
  double light_dir_;             // rad, the light gradient's direction (seeded)
  Developer dev_;
  mutable std::mutex maps_mu_;
  mutable std::vector<std::unique_ptr<LensMap>> maps_;   // one per calibration seen
};

}  // namespace sim
#endif
