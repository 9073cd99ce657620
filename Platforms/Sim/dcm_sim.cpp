// dcm_sim: the simulated robot's DCM. Serves dcm.sensor / dcm.actuator / dcm.stats / sync / sim /
// camera.image for every simulated robot (ROBOT_ID, ROBOT_ID+1, ...) from one ODE world.
//
//   dcm_sim [--lockstep] [--seed N] [--robots N | --ids A,B,..] [--duration SIM_SECONDS]
//           [--no-camera] [--report WALL_SECONDS] [--quiet] [--profile]
//
// Pacing: real time by default (absolute deadlines, one tick per control period). With --lockstep
// the DCM publishes dcm.sensor for tick N, sets sync.tick = N and wakes the participants, then waits
// until every live participant whose wake_tick <= N reports done_tick >= N (Lib/lockstep.lua), and
// only then reads dcm.actuator and steps: runs are deterministic and as fast as the machine allows.
// Sim requests (Lib/Sim.lua) are applied between ticks, also while waiting on participants.
//
// Camera: after the step to an exposure tick the physics thread takes a snapshot (camera pose, link
// poses, ball); once the tick is published the render thread (camera_worker.h) gets it, renders the
// frame and copies it into camera.image while the physics steps to the delivery tick. --profile
// prints at exit the wall time per tick of each phase and the CPU seconds per simulated second.
#include <signal.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "camera_worker.h"
#include "render.h"
#include "shm/shm.h"
#include "world.h"

