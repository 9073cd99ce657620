// sim_ball_frames: renders seeded random head-camera frames with their truth, for training and testing
// the ball and robot detectors (Tools/ball_train, Tests/vision/ball_frames_test.sh).
//   sim_ball_frames --out FILE [--count N] [--seed N] [--others K] [--ball white|orange] [--walk 1]
// Each scene: this robot somewhere on the carpet, the head anywhere in its range; the ball in view
// in about 2/3 of the scenes (0.25..5 m, also partly in view), elsewhere on the carpet otherwise;
// 0..K other robots around (0.4..4 m, any yaw), of either team; the ball turned any way (its
// pattern). The camera is the body's calibration and, with the sim's camera.realism, its
// imperfections: the light and white balance at a random time, motion blur from a random turn of
// the head (up to 4 rad/s, a head sweeping or the body swaying in a walk) and a step of the body
// (up to 0.3 m/s) during the exposure. --ball: the ball the camera sees (default: the sim config's ball.kind). The seed picks everything: training and test frames
// differ by their seeds.
// --walk 1: the robot walking: the torso swaying about its feet at a random phase of the gait (roll
// +-4 deg, pitch 0..+5 deg at twice the step rate, the camera 1 cm up and down), its sway's turn rate
// in the motion blur with the head's and body's, and the camera pose given to the vision off the true
// one by up to 1.5 deg in roll and pitch (a torso estimate from the IMU in a walk; the OP3's gait and
// its filter's error are not measured here: conservative round figures, larger than a gentle gait's).
//
// File (little-endian): "HRPBFRM1", i32 width, height, count, others; then per frame:
//   f64 f, cx, cy, camera x, y (robot frame: the torso's ground point, x forward, y left), R[9]
//       (camera -> robot frame with the torso's yaw only, row-major; x optical, y left, z up), height,
//   f64 ball u, v, radius (px, continuous coordinates), distance (m, camera to centre, horizontal
//       from the robot's torso), bearing (rad, in the robot frame), visible (fraction of its disc
//       that shows in the frame: inside the image and not hidden by a robot),
//   i32 nrobots, then per other robot f64 x, y (robot frame: the torso's ground point), u, v (px of
//       that ground point), visible (1 if it projects inside the image), team (the sim's: 1 or 2),
//   then width * height * 2 bytes of YUYV.
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <stdexcept>

#include "render.h"
#include "stance.h"
#include "tool_args.h"
#include "world.h"

namespace {

void put(FILE *f, const void *p, size_t n) {
  if (fwrite(p, 1, n, f) != n) throw std::runtime_error("write failed");
}
void putd(FILE *f, double x) { put(f, &x, 8); }
void puti(FILE *f, int32_t x) { put(f, &x, 4); }

// The pixel of p and whether it lies in the frame. The lens polynomial turns back beyond the
// frame's corners (k2 < 0), folding points far outside the view into the image: a point counts
// only when its pinhole radius is within the corners' (undistorted) one.
bool in_frame(const sim::Camera &c, const sim::Vec3 &p, double *u, double *v) {
  if (!sim::camera_project(c, p, u, v) || *u < 0 || *v < 0 || *u >= c.width || *v >= c.height) return false;
  const sim::Vec3 q = c.rot.transpose() * (p - c.pos);
  const double x = -q.y() / q.x(), y = -q.z() / q.x();
  double r2max = 0;
  const sim::Lens l = c.lens();
  for (int k = 0; k < 4; k++) {
    double cx = ((k & 1) ? c.width : 0) - c.pu(), cy = ((k & 2) ? c.height : 0) - c.pv(), xu = cx / c.fu(),
           yu = cy / c.fv();
    if (c.distorted()) l.undistort(cx / c.fu(), cy / c.fv(), &xu, &yu);
    r2max = std::max(r2max, xu * xu + yu * yu);
  }
  return x * x + y * y <= r2max;
}

}  // namespace

