// world: ODE bodies, joints, contacts, servos and sensors of the simulated field and robots.
#include "world.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace sim {

namespace {

const int kGround = 0, kBall = 1, kRobot = 2;
const double kWorldCfm = 1e-5;
// collision category bits: 0..47 the links of a robot, 48..62 robots, 63 static parts
const int kLinkBits = 48;
const unsigned long kStatic = 1ul << 63;

Mat3 rot_z(double a) { return Eigen::AngleAxisd(a, Vec3::UnitZ()).toRotationMatrix(); }

void box_solid(const Vec3 &c, const Mat3 &R, const Vec3 &size, Solid *s) {
  s->v.clear();
  for (int i = 0; i < 8; i++) {
    Vec3 h((i & 1 ? 0.5 : -0.5) * size.x(), (i & 2 ? 0.5 : -0.5) * size.y(), (i & 4 ? 0.5 : -0.5) * size.z());
    s->v.push_back(c + R * h);
  }
  s->faces = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
}

// A cylinder of radius r and length len along R's z axis as an n-sided prism.
void cylinder_solid(const Vec3 &c, const Mat3 &R, double r, double len, int n, Solid *s) {
  s->v.clear();
  s->faces.clear();
  for (int k = 0; k < 2; k++) {
    for (int i = 0; i < n; i++) {
      double a = 2 * M_PI * i / n;
      s->v.push_back(c + R * Vec3(r * std::cos(a), r * std::sin(a), (k ? 0.5 : -0.5) * len));
    }
  }
  std::vector<int> bottom, top;
  for (int i = 0; i < n; i++) {
    s->faces.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
    bottom.push_back(n - 1 - i);
    top.push_back(n + i);
  }
  s->faces.push_back(bottom);
  s->faces.push_back(top);
}

void set_yuv(Solid *s, int y, int u, int v) {
  s->yuv[0] = (unsigned char)y;
  s->yuv[1] = (unsigned char)u;
  s->yuv[2] = (unsigned char)v;
}

}  // namespace

