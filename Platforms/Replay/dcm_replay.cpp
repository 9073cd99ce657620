// dcm_replay: the Replay platform's DCM -- a recording served back into the shm blocks tick by tick (see
// replay_log.h), a driver of the DCM library, so the Lua processes run unchanged on recorded data, in
// real time, faster (--speed) or in lockstep; paused, stepped, sought and sped up from the REPL through
// the `replay` block (replay_control.h, Lib/replay.lua).
//   PLATFORM=Replay ./run_dcm --log FILE [--speed X] [--lockstep] [--lockstep-wait N] [--paused] [--quiet]
// At the end of the log (or at damage, which is reported) it stops, unless paused (then it holds the last
// tick, and a seek can go back).
#include "replay_control.h"
#include "replay_log.h"
#include "dcm/args.h"
#include "dcm/dcm.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

struct replay_hw {
  const char *path = nullptr;
  double speed = 0;                       // from the command line (0: the config's)
  double recorded_period = 0;             // s, the recorded robot's tick
  int start_paused = 0;                   // --paused: hold the first tick
  int serve_current = 0;                  // a seek read the next tick to serve: read() serves it
  int end_reported = 0;
  replay_control ctl;
  char serve[REPLAY_BLOCKS_MAX][DCM_NAME_MAX];
  int nserve = 0;
  char leave[SHMLOG_FIELDS_MAX][DCM_NAME_MAX];
  int nleave = 0;
  char camera_field[DCM_NAME_MAX] = "";
  replay_log L;
  cv::Mat bgr;
  std::vector<uint8_t> buf;
};

int configure(void *hw, dcm *d, char *err, size_t n) {
  replay_hw *h = static_cast<replay_hw *>(hw);
  if (!h->path) {
    snprintf(err, n, "no log: PLATFORM=Replay ./run_dcm --log FILE");
    return -EINVAL;
  }
  dcm_config *rc = nullptr, *pc = nullptr;
  double period = 0, speed = 0;
  int r = dcm_config_load("robot", nullptr, "Replay", &rc, err, n);
  int nj = 0;
  if (r == 0) r = nj = dcm_config_len(rc, "joints", err, n);
  if (r >= 0) r = dcm_config_num(rc, "period", &period, err, n);
  if (r == 0) r = dcm_config_load("dcm", dcm_config_robot(rc), "Replay", &pc, err, n);
  if (r == 0) r = dcm_config_num(pc, "speed", &speed, err, n);
  if (r == 0) r = dcm_config_num(pc, "start_hardness", &d->start_hardness, err, n);
  if (r == 0) r = dcm_config_num(pc, "watchdog", &d->watchdog, err, n);
  if (r == 0) r = dcm_config_int(pc, "stall_cycles", &d->stall_cycles, err, n);
  if (r == 0) r = dcm_config_num(pc, "stall_cpu", &d->stall_cpu, err, n);
  if (r == 0) r = dcm_config_num(pc, "safe_hardness", &d->safe_hardness, err, n);
  if (r == 0) r = dcm_config_str(pc, "camera_field", h->camera_field, sizeof h->camera_field, err, n);
  if (r == 0) r = h->nserve = dcm_config_strs(pc, "serve", h->serve, 1, REPLAY_BLOCKS_MAX, err, n);
  if (r >= 0) r = h->nleave = dcm_config_strs(pc, "leave", h->leave, 0, SHMLOG_FIELDS_MAX, err, n);
  if (r >= 0 && h->speed > 0) speed = h->speed;
  if (r >= 0 && !(speed > 0)) r = dcm_config_fail(pc, err, n, "key 'speed' must be > 0, got %g", speed);
  if (r >= 0) {
    d->nrobots = 1;
    d->robot[0].id = shm_robot_id();
    d->robot[0].nj = nj;
    snprintf(d->robot[0].name, sizeof d->robot[0].name, "%s", dcm_config_robot(rc));
    d->period = period / speed;
    h->recorded_period = period;
    d->simulated = 1;
  }
  dcm_config_free(rc);
  dcm_config_free(pc);
  return r < 0 ? r : 0;
}

