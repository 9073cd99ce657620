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

void FrameQueue::expose(const World &w, int r, uint32_t tick, double time, const double head[2], const Params &p,
                        const std::vector<int> *hide, Scene *scene, bool *have_scene) {
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
  j.cam.fovy = p.cam_fovy;
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
      f.copy = wk.post([this, src = f.img.data(), n = f.number, t = f.time, h0 = f.head[0], h1 = f.head[1]] {
        shm_write_begin(cam_.blk);
        memcpy(cam_.yuyv, src, bytes_);
        *cam_.time = t;
        cam_.head[0] = h0;
        cam_.head[1] = h1;
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