void params_load(const std::string &robot, Params *p) {
  Config s("sim", robot), r("robot", robot), c("camera", robot), act("actuators", robot);
  const std::string &sim_lua = s.file(), &robot_lua = r.file();
  p->timestep = s.num("physics.timestep");
  p->iterations = (int)s.num("physics.iterations");
  p->gravity = s.num("physics.gravity");
  p->rotor_inertia = s.num("physics.link_rotor_inertia");
  p->linear_damping = s.num("physics.linear_damping", 0);
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

// ---------------------------------------------------------------- construction

World::World(const Params &p, const Model &m, int nrobots, uint64_t seed)
    : World(p, std::vector<Body>(std::max(nrobots, 0), Body{m, p.joints, p.servos, p.ft}), seed) {}

World::World(const Params &p, std::vector<Body> bodies, uint64_t seed)
    : p_(p), bodies_(std::move(bodies)), seed_(seed), rng_(seed) {
  for (const Body &b : bodies_) {
    if (b.model.links.empty()) throw std::runtime_error(b.model.file + ": no links");
    if (b.model.frame_index(p_.camera_frame) < 0 && b.model.link_index(p_.camera_frame) < 0) {
      throw std::runtime_error(b.model.file + ": no link or frame '" + p_.camera_frame + "' for the camera");
    }
    if (b.servos.size() != b.joints.size()) throw std::runtime_error(b.model.file + ": no servo model for every joint");
  }
  substeps_ = (int)std::lround(p_.period / p_.timestep);
  dInitODE2(0);
  dRandSetSeed((unsigned long)(seed & 0xffffffffu));
  world_ = dWorldCreate();
  dWorldSetGravity(world_, 0, 0, -p_.gravity);
  dWorldSetQuickStepNumIterations(world_, p_.iterations);
  dWorldSetERP(world_, 0.2);
  dWorldSetCFM(world_, kWorldCfm);
  dWorldSetContactSurfaceLayer(world_, 0.0002);
  dWorldSetContactMaxCorrectingVel(world_, 1.0);
  dWorldSetAutoDisableFlag(world_, 0);
  top_ = dSimpleSpaceCreate(nullptr);
  contacts_ = dJointGroupCreate(0);
  cfb_.reserve(4096);
  cfb_owner_.reserve(4096);
  // A robot the description cannot build throws from here, and a constructor that throws gets no
  // destructor: release the ODE world first (LeakSanitizer found it, Tests/sim sim_model test 10).
  try {
    build_env();
    robots_.resize(bodies_.size());
    for (size_t r = 0; r < bodies_.size(); r++) build_robot((int)r, bodies_[r]);
    reset();
  } catch (...) {
    release();
    throw;
  }
}

World::~World() { release(); }

void World::release() {
  dJointGroupDestroy(contacts_);
  dSpaceDestroy(top_);
  dWorldDestroy(world_);
  for (GeomInfo *g : infos_) delete g;
  infos_.clear();
  dCloseODE();
}

void World::build_env() {
  auto info = [this](int kind) {
    GeomInfo *g = new GeomInfo{kind, -1, -1, -1};
    infos_.push_back(g);
    return g;
  };
  // The static parts sit at the top level, each goal in a space of its own: a robot (space) is
  // then tested against the carpet and against a goal only where their bounding boxes meet, and
  // static parts never against each other (category kStatic, collide bits without it).
  auto make_static = [](dGeomID g) {
    dGeomSetCategoryBits(g, kStatic);
    dGeomSetCollideBits(g, ~kStatic);
  };
  dGeomID ground = dCreatePlane(top_, 0, 0, 1, 0);
  dGeomSetData(ground, info(kGround));
  make_static(ground);
  // goals: posts and crossbar (seen and collidable), nets (collidable only)
  const double d = p_.post_diameter, hw = p_.goal_width / 2 + d / 2;
  const double ph = p_.goal_height + d;
  for (int side = -1; side <= 1; side += 2) {
    const double gx = side * p_.field_length / 2;
    dSpaceID env = dSimpleSpaceCreate(top_);
    make_static((dGeomID)env);
    for (int k = -1; k <= 1; k += 2) {
      dGeomID g = dCreateCylinder(env, d / 2, ph);
      dGeomSetPosition(g, gx, k * hw, ph / 2);
      dGeomSetData(g, info(kGround));
      make_static(g);
      Solid s;
      cylinder_solid(Vec3(gx, k * hw, ph / 2), Mat3::Identity(), d / 2, ph, 12, &s);
      set_yuv(&s, 235, 128, 128);
      goal_solids_.push_back(s);
    }
    Mat3 Rx = Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX()).toRotationMatrix();
    dGeomID bar = dCreateCylinder(env, d / 2, 2 * hw + d);
    make_static(bar);
    dGeomSetPosition(bar, gx, 0, p_.goal_height + d / 2);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 1, 0, 0, M_PI / 2);
    dGeomSetRotation(bar, R);
    dGeomSetData(bar, info(kGround));
    Solid s;
    cylinder_solid(Vec3(gx, 0, p_.goal_height + d / 2), Rx, d / 2, 2 * hw + d, 12, &s);
    set_yuv(&s, 235, 128, 128);
    goal_solids_.push_back(s);
    // nets: back, two sides, top; 2 cm thick so a fast ball cannot tunnel through
    const double t = 0.02, depth = p_.goal_depth, h = p_.goal_height;
    struct { double x, y, z, sx, sy, sz; } nets[] = {
        {gx + side * (depth + t / 2), 0, h / 2, t, 2 * hw, h},
        {gx + side * depth / 2, hw + t / 2, h / 2, depth, t, h},
        {gx + side * depth / 2, -hw - t / 2, h / 2, depth, t, h},
        {gx + side * depth / 2, 0, h + t / 2, depth, 2 * hw, t},
    };
    for (auto &n : nets) {
      dGeomID g = dCreateBox(env, n.sx, n.sy, n.sz);
      dGeomSetPosition(g, n.x, n.y, n.z);
      dGeomSetData(g, info(kGround));
      make_static(g);
    }
  }
  // objects on the carpet: static boxes in the top space, the carpet's contact and friction
  for (const Params::Object &o : p_.objects) {
    dGeomID g = dCreateBox(top_, o.size[0], o.size[1], o.size[2]);
    dGeomSetPosition(g, o.pos[0], o.pos[1], o.pos[2]);
    const Mat3 Rm = rot_z(o.rpy[2]) * Eigen::AngleAxisd(o.rpy[1], Vec3::UnitY()).toRotationMatrix() *
                    Eigen::AngleAxisd(o.rpy[0], Vec3::UnitX()).toRotationMatrix();
    dMatrix3 R;
    for (int a = 0; a < 3; a++) {
      for (int k = 0; k < 3; k++) R[a * 4 + k] = Rm(a, k);
      R[a * 4 + 3] = 0;
    }
    dGeomSetRotation(g, R);
    dGeomSetData(g, info(kGround));
    make_static(g);
    Solid sd;
    box_solid(Vec3(o.pos[0], o.pos[1], o.pos[2]), Rm, Vec3(o.size[0], o.size[1], o.size[2]), &sd);
    set_yuv(&sd, 120, 110, 150);   // a grey-blue board: neither field green nor line white
    goal_solids_.push_back(sd);
  }
  // ball: a hollow shell (I = 2/3 m r^2)
  const double r = p_.ball_diameter / 2;
  ball_ = dBodyCreate(world_);
  dMass mass;
  const double I = 2.0 / 3.0 * p_.ball_mass * r * r;
  dMassSetParameters(&mass, p_.ball_mass, 0, 0, 0, I, I, I, 0, 0, 0);
  dBodySetMass(ball_, &mass);
  ball_geom_ = dCreateSphere(top_, r);
  dGeomSetBody(ball_geom_, ball_);
  dGeomSetData(ball_geom_, info(kBall));
}

