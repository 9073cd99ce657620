// The kinematic whole-body controller behind wbc.h: tasks from the rigid-body model
// (Modules/dynamics), stacked by level over the contacts, solved by priority.hpp, kept inside the
// joint limits and integrated into joint angles.
#include "wbc/wbc.h"
#include "wbc/priority.hpp"
#include "wbc/tasks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <string>

using wholebody::Level;
using wholebody::LevelReport;
using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {

constexpr double CONTACT_GAIN = 20;     // 1/s: the contacts' drift in the model corrected in 50 ms
constexpr int TOP = -1000000;           // the contacts' and the locked joints' level, above any task's

int fail(wbc *w, const std::string &msg);

double thread_cpu_us() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e6 + ts.tv_nsec * 1e-3;
}

bool all_finite(const double *x, int n) {
  for (int i = 0; i < n; i++)
    if (!std::isfinite(x[i])) return false;
  return true;
}

}  // namespace

struct wbc {
  wholebody::Body body;
  double dt = 0;
  VectorXd lo, hi, speed;             // joint limits (robot order)
  std::vector<wholebody::Task> contacts;    // POSE tasks at TOP
  std::vector<wholebody::Task> tasks;
  std::string err;
  double step_us = 0;
  double max_lean = 0;                // rad of the base from upright (0: no bound)
  bool leaning = false;               // the last step stopped the base's tilting at max_lean
  bool ready = false;                 // wbc_reset done
};

namespace {

int fail(wbc *w, const std::string &msg) {
  w->err = msg;
  return -1;
}

int bad_id(wbc *w, int id) {
  if (id >= 0 && id < (int)w->tasks.size()) return 0;
  return fail(w, "no task with id " + std::to_string(id));
}

// A task's reference moves by at most max_accel * dt from the last step's (a task at rest starts
// from zero): a new target sets the task going smoothly instead of at its full rate within one step
// (a centre of mass whose speed jumps throws the ZMP to a sole's edge: z / g times the acceleration).
// The reference is kept in next_ref and becomes last_ref once the step is taken.
void limit_accel(wholebody::Task *t, VectorXd *ref, double dt) {
  if (t->max_accel > 0) {
    const VectorXd from = t->last_ref.size() == ref->size() ? t->last_ref : VectorXd::Zero(ref->size());
    const VectorXd d = *ref - from;
    const double n = d.norm(), lim = t->max_accel * dt;
    if (n > lim) *ref = from + d * (lim / n);
  }
  t->next_ref = *ref;
}

// The stack for one solve: the contacts and the locked joints on top, then the tasks by level.
// Fills `owner`: for each level, the task indices in it (-1: the top).
std::vector<Level> stack(wbc *w, const std::vector<int> &locked, const std::vector<double> &lock_rate, bool lean_locked,
                         std::vector<std::vector<int>> *owner) {
  wholebody::Body &b = w->body;
  std::map<int, std::vector<int>> by_level;
  for (size_t i = 0; i < w->tasks.size(); i++)
    if (w->tasks[i].has) by_level[w->tasks[i].level].push_back((int)i);
  std::vector<Level> levels;
  owner->clear();
  // top: contacts, locked joints
  {
    std::vector<MatrixXd> Js;
    std::vector<VectorXd> refs;
    for (auto &c : w->contacts) {
      MatrixXd J;
      VectorXd ref;
      wholebody::task_rows(b, c, &J, &ref);
      Js.push_back(J);
      refs.push_back(ref);
    }
    for (size_t k = 0; k < locked.size(); k++) {
      MatrixXd J = MatrixXd::Zero(1, b.nv);
      J(0, 6 + locked[k]) = 1;
      Js.push_back(J);
      refs.push_back(VectorXd::Constant(1, lock_rate[k]));
    }
    if (lean_locked) {
      // the base's angular velocity about the world's horizontal axes (its twist is in its own frame)
      MatrixXd J = MatrixXd::Zero(2, b.nv);
      J.middleCols(3, 3) = b.base_r.toRotationMatrix().topRows(2);
      Js.push_back(J);
      refs.push_back(VectorXd::Zero(2));
    }
    if (!Js.empty()) {
      levels.push_back(wholebody::vstack(Js, refs));
      owner->push_back({ -1 });
    }
  }
  for (auto &kv : by_level) {
    std::vector<MatrixXd> Js;
    std::vector<VectorXd> refs;
    for (int i : kv.second) {
      MatrixXd J;
      VectorXd ref;
      w->tasks[i].error = wholebody::task_rows(b, w->tasks[i], &J, &ref);
      limit_accel(&w->tasks[i], &ref, w->dt);
      Js.push_back(J);
      refs.push_back(ref);
    }
    levels.push_back(wholebody::vstack(Js, refs));
    owner->push_back(kv.second);
  }
  return levels;
}

}  // namespace

