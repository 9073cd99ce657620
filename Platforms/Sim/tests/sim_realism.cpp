// sim_realism: the sim camera's imperfections (effects.h; TAP). Seeded frames repeat bit for bit;
// the noise has the configured size; a turning camera smears the ball along the flow by the
// expected length; the drift stays within its amplitude; the ball casts a shadow; the lens model's
// distortion and undistortion invert each other.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "render.h"
#include "stance.h"
#include "world.h"
#include "tap.h"
#include "yuyv_png.h"

namespace {

// Centroid (u, v) and variances (u, v) of the ball's image, weighted by how far each pair's U lies
// below the carpet's (linear in the share of orange in a blurred pixel; lines, robots, sky and floor
// have a U above the carpet's).
void orange_moments(const std::vector<uint8_t> &img, int W, int H, double m[4]) {
  double s = 0, su = 0, sv = 0, suu = 0, svv = 0;
  for (int v = 0; v < H; v++)
    for (int u = 0; u < W; u += 2) {
      const uint8_t *px = &img[((size_t)v * W + u) * 2];
      const double wt = std::max(0, sim::Renderer::kGreen[1] - px[1]);
      s += wt;
      su += wt * (u + 0.5);
      sv += wt * v;
      suu += wt * (u + 0.5) * (u + 0.5);
      svv += wt * v * v;
    }
  m[0] = su / s;
  m[1] = sv / s;
  m[2] = suu / s - m[0] * m[0];
  m[3] = svv / s - m[1] * m[1];
}

}  // namespace