void World::build_robot(int r, const Body &body) {
  Robot &rb = robots_[r];
  rb.m = &body.model;
  rb.servo = &body.servos;
  const Model &m = body.model;
  const int nl = (int)m.links.size();
  rb.space = dSimpleSpaceCreate(top_);
  rb.body.assign(nl, nullptr);
  rb.hinge.assign(nl, nullptr);
  rb.fb.assign(nl, dJointFeedback());
  // zero pose, root frame at the origin
  std::vector<Vec3> pos(nl);
  std::vector<Mat3> rot(nl);
  for (int i = 0; i < nl; i++) {
    const Link &l = m.links[i];
    if (l.parent < 0) {
      pos[i] = Vec3::Zero();
      rot[i] = Mat3::Identity();
    } else {
      pos[i] = pos[l.parent] + rot[l.parent] * l.origin;
      rot[i] = rot[l.parent] * l.origin_rot;
    }
    dBodyID b = dBodyCreate(world_);
    dMass mass;
    Mat3 I = l.inertia;
    if (l.parent >= 0) I += p_.rotor_inertia * Mat3::Identity();
    dMassSetParameters(&mass, l.mass, 0, 0, 0, I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2));
    dBodySetMass(b, &mass);
    Vec3 c = pos[i] + rot[i] * l.com;
    dBodySetPosition(b, c.x(), c.y(), c.z());
    dMatrix3 R;
    for (int a = 0; a < 3; a++) {
      for (int k = 0; k < 3; k++) R[a * 4 + k] = rot[i](a, k);
      R[a * 4 + 3] = 0;
    }
    dBodySetRotation(b, R);
    if (p_.linear_damping > 0) dBodySetLinearDamping(b, p_.linear_damping);
    rb.body[i] = b;
    const int side = pos[i].y() > 1e-6 ? 0 : 1;   // left: +y at the zero pose
    for (const Box &bx : l.boxes) {
      dGeomID g = dCreateBox(rb.space, bx.size.x(), bx.size.y(), bx.size.z());
      dGeomSetBody(g, b);
      Vec3 off = bx.pos - l.com;
      dGeomSetOffsetPosition(g, off.x(), off.y(), off.z());
      dMatrix3 BR;
      for (int a = 0; a < 3; a++) {
        for (int k = 0; k < 3; k++) BR[a * 4 + k] = bx.rot(a, k);
        BR[a * 4 + 3] = 0;
      }
      dGeomSetOffsetRotation(g, BR);
      GeomInfo *gi = new GeomInfo{kRobot, r, i, bx.sole ? side : -1};
      infos_.push_back(gi);
      dGeomSetData(g, gi);
    }
    if (l.parent >= 0) {
      dJointID j = dJointCreateHinge(world_, nullptr);
      dJointAttach(j, b, rb.body[l.parent]);
      dJointSetHingeAnchor(j, pos[i].x(), pos[i].y(), pos[i].z());
      Vec3 ax = rot[i] * l.axis;
      dJointSetHingeAxis(j, ax.x(), ax.y(), ax.z());
      dJointSetHingeParam(j, dParamLoStop, l.lower);
      dJointSetHingeParam(j, dParamHiStop, l.upper);
      dJointSetHingeParam(j, dParamStopERP, 0.2);
      dJointSetHingeParam(j, dParamStopCFM, kWorldCfm);
      rb.hinge[i] = j;
    }
  }
  // shm joint order -> links
  rb.jlink.clear();
  for (const std::string &jn : body.joints) {
    int li = m.joint_link(jn);
    if (li < 0) throw std::runtime_error(m.file + ": no joint '" + jn + "' (listed in the robot config)");
    rb.jlink.push_back(li);
  }
  for (int k = 0; k < 4; k++) {
    rb.ft_link[k] = body.ft[k].empty() ? -1 : m.joint_link(body.ft[k]);
    if (!body.ft[k].empty() && rb.ft_link[k] < 0) {
      throw std::runtime_error(m.file + ": no joint '" + body.ft[k] + "' (robot config's ft)");
    }
  }
  const int nj = (int)body.joints.size();
  rb.cmd.assign(nj, 0);
  rb.hard.assign(nj, 1);
  rb.enable.assign(nj, 1);
  rb.mode.assign(nj, 0);
  // self-collision: not between a link and its parent or grandparent, nor between links whose
  // boxes already touch at the zero pose (the mesh boxes are larger than the parts)
  rb.allowed.assign(nl * nl, 1);
  auto related = [&](int a, int b) {
    int pa = m.links[a].parent, pb = m.links[b].parent;
    return a == b || pa == b || pb == a || (pa >= 0 && m.links[pa].parent == b) ||
           (pb >= 0 && m.links[pb].parent == a);
  };
  const int ng = dSpaceGetNumGeoms(rb.space);
  for (int a = 0; a < nl; a++)
    for (int b = 0; b < nl; b++)
      if (related(a, b)) rb.allowed[a * nl + b] = 0;
  for (int i = 0; i < ng; i++) {
    for (int k = i + 1; k < ng; k++) {
      dGeomID g1 = dSpaceGetGeom(rb.space, i), g2 = dSpaceGetGeom(rb.space, k);
      int a = ((GeomInfo *)dGeomGetData(g1))->link, b = ((GeomInfo *)dGeomGetData(g2))->link;
      dContactGeom cg[1];
      if (dCollide(g1, g2, 1, cg, sizeof(dContactGeom)) > 0) {
        rb.allowed[a * nl + b] = rb.allowed[b * nl + a] = 0;
      }
    }
  }
  // The same filter as ODE category/collide bits, so the spaces skip the pairs that can never make
  // a contact before their bounding-box test and our callback: category = the link's bit and the
  // robot's bit, collide = the links it may touch and every other robot (static parts pass
  // through their own collide bits, the ball has all bits). (Pairs are only left out, never added: contacts and their order stay the same.)
  const int nr = (int)robots_.size();
  if (nl <= kLinkBits && nr <= 63 - kLinkBits) {
    const unsigned long robots_mask = ((1ul << (kLinkBits + nr)) - 1) & ~((1ul << kLinkBits) - 1);
    const unsigned long self = 1ul << (kLinkBits + r);
    for (int i = 0; i < ng; i++) {
      dGeomID g = dSpaceGetGeom(rb.space, i);
      const int a = ((GeomInfo *)dGeomGetData(g))->link;
      unsigned long links = 0;
      for (int b = 0; b < nl; b++)
        if (rb.allowed[a * nl + b]) links |= 1ul << b;
      dGeomSetCategoryBits(g, (1ul << a) | self);
      dGeomSetCollideBits(g, links | (robots_mask & ~self));
    }
  }
}