int main(int argc, char **argv) {
  const char *out_arg = nullptr;
  int count = 100, others = 3, walk = 0;
  long seed_arg = 1;
  std::string ball_kind;
  const dcm_opt opts[] = {
      {"--out", DCM_OPT_STRING, &out_arg, 0, 0, "FILE", "the frames and their truth", nullptr, 1},
      {"--count", DCM_OPT_INT, &count, 1, 1e7, "N", "frames (default 100)", nullptr, 0},
      {"--seed", DCM_OPT_LONG, &seed_arg, 0, (double)LONG_MAX, "N", "picks everything (default 1)", nullptr, 0},
      {"--others", DCM_OPT_INT, &others, 0, 8, "K", "other robots on the field (default 3)", nullptr, 0},
      {"--ball", DCM_OPT_FUNC, &ball_kind, 0, 0, "white|orange", "the ball (default: the sim config's)",
       sim::parse_ball_kind, 0},
      {"--walk", DCM_OPT_INT, &walk, 0, 1, "0|1", "1: the robot walking (default 0)", nullptr, 0},
      DCM_OPT_END,
  };
  dcm_args("sim_ball_frames", "sim_ball_frames", opts, argc, argv);
  const std::string out = out_arg;
  const uint64_t seed = (uint64_t)seed_arg;
  try {
    sim::Params p;
    sim::Model m;
    sim::load_all(&p, &m, ball_kind);
    // teams alternate: this robot team 1, the others 2, 1, 2, ...
    p.robot_team.clear();
    for (int r = 0; r <= others; r++) p.robot_team.push_back(1 + r % 2);
    sim::World w(p, m, 1 + others, seed);
    sim::Renderer ren(p, seed);
    std::mt19937_64 rng(seed * 7919 + 17);
    auto rnd = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    FILE *f = fopen(out.c_str(), "wb");
    if (!f) throw std::runtime_error("cannot write " + out);
    put(f, "HRPBFRM1", 8);
    puti(f, p.cam_width);
    puti(f, p.cam_height);
    puti(f, count);
    puti(f, others);
    const std::vector<double> base = sim::stance_pose(m, p);
    std::vector<int> hide = {m.link_index("head_pan_link"), m.link_index("head_tilt_link")};
    const size_t n = (size_t)p.cam_width * p.cam_height * 2;
    std::vector<uint8_t> img(n), bare(n);
    std::vector<sim::Solid> solids;
    const double L = p.field_length / 2 + p.border - 0.2, Wd = p.field_width / 2 + p.border - 0.2;
    for (int k = 0; k < count; k++) {
      const double rx = rnd(-4.2, 4.2), ry = rnd(-2.8, 2.8), ryaw = rnd(-M_PI, M_PI);
      const double pan = rnd(-1.5, 1.5), tilt = rnd(-1.1, 0.3);
      std::vector<double> q = base;
      for (size_t j = 0; j < p.joints.size(); j++) {
        if (p.joints[j] == "head_pan") q[j] = pan;
        if (p.joints[j] == "head_tilt") q[j] = tilt;
      }
      w.place_robot(0, rx, ry, ryaw, q.data());
      // the ball: mostly where the head looks
      const bool look = rnd(0, 1) < 0.67;
      double bx, by;
      do {
        const double d = look ? 0.25 + 4.75 * std::pow(rnd(0, 1), 1.3) : rnd(0.3, 8);
        const double b = look ? pan + rnd(-0.45, 0.45) : rnd(-M_PI, M_PI);
        bx = rx + d * std::cos(ryaw + b);
        by = ry + d * std::sin(ryaw + b);
      } while (std::fabs(bx) > L || std::fabs(by) > Wd);
      w.place_ball(bx, by);
      const int nothers = (int)rnd(0, others + 0.999);
      for (int r = 1; r <= others; r++) {
        double ox = 30 + 3 * r, oy = 30;   // far off the carpet: not seen
        if (r <= nothers) {
          do {
            const double d = rnd(0.4, 4.0), b = pan + rnd(-0.8, 0.8);
            ox = rx + d * std::cos(ryaw + b);
            oy = ry + d * std::sin(ryaw + b);
          } while (std::fabs(ox) > L || std::fabs(oy) > Wd || std::hypot(ox - bx, oy - by) < 0.25);
        }
        w.place_robot(r, ox, oy, rnd(-M_PI, M_PI), base.data());
      }
      sim::Camera c;
      w.camera_pose(0, &c.pos, &c.rot);
      // walking: the torso's sway about the feet (rotation in the robot's heading frame), and its
      // turn rate during the exposure (the gait's period about 0.6 s: sway rate = amplitude * 2 pi / T)
      sim::Mat3 sway = sim::Mat3::Identity(), sway_start = sim::Mat3::Identity();
      sim::Mat3 est_err = sim::Mat3::Identity();
      if (walk) {
        const double phase = rnd(0, 2 * M_PI), T = 0.6, dt = ren.realism().exposure;
        auto sway_at = [&](double ph) {
          const double roll = 0.07 * std::sin(ph), pitch = 0.045 + 0.045 * std::sin(2 * ph);
          const sim::Mat3 head = Eigen::AngleAxisd(ryaw, sim::Vec3::UnitZ()).toRotationMatrix();
          return sim::Mat3(head * Eigen::AngleAxisd(roll, sim::Vec3::UnitX()).toRotationMatrix() *
                           Eigen::AngleAxisd(pitch, sim::Vec3::UnitY()).toRotationMatrix() * head.transpose());
        };
        sway = sway_at(phase);
        sway_start = sway_at(phase - 2 * M_PI * dt / T);
        const sim::Vec3 foot(rx, ry, 0);
        c.pos = foot + sway * (c.pos - foot) + sim::Vec3(0, 0, 0.01 * std::sin(2 * phase));
        c.rot = sway * c.rot;
        est_err = Eigen::AngleAxisd(rnd(-0.026, 0.026), sim::Vec3::UnitX()).toRotationMatrix() *
                  Eigen::AngleAxisd(rnd(-0.026, 0.026), sim::Vec3::UnitY()).toRotationMatrix();
      }
      c.width = p.cam_width;
      c.height = p.cam_height;
      c.fovy = p.cam_fovy;
      c.calibrate(p);
      w.solids(&solids);
      const sim::Vec3 ball = w.ball_position();
      sim::Shot shot = sim::shot_of(w, c, 0, &hide, (uint32_t)k);
      const sim::Vec3 axis = sim::Vec3(rnd(-1, 1), rnd(-1, 1), rnd(-1, 1)).normalized();
      shot.ball_rot = Eigen::AngleAxisd(rnd(-M_PI, M_PI), axis).toRotationMatrix();
      shot.time = rnd(0, 300);
      {
        const double exposure = ren.realism().exposure;
        const sim::Vec3 turn = sim::Vec3(rnd(-1, 1), rnd(-1, 1), rnd(-1, 1)).normalized();
        shot.cam_start = c;
        const sim::Mat3 swayed = sway_start * sway.transpose();   // the sway during the exposure
        shot.cam_start.rot = Eigen::AngleAxisd(-rnd(0, 4) * exposure, turn).toRotationMatrix() * swayed * c.rot;
        shot.cam_start.pos = c.pos - rnd(0, 0.3) * exposure * sim::Vec3(std::cos(ryaw), std::sin(ryaw), 0);
        shot.has_start = true;
      }
      ren.render(shot, solids, img.data());
      // the same frame without the ball: where they differ, the ball shows
      shot.ball = c.pos - 10 * c.rot.col(0);
      ren.render(shot, solids, bare.data());
      const sim::Truth t = w.truth(0);
      const double cy = std::cos(-t.yaw), sy = std::sin(-t.yaw);
      auto to_robot = [&](double x, double y, double *ox, double *oy) {
        *ox = cy * (x - t.x) - sy * (y - t.y);
        *oy = sy * (x - t.x) + cy * (y - t.y);
      };
      const double fl = c.fu();
      putd(f, fl);
      putd(f, c.pu() + 0.5);   // continuous coordinates
      putd(f, c.pv() + 0.5);
      double cxr, cyr;
      to_robot(c.pos.x(), c.pos.y(), &cxr, &cyr);
      putd(f, cxr);
      putd(f, cyr);
      // the pose the vision gets: the true one, or with the torso estimate's error when walking
      const sim::Mat3 Rr = est_err * Eigen::AngleAxisd(-t.yaw, sim::Vec3::UnitZ()).toRotationMatrix() * c.rot;
      for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) putd(f, Rr(i, j));
      putd(f, c.pos.z());
      double u = -1, v = -1, rad = 0, vis = 0;
      if (sim::camera_project(c, ball, &u, &v)) {
        u += 0.5;   // continuous coordinates
        v += 0.5;
        const double dist = (ball - c.pos).norm();
        rad = fl * w.ball_radius() / std::sqrt(std::max(1e-6, dist * dist - w.ball_radius() * w.ball_radius()));
        // the disc's pixels: how many are inside the image, and of those how many the ball drew
        int total = 0, shown = 0;
        for (int dv = (int)-rad; dv <= (int)rad; dv++)
          for (int du = (int)-rad; du <= (int)rad; du++) {
            if (du * du + dv * dv > rad * rad) continue;
            total++;
            const int pu = (int)std::floor(u + du), pv = (int)std::floor(v + dv);
            if (pu < 0 || pv < 0 || pu >= c.width || pv >= c.height) continue;
            const size_t o = ((size_t)pv * c.width + pu) * 2;
            if (img[o] != bare[o] || img[o + 1] != bare[o + 1]) shown++;
          }
        vis = total ? (double)shown / total : 0;
      }
      double bxr, byr;
      to_robot(ball.x(), ball.y(), &bxr, &byr);
      putd(f, u);
      putd(f, v);
      putd(f, rad);
      putd(f, std::hypot(bxr, byr));
      putd(f, std::atan2(byr, bxr));
      putd(f, vis);
      puti(f, nothers);
      for (int r = 1; r <= nothers; r++) {
        const sim::Truth o = w.truth(r);
        double oxr, oyr, ou = -1, ov = -1;
        to_robot(o.x, o.y, &oxr, &oyr);
        const bool in = in_frame(c, sim::Vec3(o.x, o.y, 0), &ou, &ov);
        putd(f, oxr);
        putd(f, oyr);
        putd(f, ou + 0.5);
        putd(f, ov + 0.5);
        putd(f, in ? 1 : 0);
        putd(f, p.robot_team[r]);
      }
      put(f, img.data(), n);
    }
    if (fclose(f) != 0) throw std::runtime_error("cannot write " + out);
  } catch (const std::exception &e) {
    fprintf(stderr, "sim_ball_frames: %s\n", e.what());
    return 1;
  }
  return 0;
}
