// world: the construction of the ODE world -- its parameters, the field's static parts (carpet,
// goals, objects), the ball and each robot's bodies, hinges and collision filter. The rest of the
// world by concern is listed in world_internal.h.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "world_internal.h"

namespace sim {

using namespace world_internal;

// ---------------------------------------------------------------- construction

World::World(const Params &p, const Model &m, int nrobots, uint64_t seed)
    : World(p, std::vector<Body>(std::max(nrobots, 0), Body{m, p.joints, p.servos, p.ft, p.pressure}), seed) {}

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
  dWorldSetERP(world_, kWorldErp);
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
    ode_rotation(Rm, R);
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
    set_body_pose(b, pos[i] + rot[i] * l.com, rot[i]);
    if (p_.linear_damping > 0) dBodySetLinearDamping(b, p_.linear_damping);
    rb.body[i] = b;
    const int side = pos[i].y() > 1e-6 ? 0 : 1;   // left: +y at the zero pose
    for (const Box &bx : l.boxes) {
      dGeomID g = dCreateBox(rb.space, bx.size.x(), bx.size.y(), bx.size.z());
      dGeomSetBody(g, b);
      Vec3 off = bx.pos - l.com;
      dGeomSetOffsetPosition(g, off.x(), off.y(), off.z());
      dMatrix3 BR;
      ode_rotation(bx.rot, BR);
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
  // pressure sensors: each foot's frame and the link it rides on
  rb.pressure = &body.pressure;
  if (!body.pressure.empty() && body.pressure.size() != 2) {
    throw std::runtime_error(m.file + ": foot pressure sensors for " + std::to_string(body.pressure.size()) +
                             " feet, not 2 (robot config's foot_pressure)");
  }
  for (size_t k = 0; k < body.pressure.size(); k++) {
    rb.press_frame[k] = m.frame_index(body.pressure[k].frame);
    if (rb.press_frame[k] < 0) {
      throw std::runtime_error(m.file + ": no frame '" + body.pressure[k].frame + "' (robot config's foot_pressure)");
    }
    rb.press_link[k] = m.frames[rb.press_frame[k]].link;
  }
  const int nj = (int)body.joints.size();
  rb.cmd.assign(nj, 0);
  rb.hard.assign(nj, 1);
  rb.enable.assign(nj, 1);
  rb.mode.assign(nj, 0);
  rb.actuate.assign(nj, 0);
  rb.tau.assign(nj, 0);
  rb.applied.assign(nj, 0);
  rb.stick.assign(nj, 0);
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

}  // namespace sim
