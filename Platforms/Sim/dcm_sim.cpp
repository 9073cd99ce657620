// dcm_sim: the simulated robots' DCM. Serves dcm.sensor / dcm.actuator / dcm.stats / sync / sim /
// camera.image for every simulated robot (ROBOT_ID, ROBOT_ID+1, ...) from one ODE world.
//
//   dcm_sim [--lockstep] [--lockstep-wait N] [--seed N] [--robots N | --robots BODY,BODY,..] [--ids A,B,..]
//           [--duration SIM_SECONDS] [--no-camera] [--report WALL_SECONDS] [--quiet] [--profile]
//
// Robots: --robots N puts N robots of the body $ROBOT into the world; --robots op3,darwin one robot
// of each named body (Config/robots/<BODY>), with its own description and config. Their ids are
// ROBOT_ID, ROBOT_ID+1, ... or those of --ids (as many as bodies).
//
// A driver of the DCM library (Modules/dcm): the library paces the ticks (real time: absolute
// deadlines; --lockstep: it publishes tick N and waits for every live participant of Lib/lockstep.lua;
// --lockstep-wait N: the same, and the first tick waits until N participants have joined, so that a
// scenario run by processes that start at different moments starts on the same tick every time),
// reads and checks the commands (watchdog in real time) and writes dcm.sensor and dcm.stats; this file
// drives the world: commands in, one control period of physics, sensors and truth out, camera
// frames. Sim requests (Lib/Sim.lua) are applied between ticks, also while waiting on participants.
// --profile prints at exit the wall time per tick of each phase and the CPU seconds per simulated
// second.
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "camera_worker.h"
#include "dcm/args.h"
#include "dcm/dcm.h"
#include "frames.h"
#include "render.h"
#include "world.h"

