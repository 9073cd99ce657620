// sim_bench_world: the world alone (no shared memory): one robot holding the stance, the ball,
// optionally the camera at its rate. Prints steps per second and the real-time factor.
// The camera renders on a worker thread as in the DCM (exposed at one tick, waited for
// camera.latency_ticks later), or with --inline-camera on the physics thread at the exposure tick;
// both print the same checksum of the last frame.
//   sim_bench_world [SECONDS] [--no-camera | --inline-camera] [--robots N]
#include <time.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <deque>
#include <stdexcept>

#include "camera_worker.h"
#include "render.h"
#include "stance.h"
#include "world.h"

static double clock_s(clockid_t id) {
  struct timespec ts;
  clock_gettime(id, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}
static double cpu_now() { return clock_s(CLOCK_PROCESS_CPUTIME_ID); }          // all threads
static double thread_cpu_now() { return clock_s(CLOCK_THREAD_CPUTIME_ID); }    // this thread

int main(int argc, char **argv) {
  double seconds = 20;
  bool camera = true, inline_camera = false;
  int nrobots = 1;
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "--no-camera")) camera = false;
    else if (!strcmp(argv[i], "--inline-camera")) inline_camera = true;
    else if (!strcmp(argv[i], "--robots") && i + 1 < argc) nrobots = atoi(argv[++i]);
    else seconds = atof(argv[i]);
  }
  try {
    sim::Params p;
    sim::Model m;
    sim::load_all(&p, &m);
    sim::World w(p, m, nrobots, 1);
    std::vector<double> q = sim::stance_pose(m, p);
    for (int r = 0; r < nrobots; r++) w.set_command(r, q.data(), nullptr, nullptr);
    w.reset();
    sim::Renderer ren(p, 1);
    const size_t bytes = (size_t)p.cam_width * p.cam_height * 2;
    std::vector<sim::Solid> solids;
    std::vector<int> hide = {m.link_index("head_pan_link"), m.link_index("head_tilt_link")};
    const int cl = m.frame_index(p.camera_frame);
    if (cl >= 0) hide.push_back(m.frames[cl].link);
    std::unique_ptr<sim::CameraWorker> worker;
    if (camera && !inline_camera) worker.reset(new sim::CameraWorker(w, ren, hide));
    // frame buffers in a ring, enough for every frame in flight (exposed, not yet delivered)
    const int latency = std::max(0, p.cam_latency_ticks);
    const int in_flight = nrobots * (2 + (int)(latency * p.period * p.cam_rate));
    std::vector<std::vector<uint8_t>> bufs(in_flight, std::vector<uint8_t>(bytes));
    struct Pending { int deliver_tick; uint64_t ticket; };
    std::deque<Pending> pending;
    const int ticks = (int)(seconds / p.period);
    double next_frame = 0, render_s = 0, camera_main_cpu = 0;
    int frames = 0;
    uint8_t *last_img = nullptr;
    auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_now(), m0 = thread_cpu_now();
    for (int t = 0; t < ticks; t++) {
      w.step();
      if (!camera) continue;
      auto r0 = std::chrono::steady_clock::now();
      const double rc0 = thread_cpu_now();
      while (!pending.empty() && pending.front().deliver_tick <= t + 1) {
        worker->wait(pending.front().ticket);   // delivery: the frame must be rendered by now
        pending.pop_front();
      }
      if (w.time() >= next_frame) {
        next_frame += 1.0 / p.cam_rate;
        sim::Scene scene;
        if (worker) w.snapshot(&scene);
        else w.solids(&solids);
        for (int r = 0; r < nrobots; r++) {
          sim::Camera c;
          w.camera_pose(r, &c.pos, &c.rot);
          c.width = p.cam_width;
          c.height = p.cam_height;
          c.fovy = p.cam_fovy;
          last_img = bufs[frames % in_flight].data();
          if (worker) {
            sim::CameraWorker::Job j;
            j.cam = c;
            j.scene = scene;
            j.self = r;
            j.seq = (uint32_t)frames;
            j.out = last_img;
            pending.push_back({t + 1 + latency, worker->submit(std::move(j))});
          } else {
            ren.render(sim::shot_of(w, c, r, &hide, (uint32_t)frames), solids, last_img);
          }
          frames++;
        }
      }
      render_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - r0).count();
      camera_main_cpu += thread_cpu_now() - rc0;
    }
    if (!pending.empty()) worker->wait(pending.back().ticket);
    double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = cpu_now() - c0, main_cpu = thread_cpu_now() - m0;
    const double steps = w.time() / p.timestep;
    sim::Truth tr = w.truth(0);
    printf("simulated %.1f s in %.2f s wall: real-time factor %.1f, %.0f physics steps/s, %d frames (%s)\n",
           w.time(), wall, w.time() / wall, steps / wall, frames,
           !camera ? "no camera" : worker ? "rendered on a worker thread" : "rendered on the physics thread");
    // the physics thread's camera share is the snapshot and hand-over (threaded) or everything (inline)
    printf("CPU time: %.2f s (%.4f s per simulated s): physics %.1f us per step; camera %.2f ms per frame "
           "(%.3f ms of it on the physics thread, %.2f ms wall there)\n",
           cpu, cpu / w.time(), 1e6 * (main_cpu - camera_main_cpu) / steps,
           frames ? 1e3 * (cpu - main_cpu + camera_main_cpu) / frames : 0.0,
           frames ? 1e3 * camera_main_cpu / frames : 0.0, frames ? 1e3 * render_s / frames : 0.0);
    printf("robot 0: x %.4f y %.4f z %.4f roll %.4f pitch %.4f yaw %.4f fallen %d\n", tr.x, tr.y, tr.z,
           tr.roll, tr.pitch, tr.yaw, tr.fallen);
    // the exact end state, to check that a speed-up leaves the physics bit for bit the same
    uint64_t sum = 1469598103934665603ull;   // FNV-1a of the last frame: renderer changes must keep it
    for (size_t i = 0; last_img && i < bytes; i++) sum = (sum ^ last_img[i]) * 1099511628211ull;
    if (frames) printf("last frame: fnv1a %016llx\n", (unsigned long long)sum);
    printf("end state: %a %a %a %a %a %a ball %a %a %a\n", tr.x, tr.y, tr.z, tr.roll, tr.pitch, tr.yaw,
           tr.ball[0], tr.ball[1], tr.ball[2]);
  } catch (const std::exception &e) {
    fprintf(stderr, "sim_bench_world: %s\n", e.what());
    return 1;
  }
  return 0;
}
