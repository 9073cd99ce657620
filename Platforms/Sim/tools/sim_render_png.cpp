// sim_render_png: renders one head-camera frame of the simulated world to a PNG.
//   sim_render_png [--out FILE] [--robot X Y YAW] [--ball X Y] [--head PAN TILT] [--other X Y YAW]
// Defaults: robot at (2.5, 0) facing the goal at +x, ball 1 m ahead, head level: ball and goal in view.
// Prints the ball's projected pixel position (where the renderer must put its centre).
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "render.h"
#include "stance.h"
#include "world.h"
#include "yuyv_png.h"

int main(int argc, char **argv) {
  std::string out = "sim_frame.png";
  double rx = 2.5, ry = 0, ryaw = 0, bx = 3.5, by = 0.2, pan = 0, tilt = -0.25;
  double ox = 3.8, oy = -0.8, oyaw = M_PI;
  for (int i = 1; i < argc; i++) {
    std::string a = argv[i];
    auto num = [&]() {
      if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
      return atof(argv[++i]);
    };
    try {
      if (a == "--out" && i + 1 < argc) out = argv[++i];
      else if (a == "--robot") { rx = num(); ry = num(); ryaw = num(); }
      else if (a == "--ball") { bx = num(); by = num(); }
      else if (a == "--head") { pan = num(); tilt = num(); }
      else if (a == "--other") { ox = num(); oy = num(); oyaw = num(); }
      else {
        fprintf(stderr, "usage: sim_render_png [--out FILE] [--robot X Y YAW] [--ball X Y] [--head PAN TILT] "
                        "[--other X Y YAW]\n");
        return 2;
      }
    } catch (const std::exception &e) {
      fprintf(stderr, "sim_render_png: %s\n", e.what());
      return 2;
    }
  }
  try {
    sim::Params p;
    sim::Model m;
    sim::load_all(&p, &m);
    sim::World w(p, m, 2, 1);
    std::vector<double> q = sim::stance_pose(m, p);
    for (size_t j = 0; j < p.joints.size(); j++) {
      if (p.joints[j] == "head_pan") q[j] = pan;
      if (p.joints[j] == "head_tilt") q[j] = tilt;
    }
    w.place_robot(0, rx, ry, ryaw, q.data());
    w.place_robot(1, ox, oy, oyaw, sim::stance_pose(m, p).data());
    w.place_ball(bx, by);
    sim::Renderer ren(p, 1);
    sim::Camera c;
    w.camera_pose(0, &c.pos, &c.rot);
    c.width = p.cam_width;
    c.height = p.cam_height;
    c.fovy = p.cam_fovy;
    std::vector<sim::Solid> solids;
    w.solids(&solids);
    std::vector<uint8_t> img((size_t)c.width * c.height * 2);
    std::vector<int> hide = {m.link_index("head_pan_link"), m.link_index("head_tilt_link")};
    ren.render(sim::shot_of(w, c, 0, &hide, 0), solids, img.data());
    std::string err;
    if (sim::yuyv_write_png(out, img.data(), c.width, c.height, &err) < 0) throw std::runtime_error(err);
    double u, v;
    if (sim::camera_project(c, w.ball_position(), &u, &v)) {
      printf("wrote %s (%dx%d); ball centre projects to (%.1f, %.1f)\n", out.c_str(), c.width, c.height, u, v);
    } else {
      printf("wrote %s (%dx%d); ball behind the camera\n", out.c_str(), c.width, c.height);
    }
  } catch (const std::exception &e) {
    fprintf(stderr, "sim_render_png: %s\n", e.what());
    return 1;
  }
  return 0;
}