// ---------------------------------------------------------------- placement

Vec3 World::body_pos(dBodyID b) const {
  const dReal *p = dBodyGetPosition(b);
  return Vec3(p[0], p[1], p[2]);
}

Mat3 World::body_rot(dBodyID b) const {
  const dReal *R = dBodyGetRotation(b);
  Mat3 M;
  M << R[0], R[1], R[2], R[4], R[5], R[6], R[8], R[9], R[10];
  return M;
}

void World::place_robot(int r, double x, double y, double yaw, const double *q) {
  Robot &rb = robots_[r];
  const Model &m = *rb.m;
  const int nl = (int)m.links.size();
  std::vector<double> ql(nl, 0.0);
  for (size_t j = 0; j < rb.jlink.size(); j++) {
    const Link &l = m.links[rb.jlink[j]];
    double v = q ? q[j] : rb.cmd[j];
    ql[rb.jlink[j]] = std::min(std::max(v, l.lower), l.upper);
  }
  std::vector<Vec3> pos(nl);
  std::vector<Mat3> rot(nl);
  double zmin = 1e9;
  for (int i = 0; i < nl; i++) {
    const Link &l = m.links[i];
    if (l.parent < 0) {
      pos[i] = Vec3::Zero();
      rot[i] = rot_z(yaw);
    } else {
      pos[i] = pos[l.parent] + rot[l.parent] * l.origin;
      rot[i] = rot[l.parent] * l.origin_rot * Eigen::AngleAxisd(ql[i], l.axis).toRotationMatrix();
    }
    for (const Box &b : l.boxes) {
      for (int c = 0; c < 8; c++) {
        Vec3 h((c & 1 ? 0.5 : -0.5) * b.size.x(), (c & 2 ? 0.5 : -0.5) * b.size.y(),
               (c & 4 ? 0.5 : -0.5) * b.size.z());
        zmin = std::min(zmin, (pos[i] + rot[i] * (b.pos + b.rot * h)).z());
      }
    }
  }
  const Vec3 shift(x, y, -zmin + 0.0002);
  for (int i = 0; i < nl; i++) {
    Vec3 c = pos[i] + shift + rot[i] * m.links[i].com;
    dBodyID b = rb.body[i];
    dBodySetPosition(b, c.x(), c.y(), c.z());
    dMatrix3 R;
    for (int a = 0; a < 3; a++) {
      for (int k = 0; k < 3; k++) R[a * 4 + k] = rot[i](a, k);
      R[a * 4 + 3] = 0;
    }
    dBodySetRotation(b, R);
    dBodySetLinearVel(b, 0, 0, 0);
    dBodySetAngularVel(b, 0, 0, 0);
  }
  rb.vel_start = Vec3::Zero();
  rb.push_left = 0;
}

