// sim_bench_world: the world alone (no shared memory): one robot holding the stance, the ball,
// optionally the camera at its rate. Prints steps per second and the real-time factor.
//   sim_bench_world [SECONDS] [--no-camera] [--robots N]
#include <time.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "render.h"
#include "stance.h"
#include "world.h"

static double cpu_now() {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int main(int argc, char **argv) {
  double seconds = 20;
  bool camera = true;
  int nrobots = 1;
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "--no-camera")) camera = false;
    else if (!strcmp(argv[i], "--robots") && i + 1 < argc) nrobots = atoi(argv[++i]);
    else seconds = atof(argv[i]);
  }
  try {
    sim::Params p;
    sim::Model m;
    sim::load_all(&p, &m);
    sim::World w(p, m, nrobots, 1);
    std::vector<double> q = sim::stance_pose(p.joints);
    for (int r = 0; r < nrobots; r++) w.set_command(r, q.data(), nullptr, nullptr);
    w.reset();
    sim::Renderer ren(p, 1);
    std::vector<uint8_t> img((size_t)p.cam_width * p.cam_height * 2);
    std::vector<sim::Solid> solids;
    std::vector<int> hide = {m.link_index("head_pan_link"), m.link_index("head_tilt_link")};
    const int ticks = (int)(seconds / p.period);
    double next_frame = 0, render_s = 0;
    int frames = 0;
    auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_now();
    double render_cpu = 0;
    for (int t = 0; t < ticks; t++) {
      w.step();
      if (camera && w.time() >= next_frame) {
        next_frame += 1.0 / p.cam_rate;
        auto r0 = std::chrono::steady_clock::now();
        const double rc0 = cpu_now();
        w.solids(&solids);
        for (int r = 0; r < nrobots; r++) {
          sim::Camera c;
          w.camera_pose(r, &c.pos, &c.rot);
          c.width = p.cam_width;
          c.height = p.cam_height;
          c.fovy = p.cam_fovy;
          ren.render(c, solids, r, hide, w.ball_position(), w.ball_radius(), frames, img.data());
          frames++;
        }
        render_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - r0).count();
        render_cpu += cpu_now() - rc0;
      }
    }
    double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = cpu_now() - c0;
    sim::Truth tr = w.truth(0);
    printf("simulated %.1f s in %.2f s wall: real-time factor %.1f, %.0f physics steps/s, "
           "%d frames (%.2f ms each)\n",
           w.time(), wall, w.time() / wall, w.time() / p.timestep / wall, frames,
           frames ? 1e3 * render_s / frames : 0.0);
    printf("CPU time: %.2f s (real-time factor per CPU second %.1f): physics %.1f us per step, camera %.2f ms "
           "per frame\n", cpu, w.time() / cpu, 1e6 * (cpu - render_cpu) / (w.time() / p.timestep),
           frames ? 1e3 * render_cpu / frames : 0.0);
    printf("robot 0: x %.4f y %.4f z %.4f roll %.4f pitch %.4f yaw %.4f fallen %d\n", tr.x, tr.y, tr.z,
           tr.roll, tr.pitch, tr.yaw, tr.fallen);
    // the exact end state, to check that a speed-up leaves the physics bit for bit the same
    uint64_t sum = 1469598103934665603ull;   // FNV-1a of the last frame: renderer changes must keep it
    for (uint8_t b : img) sum = (sum ^ b) * 1099511628211ull;
    if (frames) printf("last frame: fnv1a %016llx\n", (unsigned long long)sum);
    printf("end state: %a %a %a %a %a %a ball %a %a %a\n", tr.x, tr.y, tr.z, tr.roll, tr.pitch, tr.yaw,
           tr.ball[0], tr.ball[1], tr.ball[2]);
  } catch (const std::exception &e) {
    fprintf(stderr, "sim_bench_world: %s\n", e.what());
    return 1;
  }
  return 0;
}
