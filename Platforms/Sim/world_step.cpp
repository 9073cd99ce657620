// world_step: one tick of the world -- the servo commands, each joint's velocity motor (or its
// back-driven gear train, or its torque drive), pushes, the ball's air drag, the contacts and their
// surfaces, the physics steps, the sole forces and the goals.
#include <algorithm>
#include <cmath>

#include "world_internal.h"

namespace sim {

using namespace world_internal;

int World::set_command(int r, const double *cmd, const double *hardness, const int *enable, const int *mode,
                       const double *torque) {
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
    if (mode) rb.actuate[j] = mode[j] == 1;
    if (torque) {
      if (std::isfinite(torque[j])) rb.tau[j] = torque[j]; else bad++;
    }
  }
  return bad;
}

void World::servo_update(Robot &rb) {
  for (size_t j = 0; j < rb.jlink.size(); j++) {
    const Link &l = rb.m->links[rb.jlink[j]];
    dJointID h = rb.hinge[rb.jlink[j]];
    rb.applied[j] = 0;
    if (rb.enable[j] && rb.actuate[j]) {
      // torque mode: a current-controlled drive, from the actuator's data only (Config/common/
      // actuators.lua through the URDF joint: effort, damping, friction). The commanded torque is
      // applied on the hinge within the stall torque (effort) and the drive's speed-torque line: at
      // joint speed w the motor gives at most effort - damping * w in the direction of w (the back-EMF
      // damping of the torque-off model, damping = torque / speed: no torque at the no-load speed)
      // and brakes with at most effort. The gear's friction is ODE's dry friction: the hinge's motor,
      // no longer the servo, holds the joint with at most `friction` N*m where the gear stuck
      // (`stick`), which follows the joint once it is more than physics.gear_presliding away (the
      // gear slips). Holding a place, not only speed 0: QuickStep's rows are not converged at a
      // body's iterations (40 on the Hubo2+), and a row that only asks for speed 0 lets a joint
      // under a load well below its friction creep at a steady rate with the row's force near zero
      // (the Hubo2+'s shoulder 4-5 mrad/s at 40, none at 400); its angle error is corrected as ODE
      // corrects every joint's (the world's ERP per step), so the creep is undone as a servo's is.
      // The friction's limit stays the data's. The rotor inertia is the world's
      // (physics.link_rotor_inertia on every moving link), as in position mode. Hardness does not
      // apply. Not modelled (no data): the current loop's bandwidth, torque ripple, heating.
      const double angle = dJointGetHingeAngle(h);
      if (rb.mode[j] != 3) {
        dJointSetHingeParam(h, dParamCFM, kWorldCfm);
        rb.mode[j] = 3;
        rb.stick[j] = angle;
      }
      rb.stick[j] = std::min(std::max(rb.stick[j], angle - p_.gear_presliding), angle + p_.gear_presliding);
      dJointSetHingeParam(h, dParamVel, kWorldErp / p_.timestep * (rb.stick[j] - angle));
      dJointSetHingeParam(h, dParamFMax, l.friction);
      const double bw = l.damping * dJointGetHingeAngleRate(h);
      const double hi = std::min(l.effort, l.effort - bw), lo = std::max(-l.effort, -l.effort - bw);
      rb.applied[j] = std::min(std::max(rb.tau[j], lo), hi);
      dJointAddHingeTorque(h, rb.applied[j]);
    } else if (rb.enable[j] && rb.hard[j] > 0) {
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
    // the ground's force on the robot's soles (foot_force, the truth's centre of pressure) and on the
    // feet that carry pressure sensors. Only those contacts get a feedback: with a feedback on every
    // contact of a robot with the ground, the same lockstep run no longer repeated itself (the
    // DARwIn-OP's turn in darwin_walk_test measured 1.233 or 1.087 rad/s from run to run).
    const GeomInfo *rob = a->kind == kRobot ? a : (b->kind == kRobot ? b : nullptr);
    const Robot *rr = rob ? &robots_[rob->robot] : nullptr;
    const int press = !rr ? -1 : rr->press_link[0] == rob->link ? 0 : rr->press_link[1] == rob->link ? 1 : -1;
    if (rob && (rob->sole >= 0 || press >= 0) && ground && cfb_.size() < cfb_.capacity()) {
      cfb_.push_back(dJointFeedback());
      const dReal *cp = c[i].geom.pos;
      cfb_owner_.push_back({rob->robot, rob->sole, press, rob == a ? 0 : 1, Vec3(cp[0], cp[1], cp[2])});
      dJointSetFeedback(j, &cfb_.back());
    }
  }
}

void World::physics_step() {
  for (size_t r = 0; r < robots_.size(); r++) {
    Robot &rb = robots_[r];
    servo_update(rb);
    if (rb.push_left > 0) {
      dBodyAddForce(rb.body[0], rb.push_force.x(), rb.push_force.y(), rb.push_force.z());
      rb.push_left -= p_.timestep;
    }
    if (rb.push_at_left > 0) {
      Vec3 lp;
      Mat3 lR;
      link_pose((int)r, rb.push_at, &lp, &lR);
      const Vec3 at = lp + lR * rb.push_at_offset;
      dBodyAddForceAtPos(rb.body[rb.push_at], rb.push_at_force.x(), rb.push_at_force.y(), rb.push_at_force.z(),
                         at.x(), at.y(), at.z());
      rb.push_at_left -= p_.timestep;
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
    const ContactUse &u = cfb_owner_[i];
    Robot &rb = robots_[u.robot];
    const dReal *fv = u.which == 0 ? cfb_[i].f1 : cfb_[i].f2;
    const Vec3 f(fv[0], fv[1], fv[2]), m = u.pos.cross(f);
    rb.ground_f += f;
    rb.ground_m += m;
    if (u.sole >= 0) rb.foot_acc[u.sole] += f.z();
    if (u.press >= 0) {
      rb.press_f[u.press] += f;
      rb.press_m[u.press] += m;
    }
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
    rb.ground_f = rb.ground_m = Vec3::Zero();
    for (int k = 0; k < 2; k++) rb.press_f[k] = rb.press_m[k] = Vec3::Zero();
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
    rb.ground_f /= substeps_;
    rb.ground_m /= substeps_;
    for (int k = 0; k < 2; k++) {
      rb.press_f[k] /= substeps_;
      rb.press_m[k] /= substeps_;
    }
  }
}

}  // namespace sim