// BT.601 video range, the inverse of OpenCV's YUV2BGR_YUYV that the recorder compresses through
inline uint8_t clamp8(double v) { return (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v + 0.5); }
inline double luma(const uint8_t *bgr) { return 16 + (65.481 * bgr[2] + 128.553 * bgr[1] + 24.966 * bgr[0]) / 255; }
inline double cb(const uint8_t *bgr) { return 128 + (-37.797 * bgr[2] - 74.203 * bgr[1] + 112.0 * bgr[0]) / 255; }
inline double cr(const uint8_t *bgr) { return 128 + (112.0 * bgr[2] - 93.786 * bgr[1] - 18.214 * bgr[0]) / 255; }

// JPEG -> the YUYV the camera block holds (4:2:2: each pixel pair shares the mean of its U and V)
int decode_frame(void *ctx, const uint8_t *data, size_t len, int w, int h, uint8_t *yuyv, size_t cap) {
  replay_hw *hw = static_cast<replay_hw *>(ctx);
  if (w <= 0 || h <= 0 || w % 2 || (size_t)w * (size_t)h * 2 > cap) return -EINVAL;
  const cv::Mat in(1, (int)len, CV_8UC1, const_cast<uint8_t *>(data));
  hw->bgr = cv::imdecode(in, cv::IMREAD_COLOR);
  if (hw->bgr.empty() || hw->bgr.cols != w || hw->bgr.rows != h) return -EINVAL;
  for (int y = 0; y < h; y++) {
    const uint8_t *p = hw->bgr.ptr<uint8_t>(y);
    uint8_t *o = yuyv + (size_t)y * (size_t)w * 2;
    for (int x = 0; x < w; x += 2, p += 6, o += 4) {
      o[0] = clamp8(luma(p));
      o[1] = clamp8((cb(p) + cb(p + 3)) / 2);
      o[2] = clamp8(luma(p + 3));
      o[3] = clamp8((cr(p) + cr(p + 3)) / 2);
    }
  }
  return 0;
}

int open_log(void *hw, dcm *d, char *err, size_t n) {
  replay_hw *h = static_cast<replay_hw *>(hw);
  const char *serve[REPLAY_BLOCKS_MAX], *leave[SHMLOG_FIELDS_MAX];
  for (int i = 0; i < h->nserve; i++) serve[i] = h->serve[i];
  for (int i = 0; i < h->nleave; i++) leave[i] = h->leave[i];
  int rc = replay_log_open(&h->L, h->path, d->schema, d->robot[0].id, serve, h->nserve, leave, h->nleave,
                           h->camera_field, decode_frame, h, err, n);
  if (rc == 0) rc = replay_control_open(&h->ctl, d->schema, d->robot[0].id, h->recorded_period / d->period, err, n);
  if (rc == 0) h->ctl.paused = h->start_paused;
  return rc;
}

void report_end(replay_hw *h, dcm *d) {
  const replay_log *L = &h->L;
  if (h->end_reported) return;
  h->end_reported = 1;
  if (L->damage[0])
    fprintf(stderr, "dcm_replay: %s: damaged: %s; replayed %llu ticks up to t=%.3f s\n", h->path, L->damage,
            (unsigned long long)L->ticks, L->time);
  else
    dcm_log(d, "end of %s: %llu ticks, t=%.3f..%.3f s, %llu frames%s", h->path, (unsigned long long)L->ticks,
            L->first_time, L->time, (unsigned long long)L->frames, L->bad_frames ? " (some frames undecodable)" : "");
}

// The first tick, so that the start publishes the recorded pose.
int enable(void *hw, dcm *d, char *err, size_t n) {
  replay_hw *h = static_cast<replay_hw *>(hw);
  const int rc = replay_log_next(&h->L);
  if (rc <= 0) {
    snprintf(err, n, "%s: no tick to replay%s%s", h->path, h->L.damage[0] ? ": " : "", h->L.damage);
    return -EINVAL;
  }
  replay_log_serve(&h->L);
  dcm_log(d, "replaying %s from t=%.3f s, a tick every %.4f s", h->path, h->L.time, d->period);
  return 0;
}

void write(void *, dcm *) {}   // commands go nowhere: the robot's body is the recording