void World::place_ball(double x, double y, double vx, double vy) {
  const double r = p_.ball_diameter / 2;
  dBodySetPosition(ball_, x, y, r);
  dBodySetLinearVel(ball_, vx, vy, 0);
  dBodySetAngularVel(ball_, -vy / r, vx / r, 0);   // rolling without slipping
  const dQuaternion q0 = {1, 0, 0, 0};
  dBodySetQuaternion(ball_, q0);
  in_goal_ = 0;
  ball_touch_ = -1;
}

void World::reset() {
  const int nstart = (int)p_.start.size() / 3;
  for (int r = 0; r < nrobots(); r++) {
    const double *s = &p_.start[3 * (r % nstart)];
    place_robot(r, s[0], s[1], s[2]);
  }
  place_ball(p_.ball_start[0], p_.ball_start[1]);
  score_[0] = score_[1] = 0;
  // a reset world evolves the same whenever the reset happens: restart every random sequence
  dRandSetSeed((unsigned long)(seed_ & 0xffffffffu));
  rng_.seed(seed_);
  normal_.reset();
}

void World::push(int r, double fx, double fy, double duration) {
  Robot &rb = robots_[r];
  rb.push_force = Vec3(fx, fy, 0);
  rb.push_left = duration;
}

// ---------------------------------------------------------------- stepping

int World::set_command(int r, const double *cmd, const double *hardness, const int *enable) {
  Robot &rb = robots_[r];
  int bad = 0;
  for (size_t j = 0; j < rb.cmd.size(); j++) {
    if (cmd) {
      if (std::isfinite(cmd[j])) rb.cmd[j] = cmd[j]; else bad++;
    }
    if (hardness) {
      if (std::isfinite(hardness[j])) rb.hard[j] = std::min(std::max(hardness[j], 0.0), 1.0); else bad++;
    }
    if (enable) rb.enable[j] = enable[j] != 0;
  }
  return bad;
}

void World::servo_update(Robot &rb) {
  for (size_t j = 0; j < rb.jlink.size(); j++) {
    const Link &l = rb.m->links[rb.jlink[j]];
    dJointID h = rb.hinge[rb.jlink[j]];
    if (rb.enable[j] && rb.hard[j] > 0) {
      if (rb.mode[j] != 1) {
        dJointSetHingeParam(h, dParamCFM, kWorldCfm);
        rb.mode[j] = 1;
      }
      const double target = std::min(std::max(rb.cmd[j], l.lower), l.upper);
      double v = (*rb.servo)[j].gain * (target - dJointGetHingeAngle(h));
      v = std::min(std::max(v, -l.velocity), l.velocity);
      dJointSetHingeParam(h, dParamVel, v);
      dJointSetHingeParam(h, dParamFMax, rb.hard[j] * l.effort);
    } else {
      // torque off: the gear train back-drives with viscous damping (and some friction)
      if (rb.mode[j] != 2) {
        dJointSetHingeParam(h, dParamCFM, l.damping > 0 ? 1.0 / l.damping : kWorldCfm);
        rb.mode[j] = 2;
      }
      dJointSetHingeParam(h, dParamVel, 0);
      dJointSetHingeParam(h, dParamFMax, l.damping > 0 ? l.effort : l.friction);
    }
  }
}

void World::near_cb(void *data, dGeomID o1, dGeomID o2) {
  static_cast<World *>(data)->collide(o1, o2);
}