int main() {
  try {
    sim::Params p;
    sim::Model m;
    sim::load_all(&p, &m);
    p.ball_kind = "orange";
    p.realism.on = true;
    const int W = p.cam_width, H = p.cam_height;
    sim::World w(p, m, 1, 3);
    std::vector<double> q = sim::stance_pose(m, p);
    for (size_t j = 0; j < p.joints.size(); j++)
      if (p.joints[j] == "head_tilt") q[j] = -0.35;
    w.place_robot(0, 0, 0, 0, q.data());
    w.place_ball(1.0, 0);
    std::vector<int> all;
    for (size_t i = 0; i < m.links.size(); i++) all.push_back((int)i);
    std::vector<sim::Solid> solids;
    w.solids(&solids);
    sim::Camera c;
    w.camera_pose(0, &c.pos, &c.rot);
    c.calibrate(p);
    std::vector<uint8_t> a((size_t)W * H * 2), b(a.size()), d(a.size());

    // 1. determinism
    sim::Renderer r1(p, 7), r2(p, 7);
    sim::Shot sh = sim::shot_of(w, c, 0, &all, 5);
    sh.time = 12.3;
    r1.render(sh, solids, a.data());
    r2.render(sh, solids, b.data());
    sh.frame = 6;
    r1.render(sh, solids, d.data());
    check(a == b, "the same seed, frame and scene: the same frame, bit for bit");
    check(a != d, "the next frame has other noise");

    // 2. noise: flat light, no drift, no shadows; the noisy frame against the same without noise, over
    // the carpet (its grey in the noise-free frame)
    sim::Params pn = p;
    pn.realism.gain_drift = pn.realism.wb_drift = pn.realism.light_gradient = 0;
    pn.realism.shadow_robot = pn.realism.shadow_ball = 0;
    sim::Params pq = pn;
    pq.realism.noise_luma = pq.realism.noise_chroma = 0;
    sim::Renderer rn(pn, 7), rq(pq, 7);
    rn.render(sh, solids, a.data());
    rq.render(sh, solids, b.data());
    double sy = 0, sy2 = 0, sc = 0, sc2 = 0, ny = 0, nc = 0, ygrey = 0;
    for (size_t i = 0; i < a.size(); i += 4) {
      if (b[i + 1] != sim::Renderer::kGreen[1] || b[i + 3] != sim::Renderer::kGreen[2]) continue;
      for (int k = 0; k < 4; k += 2) {
        const double e = (double)a[i + k] - b[i + k];
        sy += e;
        sy2 += e * e;
        ygrey += b[i + k];
        ny++;
      }
      for (int k = 1; k < 4; k += 2) {
        const double e = (double)a[i + k] - b[i + k];
        sc += e;
        sc2 += e * e;
        nc++;
      }
    }
    const double ysd = std::sqrt(sy2 / ny - (sy / ny) * (sy / ny)), csd = std::sqrt(sc2 / nc - (sc / nc) * (sc / nc));
    const double expect_y = pn.realism.noise_luma * std::sqrt(ygrey / ny / 128);
    printf("# carpet (%.0f px, grey %.0f): luma noise sd %.2f (expected %.2f), chroma sd %.2f (expected %.2f)\n", ny,
           ygrey / ny, ysd, expect_y, csd, pn.realism.noise_chroma);
    check(ny > 10000 && std::fabs(ysd - expect_y) < 0.15 * expect_y + 0.3,
          "luma noise as configured (shot noise at the carpet's grey)");
    check(std::fabs(csd - pn.realism.noise_chroma) < 0.15 * pn.realism.noise_chroma + 0.3, "chroma noise as configured");

    // 3. motion blur: the camera turned by an angle giving 12 px of flow at the image centre during
    // the exposure: the ball's image (weighted by its orange: U below the carpet's, which is linear in
    // the mix) moves by half the flow toward where it was at the start and spreads by its length
    // (variance + flow^2 / 12), not upwards
    const double flow = 12, yaw = std::atan(flow / c.fu());
    double m0[4], m1[4];
    sh.has_start = false;
    rq.render(sh, solids, a.data());
    orange_moments(a, W, H, m0);
    sh.has_start = true;
    sh.cam_start = c;
    sh.cam_start.rot = Eigen::AngleAxisd(yaw, sim::Vec3::UnitZ()).toRotationMatrix() * c.rot;
    rq.render(sh, solids, b.data());
    orange_moments(b, W, H, m1);
    if (getenv("SIM_REALISM_PNG")) {   // to look at: the still and the turning camera's frames
      std::string err;
      sim::yuyv_write_png(std::string(getenv("SIM_REALISM_PNG")) + "_still.png", a.data(), W, H, &err);
      sim::yuyv_write_png(std::string(getenv("SIM_REALISM_PNG")) + "_turning.png", b.data(), W, H, &err);
    }
    // the still frame from the exposure's start: the smear lies between the two still images
    double m2[4];
    sim::Shot s0 = sh;
    s0.has_start = false;
    s0.cam = sh.cam_start;
    rq.render(s0, solids, d.data());
    orange_moments(d, W, H, m2);
    printf("# the ball still at the end %.1f px, at the start %.1f px, blurred %.1f px\n", m0[0], m2[0], m1[0]);
    const double shift = m1[0] - m0[0], spread = std::sqrt(std::max(0.0, 12 * (m1[2] - m0[2])));
    printf("# turning %.2f deg during the exposure (%.0f px of flow): the ball moves %.1f px across, %.1f px up, "
           "spreads %.1f px across, %.1f px^2 of variance up\n",
           yaw * 180 / M_PI, flow, shift, m1[1] - m0[1], spread, m1[3] - m0[3]);
    check(std::fabs(std::fabs(shift) - flow / 2) < 1.0 && std::fabs(spread - flow) < 2.0 &&
              std::fabs(m1[1] - m0[1]) < 0.5 && std::fabs(m1[3] - m0[3]) < 2,
          "a camera turning during the exposure smears the ball along the flow by its length");
    // (it once smeared it the other way, beyond the end: no pose during the exposure saw it there)
    check(std::fabs(m1[0] - (m0[0] + m2[0]) / 2) < 1.0,
          "the smear lies between the ball's still images at the exposure's start and end");

    // 4. drift within its amplitude, and moving
    double gmin = 9, gmax = 0, wmin = 9, wmax = 0;
    for (double t = 0; t < 120; t += 0.5) {
      double g, wr, wb;
      sim::realism_drift(p.realism, 7, 0, t, &g, &wr, &wb);
      gmin = std::min(gmin, g);
      gmax = std::max(gmax, g);
      wmin = std::min(wmin, std::min(wr, wb));
      wmax = std::max(wmax, std::max(wr, wb));
    }
    printf("# over 120 s: exposure gain %.3f..%.3f, white-balance gains %.3f..%.3f\n", gmin, gmax, wmin, wmax);
    check(gmin >= 1 - p.realism.gain_drift - 1e-9 && gmax <= 1 + p.realism.gain_drift + 1e-9 &&
              gmax - gmin > p.realism.gain_drift && wmin >= 1 - p.realism.wb_drift - 1e-9 &&
              wmax <= 1 + p.realism.wb_drift + 1e-9,
          "exposure and white balance drift within their amplitudes");

    // 5. the ball's contact shadow: the carpet just beside its foot against the carpet 0.3 m aside
    sim::Params ps = pn;
    ps.realism.shadow_ball = p.realism.shadow_ball;
    ps.realism.noise_luma = ps.realism.noise_chroma = 0;
    sim::Renderer rs(ps, 7);
    sh.has_start = false;
    rs.render(sh, solids, a.data());
    double us, vs, uf, vf;
    const sim::Vec3 ball = w.ball_position();
    const double rr = w.ball_radius();
    const bool ok = sim::camera_project(c, sim::Vec3(ball.x() - 0.0, ball.y() + 1.1 * rr, 0), &us, &vs) &&
                    sim::camera_project(c, sim::Vec3(ball.x(), ball.y() + 0.3, 0), &uf, &vf);
    const int ys = ok ? a[((size_t)std::lround(vs) * W + std::lround(us)) * 2] : 0;
    const int yf = ok ? a[((size_t)std::lround(vf) * W + std::lround(uf)) * 2] : 0;
    printf("# carpet luma beside the ball %d, 0.3 m aside %d\n", ys, yf);
    check(ok && ys < 0.9 * yf, "the ball casts a soft shadow on the carpet");

    // 6. the lens model
    const sim::Lens l = c.lens();
    double worst = 0;
    for (double x = -0.6; x <= 0.6; x += 0.05)
      for (double y = -0.45; y <= 0.45; y += 0.05) {
        const double k = l.factor(x * x + y * y);
        double ux, uy;
        l.undistort(x * k, y * k, &ux, &uy);
        worst = std::max(worst, std::hypot(ux - x, uy - y));
      }
    printf("# lens k1 %g, k2 %g: undistort(distort(x)) within %.2g\n", l.k1, l.k2, worst);
    check(worst < 1e-9, "the lens's undistortion inverts its distortion over the image");
  } catch (const std::exception &e) {
    check(false, e.what());
  }
  return tap_done();
}