void read(void *hw, dcm *d) {
  replay_hw *h = static_cast<replay_hw *>(hw);
  if (h->serve_current) {
    h->serve_current = 0;
    replay_log_serve(&h->L);
    return;
  }
  const int rc = replay_log_next(&h->L);
  if (rc > 0) {
    h->end_reported = 0;
    replay_log_serve(&h->L);
    return;
  }
  report_end(h, d);
  if (!h->ctl.paused) dcm_stop(d);   // paused: the last tick stays, a seek may go back
}

// Between two cycles: the REPL's commands. While paused the clock is held here (no tick is published,
// so every process waits as for a stopped DCM); a step lets cycles through one by one, a seek reads up to
// its tick so that the next cycle serves it.
void published(void *hw, dcm *d) {
  replay_hw *h = static_cast<replay_hw *>(hw);
  replay_control *c = &h->ctl;
  replay_control_poll(c);
  const int held = replay_control_holds(c);
  if (held) {
    replay_control_publish(c, &h->L, 1);
    while (!*d->stop && replay_control_holds(c))
      if (!replay_control_poll(c)) usleep(2000);
  }
  if (c->speed_changed) {
    c->speed_changed = 0;
    d->period = d->pacer.period = h->recorded_period / c->speed;
  }
  if (c->seek_pending) {
    c->seek_pending = 0;
    if (replay_log_seek(&h->L, c->seek_to) > 0) h->serve_current = 1;
    else fprintf(stderr, "dcm_replay: seek to %.3f s: no tick to serve%s%s\n", c->seek_to,
                 h->L.damage[0] ? ": " : "", h->L.damage);
  }
  if (c->paused && c->steps > 0) c->steps--;
  // real time: the deadlines start again from now (the hold is no overrun)
  if (held) d->pacer.deadline = d->pacer.clock.now(d->pacer.clock.ctx);
  replay_control_publish(c, &h->L, 0);
}

// The recorded sensors, but the tick and the pid, which are this DCM's
void publish(void *hw, dcm *d, int, const dcm_blk_dcm_sensor *s) {
  replay_hw *h = static_cast<replay_hw *>(hw);
  const replay_block *rb = &h->L.b[h->L.sensor];
  uint8_t *seg = reinterpret_cast<uint8_t *>(shm_block_header(s->blk));
  static const size_t sizes[] = { 0, 8, 4, 4, 4, 8, 8, 1, 2, 2 };
  for (int k = 0; k < rb->now.nfields; k++) {
    const shmlog_field *f = &rb->now.field[k];
    if (!strcmp(f->name, "tick") || !strcmp(f->name, "dcm_pid")) continue;
    memcpy(seg + f->shm_offset, rb->stage + f->shm_offset, sizes[f->type] * (size_t)f->count);
  }
  d->time = h->L.time;
}

void close_log(void *hw, dcm *) {
  replay_hw *h = static_cast<replay_hw *>(hw);
  replay_control_close(&h->ctl);
  replay_log_close(&h->L);
}

}  // namespace

int main(int argc, char **argv) {
  static replay_hw H;
  static dcm D;
  D.name = "dcm_replay";
  D.max_cycles = -1;
  const dcm_opt opts[] = {
    {"--log", DCM_OPT_STRING, &H.path, 0, 0, "FILE", "the recording to serve", nullptr, 1},
    {"--speed", DCM_OPT_DOUBLE, &H.speed, 0.01, 1000, "X", "times the recorded rate (default: dcm.lua's)", nullptr,
     0},
    DCM_OPT_LOCKSTEP(&D),
    DCM_OPT_CYCLES(&D, "stop after N cycles (default: at the end of the log)"),
    {"--paused", DCM_OPT_FLAG, &H.start_paused, 0, 0, nullptr, "hold the first tick (the REPL's replay.resume())",
     nullptr, 0},
    DCM_OPT_QUIET(&D),
    DCM_OPT_END,
  };
  dcm_args(D.name, "PLATFORM=Replay ./run_dcm", opts, argc, argv);
  if (D.sync.start_with > 0) D.lockstep = 1;
  static const dcm_driver drv = { configure, open_log, enable, write, read, publish, nullptr, nullptr, published,
                                  close_log };
  const int rc = dcm_run(&D, &drv, &H);
  if (rc) return rc;
  return H.L.damage[0] ? 3 : 0;
}