void World::collide(dGeomID o1, dGeomID o2) {
  if (dGeomIsSpace(o1) || dGeomIsSpace(o2)) {
    dSpaceCollide2(o1, o2, this, &World::near_cb);
    return;
  }
  const GeomInfo *a = (const GeomInfo *)dGeomGetData(o1), *b = (const GeomInfo *)dGeomGetData(o2);
  if (a->kind == kGround && b->kind == kGround) return;
  if (a->kind == kRobot && b->kind == kRobot && a->robot == b->robot) {
    const int nl = (int)robots_[a->robot].m->links.size();
    if (!robots_[a->robot].allowed[a->link * nl + b->link]) return;
  }
  dContact c[16];
  const int maxc = std::min(16, p_.max_contacts);
  int n = dCollide(o1, o2, maxc, &c[0].geom, sizeof(dContact));
  if (n <= 0) return;
  const double h = p_.timestep;
  dSurfaceParameters s{};
  const bool ball = a->kind == kBall || b->kind == kBall;
  const bool ground = a->kind == kGround || b->kind == kGround;
  if (ball && ground) {
    // carpet under the ball: sliding friction, rolling resistance, a bounce
    s.mode = dContactApprox1 | dContactRolling | dContactBounce | dContactSoftERP | dContactSoftCFM;
    s.mu = p_.ball_mu;
    s.rho = s.rho2 = p_.ball_rolling;
    s.rhoN = p_.ball_rolling;
    s.bounce = p_.ball_bounce;
    s.bounce_vel = 0.2;
    const double kp = 2e4, kd = 20;
    s.soft_erp = h * kp / (h * kp + kd);
    s.soft_cfm = 1 / (h * kp + kd);
  } else if (ball) {
    if (a->kind == kRobot || b->kind == kRobot) {
      ball_touch_ = a->kind == kRobot ? a->robot : b->robot;
      ball_touch_time_ = time_;
    }
    s.mode = dContactApprox1 | dContactBounce;
    s.mu = 0.5;
    s.bounce = p_.ball_bounce;
    s.bounce_vel = 0.1;
  } else {
    s.mode = dContactApprox1 | dContactSoftERP | dContactSoftCFM;
    s.mu = ground ? p_.mu : p_.robot_mu;
    s.soft_erp = h * p_.kp / (h * p_.kp + p_.kd);
    s.soft_cfm = 1 / (h * p_.kp + p_.kd);
  }
  dBodyID b1 = dGeomGetBody(o1), b2 = dGeomGetBody(o2);
  for (int i = 0; i < n; i++) {
    c[i].surface = s;
    dJointID j = dJointCreateContact(world_, contacts_, &c[i]);
    dJointAttach(j, b1, b2);
    // vertical force under the soles
    const GeomInfo *sole = a->sole >= 0 ? a : (b->sole >= 0 ? b : nullptr);
    if (sole && ground && cfb_.size() < cfb_.capacity()) {
      cfb_.push_back(dJointFeedback());
      cfb_owner_.push_back({sole->robot * 4 + sole->sole * 2 + (sole == a ? 0 : 1), 0});
      dJointSetFeedback(j, &cfb_.back());
    }
  }
}

void World::physics_step() {
  for (Robot &rb : robots_) {
    servo_update(rb);
    if (rb.push_left > 0) {
      dBodyAddForce(rb.body[0], rb.push_force.x(), rb.push_force.y(), rb.push_force.z());
      rb.push_left -= p_.timestep;
    }
  }
  // air drag on the ball: 0.5 * rho * Cd * A * v^2
  {
    const dReal *v = dBodyGetLinearVel(ball_);
    const double r = p_.ball_diameter / 2, speed = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    const double k = 0.5 * 1.2 * 0.47 * M_PI * r * r * speed;
    dBodyAddForce(ball_, -k * v[0], -k * v[1], -k * v[2]);
  }
  cfb_.clear();
  cfb_owner_.clear();
  dSpaceCollide(top_, this, &World::near_cb);
  for (Robot &rb : robots_) dSpaceCollide(rb.space, this, &World::near_cb);
  dWorldQuickStep(world_, p_.timestep);
  for (size_t i = 0; i < cfb_.size(); i++) {
    const int code = cfb_owner_[i].first;
    const int r = code / 4, side = (code / 2) % 2, which = code % 2;
    robots_[r].foot_acc[side] += which == 0 ? cfb_[i].f1[2] : cfb_[i].f2[2];
  }
  dJointGroupEmpty(contacts_);
  check_goal();
  time_ += p_.timestep;
}

void World::set_hinge_feedback(bool on) {
  for (Robot &rb : robots_) {
    for (size_t i = 0; i < rb.hinge.size(); i++) {
      if (rb.hinge[i]) dJointSetFeedback(rb.hinge[i], on ? &rb.fb[i] : nullptr);
    }
  }
}

void World::check_goal() {
  const dReal *b = dBodyGetPosition(ball_);
  const double r = p_.ball_diameter / 2;
  const double line = p_.field_length / 2 + p_.line_width / 2 + r;
  if (in_goal_ != 0) {
    if (std::fabs(b[0]) < p_.field_length / 2) in_goal_ = 0;
    return;
  }
  if (std::fabs(b[0]) > line && std::fabs(b[1]) < p_.goal_width / 2 && b[2] < p_.goal_height) {
    in_goal_ = b[0] > 0 ? 1 : -1;
    score_[b[0] > 0 ? 0 : 1]++;
  }
}

