// sim_camera_frames: seeded scenes of the sim camera, each rendered by the clean camera and by the
// realistic one (sim.lua camera.realism's settings; effects.h), to PNGs and/or timed.
//   sim_camera_frames [--out DIR] [--scenes N] [--seed S] [--ball white|orange] [--montage FILE]
//                     [--montage-scene K] [--bench] [--only clean|realistic] [--raw FILE]
// A scene: four robots (two per team) and the ball on the field at seeded places, the camera of
// robot 0 with its head anywhere, turning during the exposure at up to 4 rad/s (a head scan; the
// camera pose at the exposure's start from the head angle then, as the DCM takes it from its pose
// history), at a seeded time (the exposure and white-balance drift). --out writes DIR/scene_NN.png:
// the clean frame on the left, the realistic one on the right. --montage writes one small PNG for
// the README: scene K's (default: the first with the ball well in view) clean | realistic frames at
// half size (640 x 240; the halving averages most of the noise away: the full frames show it).
// --bench prints the CPU time per frame of each camera (this thread's, so other load matters less).
// --only renders one camera's frames (the other's stay black): a profile of that camera alone
// (perf record build/bin/sim_camera_frames --scenes 400 --only realistic).
// --raw writes every scene's clean then realistic frame (YUYV, W x H x 2 bytes each) to FILE: two
// renderers' frames compared byte by byte (Tools/bench/camera_diff.py).
#include <time.h>

#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>

#include "render.h"
#include "stance.h"
#include "tool_args.h"
#include "world.h"
#include "yuyv_png.h"

