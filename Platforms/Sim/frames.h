// frames: one simulated robot's camera frames from exposure to delivery into camera.image.
//
// After the step to an exposure tick the physics thread takes a snapshot (camera pose, link poses,
// ball); once the tick is published the render thread (camera_worker.h) gets it, renders the frame
// and copies it into camera.image while the physics steps to the delivery tick.
#ifndef HRP_SIM_FRAMES_H
#define HRP_SIM_FRAMES_H

#include <cstdint>
#include <deque>
#include <vector>

#include "camera_worker.h"
#include "dcm/dcm.h"
#include "world.h"

namespace sim {

class FrameQueue {
 public:
  // Binds camera.image of robot `id` and checks it holds the camera's frames.
  void open(const shm_schema *schema, int id, const Params &p);
  void close();
  // Camera of robot r after the step to `tick`: if a frame is due, its snapshot (`scene` is taken
  // once per tick for all robots) and its place in the queue. time: robot clock at exposure;
  // head: head pan / tilt at exposure; angle: the torso's roll / pitch then (the IMU's, as dcm.sensor's
  // angle); p: the robot's camera; hide: its links the camera does not see.
  void expose(const World &w, int r, uint32_t tick, double time, const double head[2], const double angle[2],
              const Params &p,
              const std::vector<int> *hide, Scene *scene, bool *have_scene);
  // Once tick `tick` is published: hands the new frames to the worker, and (copy_early) the copies
  // into camera.image of the frames due at the next tick, made while the physics steps. In lockstep
  // copy_early is false: a frame then appears between two ticks (at deliver), never during the tick
  // before its own, where a participant would see it early or not depending on the copy's speed.
  void hand_over(CameraWorker &wk, uint32_t tick, bool copy_early = true);
  // Returns once every frame due at `tick` is in camera.image (before the tick's sensors appear).
  void deliver(CameraWorker &wk, uint32_t tick);
  // Drops what is still queued (after the worker has finished).
  void clear() { pending_.clear(); }

 private:
  struct Frame {
    uint32_t number;              // camera.image frame (1, 2, ... per robot)
    uint32_t deliver_tick;
    double time;                  // exposure
    double head[2];
    double angle[2];
    CameraWorker::Job job;
    std::vector<uint8_t> img;
    uint64_t render = 0, copy = 0;   // the worker's tickets (0: not queued yet)
  };
  // the camera's pose at the last ticks (realism: the pose at the exposure's start, for its blur)
  struct Pose {
    double t;
    Vec3 pos;
    Mat3 rot;
  };
  std::deque<Pose> poses_;
  bool pose_at(double t, Vec3 *pos, Mat3 *rot) const;
  dcm_blk_camera_image cam_ = {};
  size_t bytes_ = 0;
  double next_frame_ = 0;
  uint32_t exposed_ = 0;
  std::deque<Frame> pending_;
  std::vector<std::vector<uint8_t>> spare_;   // image buffers of delivered frames, for reuse
};

}  // namespace sim
#endif
