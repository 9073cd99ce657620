// sim_camera: the head camera's rasterizer (TAP). The ball's rendered centroid must match the
// projection of its centre, its size the pinhole model; the goal and lines must show up white.
// Frames rendered on the worker thread while the world steps on must equal those rendered in place.
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "camera_worker.h"
#include "render.h"
#include "stance.h"
#include "world.h"
#include "tap.h"

int main() {
  try {
    sim::Params p;
    sim::Model m;
    sim::load_all(&p, &m);
    sim::World w(p, m, 1, 3);
    sim::Renderer ren(p, 3);
    const int W = p.cam_width, H = p.cam_height;
    std::vector<uint8_t> img((size_t)W * H * 2);
    std::vector<sim::Solid> solids;
    std::vector<int> hide = {m.link_index("head_pan_link"), m.link_index("head_tilt_link")};
    int pan = -1, tilt = -1;
    for (size_t j = 0; j < p.joints.size(); j++) {
      if (p.joints[j] == "head_pan") pan = (int)j;
      if (p.joints[j] == "head_tilt") tilt = (int)j;
    }
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(0, 1);
    int scenes = 0, inview = 0, worst_scene = -1;
    double worst = 0, worst_size = 0;
    while (scenes < 60) {
      // robot somewhere in its half facing roughly forward, ball 0.3..4 m ahead, head anywhere
      std::vector<double> q = sim::stance_pose(m, p);
      q[pan] = -1.2 + 2.4 * U(rng);
      q[tilt] = -1.0 + 1.2 * U(rng);
      const double rx = -3 + 3 * U(rng), ry = -2 + 4 * U(rng), yaw = -1 + 2 * U(rng);
      const double d = 0.3 + 3.7 * U(rng), b = q[pan] + yaw + (-0.4 + 0.8 * U(rng));
      w.place_robot(0, rx, ry, yaw, q.data());
      w.place_ball(rx + d * std::cos(b), ry + d * std::sin(b));
      sim::Camera c;
      w.camera_pose(0, &c.pos, &c.rot);
      c.width = W;
      c.height = H;
      c.fovy = p.cam_fovy;
      double pu, pv;
      const sim::Vec3 ball = w.ball_position();
      scenes++;
      if (!sim::camera_project(c, ball, &pu, &pv)) continue;
      const double dist = (ball - c.pos).norm();
      const double rpx = c.focal() * w.ball_radius() / dist;
      // only balls fully inside the image
      if (pu - 1.5 * rpx < 0 || pu + 1.5 * rpx > W - 1 || pv - 1.5 * rpx < 0 || pv + 1.5 * rpx > H - 1) continue;
      w.solids(&solids);
      // the robot's own arms may hide the ball: this part checks the projection, so hide them all
      std::vector<int> all;
      for (size_t i = 0; i < m.links.size(); i++) all.push_back((int)i);
      ren.render(sim::shot_of(w, c, 0, &all, (uint32_t)scenes), solids, img.data());
      double su = 0, sv = 0, n = 0;
      for (int v = 0; v < H; v++) {
        for (int u = 0; u < W; u++) {
          const uint8_t *px = &img[(size_t)v * W * 2 + 4 * (u / 2)];
          if (px[1] < 90 && px[3] > 180) {   // orange chroma
            su += u;
            sv += v;
            n++;
          }
        }
      }
      if (n < 3) {
        printf("# scene %d: ball at %.2f m not found (occluded by the robot itself?)\n", scenes, dist);
        continue;
      }
      inview++;
      // The exact silhouette of a sphere is an ellipse centred on the radial line through its
      // projected centre: with theta the angle off the optical axis and alpha = asin(r / dist),
      // A = cos^2 alpha - sin^2 theta, K = A x0^2 + cos^2 theta - cos^2 alpha, its centre is at
      // x0 = sin theta cos theta / A (normalised), semi-axes sqrt(K / A) and sqrt(K) / cos alpha.
      const sim::Vec3 qc = c.rot.transpose() * (ball - c.pos);
      const double theta = std::atan2(std::hypot(qc.y(), qc.z()), qc.x());
      const double alpha = std::asin(w.ball_radius() / dist);
      const double A = std::pow(std::cos(alpha), 2) - std::pow(std::sin(theta), 2);
      const double x0 = std::sin(theta) * std::cos(theta) / A;
      const double K = A * x0 * x0 + std::pow(std::cos(theta), 2) - std::pow(std::cos(alpha), 2);
      const double semi_a = std::sqrt(K / A), semi_b = std::sqrt(K) / std::cos(alpha);
      const double f = c.focal(), rn = std::hypot(pu - (W - 1) / 2.0, pv - (H - 1) / 2.0);
      double eu = (W - 1) / 2.0, ev = (H - 1) / 2.0;
      if (rn > 1e-9) {
        eu += (pu - (W - 1) / 2.0) / rn * f * x0;
        ev += (pv - (H - 1) / 2.0) / rn * f * x0;
      }
      const double err = std::hypot(su / n - eu, sv / n - ev);
      const double expect_r = f * std::sqrt(semi_a * semi_b);
      const double size_err = std::fabs(std::sqrt(n / M_PI) - expect_r) / expect_r;
      if (std::hypot(eu - pu, ev - pv) > 0.5) {
        printf("# scene %d: ball at %.2f m, %.0f deg off axis: silhouette centre %.1f px from the centre's "
               "projection, rendered centroid %.2f px from the silhouette centre\n",
               scenes, dist, theta * 180 / M_PI, std::hypot(eu - pu, ev - pv), err);
      }
      if (err > worst) {
        worst = err;
        worst_scene = scenes;
      }
      worst_size = std::max(worst_size, size_err);
    }
    printf("# %d scenes, %d with the ball fully in view: centroid vs projection max %.2f px (scene %d), "
           "radius error max %.1f%%\n", scenes, inview, worst, worst_scene, 100 * worst_size);
    check(inview >= 20, "enough scenes with the ball in view");
    check(worst < 1.0, "ball's rendered centroid within 1 px of its projection (exact sphere silhouette)");
    check(worst_size < 0.05, "ball's rendered area within 5% of the projected silhouette's");

    // a goal and the lines: looking at the +x goal from the penalty mark
    std::vector<double> q = sim::stance_pose(m, p);
    q[tilt] = 0;
    w.place_robot(0, 1.5, 0, 0, q.data());
    w.place_ball(3.3, 0);
    sim::Camera c;
    w.camera_pose(0, &c.pos, &c.rot);
    c.width = W;
    c.height = H;
    c.fovy = p.cam_fovy;
    w.solids(&solids);
    ren.render(sim::shot_of(w, c, 0, &hide, 0), solids, img.data());
    double pu, pv;
    const double post_y = p.goal_width / 2 + p.post_diameter / 2;
    bool ok = sim::camera_project(c, sim::Vec3(p.field_length / 2, post_y, 0.8), &pu, &pv);
    ok = ok && pu >= 0 && pu <= W - 1 && pv >= 0 && pv <= H - 1;
    const uint8_t *px = ok ? &img[(size_t)std::lround(pv) * W * 2 + 2 * std::lround(pu)] : img.data();
    printf("# post pixel (%.1f, %.1f) luma %d\n", pu, pv, px[0]);
    check(ok && px[0] > 170, "left goal post renders bright white where it projects");
    ok = sim::camera_project(c, sim::Vec3(p.field_length / 2 - 0.5, 0.6, 0), &pu, &pv);
    ok = ok && pu >= 0 && pu <= W - 1 && pv >= 0 && pv <= H - 1;
    px = ok ? &img[(size_t)std::lround(pv) * W * 2 + 4 * (std::lround(pu) / 2)] : img.data();
    check(ok && px[1] < 115 && px[3] < 110, "the carpet renders green");

    // the render thread: frames exposed every 4th tick of a robot that turns its head while the
    // world steps on, against the same frames rendered on this thread at the exposure tick
    {
      sim::World w2(p, m, 1, 5);
      std::vector<int> hide2 = hide;
      const int cl = m.frame_index(p.camera_frame);
      if (cl >= 0) hide2.push_back(m.frames[cl].link);
      sim::CameraWorker worker(w2, ren, hide2);
      std::vector<double> q2 = sim::stance_pose(m, p);
      w2.set_command(0, q2.data(), nullptr, nullptr);
      w2.reset();
      w2.place_ball(0.0, 0.3);
      const int nframes = 12;
      std::vector<std::vector<uint8_t>> direct(nframes), threaded(nframes);
      uint64_t last = 0;
      for (int k = 0; k < nframes; k++) {
        q2[pan] = 0.1 * k - 0.6;
        q2[tilt] = -0.3 - 0.02 * k;
        w2.set_command(0, q2.data(), nullptr, nullptr);
        for (int t = 0; t < 4; t++) w2.step();
        sim::CameraWorker::Job j;
        w2.camera_pose(0, &j.cam.pos, &j.cam.rot);
        j.cam.width = W;
        j.cam.height = H;
        j.cam.fovy = p.cam_fovy;
        w2.snapshot(&j.scene);
        j.self = 0;
        j.seq = (uint32_t)k;
        threaded[k].assign(img.size(), 0);
        direct[k].assign(img.size(), 0);
        j.out = threaded[k].data();
        sim::Camera c2 = j.cam;
        last = worker.submit(j);
        w2.solids(&solids);
        ren.render(sim::shot_of(w2, c2, 0, &hide2, (uint32_t)k), solids, direct[k].data());
      }
      worker.wait(last);
      int same = 0;
      for (int k = 0; k < nframes; k++) same += direct[k] == threaded[k];
      printf("# %d of %d frames from the render thread identical to frames rendered in place\n", same, nframes);
      check(same == nframes, "frames rendered on the worker thread are bit-identical to frames rendered in place");
    }
  } catch (const std::exception &e) {
    check(false, e.what());
    return tap_done();
  }
  return tap_done();
}