extern "C" {

int wbc_new(const char *urdf, int njoint, const char *const *joints, double dt, wbc **out, char *err, size_t errlen) {
  if (!out || !urdf || (joints && njoint < 1) || !(dt > 0)) {
    snprintf(err, errlen, "wbc: a URDF, its joints and a positive step are needed");
    return -1;
  }
  wbc *w = new wbc;
  if (!wholebody::body_load(&w->body, urdf, njoint, joints, err, errlen)) {
    delete w;
    return -1;
  }
  w->dt = dt;
  const int nj = w->body.nj;
  w->lo = VectorXd::Constant(nj, -M_PI);
  w->hi = VectorXd::Constant(nj, M_PI);
  w->speed = VectorXd::Constant(nj, 5.0);
  *out = w;
  return 0;
}

void wbc_free(wbc *w) {
  if (!w) return;
  wholebody::body_free(&w->body);
  delete w;
}

const char *wbc_error(const wbc *w) { return w ? w->err.c_str() : "wbc: no controller"; }
int wbc_njoint(const wbc *w) { return w->body.nj; }
const char *wbc_joint_name(const wbc *w, int j) {
  return j >= 0 && j < w->body.nj ? w->body.joints[j].c_str() : nullptr;
}

int wbc_set_limits(wbc *w, const double *lo, const double *hi, const double *speed) {
  const int n = w->body.nj;
  for (int j = 0; j < n; j++) {
    const std::string name = w->body.joints[j];
    if (!std::isfinite(lo[j]) || !std::isfinite(hi[j]) || lo[j] >= hi[j])
      return fail(w, "joint '" + name + "': limits must be finite with lo < hi");
    if (!(speed[j] > 0) || !std::isfinite(speed[j])) return fail(w, "joint '" + name + "': speed must be positive");
  }
  w->lo = Eigen::Map<const VectorXd>(lo, n);
  w->hi = Eigen::Map<const VectorXd>(hi, n);
  w->speed = Eigen::Map<const VectorXd>(speed, n);
  return 0;
}

int wbc_set_contacts(wbc *w, int n, const char *const *frames) {
  std::vector<wholebody::Task> cs;
  for (int i = 0; i < n; i++) {
    wholebody::Task t;
    std::string why;
    if (!wholebody::task_init(w->body, &t, frames[i], WBC_POSE, frames[i], TOP, CONTACT_GAIN, 0, &why)) return fail(w, why);
    for (auto &old : w->contacts)
      if (old.frame == t.frame) t = old;   // a contact kept keeps its anchor
    cs.push_back(t);
  }
  if (w->ready) {
    // running: a new contact is held where the model has it now
    if (!wholebody::body_update(&w->body)) return fail(w, w->body.err);
    for (auto &c : cs)
      if (!c.has) {
        wholebody::frame_pose(w->body, c.fid, &c.pos, &c.rot);
        c.has = true;
      }
  }
  w->contacts = cs;
  return 0;
}

int wbc_reset(wbc *w, const double *q) {
  wholebody::Body &b = w->body;
  if (!q || !all_finite(q, b.nj)) return fail(w, "wbc_reset: the joint angles must be finite");
  if (w->contacts.empty()) return fail(w, "wbc_reset: no contact frames (wbc_set_contacts)");
  b.q = Eigen::Map<const VectorXd>(q, b.nj);
  b.base_p.setZero();
  b.base_r = Quaterniond::Identity();
  if (!wholebody::body_update(&b)) return fail(w, b.err);
  // the stance frame: the contacts' mean position and orientation (made a rotation), level
  Vector3d p = Vector3d::Zero();
  Matrix3d R = Matrix3d::Zero();
  for (auto &c : w->contacts) {
    Vector3d cp;
    Matrix3d cr;
    wholebody::frame_pose(b, c.fid, &cp, &cr);
    p += cp / w->contacts.size();
    R += cr / w->contacts.size();
  }
  Eigen::JacobiSVD<Matrix3d> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Matrix3d Rs = svd.matrixU() * svd.matrixV().transpose();
  if (Rs.determinant() < 0) return fail(w, "wbc_reset: the contacts' orientations do not average to a rotation");
  b.base_r = Quaterniond(Rs.transpose()).normalized();
  b.base_p = -(Rs.transpose() * p);
  if (!wholebody::body_update(&b)) return fail(w, b.err);
  for (auto &c : w->contacts) {
    wholebody::frame_pose(b, c.fid, &c.pos, &c.rot);
    c.has = true;
  }
  w->ready = true;
  return 0;
}

int wbc_task_add(wbc *w, const char *name, int kind, const char *frame, int level, double gain, double max_rate) {
  if (!name || !*name) return fail(w, "a task needs a name");
  if (wbc_task_id(w, name) >= 0) return fail(w, std::string("task '") + name + "' exists");
  if (!std::isfinite(gain) || gain < 0) return fail(w, std::string("task '") + name + "': gain must be >= 0");
  wholebody::Task t;
  std::string why;
  if (!wholebody::task_init(w->body, &t, name, kind, frame ? frame : "", level, gain, max_rate, &why)) return fail(w, why);
  w->tasks.push_back(t);
  return (int)w->tasks.size() - 1;
}

int wbc_task_id(const wbc *w, const char *name) {
  for (size_t i = 0; i < w->tasks.size(); i++)
    if (w->tasks[i].name == name) return (int)i;
  return -1;
}

int wbc_task_target(wbc *w, int id, const double *target, int n) {
  if (bad_id(w, id)) return -1;
  std::string why;
  if (!wholebody::task_set_target(w->body, &w->tasks[id], target, n, &why)) return fail(w, why);
  return 0;
}

int wbc_task_clear(wbc *w, int id) {
  if (bad_id(w, id)) return -1;
  w->tasks[id].has = false;
  return 0;
}

int wbc_task_accel(wbc *w, int id, double max_accel) {
  if (bad_id(w, id)) return -1;
  if (!std::isfinite(max_accel) || max_accel < 0)
    return fail(w, "task '" + w->tasks[id].name + "': max_accel must be >= 0");
  w->tasks[id].max_accel = max_accel;
  return 0;
}

int wbc_task_gain(wbc *w, int id, double gain) {
  if (bad_id(w, id)) return -1;
  if (!std::isfinite(gain) || gain < 0) return fail(w, "task '" + w->tasks[id].name + "': gain must be >= 0");
  w->tasks[id].gain = gain;
  return 0;
}

int wbc_task_level(wbc *w, int id, int level) {
  if (bad_id(w, id)) return -1;
  if (level <= TOP) return fail(w, "task '" + w->tasks[id].name + "': level out of range");
  w->tasks[id].level = level;
  return 0;
}

int wbc_task_status_of(wbc *w, int id, wbc_task_status *out) {
  if (bad_id(w, id) || !out) return -1;
  const wholebody::Task &t = w->tasks[id];
  out->kind = t.kind;
  out->level = t.level;
  out->rows = t.report.rows;
  out->rank = t.report.rank;
  out->feasible = t.report.feasible;
  out->enabled = t.has;
  out->error = t.error;
  out->sigma_min = t.report.sigma_min;
  out->sigma_max = t.report.sigma_max;
  out->damping = t.report.damping;
  return 0;
}

int wbc_ntask(const wbc *w) { return (int)w->tasks.size(); }
const char *wbc_task_name(const wbc *w, int id) {
  return id >= 0 && id < (int)w->tasks.size() ? w->tasks[id].name.c_str() : nullptr;
}

int wbc_step(wbc *w, double *q_out) {
  if (!w->ready) return fail(w, "wbc_step before wbc_reset");
  const double t0 = thread_cpu_us();
  wholebody::Body &b = w->body;
  if (!wholebody::body_update(&b)) return fail(w, b.err);
  const int nj = b.nj;
  std::vector<int> locked;
  std::vector<double> lock_rate;
  std::vector<std::vector<int>> owner;
  std::vector<LevelReport> reports;
  VectorXd qd;
  bool lean_locked = false;
  // solve; a joint the step would carry past a limit is locked at it (a constraint on top) and the
  // stack solved again, until none does; the same for the base's lean past max_lean, whose tilting
  // is stopped
  for (int pass = 0; pass <= nj + 1; pass++) {
    const std::vector<Level> levels = stack(w, locked, lock_rate, lean_locked, &owner);
    qd = wholebody::solve_velocity(levels, b.nv, wholebody::Damping(), &reports);
    int added = 0;
    if (w->max_lean > 0 && !lean_locked) {
      const Vector3d wl = qd.segment<3>(3) * w->dt;
      const Quaterniond next = wl.norm() > 0 ? b.base_r * Quaterniond(Eigen::AngleAxisd(wl.norm(), wl.normalized()))
                                             : b.base_r;
      const double tilt = std::acos(std::min(1.0, std::max(-1.0, next.toRotationMatrix()(2, 2))));
      const double now = std::acos(std::min(1.0, std::max(-1.0, b.base_r.toRotationMatrix()(2, 2))));
      if (tilt > w->max_lean && tilt > now) {
        lean_locked = true;
        added++;
      }
    }
    for (int j = 0; j < nj; j++) {
      if (std::find(locked.begin(), locked.end(), j) != locked.end()) continue;
      const double next = b.q(j) + qd(6 + j) * w->dt;
      if (next > w->hi(j) || next < w->lo(j)) {
        locked.push_back(j);
        const double lim = next > w->hi(j) ? w->hi(j) : w->lo(j);
        lock_rate.push_back((lim - b.q(j)) / w->dt);
        added++;
      }
    }
    if (!added) break;
  }
  // speed limits: the whole step scaled (every task's direction kept)
  double scale = 1;
  for (int j = 0; j < nj; j++) {
    const double r = std::fabs(qd(6 + j));
    if (r > w->speed(j)) scale = std::min(scale, w->speed(j) / r);
  }
  qd *= scale;
  for (auto &t : w->tasks) {
    if (t.has) t.last_ref = t.next_ref * scale;   // what the step asked of the task, scaled as it was
    else t.last_ref.resize(0);
  }
  for (size_t k = 0; k < owner.size(); k++)
    for (int i : owner[k])
      if (i >= 0) w->tasks[i].report = reports[k];
  wholebody::body_integrate(&b, qd, w->dt);
  for (int j = 0; j < nj; j++) q_out[j] = b.q(j);
  w->step_us = thread_cpu_us() - t0;
  w->leaning = lean_locked;
  return (int)locked.size() + (lean_locked ? 1 : 0);
}

int wbc_set_max_lean(wbc *w, double rad) {
  if (!std::isfinite(rad) || rad < 0 || rad >= M_PI / 2) return fail(w, "max_lean must be within 0..pi/2 rad");
  w->max_lean = rad;
  return 0;
}

int wbc_leaning(const wbc *w) { return w->leaning ? 1 : 0; }

int wbc_frame_pose(wbc *w, const char *frame, double *pos, double *rot) {
  wholebody::Body &b = w->body;
  if (!wholebody::body_update(&b)) return fail(w, b.err);
  if (std::string(frame) == "com") {
    Vector3d c;
    wholebody::com(b, &c, nullptr);
    for (int k = 0; k < 3; k++) pos[k] = c(k);
    return 0;
  }
  const int fid = wholebody::frame_id(b, frame);
  if (fid < 0) return fail(w, std::string("no frame '") + frame + "' in the body");
  Vector3d p;
  Matrix3d R;
  wholebody::frame_pose(b, fid, &p, &R);
  for (int k = 0; k < 3; k++) pos[k] = p(k);
  if (rot)
    for (int r = 0; r < 3; r++)
      for (int c = 0; c < 3; c++) rot[r * 3 + c] = R(r, c);
  return 0;
}

int wbc_base(const wbc *w, double *base7) {
  const wholebody::Body &b = w->body;
  for (int k = 0; k < 3; k++) base7[k] = b.base_p(k);
  base7[3] = b.base_r.x();
  base7[4] = b.base_r.y();
  base7[5] = b.base_r.z();
  base7[6] = b.base_r.w();
  return 0;
}

double wbc_step_us(const wbc *w) { return w->step_us; }

}  // extern "C"
