// camera_worker: renders camera frames on a thread of its own while the physics steps on.
//
// A frame exposed at tick N is delivered at tick N + latency, so the physics thread only takes a
// snapshot at exposure (the link poses and the ball, a few microseconds) and waits for the pixels
// at delivery. The worker renders from that snapshot alone, so a frame is bit for bit the one the
// physics thread would have rendered itself at the exposure tick.
#ifndef HRP_SIM_CAMERA_WORKER_H
#define HRP_SIM_CAMERA_WORKER_H

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "render.h"
#include "world.h"

namespace sim {

class CameraWorker {
 public:
  // `hide`: links of the camera's own robot that the camera does not see (its head).
  CameraWorker(const World &w, const Renderer &r, std::vector<int> hide);
  ~CameraWorker();
  CameraWorker(const CameraWorker &) = delete;
  CameraWorker &operator=(const CameraWorker &) = delete;

  struct Job {
    Camera cam;             // at the exposure's end (the frame's tick)
    Camera cam_start;       // at its start (motion blur), if has_start
    bool has_start = false;
    double time = 0;        // s, exposure
    Scene scene;
    int self = 0;           // the robot whose camera it is
    uint32_t seq = 0;       // frame number for the sensor noise
    uint8_t *out = nullptr; // width * height * 2 bytes, untouched by the caller until wait()
    const std::vector<int> *hide = nullptr;   // links of `self` not seen (null: the worker's own list)
    std::function<void()> fn;   // instead of rendering (post())
  };
  // Queues a job (rendered in order of submission); returns its ticket.
  uint64_t submit(Job j);
  // Queues other work behind the jobs queued so far (the copy of a rendered frame into shared
  // memory, done while the physics steps); returns its ticket.
  uint64_t post(std::function<void()> fn);
  // Returns once the job with this ticket (and every earlier one) is rendered.
  void wait(uint64_t ticket);

 private:
  void run();
  uint64_t queue(Job j);

  const World &world_;
  const Renderer &ren_;
  const std::vector<int> hide_;
  std::mutex mu_;
  std::condition_variable cv_, done_cv_;
  std::deque<Job> jobs_;
  uint64_t submitted_ = 0, done_ = 0;
  bool quit_ = false;
  std::thread th_;
};

}  // namespace sim
#endif
