// world_params: a body's configs (sim.lua, robot.lua, camera.lua, actuators.lua through the
// Config layers) into the world's Params, checked where they are read.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "pressure.h"
#include "world_internal.h"

namespace sim {

void params_load(const std::string &robot, Params *p) {
  Config s("sim", robot), r("robot", robot), c("camera", robot), act("actuators", robot);
  const std::string &sim_lua = s.file(), &robot_lua = r.file();
  p->timestep = s.num("physics.timestep");
  p->iterations = (int)s.num("physics.iterations");
  p->gravity = s.num("physics.gravity");
  p->rotor_inertia = s.num("physics.link_rotor_inertia");
  p->linear_damping = s.num("physics.linear_damping", 0);
  p->gear_presliding = s.num("physics.gear_presliding");
  if (!(p->gear_presliding >= 0)) throw std::runtime_error(sim_lua + ": physics.gear_presliding must be >= 0 (rad)");
  p->temperature = s.num("servo.temperature");
  p->mu = s.num("contact.mu");
  p->kp = s.num("contact.kp");
  p->kd = s.num("contact.kd");
  p->max_contacts = (int)s.num("contact.max_contacts");
  p->robot_mu = s.num("contact.robot_mu");
  p->gyro_noise = s.num("imu.gyro_noise");
  p->accel_noise = s.num("imu.accel_noise");
  p->field_length = s.num("field.length");
  p->field_width = s.num("field.width");
  p->border = s.num("field.border");
  p->line_width = s.num("field.line_width");
  p->circle_diameter = s.num("field.centre_circle_diameter");
  p->goal_area_length = s.num("field.goal_area_length");
  p->goal_area_width = s.num("field.goal_area_width");
  p->penalty_area_length = s.num("field.penalty_area_length");
  p->penalty_area_width = s.num("field.penalty_area_width");
  p->penalty_mark_distance = s.num("field.penalty_mark_distance");
  p->penalty_mark_size = s.num("field.penalty_mark_size");
  p->goal_width = s.num("goal.width");
  p->goal_height = s.num("goal.height");
  p->goal_depth = s.num("goal.depth");
  p->post_diameter = s.num("goal.post_diameter");
  p->ball_diameter = s.num("ball.diameter");
  p->ball_mass = s.num("ball.mass");
  p->ball_mu = s.num("ball.mu");
  p->ball_rolling = s.num("ball.rolling");
  p->ball_bounce = s.num("ball.bounce");
  std::vector<double> bs = s.nums("ball.start");
  if (bs.size() != 2) throw std::runtime_error(sim_lua + ": 'ball.start' must be {x, y}");
  p->ball_start[0] = bs[0];
  p->ball_start[1] = bs[1];
  p->ball_kind = s.str("ball.kind");
  if (p->ball_kind != "orange" && p->ball_kind != "white") {
    throw std::runtime_error(sim_lua + ": 'ball.kind' is '" + p->ball_kind + "', not 'orange' or 'white'");
  }
  for (int t = 0; t < 2; t++) {
    const std::string key = "teams.colours." + std::to_string(t + 1);
    std::vector<double> yuv = s.nums(key);
    if (yuv.size() != 3) throw std::runtime_error(sim_lua + ": '" + key + "' must be {Y, U, V}");
    for (int k = 0; k < 3; k++) {
      if (!(yuv[k] >= 0 && yuv[k] <= 255)) throw std::runtime_error(sim_lua + ": '" + key + "' must be in 0..255");
      p->team_yuv[t][k] = (unsigned char)std::lround(yuv[k]);
    }
  }
  p->robot_team.clear();
  for (int i = 1; s.has("teams.of_robot." + std::to_string(i)); i++) {
    const double t = s.num("teams.of_robot." + std::to_string(i));
    if (t != 1 && t != 2) {
      throw std::runtime_error(sim_lua + ": 'teams.of_robot[" + std::to_string(i) + "]' must be 1 or 2");
    }
    p->robot_team.push_back((int)t);
  }
  p->camera_frame = s.str("camera.frame");
  // the camera's image and optics are the body's (camera.lua); its pose is the URDF's camera frame
  p->cam_width = (int)c.num("width");
  p->cam_height = (int)c.num("height");
  p->cam_rate = c.num("fps");
  p->cam_fovy = c.num("fovy");
  p->cam_latency_ticks = (int)s.num("camera.latency_ticks");
  p->cam_noise = s.num("camera.noise");
  realism_load(s, &p->realism);
  // the calibration (OpenCV's convention), robot data shared with the vision's projection
  const std::string &camera_lua = c.file();
  p->cam_fx = c.num("intrinsics.fx");
  p->cam_fy = c.num("intrinsics.fy");
  p->cam_cx = c.num("intrinsics.cx");
  p->cam_cy = c.num("intrinsics.cy");
  p->cam_k1 = c.num("distortion.k1");
  p->cam_k2 = c.num("distortion.k2");
  if (!(p->cam_fx > 0 && p->cam_fy > 0) || !std::isfinite(p->cam_cx) || !std::isfinite(p->cam_cy) ||
      !std::isfinite(p->cam_k1) || !std::isfinite(p->cam_k2)) {
    throw std::runtime_error(camera_lua + ": 'intrinsics' needs fx, fy > 0 and finite cx, cy; 'distortion' finite k1, k2");
  }
  p->start.clear();
  for (int i = 1; s.has("start." + std::to_string(i) + ".1"); i++) {
    std::vector<double> v = s.nums("start." + std::to_string(i));
    if (v.size() != 3) throw std::runtime_error(sim_lua + ": 'start[" + std::to_string(i) + "]' must be {x, y, yaw}");
    p->start.insert(p->start.end(), v.begin(), v.end());
  }
  if (p->start.empty()) throw std::runtime_error(sim_lua + ": missing list 'start'");
  p->objects.clear();
  for (int i = 1; s.has("objects." + std::to_string(i)); i++) {
    const std::string key = "objects." + std::to_string(i);
    Params::Object o{};
    struct { const char *name; double *dst; bool positive; } parts[] = {
        {"pos", o.pos, false}, {"size", o.size, true}, {"rpy", o.rpy, false}};
    for (auto &part : parts) {
      std::vector<double> v = s.nums(key + "." + part.name);
      if (v.size() != 3 || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]) ||
          (part.positive && (v[0] <= 0 || v[1] <= 0 || v[2] <= 0)))
        throw std::runtime_error(sim_lua + ": '" + key + "." + part.name + "' must be 3 finite numbers" +
                                 (part.positive ? " above 0" : ""));
      std::copy(v.begin(), v.end(), part.dst);
    }
    p->objects.push_back(o);
  }
  p->fall_angle = s.num("fall_angle");
  p->watchdog = s.num("watchdog");
  p->stall_cycles = (int)s.num("stall_cycles");
  p->stall_cpu = s.num("stall_cpu");
  p->safe_hardness = s.num("safe_hardness");
  p->start_hardness = s.num("start_hardness");
  p->battery = s.num("battery");
  p->name = r.str("name");
  p->joints = r.strs("joints");
  p->lleg = r.has("groups.lleg") ? r.strs("groups.lleg") : std::vector<std::string>();
  p->rleg = r.has("groups.rleg") ? r.strs("groups.rleg") : std::vector<std::string>();
  p->head = r.has("groups.head") ? r.strs("groups.head") : std::vector<std::string>();
  // 6-axis force/torque sensors: { lfoot = joint, rfoot = ..., lhand = ..., rhand = ... }, each optional
  static const char *const ft_slots[4] = {"lfoot", "rfoot", "lhand", "rhand"};
  for (int k = 0; k < 4; k++) {
    const std::string key = std::string("ft.") + ft_slots[k];
    p->ft[k] = r.has(key) ? r.str(key) : "";
    if (r.has(key) && std::find(p->joints.begin(), p->joints.end(), p->ft[k]) == p->joints.end()) {
      throw std::runtime_error(robot_lua + ": '" + key + "' is '" + p->ft[k] + "', not one of its joints");
    }
  }
  // point pressure sensors under the feet: { lfoot = { frame = F, points = { {x, y}, ... } }, rfoot = ... },
  // both feet or none; the frame is checked against the description where the robot is built
  p->pressure.clear();
  if (r.has("foot_pressure")) {
    for (const char *foot : {"lfoot", "rfoot"}) {
      const std::string key = std::string("foot_pressure.") + foot;
      if (!r.has(key + ".frame")) throw std::runtime_error(robot_lua + ": missing string '" + key + ".frame'");
      PressureFoot pf;
      pf.frame = r.str(key + ".frame");
      for (int i = 1; r.has(key + ".points." + std::to_string(i)); i++) {
        std::vector<double> v = r.nums(key + ".points." + std::to_string(i));
        if (v.size() != 2) throw std::runtime_error(robot_lua + ": '" + key + ".points[" + std::to_string(i) + "]' must be {x, y}");
        pf.xy.insert(pf.xy.end(), v.begin(), v.end());
      }
      if (!pressure_layout_ok(pf.xy)) {
        throw std::runtime_error(robot_lua + ": '" + key + ".points' must be at least 3 finite {x, y}, not all on one line");
      }
      p->pressure.push_back(pf);
    }
  }
  // each joint's servo: the actuator model robot.lua names for it
  p->servos.clear();
  for (const std::string &j : p->joints) {
    if (!r.has("actuator." + j)) throw std::runtime_error(robot_lua + ": missing string 'actuator." + j + "' (its model)");
    Servo sv;
    sv.model = r.str("actuator." + j);
    if (!act.has(sv.model + ".gain")) {
      throw std::runtime_error(robot_lua + ": actuator." + j + " is '" + sv.model + "', not a model of " + act.file());
    }
    sv.gain = act.num(sv.model + ".gain");
    sv.resolution = act.num(sv.model + ".resolution");
    sv.speed_unit = act.num(sv.model + ".speed_unit");
    if (!(sv.gain > 0) || !(sv.resolution >= 2) || !(sv.speed_unit > 0)) {
      throw std::runtime_error(act.file() + ": model '" + sv.model + "' needs gain, speed_unit > 0, resolution >= 2");
    }
    p->servos.push_back(sv);
  }
  p->period = r.num("period");
  p->urdf = r.str("description");
  if (!p->urdf.empty() && p->urdf[0] != '/') p->urdf = robot_dir(r.str("name")) + "/" + p->urdf;
  double n = p->period / p->timestep;
  if (!(p->timestep > 0) || std::fabs(n - std::round(n)) > 1e-6 || n < 1) {
    throw std::runtime_error(sim_lua + ": 'physics.timestep' must divide the period of " + robot_lua);
  }
  if (p->cam_width < 2 || p->cam_width % 2 || p->cam_height < 2 || !(p->cam_rate > 0)) {
    throw std::runtime_error(sim_lua + ": 'camera' needs an even width, a height and a positive rate");
  }
}

}  // namespace sim