void World::step() {
  for (Robot &rb : robots_) {
    const dReal *v = dBodyGetLinearVel(rb.body[0]);
    rb.vel_start = Vec3(v[0], v[1], v[2]);
    rb.foot_acc[0] = rb.foot_acc[1] = 0;
  }
  // joint torques (`load`) are read once per tick: ODE computes the hinges' feedback in the last
  // physics step only (feedback is output, it does not enter the dynamics)
  for (int i = 0; i < substeps_; i++) {
    if (i == substeps_ - 1) set_hinge_feedback(true);
    physics_step();
  }
  set_hinge_feedback(false);
  for (Robot &rb : robots_) {
    const dReal *v = dBodyGetLinearVel(rb.body[0]);
    Vec3 a = (Vec3(v[0], v[1], v[2]) - rb.vel_start) / p_.period + Vec3(0, 0, p_.gravity);
    Vec3 ab = body_rot(rb.body[0]).transpose() * a;
    for (int k = 0; k < 3; k++) rb.accel[k] = ab[k];
    rb.foot_acc[0] /= substeps_;
    rb.foot_acc[1] /= substeps_;
  }
}

// ---------------------------------------------------------------- sensing

std::vector<double> World::joint_positions(int r) const {
  const Robot &rb = robots_[r];
  std::vector<double> q(rb.jlink.size());
  for (size_t j = 0; j < q.size(); j++) q[j] = dJointGetHingeAngle(rb.hinge[rb.jlink[j]]);
  return q;
}

void World::sense(int r, Sensors *s) {
  Robot &rb = robots_[r];
  const size_t nj = rb.jlink.size();
  s->position.resize(nj);
  s->velocity.resize(nj);
  s->load.resize(nj);
  for (size_t j = 0; j < nj; j++) {
    const Servo &sv = (*rb.servo)[j];
    const double qstep = 2 * M_PI / sv.resolution, vstep = sv.speed_unit;
    const int li = rb.jlink[j];
    dJointID h = rb.hinge[li];
    s->position[j] = std::round(dJointGetHingeAngle(h) / qstep) * qstep;
    s->velocity[j] = std::round(dJointGetHingeAngleRate(h) / vstep) * vstep;
    dVector3 ax;
    dJointGetHingeAxis(h, ax);
    const dJointFeedback &f = rb.fb[li];
    s->load[j] = f.t1[0] * ax[0] + f.t1[1] * ax[1] + f.t1[2] * ax[2];
  }
  const Mat3 R = body_rot(rb.body[0]);
  const dReal *w = dBodyGetAngularVel(rb.body[0]);
  Vec3 g = R.transpose() * Vec3(w[0], w[1], w[2]);
  for (int k = 0; k < 3; k++) {
    s->gyro[k] = g[k] + p_.gyro_noise * normal_(rng_);
    s->accel[k] = rb.accel[k] + p_.accel_noise * normal_(rng_);
  }
  s->angle[0] = std::atan2(R(2, 1), R(2, 2));
  s->angle[1] = std::asin(std::min(1.0, std::max(-1.0, -R(2, 0))));
  s->angle[2] = std::atan2(R(1, 0), R(0, 0));
  s->foot_force[0] = rb.foot_acc[0];
  s->foot_force[1] = rb.foot_acc[1];
  sense_ft(rb, s->ft);
}

void World::link_pose(int r, int link, Vec3 *pos, Mat3 *rot) const {
  dBodyID b = robots_[r].body[link];
  *rot = body_rot(b);
  *pos = body_pos(b) - *rot * robots_[r].m->links[link].com;
}

Truth World::truth(int r) const {
  Truth t;
  Vec3 p;
  Mat3 R;
  link_pose(r, 0, &p, &R);
  t.x = p.x();
  t.y = p.y();
  t.z = p.z();
  t.yaw = std::atan2(R(1, 0), R(0, 0));
  t.pitch = std::asin(std::min(1.0, std::max(-1.0, -R(2, 0))));
  t.roll = std::atan2(R(2, 1), R(2, 2));
  t.fallen = std::acos(std::min(1.0, std::max(-1.0, R(2, 2)))) > p_.fall_angle;
  const dReal *bp = dBodyGetPosition(ball_), *bv = dBodyGetLinearVel(ball_);
  t.ball[0] = bp[0];
  t.ball[1] = bp[1];
  t.ball[2] = bp[2];
  t.ball[3] = bv[0];
  t.ball[4] = bv[1];
  return t;
}

Vec3 World::ball_position() const { return body_pos(ball_); }

Mat3 World::ball_rotation() const { return body_rot(ball_); }

int World::team(int r) const {
  if (r < (int)p_.robot_team.size()) return p_.robot_team[r];
  return r < ((int)robots_.size() + 1) / 2 ? 1 : 2;
}