namespace {

double thread_cpu() {
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

// Copies a w x h window at (u0, v0) of a W-wide YUYV image into dst at (du, dv) of a DW-wide one
// (u0, du even).
void blit(const uint8_t *src, int W, int u0, int v0, int w, int h, uint8_t *dst, int DW, int du, int dv) {
  for (int v = 0; v < h; v++) memcpy(dst + ((size_t)(dv + v) * DW + du) * 2, src + ((size_t)(v0 + v) * W + u0) * 2, (size_t)w * 2);
}

}  // namespace

int main(int argc, char **argv) {
  const char *out_arg = "", *montage_arg = "", *raw_arg = "";
  std::string ball_kind;
  int nscenes = 8, montage_scene = -1, bench = 0;
  const char *only_arg = "";
  long seed_arg = 1;
  const dcm_opt opts[] = {
      {"--out", DCM_OPT_STRING, &out_arg, 0, 0, "DIR", "DIR/scene_NN.png: clean | realistic", nullptr, 0},
      {"--scenes", DCM_OPT_INT, &nscenes, 1, 1e6, "N", "scenes (default 8)", nullptr, 0},
      {"--seed", DCM_OPT_LONG, &seed_arg, 0, (double)LONG_MAX, "S", "picks the scenes (default 1)", nullptr, 0},
      {"--ball", DCM_OPT_FUNC, &ball_kind, 0, 0, "white|orange", "the ball (default: the sim config's)",
       sim::parse_ball_kind, 0},
      {"--montage", DCM_OPT_STRING, &montage_arg, 0, 0, "FILE", "one half-size PNG of a scene", nullptr, 0},
      {"--montage-scene", DCM_OPT_INT, &montage_scene, 0, 1e6, "K",
       "the montage's scene (default: the first with the ball well in view)", nullptr, 0},
      {"--bench", DCM_OPT_FLAG, &bench, 0, 0, nullptr, "CPU time per frame of each camera", nullptr, 0},
      {"--raw", DCM_OPT_STRING, &raw_arg, 0, 0, "FILE", "every scene's clean and realistic YUYV frames", nullptr, 0},
      {"--only", DCM_OPT_STRING, &only_arg, 0, 0, "clean|realistic", "render one camera only (profiling)", nullptr, 0},
      DCM_OPT_END,
  };
  dcm_args("sim_camera_frames", "sim_camera_frames", opts, argc, argv);
  const std::string out = out_arg, montage = montage_arg, only = only_arg, raw = raw_arg;
  if (!only.empty() && only != "clean" && only != "realistic") {
    fprintf(stderr, "sim_camera_frames: --only takes clean or realistic, not '%s'\n", only_arg);
    return 2;
  }
  const bool do_clean = only != "realistic", do_real = only != "clean";
  const uint64_t seed = (uint64_t)seed_arg;
  try {
    sim::Params p;
    sim::Model m;
    sim::load_all(&p, &m, ball_kind);
    sim::Params pc = p, pr = p;
    pc.realism.on = false;
    pr.realism.on = true;
    sim::Renderer clean(pc, seed), real(pr, seed);
    sim::World w(p, m, 4, seed);
    const int W = p.cam_width, H = p.cam_height;
    std::vector<uint8_t> a((size_t)W * H * 2), b(a.size()), pair((size_t)2 * W * H * 2);
    std::vector<int> hide = {m.link_index("head_pan_link"), m.link_index("head_tilt_link")};
    const int cl = m.frame_index(p.camera_frame);
    if (cl >= 0) hide.push_back(m.frames[cl].link);
    int pan = -1, tilt = -1;
    for (size_t j = 0; j < p.joints.size(); j++) {
      if (p.joints[j] == "head_pan") pan = (int)j;
      if (p.joints[j] == "head_tilt") tilt = (int)j;
    }
    if (pan < 0 || tilt < 0) throw std::runtime_error("the body has no head_pan / head_tilt joints");
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0, 1);
    double t_clean = 0, t_real = 0;
    bool montage_done = montage.empty();
    std::vector<sim::Solid> solids;
    FILE *raw_f = nullptr;
    if (!raw.empty() && !(raw_f = fopen(raw.c_str(), "wb"))) throw std::runtime_error(raw + ": cannot write");
    for (int s = 0; s < nscenes; s++) {
      // robot 0 in its half looking roughly forward; the others and the ball 0.5..4 m ahead of it
      const double rx = -3.5 + 3 * U(rng), ry = -2.5 + 5 * U(rng), yaw = -0.8 + 1.6 * U(rng);
      std::vector<double> q = sim::stance_pose(m, p);
      q[pan] = -0.8 + 1.6 * U(rng);
      q[tilt] = -0.9 + 0.7 * U(rng);
      auto ahead = [&](double *x, double *y) {
        const double d = 0.5 + 3.5 * U(rng), b2 = yaw + q[pan] + (-0.5 + U(rng));
        *x = rx + d * std::cos(b2);
        *y = ry + d * std::sin(b2);
      };
      const double omega = 4 * U(rng) * (U(rng) < 0.5 ? -1 : 1);   // rad/s of head pan
      std::vector<double> q0 = q;
      q0[pan] -= omega * p.realism.exposure;
      w.place_robot(0, rx, ry, yaw, q0.data());
      sim::Camera c0;
      w.camera_pose(0, &c0.pos, &c0.rot);
      w.place_robot(0, rx, ry, yaw, q.data());
      for (int r = 1; r < 4; r++) {
        double x, y;
        ahead(&x, &y);
        w.place_robot(r, x, y, 2 * M_PI * U(rng), sim::stance_pose(m, p).data());
      }
      double bx, by;
      ahead(&bx, &by);
      w.place_ball(bx, by);
      sim::Camera c;
      w.camera_pose(0, &c.pos, &c.rot);
      c.calibrate(p);
      c0.width = c.width;
      c0.height = c.height;
      c0.calibrate(p);
      w.solids(&solids);
      sim::Shot sh = sim::shot_of(w, c, 0, &hide, (uint32_t)s);
      sh.time = 60 * U(rng);
      sh.cam_start = c0;
      sh.has_start = true;
      double t0 = thread_cpu();
      if (do_clean) clean.render(sh, solids, a.data());
      t_clean += thread_cpu() - t0;
      t0 = thread_cpu();
      if (do_real) real.render(sh, solids, b.data());
      t_real += thread_cpu() - t0;
      if (raw_f && (fwrite(a.data(), 1, a.size(), raw_f) != a.size() || fwrite(b.data(), 1, b.size(), raw_f) != b.size()))
        throw std::runtime_error(raw + ": write failed");
      if (!out.empty()) {
        blit(a.data(), W, 0, 0, W, H, pair.data(), 2 * W, 0, 0);
        blit(b.data(), W, 0, 0, W, H, pair.data(), 2 * W, W, 0);
        char name[64];
        snprintf(name, sizeof name, "/scene_%02d.png", s);
        std::string err;
        if (sim::yuyv_write_png(out + name, pair.data(), 2 * W, H, &err) < 0) throw std::runtime_error(err);
        printf("%s: robot (%.2f, %.2f, %.2f) head (%.2f, %.2f) turning %.1f rad/s, ball (%.2f, %.2f), t %.1f s\n",
               (out + name).c_str(), rx, ry, yaw, q[pan], q[tilt], omega, bx, by, sh.time);
      }
      double bu, bv;
      const bool ball_in = sim::camera_project(c, w.ball_position(), &bu, &bv) && bu > 40 && bu < W - 40 &&
                           bv > 40 && bv < H - 40;
      if (!montage_done && (montage_scene >= 0 ? s == montage_scene : ball_in)) {
        // both frames at half size, side by side: each output pixel the mean of 2 x 2
        const int mw = W / 2, mh = H / 2;
        std::vector<uint8_t> mon((size_t)2 * mw * mh * 2);
        for (int side = 0; side < 2; side++) {
          const uint8_t *f = side ? b.data() : a.data();
          for (int v = 0; v < mh; v++)
            for (int u = 0; u < mw; u += 2) {
              const uint8_t *p0 = f + ((size_t)(2 * v) * W + 2 * u) * 2, *p1 = p0 + (size_t)W * 2;
              uint8_t *o = mon.data() + ((size_t)v * 2 * mw + side * mw + u) * 2;
              o[0] = (uint8_t)((p0[0] + p0[2] + p1[0] + p1[2] + 2) / 4);
              o[2] = (uint8_t)((p0[4] + p0[6] + p1[4] + p1[6] + 2) / 4);
              o[1] = (uint8_t)((p0[1] + p0[5] + p1[1] + p1[5] + 2) / 4);
              o[3] = (uint8_t)((p0[3] + p0[7] + p1[3] + p1[7] + 2) / 4);
            }
        }
        std::string err;
        if (sim::yuyv_write_png(montage, mon.data(), 2 * mw, mh, &err) < 0) throw std::runtime_error(err);
        printf("%s: scene %d, clean | realistic at half size (%dx%d)\n", montage.c_str(), s, 2 * mw, mh);
        montage_done = true;
      }
    }
    if (raw_f && fclose(raw_f) != 0) throw std::runtime_error(raw + ": write failed");
    if (bench) {
      printf("camera %dx%d, %d scenes (4 robots, the ball, head turning up to 4 rad/s): CPU per frame clean "
             "%.2f ms, realistic %.2f ms (%+.2f ms, x%.2f)\n",
             W, H, nscenes, 1e3 * t_clean / nscenes, 1e3 * t_real / nscenes, 1e3 * (t_real - t_clean) / nscenes,
             t_real / t_clean);
    }
  } catch (const std::exception &e) {
    fprintf(stderr, "sim_camera_frames: %s\n", e.what());
    return 1;
  }
  return 0;
}
