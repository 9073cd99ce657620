// frames: camera frames of one simulated robot, exposure to delivery (see frames.h).
#include "frames.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace sim {

void FrameQueue::open(const shm_schema *schema, int id, const Params &p) {
  char err[512];
  if (dcm_blocks_open(schema, id, DCM_BLK_camera_image(&cam_), err, sizeof err) < 0) throw std::runtime_error(err);
  bytes_ = (size_t)p.cam_width * p.cam_height * 2;
  if ((size_t)cam_.n.yuyv < bytes_) {
    throw std::runtime_error("camera.image: field 'yuyv' holds " + std::to_string(cam_.n.yuyv) +
                             " bytes, the sim camera needs " + std::to_string(bytes_) + " (" +
                             std::to_string(p.cam_width) + "x" + std::to_string(p.cam_height) + " YUYV)");
  }
  *cam_.width = p.cam_width;
  *cam_.height = p.cam_height;
  next_frame_ = 0;
}

void FrameQueue::close() {
  if (cam_.blk) shm_block_close(cam_.blk);
  cam_.blk = nullptr;
}

bool FrameQueue::pose_at(double t, Vec3 *pos, Mat3 *rot) const {
  if (poses_.empty() || t < poses_.front().t - 1e-9) return false;
  for (size_t i = 1; i < poses_.size(); i++) {
    const Pose &a = poses_[i - 1], &b = poses_[i];
    if (t > b.t + 1e-12) continue;
    const double s = b.t > a.t ? (t - a.t) / (b.t - a.t) : 1.0;
    *pos = a.pos + s * (b.pos - a.pos);
    *rot = Eigen::Quaterniond(a.rot).slerp(s, Eigen::Quaterniond(b.rot)).toRotationMatrix();
    return true;
  }
  *pos = poses_.back().pos;
  *rot = poses_.back().rot;
  return true;
}

void FrameQueue::expose(const World &w, int r, uint32_t tick, double time, const double head[2],
                        const double angle[2], const Params &p,
                        const std::vector<int> *hide, Scene *scene, bool *have_scene) {
  const bool blur = p.realism.on && p.realism.exposure > 0;
  if (blur) {
    // every tick: the poses of the last exposure time and a tick more
    Pose x;
    x.t = w.time();
    w.camera_pose(r, &x.pos, &x.rot);
    poses_.push_back(x);
    while (poses_.size() > 2 && poses_[1].t < x.t - p.realism.exposure - 1e-9) poses_.pop_front();
  }
  if (w.time() + 1e-9 < next_frame_) return;
  next_frame_ += 1.0 / p.cam_rate;
  if (!*have_scene) {
    w.snapshot(scene);
    *have_scene = true;
  }
  pending_.emplace_back();
  Frame &f = pending_.back();
  f.number = ++exposed_;
  f.deliver_tick = tick + (uint32_t)std::max(0, p.cam_latency_ticks);
  f.time = time;
  f.head[0] = head[0];
  f.head[1] = head[1];
  f.angle[0] = angle[0];
  f.angle[1] = angle[1];
  if (!spare_.empty()) {
    // a buffer that is already mapped: no page faults and zeroing on the physics thread
    f.img = std::move(spare_.back());
    spare_.pop_back();
  }
  f.img.resize(bytes_);
  CameraWorker::Job &j = f.job;
  w.camera_pose(r, &j.cam.pos, &j.cam.rot);
  j.cam.width = p.cam_width;
  j.cam.height = p.cam_height;
  j.cam.calibrate(p);
  j.time = time;
  j.has_start = blur && pose_at(w.time() - p.realism.exposure, &j.cam_start.pos, &j.cam_start.rot);
  if (j.has_start) {
    const Vec3 pos = j.cam_start.pos;
    const Mat3 rot = j.cam_start.rot;
    j.cam_start = j.cam;
    j.cam_start.pos = pos;
    j.cam_start.rot = rot;
  }
  j.scene = *scene;
  j.self = r;
  j.hide = hide;
  j.seq = f.number + 7919u * (uint32_t)r;
  j.out = f.img.data();
}

void FrameQueue::hand_over(CameraWorker &wk, uint32_t tick, bool copy_early) {
  for (Frame &f : pending_) {
    if (!f.render) f.render = wk.submit(std::move(f.job));
    if (!f.copy && f.deliver_tick <= tick + (copy_early ? 1 : 0)) {
      // camera.image is written by this worker job only (the physics thread never touches it)
      f.copy = wk.post([this, src = f.img.data(), n = f.number, t = f.time, h0 = f.head[0], h1 = f.head[1],
                         a0 = f.angle[0], a1 = f.angle[1]] {
        shm_write_begin(cam_.blk);
        memcpy(cam_.yuyv, src, bytes_);
        *cam_.time = t;
        cam_.head[0] = h0;
        cam_.head[1] = h1;
        cam_.angle[0] = a0;
        cam_.angle[1] = a1;
        *cam_.frame = n;
        shm_write_end(cam_.blk);
      });
    }
  }
}

void FrameQueue::deliver(CameraWorker &wk, uint32_t tick) {
  while (!pending_.empty() && pending_.front().deliver_tick <= tick) {
    Frame &f = pending_.front();
    if (!f.copy) hand_over(wk, tick - 1);   // not handed over yet (no latency)
    wk.wait(f.copy);
    spare_.push_back(std::move(f.img));   // copied: the worker is done with it
    pending_.pop_front();
  }
}

}  // namespace sim
