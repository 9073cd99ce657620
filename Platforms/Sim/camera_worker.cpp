// camera_worker: the render thread of the sim camera.
#include "camera_worker.h"

#include <pthread.h>
#include <sched.h>

namespace sim {

CameraWorker::CameraWorker(const World &w, const Renderer &r, std::vector<int> hide)
    : world_(w), ren_(r), hide_(std::move(hide)), th_([this] { run(); }) {
  // SCHED_BATCH: a job handed over does not preempt the physics thread that submitted it (a woken
  // normal thread often does, on the same core); the worker still gets its fair share of the CPU.
  // Only from the normal policy (a sim started at real-time priority keeps it); not fatal if refused.
  int policy = 0;
  sched_param sp{};
  if (pthread_getschedparam(th_.native_handle(), &policy, &sp) == 0 && policy == SCHED_OTHER) {
    sp.sched_priority = 0;
    pthread_setschedparam(th_.native_handle(), SCHED_BATCH, &sp);
  }
}

CameraWorker::~CameraWorker() {
  {
    std::lock_guard<std::mutex> l(mu_);
    quit_ = true;
  }
  cv_.notify_all();
  th_.join();
}

uint64_t CameraWorker::submit(Job j) {
  j.fn = nullptr;
  return queue(std::move(j));
}

uint64_t CameraWorker::post(std::function<void()> fn) {
  Job j;
  j.fn = std::move(fn);
  return queue(std::move(j));
}

uint64_t CameraWorker::queue(Job j) {
  uint64_t ticket;
  {
    std::lock_guard<std::mutex> l(mu_);
    jobs_.push_back(std::move(j));
    ticket = ++submitted_;
  }
  cv_.notify_one();
  return ticket;
}

void CameraWorker::wait(uint64_t ticket) {
  std::unique_lock<std::mutex> l(mu_);
  done_cv_.wait(l, [&] { return done_ >= ticket; });
}

void CameraWorker::run() {
  std::vector<Solid> solids;
  for (;;) {
    Job j;
    {
      std::unique_lock<std::mutex> l(mu_);
      cv_.wait(l, [&] { return quit_ || !jobs_.empty(); });
      if (jobs_.empty()) return;
      j = std::move(jobs_.front());
      jobs_.pop_front();
    }
    if (j.fn) {
      j.fn();
    } else {
      world_.solids(j.scene, &solids);
      Shot sh;
      sh.cam = j.cam;
      sh.ball = j.scene.ball;
      sh.ball_rot = j.scene.ball_rot;
      sh.ball_radius = world_.ball_radius();
      sh.self = j.self;
      sh.hide = j.hide ? j.hide : &hide_;
      sh.frame = j.seq;
      ren_.render(sh, solids, j.out);
    }
    {
      std::lock_guard<std::mutex> l(mu_);
      done_++;
    }
    done_cv_.notify_all();
  }
}

}  // namespace sim