void World::camera_pose(int r, Vec3 *pos, Mat3 *rot) const {
  const Model &m = *robots_[r].m;
  int fi = m.frame_index(p_.camera_frame);
  Vec3 lp;
  Mat3 lR;
  if (fi >= 0) {
    const Frame &f = m.frames[fi];
    link_pose(r, f.link, &lp, &lR);
    *pos = lp + lR * f.pos;
    *rot = lR * f.rot;
  } else {
    link_pose(r, m.link_index(p_.camera_frame), pos, rot);
  }
}

void World::snapshot(Scene *s) const {
  s->first.resize(robots_.size());
  size_t n = 0;
  for (size_t r = 0; r < robots_.size(); r++) {
    s->first[r] = n;
    n += robots_[r].m->links.size();
  }
  s->link_pos.resize(n);
  s->link_rot.resize(n);
  for (size_t r = 0; r < robots_.size(); r++)
    for (size_t i = 0; i < robots_[r].m->links.size(); i++)
      link_pose((int)r, (int)i, &s->link_pos[s->first[r] + i], &s->link_rot[s->first[r] + i]);
  s->ball = ball_position();
  s->ball_rot = ball_rotation();
}

void World::solids(std::vector<Solid> *out) const {
  Scene s;
  snapshot(&s);
  solids(s, out);
}

void World::solids(const Scene &scene, std::vector<Solid> *out) const {
  out->clear();
  for (const Solid &s : goal_solids_) out->push_back(s);
  for (size_t r = 0; r < scene.first.size(); r++) {
    const Model &m = *robots_[r].m;
    for (size_t i = 0; i < m.links.size(); i++) {
      const Vec3 &p = scene.link_pos[scene.first[r] + i];
      const Mat3 &R = scene.link_rot[scene.first[r] + i];
      // the torso (the root link) wears the team's jersey, the head is dark, the rest grey
      const unsigned char *jersey = p_.team_yuv[team((int)r) - 1];
      const bool dark = m.links[i].name.find("head") != std::string::npos;
      for (const Box &b : m.links[i].boxes) {
        Solid s;
        box_solid(p + R * b.pos, R * b.rot, b.size, &s);
        if (i == 0) set_yuv(&s, jersey[0], jersey[1], jersey[2]);
        else if (dark) set_yuv(&s, 60, 128, 128);
        else set_yuv(&s, 120, 128, 128);
        s.robot = (int)r;
        s.link = (int)i;
        out->push_back(s);
      }
    }
  }
}

}  // namespace sim

namespace sim {

std::string hrp_root() {
  const char *r = getenv("HRP_ROOT");
  return r && *r ? r : HRP_ROOT_DEFAULT;
}

std::string robot_dir(const std::string &robot) { return hrp_root() + "/Config/robots/" + robot; }

// Every joint of a description is driven: each must be in the robot's joint list.
static void check_joints(const Params &p, const Model &m) {
  for (const Link &l : m.links) {
    if (!l.joint.empty() && std::find(p.joints.begin(), p.joints.end(), l.joint) == p.joints.end()) {
      throw std::runtime_error(p.urdf + ": joint '" + l.joint + "' is not in the robot config's joints");
    }
  }
}

void load_all(Params *p, Model *m) {
  params_load("", p);
  std::string err;
  if (model_load(p->urdf, m, &err) < 0) throw std::runtime_error(err);
  check_joints(*p, *m);
}

void load_bodies(const std::vector<std::string> &robots, std::vector<Params> *params, std::vector<Body> *bodies) {
  params->clear();
  bodies->clear();
  for (size_t r = 0; r < robots.size(); r++) {
    size_t same = 0;   // a body already loaded is copied, not read again
    while (same < r && robots[same] != robots[r]) same++;
    if (same < r) {
      params->push_back((*params)[same]);
      bodies->push_back((*bodies)[same]);
      continue;
    }
    Params p;
    params_load(robots[r], &p);
    Body b;
    std::string err;
    if (model_load(p.urdf, &b.model, &err) < 0) throw std::runtime_error(err);
    check_joints(p, b.model);
    b.joints = p.joints;
    b.servos = p.servos;
    b.ft = p.ft;
    // one world steps every robot with one control period
    if (r > 0 && std::fabs(p.period - (*params)[0].period) > 1e-12) {
      throw std::runtime_error("robot '" + robots[r] + "' has a control period of " + std::to_string(p.period) +
                               " s, robot '" + robots[0] + "' one of " + std::to_string((*params)[0].period) +
                               " s: one world steps all robots with one period (robot.lua 'period')");
    }
    params->push_back(p);
    bodies->push_back(std::move(b));
  }
}

}  // namespace sim