namespace {

struct Options {
  int no_camera = 0, profile = 0;
  uint64_t seed = 1;
  int nrobots = 1;                   // --robots N (robots of the body $ROBOT)
  std::vector<int> ids;
  std::vector<std::string> bodies;   // per robot ("": $ROBOT)
  double duration = -1;
  double report = 5;
};

// "a,b,c" -> {"a", "b", "c"}
std::vector<std::string> split(const std::string &l) {
  std::vector<std::string> v;
  for (size_t k = 0; k < l.size();) {
    size_t e = l.find(',', k);
    v.push_back(l.substr(k, e == std::string::npos ? std::string::npos : e - k));
    k = e == std::string::npos ? l.size() : e + 1;
  }
  return v;
}

// --seed N
int parse_seed(const char *v, void *out, char *err, size_t n) {
  long seed;
  if (dcm_args_long(v, 0, LONG_MAX, &seed, err, n) < 0) return -EINVAL;
  *static_cast<uint64_t *>(out) = (uint64_t)seed;
  return 0;
}

// --robots N | BODY,BODY,..: a number is a count of robots of the body $ROBOT, else the bodies
int parse_robots(const char *v, void *out, char *err, size_t n) {
  Options &o = *static_cast<Options *>(out);
  if (!std::isdigit((unsigned char)v[0])) {
    o.bodies = split(v);
    return 0;
  }
  long k;
  if (dcm_args_long(v, 1, DCM_ROBOTS_MAX, &k, err, n) < 0) return -EINVAL;
  o.nrobots = (int)k;
  return 0;
}

// --ids A,B,..: the robots' ids, in the order of the bodies
int parse_ids(const char *v, void *out, char *err, size_t n) {
  std::vector<int> &ids = *static_cast<std::vector<int> *>(out);
  for (const std::string &id : split(v)) {
    long k;
    if (dcm_args_long(id.c_str(), 1, INT_MAX, &k, err, n) < 0) return -EINVAL;
    ids.push_back((int)k);
  }
  return 0;
}

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
  void start() { mark = shm_now(); }
  void lap(Phase p) {
    const double t = shm_now();
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

// What the sim adds to a robot beyond the library's blocks.
struct SimRobot {
  dcm_blk_sim sim = {};
  sim::FrameQueue frames;
  std::vector<int> hide;           // its links its camera does not see (its head)
  int head[2] = {-1, -1};          // shm index of head_pan / head_tilt (-1: none)
  double button_until[2] = {-1, -1};
  uint32_t refused = 0;            // Sim requests with NaN / inf arguments
};

// The driver's state: the world and everything around it.
struct Sim {
  Options o;
  std::vector<sim::Params> params;   // per robot; the world's own numbers are robot 0's
  std::vector<sim::Body> bodies;
  std::unique_ptr<sim::World> world;
  std::unique_ptr<sim::Renderer> ren;
  std::unique_ptr<sim::CameraWorker> worker;
  std::vector<SimRobot> rob;
  Profile prof;
  double sim0 = 0, wall0 = 0, rtf = 0;
  double last_print = 0, print_sim = 0;
  sim::Sensors sensors;
};

// Request 6 of robot r: the field-frame pose of the link or frame that link_name names into
// link_pose, link_status 0; 1 if the body has none of that name, 2 if its pose is not finite (a
// world that blew up: no NaN is handed out).
void answer_link_truth(Sim &s, int r) {
  const dcm_blk_sim &b = s.rob[r].sim;
  const size_t cap = (size_t)b.n.link_name;
  std::string name;
  for (size_t k = 0; k < cap && b.link_name[k]; k++) name += (char)b.link_name[k];
  sim::Vec3 p = sim::Vec3::Zero();
  sim::Mat3 R = sim::Mat3::Identity();
  const bool found = s.world->frame_pose(r, name, &p, &R);
  const double pose[6] = {p.x(), p.y(), p.z(), std::atan2(R(2, 1), R(2, 2)),
                          std::asin(std::min(1.0, std::max(-1.0, -R(2, 0)))), std::atan2(R(1, 0), R(0, 0))};
  bool finite = true;
  for (double v : pose) finite = finite && std::isfinite(v);
  shm_write_begin(b.blk);
  *b.link_status = !found ? 1 : !finite ? 2 : 0;
  if (found && finite) memcpy(b.link_pose, pose, sizeof pose);
  shm_write_end(b.blk);
}

// Request 7: a force (args fx, fy, fz N, field frame; duration s) at the link or frame link_name;
// link_status says whether the body has it (0) or not (1).
void push_link(Sim &s, int r, const double *a) {
  const dcm_blk_sim &b = s.rob[r].sim;
  const size_t cap = (size_t)b.n.link_name;
  std::string name;
  for (size_t k = 0; k < cap && b.link_name[k]; k++) name += (char)b.link_name[k];
  const bool found = a[3] >= 0 && s.world->push_link(r, name, a[0], a[1], a[2], a[3]);
  shm_write_begin(b.blk);
  *b.link_status = found ? 0 : 1;
  shm_write_end(b.blk);
}

// The body's links (its root first) and frames, space-separated, into link_names; as many whole
// names as the field holds.
void publish_link_names(const SimRobot &x, const sim::Model &m) {
  std::string all;
  auto add = [&](const std::string &n) {
    const std::string more = (all.empty() ? "" : " ") + n;
    if (all.size() + more.size() < (size_t)x.sim.n.link_names) all += more;   // room for the NUL
  };
  for (const sim::Link &l : m.links) add(l.name);
  for (const sim::Frame &f : m.frames) add(f.name);
  shm_write_begin(x.sim.blk);
  memset(x.sim.link_names, 0, (size_t)x.sim.n.link_names);
  memcpy(x.sim.link_names, all.data(), all.size());
  shm_write_end(x.sim.blk);
}

// Applies a pending sim request of robot r; returns true if one was applied.
bool apply_request(Sim &s, int r) {
  SimRobot &x = s.rob[r];
  sim::World &w = *s.world;
  const uint32_t seq = shm_load_acquire_u32(x.sim.request_seq);
  if (seq == *(volatile uint32_t *)x.sim.done_seq) return false;
  const double *a = x.sim.args;
  bool ok = true;
  for (int k = 0; k < 4; k++) ok = ok && std::isfinite(a[k]);
  if (ok) {
    switch (*x.sim.request) {
      case 1: w.reset(); break;
      case 2: w.place_robot(r, a[0], a[1], a[2]); break;
      case 3: w.place_ball(a[0], a[1], a[2], a[3]); break;
      case 4: w.push(r, a[0], a[1], a[2]); break;
      case 5:
        if (a[0] == 0 || a[0] == 1) x.button_until[(int)a[0]] = w.time() + a[1];
        break;
      case 6: answer_link_truth(s, r); break;
      case 7: push_link(s, r, a); break;
      default: break;
    }
  } else {
    x.refused++;
  }
  shm_store_release_u32(x.sim.done_seq, seq);
  shm_futex_wake(x.sim.done_seq);
  return true;
}

void publish_truth(Sim &s, int r) {
  const dcm_blk_sim &b = s.rob[r].sim;
  sim::Truth t = s.world->truth(r);
  shm_write_begin(b.blk);
  const double rob[6] = {t.x, t.y, t.z, t.yaw, t.roll, t.pitch};
  memcpy(b.robot, rob, sizeof rob);
  *b.fallen = t.fallen;
  memcpy(b.ball, t.ball, sizeof t.ball);
  b.score[0] = s.world->score(0);
  b.score[1] = s.world->score(1);
  *b.realtime_factor = s.rtf;
  *b.ball_touch = s.world->ball_touch();
  *b.ball_touch_time = s.world->ball_touch_time();
  memcpy(b.cop, t.cop, sizeof t.cop);
  shm_write_end(b.blk);
}

// ---------------------------------------------------------------- the driver

int sim_configure(void *hw, dcm *d, char *err, size_t errlen) {
  Sim &s = *static_cast<Sim *>(hw);
  if (s.o.ids.size() > DCM_ROBOTS_MAX) {
    snprintf(err, errlen, "at most %d robots in one world", DCM_ROBOTS_MAX);
    return -EINVAL;
  }
  try {
    sim::load_bodies(s.o.bodies, &s.params, &s.bodies);
  } catch (const std::exception &e) {
    snprintf(err, errlen, "%s", e.what());
    return -EINVAL;
  }
  d->nrobots = (int)s.o.ids.size();
  for (int r = 0; r < d->nrobots; r++) {
    d->robot[r].id = s.o.ids[r];
    d->robot[r].nj = (int)s.bodies[r].joints.size();
    // the guard clamps a torque to the joint's actuator torque (the URDF effort the drive applies)
    const sim::Model &m = s.bodies[r].model;
    for (int j = 0; j < d->robot[r].nj; j++) {
      const int li = m.joint_link(s.bodies[r].joints[j]);
      d->robot[r].torque_limit[j] = li >= 0 ? m.links[li].effort : 0;
    }
    snprintf(d->robot[r].name, sizeof d->robot[r].name, "%s", s.params[r].name.c_str());

  }
  const sim::Params &p = s.params[0];
  d->period = p.period;
  d->watchdog = p.watchdog;
  d->stall_cycles = p.stall_cycles;
  d->stall_cpu = p.stall_cpu;
  d->safe_hardness = p.safe_hardness;
  d->start_hardness = p.start_hardness;
  d->simulated = 1;
  return 0;
}

int sim_open(void *hw, dcm *d, char *err, size_t errlen) {
  Sim &s = *static_cast<Sim *>(hw);
  try {
    s.world.reset(new sim::World(s.params[0], s.bodies, s.o.seed));
    s.ren.reset(new sim::Renderer(s.params[0], s.o.seed));
    s.rob.resize(d->nrobots);
    for (int r = 0; r < d->nrobots; r++) {
      SimRobot &x = s.rob[r];
      // every pressure sensor has its place in dcm.sensor
      long npress = 0;
      for (const sim::PressureFoot &f : s.params[r].pressure) npress += (long)f.xy.size() / 2;
      const long room = shm_schema_const(d->schema, "npressure");
      if (npress > room) {
        snprintf(err, errlen, "robot '%s': %ld foot pressure sensors (robot.lua foot_pressure), room for %ld in "
                 "dcm.sensor (Config/shm.schema npressure)", s.params[r].name.c_str(), npress, room);
        return -EINVAL;
      }
      if (dcm_blocks_open(d->schema, d->robot[r].id, DCM_BLK_sim(&x.sim), err, errlen) < 0) return -EIO;
      x.frames.open(d->schema, d->robot[r].id, s.params[r]);
      const std::vector<std::string> &joints = s.bodies[r].joints;
      for (int j = 0; j < d->robot[r].nj; j++) {
        if (joints[j] == "head_pan") x.head[0] = j;
        if (joints[j] == "head_tilt") x.head[1] = j;
      }
      const sim::Model &m = s.world->model(r);
      publish_link_names(x, m);
      x.hide = {m.link_index("head_pan_link"), m.link_index("head_tilt_link")};
      const int cl = m.frame_index(s.params[r].camera_frame);
      if (cl >= 0) x.hide.push_back(m.frames[cl].link);
    }
  } catch (const std::exception &e) {
    snprintf(err, errlen, "%s", e.what());
    return -EINVAL;
  }
  return 0;
}

// The robots hold what their actuator blocks say (a blank block: the zero pose, which the library
// then gives them to hold); the world starts from there.
int sim_enable(void *hw, dcm *d, char *err, size_t errlen) {
  Sim &s = *static_cast<Sim *>(hw);
  sim::World &w = *s.world;
  for (int r = 0; r < d->nrobots; r++) {
    dcm_robot &R = d->robot[r];
    if (shm_block_header(R.actuator.blk)->writes != 0) {
      dcm_command_read(&R.actuator, R.nj, &R.cmd);
      w.set_command(r, R.cmd.position, R.cmd.hardness, R.cmd.enable);
    }
    *s.rob[r].sim.done_seq = *s.rob[r].sim.request_seq;
  }
  w.reset();
  for (int r = 0; r < d->nrobots; r++) publish_truth(s, r);
  if (!s.o.no_camera) s.worker.reset(new sim::CameraWorker(w, *s.ren, s.rob[0].hide));
  if (!d->quiet) {
    const sim::Params &p = s.params[0];
    printf("dcm_sim: %d robot(s) (", d->nrobots);
    for (int r = 0; r < d->nrobots; r++) printf("%s%s %d", r ? ", " : "", d->robot[r].name, d->robot[r].id);
    printf("), %s, seed %llu, physics %.1f ms x %d per %.0f ms tick, camera %s\n",
           d->lockstep ? "lockstep" : "real time", (unsigned long long)s.o.seed, p.timestep * 1e3,
           (int)std::lround(p.period / p.timestep), p.period * 1e3,
           !s.o.no_camera ? (std::to_string(p.cam_width) + "x" + std::to_string(p.cam_height) + " @ " +
                         std::to_string((int)p.cam_rate) + " Hz").c_str()
                      : "off");
    fflush(stdout);
  }
  s.sim0 = w.time();
  s.wall0 = s.last_print = shm_now();
  s.prof.start();   // the profile's first lap starts with the loop
  (void)err;
  (void)errlen;
  return 0;
}

void sim_published(void *hw, dcm *d) {
  Sim &s = *static_cast<Sim *>(hw);
  s.prof.lap(Profile::kPublish);
  if (s.worker)
    for (SimRobot &x : s.rob) x.frames.hand_over(*s.worker, d->tick, !d->lockstep);
  s.prof.lap(Profile::kHandOver);
}

void sim_idle(void *hw, dcm *d, int alone) {
  Sim &s = *static_cast<Sim *>(hw);
  for (int r = 0; r < d->nrobots; r++)
    while (apply_request(s, r)) publish_truth(s, r);
  if (alone) s.prof.start();   // time without any participant is not the DCM's
}

void sim_write(void *hw, dcm *d) {
  Sim &s = *static_cast<Sim *>(hw);
  s.prof.lap(Profile::kWait);
  for (int r = 0; r < d->nrobots; r++) {
    const dcm_command &c = d->robot[r].cmd;
    s.world->set_command(r, c.position, c.hardness, c.enable, c.mode, c.torque);
    while (apply_request(s, r)) {}
  }
  s.prof.lap(Profile::kCommands);
}

void sim_read(void *hw, dcm *d) {
  Sim &s = *static_cast<Sim *>(hw);
  sim::World &w = *s.world;
  // --duration: the tick published last (at the duration) has had its lockstep round; stepping on would
  // publish one that no participant works on (the DCM library publishes nothing after a stop in read)
  if (s.o.duration >= 0 && w.time() >= s.o.duration - 1e-9) {
    dcm_stop(d);
    return;
  }
  w.step();
  s.prof.lap(Profile::kPhysics);
  // camera: expose now, deliver latency_ticks later
  const uint32_t tick = d->tick + 1;
  if (s.worker) {
    bool have_scene = false;
    sim::Scene scene;
    for (int r = 0; r < d->nrobots; r++) {
      const std::vector<double> q = w.joint_positions(r);
      const SimRobot &x = s.rob[r];
      const double head[2] = {x.head[0] >= 0 ? q[x.head[0]] : 0, x.head[1] >= 0 ? q[x.head[1]] : 0};
      const sim::Truth t = w.truth(r);   // the torso's roll and pitch, as dcm.sensor's angle has them
      const double angle[2] = {t.roll, t.pitch};
      s.rob[r].frames.expose(w, r, tick, tick * d->period, head, angle, s.params[r], &x.hide, &scene,
                             &have_scene);
    }
    s.prof.lap(Profile::kExpose);
    for (SimRobot &x : s.rob) x.frames.deliver(*s.worker, tick);
    s.prof.lap(Profile::kFrames);
  }
  // truth (and frames, above) before the sensors, so that a process woken by the new sensor tick
  // finds everything else of that tick in place
  for (int r = 0; r < d->nrobots; r++) publish_truth(s, r);
}

void sim_publish(void *hw, dcm *d, int r, const dcm_blk_dcm_sensor *o) {
  Sim &s = *static_cast<Sim *>(hw);
  sim::World &w = *s.world;
  sim::Sensors &x = s.sensors;
  w.sense(r, &x);
  const size_t nd = sizeof(double) * (size_t)d->robot[r].nj;
  memcpy(o->position, x.position.data(), nd);
  memcpy(o->velocity, x.velocity.data(), nd);
  memcpy(o->load, x.load.data(), nd);
  for (int j = 0; j < d->robot[r].nj; j++) o->temperature[j] = s.params[r].temperature;
  memcpy(o->gyro, x.gyro, sizeof x.gyro);
  memcpy(o->accelerometer, x.accel, sizeof x.accel);
  memcpy(o->angle, x.angle, sizeof x.angle);
  memcpy(o->foot_force, x.foot_force, sizeof x.foot_force);
  memcpy(o->ft, x.ft, sizeof x.ft);
  for (int k = 0; k < o->n.foot_pressure; k++) o->foot_pressure[k] = k < (int)x.pressure.size() ? x.pressure[k] : 0;
  for (int k = 0; k < 2; k++) o->button[k] = w.time() < s.rob[r].button_until[k];
  *o->battery = s.params[r].battery;
}

void sim_stats(void *hw, dcm *d, int r, const dcm_blk_dcm_stats *o) {
  Sim &s = *static_cast<Sim *>(hw);
  if (r == 0 && d->pacer.closed) s.rtf = d->pacer.rate * d->period;   // simulated s per wall s
  *o->realtime_factor = s.rtf;
  *o->nan_commands += s.rob[r].refused;
  if (r != d->nrobots - 1) return;
  const sim::World &w = *s.world;
  const double t = shm_now();
  if (!d->quiet && t - s.last_print >= s.o.report) {
    printf("dcm_sim: sim time %.1f s, real-time factor %.2f (%.1f ticks/s)%s\n", w.time(),
           (w.time() - s.print_sim) / (t - s.last_print), d->pacer.rate,
           d->sync.dropped ? " (participants dropped)" : "");
    fflush(stdout);
    s.last_print = t;
    s.print_sim = w.time();
  }
}

void sim_close(void *hw, dcm *d) {
  Sim &s = *static_cast<Sim *>(hw);
  if (s.world) {
    const double wall = shm_now() - s.wall0;
    if (s.o.profile) s.prof.print(d->pacer.cycles, s.world->time() - s.sim0);
    if (!d->quiet && s.wall0 > 0) {
      printf("dcm_sim: stopped at sim time %.3f s after %.2f s wall: real-time factor %.2f\n", s.world->time(), wall,
             wall > 0 ? s.world->time() / wall : 0.0);
    }
  }
  s.worker.reset();   // finishes what it was given (renders, copies into camera.image)
  for (SimRobot &x : s.rob) {
    x.frames.clear();
    x.frames.close();
    if (x.sim.blk) shm_block_close(x.sim.blk);
    x.sim.blk = nullptr;
  }
}

}  // namespace

int main(int argc, char **argv) {
  static Sim s;
  static dcm d;
  d.name = "dcm_sim";
  d.max_cycles = -1;
  const dcm_opt opts[] = {
      DCM_OPT_LOCKSTEP(&d),
      {"--seed", DCM_OPT_FUNC, &s.o.seed, 0, 0, "N", "the world's random seed (default 1)", parse_seed, 0},
      {"--robots", DCM_OPT_FUNC, &s.o, 0, 0, "N|BODY,..",
       "N robots of the body $ROBOT, or one robot of each body named (default 1)", parse_robots, 0},
      {"--ids", DCM_OPT_FUNC, &s.o.ids, 0, 0, "A,B,..", "the robots' ids (default: ROBOT_ID, ROBOT_ID+1, ..)",
       parse_ids, 0},
      {"--duration", DCM_OPT_DOUBLE, &s.o.duration, 0, HUGE_VAL, "SIM_S", "stop at this sim time (default: never)",
       nullptr, 0},
      {"--no-camera", DCM_OPT_FLAG, &s.o.no_camera, 0, 0, nullptr, "render no camera images", nullptr, 0},
      {"--report", DCM_OPT_DOUBLE, &s.o.report, 0, HUGE_VAL, "WALL_S", "s of wall time between status lines (default 5)",
       nullptr, 0},
      DCM_OPT_QUIET(&d),
      {"--profile", DCM_OPT_FLAG, &s.o.profile, 0, 0, nullptr,
       "at exit: wall time per tick of each phase, CPU s per simulated s", nullptr, 0},
      DCM_OPT_END,
  };
  dcm_args(d.name, "[PLATFORM=Sim] ./run_dcm", opts, argc, argv);
  if (d.sync.start_with > 0) d.lockstep = 1;
  int nrobots = s.o.nrobots;
  if (!s.o.bodies.empty()) nrobots = (int)s.o.bodies.size();
  if (!s.o.ids.empty() && !s.o.bodies.empty() && s.o.ids.size() != s.o.bodies.size()) {
    fprintf(stderr, "dcm_sim: %zu ids for %zu bodies\n", s.o.ids.size(), s.o.bodies.size());
    return 2;
  }
  if (s.o.ids.empty())
    for (int k = 0; k < nrobots; k++) s.o.ids.push_back(shm_robot_id() + k);
  if (s.o.bodies.empty()) s.o.bodies.assign(s.o.ids.size(), "");
  dcm_driver drv = {};
  drv.configure = sim_configure;
  drv.open = sim_open;
  drv.enable = sim_enable;
  drv.write = sim_write;
  drv.read = sim_read;
  drv.publish = sim_publish;
  drv.stats = sim_stats;
  drv.idle = sim_idle;
  drv.published = sim_published;
  drv.close = sim_close;
  return dcm_run(&d, &drv, &s);
}