namespace {

std::atomic<bool> g_stop{false};
// lockstep: how long the DCM polls for the participants' answer before it sleeps on the futex
const double kSpinSeconds = 100e-6;
void on_signal(int) { g_stop = true; }

struct Options {
  bool lockstep = false, camera = true, quiet = false, profile = false;
  uint64_t seed = 1;
  std::vector<int> ids;
  double duration = -1;
  double report = 5;
};

void usage() {
  fprintf(stderr,
          "usage: dcm_sim [--lockstep] [--seed N] [--robots N | --ids A,B,..] [--duration SIM_S]\n"
          "               [--no-camera] [--report WALL_S] [--quiet] [--profile]\n");
}

// Fields of one block, looked up once.
template <typename T>
T *req(shm_block *b, const char *field, int type, int count) {
  char err[256];
  void *p = shm_field_require(b, field, type, count, err, sizeof err);
  if (!p) throw std::runtime_error(err);
  return static_cast<T *>(p);
}

shm_block *open_block(const shm_schema *s, const char *name, int id) {
  shm_block *b = nullptr;
  char err[512];
  if (shm_block_open(s, name, id, SHM_OPEN_CREATE, &b, err, sizeof err) < 0) throw std::runtime_error(err);
  return b;
}

// A camera frame from its exposure to its delivery. The physics thread takes the snapshot at
// exposure; after publishing the tick it hands the frame to the render worker, which renders it and,
// while the physics steps to the delivery tick, copies it into camera.image.
struct Frame {
  uint32_t number;              // camera.image frame (1, 2, ... per robot)
  uint32_t deliver_tick;
  double time;                  // exposure
  double head[2];
  sim::CameraWorker::Job job;
  std::vector<uint8_t> img;
  uint64_t render = 0, copy = 0;   // the worker's tickets (0: not queued yet)
};

// One simulated robot's blocks.
struct RobotIO {
  int id = 0;
  shm_block *sensor = nullptr, *actuator = nullptr, *stats = nullptr, *sync = nullptr, *simb = nullptr,
            *cam = nullptr;
  // dcm.sensor
  double *s_time, *s_period, *s_pos, *s_vel, *s_load, *s_temp, *s_gyro, *s_acc, *s_angle, *s_foot, *s_batt;
  uint32_t *s_tick;
  int32_t *s_button, *s_pid;
  // dcm.actuator
  double *a_cmd, *a_hard;
  int32_t *a_en;
  uint32_t *a_ack;
  // dcm.stats
  double *st_rate, *st_rtf, *st_jp99, *st_jmax;
  uint32_t *st_cycles, *st_missed, *st_nan, *st_wd;
  // sync
  int32_t *y_lockstep, *y_pid;
  uint32_t *y_tick, *y_done_count, *y_wake, *y_done;
  int nsync = 0;
  // sim
  double *m_robot, *m_ball, *m_args, *m_rtf;
  int32_t *m_fallen, *m_score, *m_request;
  uint32_t *m_req_seq, *m_done_seq;
  // camera.image
  int32_t *c_w, *c_h;
  uint32_t *c_frame;
  double *c_time, *c_head;
  uint8_t *c_yuyv;
  size_t cam_bytes = 0;
  // state
  uint32_t last_ack = 0;
  double ack_time = 0;
  bool holding = false;
  uint32_t nan_count = 0, wd_trips = 0;
  double button_until[2] = {-1, -1};
  double next_frame = 0;
  uint32_t exposed = 0;
  std::deque<Frame> pending;
  std::vector<std::vector<uint8_t>> spare;   // image buffers of delivered frames, for reuse
};

double now() { return shm_now(); }

double cpu_seconds(clockid_t clock) {
  struct timespec ts;
  clock_gettime(clock, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

// --profile: wall time of each phase of a tick on the physics thread, and CPU time per simulated
// second (the figure that depends least on what else the machine is doing).
struct Profile {
  enum Phase { kWait, kCommands, kPhysics, kFrames, kExpose, kPublish, kHandOver, kCount };
  double sum[kCount] = {};
  double mark = 0;
  void start() { mark = now(); }
  void lap(Phase p) {
    const double t = now();
    sum[p] += t - mark;
    mark = t;
  }
  void print(uint32_t ticks, double sim_seconds) const {
    static const char *names[kCount] = {"wait for participants/clock", "commands", "physics", "deliver frames",
                                        "expose frames", "publish", "hand frames to the worker"};
    double total = 0;
    for (int k = 0; k < kCount; k++) total += sum[k];
    if (ticks == 0 || !(sim_seconds > 0) || !(total > 0)) return;
    printf("dcm_sim profile: %.2f s simulated in %.2f s wall (real-time factor %.2f); us per tick:", sim_seconds,
           total, sim_seconds / total);
    for (int k = 0; k < kCount; k++) printf("%s %s %.1f", k ? "," : "", names[k], 1e6 * sum[k] / ticks);
    printf("\n");
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    const double proc = ru.ru_utime.tv_sec + 1e-6 * ru.ru_utime.tv_usec + ru.ru_stime.tv_sec + 1e-6 * ru.ru_stime.tv_usec;
    const double main_cpu = cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
    printf("dcm_sim profile: CPU s per simulated s: %.4f (physics thread %.4f, camera thread %.4f)\n",
           proc / sim_seconds, main_cpu / sim_seconds, (proc - main_cpu) / sim_seconds);
    fflush(stdout);
  }
};

void open_robot(const shm_schema *schema, int id, int nj, const sim::Params &p, RobotIO *io) {
  io->id = id;
  io->sensor = open_block(schema, "dcm.sensor", id);
  io->actuator = open_block(schema, "dcm.actuator", id);
  io->stats = open_block(schema, "dcm.stats", id);
  io->sync = open_block(schema, "sync", id);
  io->simb = open_block(schema, "sim", id);
  io->cam = open_block(schema, "camera.image", id);
  shm_block *b = io->sensor;
  io->s_time = req<double>(b, "time", SHM_F64, 1);
  io->s_tick = req<uint32_t>(b, "tick", SHM_U32, 1);
  io->s_period = req<double>(b, "period", SHM_F64, 1);
  io->s_pos = req<double>(b, "position", SHM_F64, nj);
  io->s_vel = req<double>(b, "velocity", SHM_F64, nj);
  io->s_load = req<double>(b, "load", SHM_F64, nj);
  io->s_temp = req<double>(b, "temperature", SHM_F64, nj);
  io->s_gyro = req<double>(b, "gyro", SHM_F64, 3);
  io->s_acc = req<double>(b, "accelerometer", SHM_F64, 3);
  io->s_angle = req<double>(b, "angle", SHM_F64, 3);
  io->s_foot = req<double>(b, "foot_force", SHM_F64, 2);
  io->s_button = req<int32_t>(b, "button", SHM_I32, 2);
  io->s_batt = req<double>(b, "battery", SHM_F64, 1);
  io->s_pid = req<int32_t>(b, "dcm_pid", SHM_I32, 1);
  b = io->actuator;
  io->a_cmd = req<double>(b, "command", SHM_F64, nj);
  io->a_hard = req<double>(b, "hardness", SHM_F64, nj);
  io->a_en = req<int32_t>(b, "torque_enable", SHM_I32, nj);
  io->a_ack = req<uint32_t>(b, "tick_ack", SHM_U32, 1);
  b = io->stats;
  io->st_rate = req<double>(b, "rate", SHM_F64, 1);
  io->st_jp99 = req<double>(b, "jitter_p99", SHM_F64, 1);
  io->st_jmax = req<double>(b, "jitter_max", SHM_F64, 1);
  io->st_cycles = req<uint32_t>(b, "cycles", SHM_U32, 1);
  io->st_missed = req<uint32_t>(b, "missed_cycles", SHM_U32, 1);
  io->st_nan = req<uint32_t>(b, "nan_commands", SHM_U32, 1);
  io->st_wd = req<uint32_t>(b, "watchdog_trips", SHM_U32, 1);
  io->st_rtf = req<double>(b, "realtime_factor", SHM_F64, 1);
  b = io->sync;
  int type = 0;
  shm_field_ptr(b, "pid", &type, &io->nsync);
  io->y_lockstep = req<int32_t>(b, "lockstep", SHM_I32, 1);
  io->y_tick = req<uint32_t>(b, "tick", SHM_U32, 1);
  io->y_done_count = req<uint32_t>(b, "done_count", SHM_U32, 1);
  io->y_pid = req<int32_t>(b, "pid", SHM_I32, io->nsync);
  io->y_wake = req<uint32_t>(b, "wake_tick", SHM_U32, io->nsync);
  io->y_done = req<uint32_t>(b, "done_tick", SHM_U32, io->nsync);
  b = io->simb;
  io->m_robot = req<double>(b, "robot", SHM_F64, 6);
  io->m_fallen = req<int32_t>(b, "fallen", SHM_I32, 1);
  io->m_ball = req<double>(b, "ball", SHM_F64, 5);
  io->m_score = req<int32_t>(b, "score", SHM_I32, 2);
  io->m_req_seq = req<uint32_t>(b, "request_seq", SHM_U32, 1);
  io->m_request = req<int32_t>(b, "request", SHM_I32, 1);
  io->m_args = req<double>(b, "args", SHM_F64, 4);
  io->m_done_seq = req<uint32_t>(b, "done_seq", SHM_U32, 1);
  io->m_rtf = req<double>(b, "realtime_factor", SHM_F64, 1);
  b = io->cam;
  io->c_w = req<int32_t>(b, "width", SHM_I32, 1);
  io->c_h = req<int32_t>(b, "height", SHM_I32, 1);
  io->c_frame = req<uint32_t>(b, "frame", SHM_U32, 1);
  io->c_time = req<double>(b, "time", SHM_F64, 1);
  io->c_head = req<double>(b, "head", SHM_F64, 2);
  int count = 0;
  shm_field_ptr(b, "yuyv", &type, &count);
  io->cam_bytes = (size_t)p.cam_width * p.cam_height * 2;
  if ((size_t)count < io->cam_bytes) {
    throw std::runtime_error("camera.image: field 'yuyv' holds " + std::to_string(count) + " bytes, the sim camera needs " +
                             std::to_string(io->cam_bytes) + " (" + std::to_string(p.cam_width) + "x" +
                             std::to_string(p.cam_height) + " YUYV)");
  }
  io->c_yuyv = req<uint8_t>(b, "yuyv", SHM_U8, (int)io->cam_bytes);
}

// Reads dcm.actuator into the world (a torn read is retried; NaN/inf entries are ignored).
void read_actuator(sim::World &w, int r, RobotIO &io, int nj) {
  std::vector<double> cmd(nj), hard(nj);
  std::vector<int> en(nj);
  uint32_t ack = 0;
  for (int attempt = 0; attempt < 1000; attempt++) {
    uint32_t seq = shm_read_begin(io.actuator);
    memcpy(cmd.data(), io.a_cmd, nj * sizeof(double));
    memcpy(hard.data(), io.a_hard, nj * sizeof(double));
    for (int j = 0; j < nj; j++) en[j] = io.a_en[j];
    ack = *(volatile uint32_t *)io.a_ack;
    if (!shm_read_retry(io.actuator, seq)) break;
  }
  io.nan_count += (uint32_t)w.set_command(r, cmd.data(), hard.data(), en.data());
  if (ack != io.last_ack) {
    io.last_ack = ack;
    io.ack_time = w.time();
    io.holding = false;
  }
}

// Applies a pending sim request of robot r; returns true if one was applied.
bool apply_request(sim::World &w, int r, RobotIO &io) {
  const uint32_t seq = shm_load_acquire_u32(io.m_req_seq);
  if (seq == *(volatile uint32_t *)io.m_done_seq) return false;
  const double *a = io.m_args;
  bool ok = true;
  for (int k = 0; k < 4; k++) ok = ok && std::isfinite(a[k]);
  if (ok) {
    switch (*io.m_request) {
      case 1: w.reset(); break;
      case 2: w.place_robot(r, a[0], a[1], a[2]); break;
      case 3: w.place_ball(a[0], a[1], a[2], a[3]); break;
      case 4: w.push(r, a[0], a[1], a[2]); break;
      case 5:
        if (a[0] == 0 || a[0] == 1) io.button_until[(int)a[0]] = w.time() + a[1];
        break;
      default: break;
    }
  } else {
    io.nan_count++;
  }
  shm_store_release_u32(io.m_done_seq, seq);
  shm_futex_wake(io.m_done_seq);
  return true;
}

void publish_truth(sim::World &w, int r, RobotIO &io, double rtf) {
  sim::Truth t = w.truth(r);
  shm_write_begin(io.simb);
  const double rob[6] = {t.x, t.y, t.z, t.yaw, t.roll, t.pitch};
  memcpy(io.m_robot, rob, sizeof rob);
  *io.m_fallen = t.fallen;
  memcpy(io.m_ball, t.ball, sizeof t.ball);
  io.m_score[0] = w.score(0);
  io.m_score[1] = w.score(1);
  *io.m_rtf = rtf;
  shm_write_end(io.simb);
}

void publish_sensors(sim::World &w, int r, RobotIO &io, uint32_t tick, const sim::Params &p) {
  sim::Sensors s;
  w.sense(r, &s);
  const int nj = w.njoints();
  shm_write_begin(io.sensor);
  *io.s_time = tick * p.period;
  *io.s_tick = tick;
  *io.s_period = p.period;
  memcpy(io.s_pos, s.position.data(), nj * sizeof(double));
  memcpy(io.s_vel, s.velocity.data(), nj * sizeof(double));
  memcpy(io.s_load, s.load.data(), nj * sizeof(double));
  for (int j = 0; j < nj; j++) io.s_temp[j] = p.temperature;
  memcpy(io.s_gyro, s.gyro, sizeof s.gyro);
  memcpy(io.s_acc, s.accel, sizeof s.accel);
  memcpy(io.s_angle, s.angle, sizeof s.angle);
  memcpy(io.s_foot, s.foot_force, sizeof s.foot_force);
  for (int k = 0; k < 2; k++) io.s_button[k] = w.time() < io.button_until[k];
  *io.s_batt = p.battery;
  *io.s_pid = getpid();
  shm_write_end(io.sensor);
}

// Camera of robot r after the step to `tick`: if a frame is due, its snapshot (`scene` is taken
// once per tick for all robots) and its place in the queue of frames to deliver.
void expose(const sim::World &w, int r, RobotIO &x, uint32_t tick, double t_offset, const sim::Params &p,
            const std::vector<int> &head_idx, sim::Scene *scene, bool *have_scene) {
  if (w.time() + 1e-9 < x.next_frame) return;
  x.next_frame += 1.0 / p.cam_rate;
  if (!*have_scene) {
    w.snapshot(scene);
    *have_scene = true;
  }
  x.pending.emplace_back();
  Frame &f = x.pending.back();
  f.number = ++x.exposed;
  f.deliver_tick = tick + (uint32_t)std::max(0, p.cam_latency_ticks);
  f.time = t_offset + w.time();
  const std::vector<double> q = w.joint_positions(r);
  f.head[0] = head_idx[0] >= 0 ? q[head_idx[0]] : 0;
  f.head[1] = head_idx[1] >= 0 ? q[head_idx[1]] : 0;
  if (!x.spare.empty()) {
    // a buffer that is already mapped: no page faults and zeroing on the physics thread
    f.img = std::move(x.spare.back());
    x.spare.pop_back();
  }
  f.img.resize(x.cam_bytes);
  sim::CameraWorker::Job &j = f.job;
  w.camera_pose(r, &j.cam.pos, &j.cam.rot);
  j.cam.width = p.cam_width;
  j.cam.height = p.cam_height;
  j.cam.fovy = p.cam_fovy;
  j.scene = *scene;
  j.self = r;
  j.seq = f.number + 7919u * (uint32_t)r;
  j.out = f.img.data();
}

// Once tick `tick` is published: hands the new frames to the worker, and the frames due at the
// next tick, whose copy into camera.image the worker then makes while the physics steps. Called
// while the participants work on the tick, so its system calls cost the physics thread nothing.
void hand_over(sim::CameraWorker &wk, RobotIO &x, uint32_t tick) {
  for (Frame &f : x.pending) {
    if (!f.render) f.render = wk.submit(std::move(f.job));
    if (!f.copy && f.deliver_tick <= tick + 1) {
      // camera.image is written by this worker job only (the physics thread never touches it)
      f.copy = wk.post([&x, src = f.img.data(), n = f.number, t = f.time, h0 = f.head[0], h1 = f.head[1]] {
        shm_write_begin(x.cam);
        memcpy(x.c_yuyv, src, x.cam_bytes);
        *x.c_time = t;
        x.c_head[0] = h0;
        x.c_head[1] = h1;
        *x.c_frame = n;
        shm_write_end(x.cam);
      });
    }
  }
}

// Returns once every frame due at `tick` is in camera.image (before the tick's sensors appear).
void deliver(sim::CameraWorker &wk, RobotIO &x, uint32_t tick) {
  while (!x.pending.empty() && x.pending.front().deliver_tick <= tick) {
    Frame &f = x.pending.front();
    if (!f.copy) hand_over(wk, x, tick - 1);   // not handed over yet (no latency)
    wk.wait(f.copy);
    x.spare.push_back(std::move(f.img));   // copied: the worker is done with it
    x.pending.pop_front();
  }
}

}  // namespace

int main(int argc, char **argv) {
  Options o;
  int nrobots = 1;
  for (int i = 1; i < argc; i++) {
    std::string a = argv[i];
    auto next = [&]() -> const char * {
      if (i + 1 >= argc) {
        fprintf(stderr, "dcm_sim: %s needs a value\n", a.c_str());
        exit(2);
      }
      return argv[++i];
    };
    if (a == "--lockstep") o.lockstep = true;
    else if (a == "--seed") o.seed = strtoull(next(), nullptr, 10);
    else if (a == "--robots") nrobots = atoi(next());
    else if (a == "--ids") {
      std::string s = next();
      for (size_t k = 0; k < s.size();) {
        size_t e = s.find(',', k);
        o.ids.push_back(atoi(s.substr(k, e - k).c_str()));
        k = e == std::string::npos ? s.size() : e + 1;
      }
    } else if (a == "--duration") o.duration = atof(next());
    else if (a == "--no-camera") o.camera = false;
    else if (a == "--report") o.report = atof(next());
    else if (a == "--quiet") o.quiet = true;
    else if (a == "--profile") o.profile = true;
    else if (a == "-h" || a == "--help") {
      usage();
      return 0;
    } else {
      fprintf(stderr, "dcm_sim: unknown argument '%s'\n", a.c_str());
      usage();
      return 2;
    }
  }
  if (o.ids.empty()) {
    if (nrobots < 1) {
      fprintf(stderr, "dcm_sim: --robots must be at least 1\n");
      return 2;
    }
    for (int k = 0; k < nrobots; k++) o.ids.push_back(shm_robot_id() + k);
  }
  signal(SIGINT, on_signal);
  signal(SIGTERM, on_signal);

  sim::Params p;
  sim::Model m;
  std::unique_ptr<sim::World> world;
  std::unique_ptr<sim::Renderer> ren;
  std::vector<RobotIO> io(o.ids.size());
  shm_schema *schema = nullptr;
  try {
    sim::load_all(&p, &m);
    world.reset(new sim::World(p, m, (int)o.ids.size(), o.seed));
    ren.reset(new sim::Renderer(p, o.seed));
    char err[512];
    if (shm_schema_load(nullptr, &schema, err, sizeof err) < 0) throw std::runtime_error(err);
    const int nj = world->njoints();
    const long sj = shm_schema_const(schema, "njoint");
    if (sj < nj) {
      throw std::runtime_error("robot config has " + std::to_string(nj) + " joints, the shm schema's njoint is only " +
                               std::to_string(sj));
    }
    for (size_t r = 0; r < io.size(); r++) open_robot(schema, o.ids[r], nj, p, &io[r]);
  } catch (const std::exception &e) {
    fprintf(stderr, "dcm_sim: %s\n", e.what());
    return 2;
  }
  sim::World &w = *world;
  const int nj = w.njoints();

  // Start: the robot holds what the actuator block says; a block nobody has written yet gets the
  // zero pose at full hardness, so a fresh sim shows a standing robot.
  uint32_t tick = 0;
  for (size_t r = 0; r < io.size(); r++) {
    RobotIO &x = io[r];
    bool blank = shm_block_header(x.actuator)->writes == 0;
    for (int j = 0; j < nj && blank; j++) blank = x.a_hard[j] == 0 && x.a_en[j] == 0 && x.a_cmd[j] == 0;
    if (blank) {
      shm_write_begin(x.actuator);
      for (int j = 0; j < nj; j++) {
        x.a_cmd[j] = 0;
        x.a_hard[j] = 1;
        x.a_en[j] = 1;
      }
      shm_write_end(x.actuator);
    }
    read_actuator(w, (int)r, x, nj);
    // continue the robot's clock across DCM restarts: participants keep counting ticks
    tick = std::max(tick, std::max(*x.s_tick, *x.y_tick));
    tick = std::max(tick, 1u);   // tick 0 never appears: a participant joining at 0 holds tick 0 - 1
    *x.m_done_seq = *x.m_req_seq;
  }
  w.reset();
  const double t_offset = tick * p.period;
  for (size_t r = 0; r < io.size(); r++) {
    RobotIO &x = io[r];
    x.ack_time = 0;
    x.next_frame = 0;
    *x.c_w = p.cam_width;
    *x.c_h = p.cam_height;
    shm_write_begin(x.stats);
    *x.st_cycles = 0;
    *x.st_missed = 0;
    *x.st_nan = 0;
    *x.st_wd = 0;
    shm_write_end(x.stats);
    // a participant registered with an old DCM: consult it from the first tick on
    for (int k = 0; k < x.nsync; k++) {
      if (x.y_pid[k] != 0 && x.y_wake[k] != 0xffffffffu && x.y_wake[k] > tick) x.y_wake[k] = tick;
    }
    publish_sensors(w, (int)r, x, tick, p);
    publish_truth(w, (int)r, x, 0);
    *x.y_lockstep = o.lockstep ? 1 : 0;
  }
  if (!o.quiet) {
    printf("dcm_sim: %zu robot(s) (ids", io.size());
    for (int id : o.ids) printf(" %d", id);
    printf("), %s, seed %llu, physics %.1f ms x %d per %.0f ms tick, camera %s\n",
           o.lockstep ? "lockstep" : "real time", (unsigned long long)o.seed, p.timestep * 1e3,
           (int)std::lround(p.period / p.timestep), p.period * 1e3,
           o.camera ? (std::to_string(p.cam_width) + "x" + std::to_string(p.cam_height) + " @ " +
                       std::to_string((int)p.cam_rate) + " Hz").c_str()
                    : "off");
    fflush(stdout);
  }

  std::unique_ptr<sim::CameraWorker> worker;
  if (o.camera) {
    std::vector<int> hide = {m.link_index("head_pan_link"), m.link_index("head_tilt_link")};
    int cl = m.frame_index(p.camera_frame);
    if (cl >= 0) hide.push_back(m.frames[cl].link);
    worker.reset(new sim::CameraWorker(w, *ren, hide));
  }
  std::vector<int> head_idx = {-1, -1};
  for (int j = 0; j < nj; j++) {
    if (p.joints[j] == "head_pan") head_idx[0] = j;
    if (p.joints[j] == "head_tilt") head_idx[1] = j;
  }

  const double wall0 = now();
  double report_wall = wall0, report_sim = 0;
  uint32_t report_tick = tick;
  double rtf = 0, rate = 0, last_jp99 = 0, last_jmax = 0;
  std::vector<double> jitter;
  double deadline = wall0;
  uint32_t cycles = 0, missed = 0;
  uint32_t dropped = 0;
  Profile prof;
  const double sim0 = w.time();

  while (!g_stop) {
    prof.start();
    // ---- wait: lockstep participants or the wall clock
    if (o.lockstep) {
      for (size_t r = 0; r < io.size(); r++) {
        RobotIO &x = io[r];
        shm_store_release_u32(x.y_tick, tick);
        shm_futex_wake(x.y_tick);
      }
      prof.lap(Profile::kPublish);
      for (RobotIO &x : io)
        if (worker) hand_over(*worker, x, tick);
      prof.lap(Profile::kHandOver);
      // no participant anywhere: hold the clock until one joins (a lockstep run starts on a
      // defined tick and burns no CPU meanwhile)
      for (;;) {
        bool any = false;
        for (size_t r = 0; r < io.size() && !any; r++) {
          for (int k = 0; k < io[r].nsync && !any; k++) {
            const int pid = __atomic_load_n(&io[r].y_pid[k], __ATOMIC_ACQUIRE);
            // one that answered the last tick needs no system call to prove it is alive
            const bool answered = __atomic_load_n(&io[r].y_done[k], __ATOMIC_ACQUIRE) + 1 >= tick;
            if (pid != 0 && (answered || shm_pid_alive(pid))) any = true;
          }
        }
        if (any || g_stop) break;
        for (size_t r = 0; r < io.size(); r++) {
          while (apply_request(w, (int)r, io[r])) publish_truth(w, (int)r, io[r], rtf);
        }
        shm_futex_wait(io[0].y_done_count, shm_load_acquire_u32(io[0].y_done_count), 0.02);
        prof.start();   // time without any participant is not the DCM's
      }
      for (size_t r = 0; r < io.size() && !g_stop; r++) {
        RobotIO &x = io[r];
        double since = now();
        for (;;) {
          while (apply_request(w, (int)r, x)) publish_truth(w, (int)r, x, rtf);
          const uint32_t c = shm_load_acquire_u32(x.y_done_count);
          int pending = -1;
          for (int k = 0; k < x.nsync; k++) {
            const int pid = __atomic_load_n(&x.y_pid[k], __ATOMIC_ACQUIRE);
            if (pid == 0) continue;
            if (__atomic_load_n(&x.y_wake[k], __ATOMIC_ACQUIRE) > tick) continue;
            if (__atomic_load_n(&x.y_done[k], __ATOMIC_ACQUIRE) >= tick) continue;
            pending = k;
            break;
          }
          if (pending < 0 || g_stop) break;
          if (now() - since > 0.2) {
            // drop participants that died without leaving
            for (int k = 0; k < x.nsync; k++) {
              const int pid = x.y_pid[k];
              if (pid != 0 && !shm_pid_alive(pid) && shm_cas_i32(&x.y_pid[k], pid, 0)) dropped++;
            }
            since = now();
          }
          // the participants usually answer within tens of microseconds: poll a little before
          // sleeping, which saves the DCM's own wake-up latency on every tick
          const double spin_until = now() + kSpinSeconds;
          while (shm_load_acquire_u32(x.y_done_count) == c && now() < spin_until) {
            for (int k = 0; k < 64; k++) __builtin_ia32_pause();
          }
          if (shm_load_acquire_u32(x.y_done_count) == c) shm_futex_wait(x.y_done_count, c, 0.05);
        }
      }
    } else {
      for (RobotIO &x : io)
        if (worker) hand_over(*worker, x, tick);
      prof.lap(Profile::kHandOver);
      deadline += p.period;
      double late = now() - deadline;
      if (late < 0) {
        struct timespec ts;
        ts.tv_sec = (time_t)deadline;
        ts.tv_nsec = (long)((deadline - (double)ts.tv_sec) * 1e9);
        while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR && !g_stop) {}
        late = now() - deadline;
      }
      jitter.push_back(std::fabs(late));
      if (late > p.period) {
        missed++;
        if (late > 0.1) deadline = now();   // far behind (stopped, overloaded): do not race to catch up
      }
    }
    if (g_stop) break;
    prof.lap(Profile::kWait);

    // ---- commands and requests, then one control period of physics
    for (size_t r = 0; r < io.size(); r++) {
      RobotIO &x = io[r];
      read_actuator(w, (int)r, x, nj);
      // real time: a Lua side that stopped answering leaves the last commands in place, so the
      // robot holds its pose; the trip is counted once per silence
      if (!o.lockstep && !x.holding && x.last_ack != 0 && w.time() - x.ack_time > p.watchdog) {
        x.holding = true;
        x.wd_trips++;
      }
      while (apply_request(w, (int)r, x)) {}
    }
    prof.lap(Profile::kCommands);
    w.step();
    tick++;
    cycles++;
    prof.lap(Profile::kPhysics);

    // ---- camera: expose now, deliver latency_ticks later
    if (worker) {
      bool have_scene = false;
      sim::Scene scene;
      for (size_t r = 0; r < io.size(); r++) expose(w, (int)r, io[r], tick, t_offset, p, head_idx, &scene, &have_scene);
      prof.lap(Profile::kExpose);
      for (RobotIO &x : io) deliver(*worker, x, tick);
      prof.lap(Profile::kFrames);
    }

    // ---- publish: truth (and frames, above) before the sensors, so that a process woken by the
    // new sensor tick finds everything else of that tick in place
    for (size_t r = 0; r < io.size(); r++) {
      publish_truth(w, (int)r, io[r], rtf);
      publish_sensors(w, (int)r, io[r], tick, p);
    }

    // ---- statistics and the real-time factor
    const double t = now();
    if (t - report_wall >= std::min(1.0, o.report) || (o.duration >= 0 && w.time() >= o.duration - 1e-9)) {
      const double sim_dt = w.time() - report_sim;
      rtf = sim_dt / (t - report_wall);
      rate = (tick - report_tick) / (t - report_wall);
      double jp99 = 0, jmax = 0;
      if (!jitter.empty()) {
        std::sort(jitter.begin(), jitter.end());
        jp99 = jitter[(size_t)(0.99 * (jitter.size() - 1))];
        jmax = jitter.back();
        jitter.clear();
      }
      static double last_print = wall0;
      static double print_sim = 0;
      if (!o.quiet && (t - last_print >= o.report)) {
        printf("dcm_sim: sim time %.1f s, real-time factor %.2f (%.1f ticks/s)%s\n", w.time(),
               (w.time() - print_sim) / (t - last_print), rate, dropped ? " (participants dropped)" : "");
        fflush(stdout);
        last_print = t;
        print_sim = w.time();
      }
      last_jp99 = jp99;
      last_jmax = jmax;
      report_wall = t;
      report_sim = w.time();
      report_tick = tick;
    }
    for (size_t r = 0; r < io.size(); r++) {
      RobotIO &x = io[r];
      shm_write_begin(x.stats);
      *x.st_rate = rate;
      *x.st_rtf = rtf;
      *x.st_jp99 = last_jp99;
      *x.st_jmax = last_jmax;
      *x.st_cycles = cycles;
      *x.st_missed = missed;
      *x.st_nan = x.nan_count;
      *x.st_wd = x.wd_trips;
      shm_write_end(x.stats);
    }
    prof.lap(Profile::kPublish);
    if (o.duration >= 0 && w.time() >= o.duration - 1e-9) break;
  }

  const double wall = now() - wall0;
  if (o.profile) prof.print(cycles, w.time() - sim0);
  if (!o.quiet) {
    printf("dcm_sim: stopped at sim time %.3f s after %.2f s wall: real-time factor %.2f\n", w.time(), wall,
           wall > 0 ? w.time() / wall : 0.0);
  }
  worker.reset();   // finishes what it was given (renders into x.pending, copies into camera.image)
  for (RobotIO &x : io) {
    *x.y_lockstep = 0;
    shm_futex_wake(x.y_tick);
    x.pending.clear();
    shm_block *bs[] = {x.sensor, x.actuator, x.stats, x.sync, x.simb, x.cam};
    for (shm_block *b : bs) shm_block_close(b);
  }
  shm_schema_free(schema);
  return 0;
}
