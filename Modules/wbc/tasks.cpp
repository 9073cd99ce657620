// The body and its tasks (tasks.hpp): the model's state, each kind's rows and reference.
#include "wbc/tasks.hpp"
#include "wbc/wbc.h"

#include <cmath>
#include <cstdio>

namespace wholebody {

using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using Eigen::VectorXd;
using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

bool body_load(Body *b, const char *urdf, int nj, const char *const *joints, char *err, size_t errlen) {
  if (dyn_model_load(urdf, nj, joints, &b->model, err, errlen) < 0) return false;
  b->nj = dyn_njoint(b->model);
  b->nv = dyn_nv(b->model);
  for (int j = 0; j < b->nj; j++) b->joints.push_back(dyn_joint_name(b->model, j));
  b->q = VectorXd::Zero(b->nj);
  b->base_p.setZero();
  b->base_r = Quaterniond::Identity();
  b->buf.assign(6 * (size_t)b->nv, 0.0);
  return true;
}

void body_free(Body *b) {
  dyn_model_destroy(b->model);
  b->model = nullptr;
}

bool body_update(Body *b) {
  const double base[7] = { b->base_p(0), b->base_p(1), b->base_p(2), b->base_r.x(), b->base_r.y(), b->base_r.z(),
                           b->base_r.w() };
  if (dyn_set_state(b->model, base, b->q.data(), nullptr) < 0) {
    b->err = dyn_error(b->model);
    return false;
  }
  return true;
}

void body_integrate(Body *b, const VectorXd &qd, double dt) {
  const Vector3d v = qd.head<3>(), w = qd.segment<3>(3);
  b->base_p += b->base_r * (v * dt);
  const double angle = w.norm() * dt;
  if (angle > 0) b->base_r = (b->base_r * Quaterniond(Eigen::AngleAxisd(angle, w.normalized()))).normalized();
  b->q += qd.tail(b->nj) * dt;
}

int frame_id(Body &b, const std::string &name) { return dyn_frame_id(b.model, name.c_str()); }

void frame_pose(Body &b, int fid, Vector3d *p, Matrix3d *R) {
  double pos[3], rot[9];
  dyn_frame_pose(b.model, fid, pos, rot);
  *p = Vector3d(pos[0], pos[1], pos[2]);
  if (R) *R = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(rot);
}

void com(Body &b, Vector3d *c, MatrixXd *J) {
  double p[3];
  dyn_com(b.model, p, J ? b.buf.data() : nullptr);
  *c = Vector3d(p[0], p[1], p[2]);
  if (J) *J = Eigen::Map<const RowMat>(b.buf.data(), 3, b.nv);
}

namespace {

MatrixXd frame_jacobian(Body &b, int fid) {
  dyn_frame_jacobian(b.model, fid, DYN_WORLD_ALIGNED, b.buf.data());
  return Eigen::Map<const RowMat>(b.buf.data(), 6, b.nv);
}

// The rotation vector taking R to Rd, in world axes: log(Rd R^T).
Vector3d rotation_error(const Matrix3d &Rd, const Matrix3d &R) {
  const Eigen::AngleAxisd aa(Rd * R.transpose());
  return aa.axis() * aa.angle();
}

int target_count(const Body &b, int kind) {
  switch (kind) {
    case WBC_POSITION: case WBC_COM: return 3;
    case WBC_ORIENTATION: return 9;
    case WBC_POSE: return 12;
    case WBC_COM_XY: return 2;
    case WBC_POSTURE: return b.nj;
  }
  return -1;
}

}  // namespace

bool task_init(Body &b, Task *t, const std::string &name, int kind, const std::string &frame, int level, double gain,
               double max_rate, std::string *why) {
  if (kind < WBC_POSITION || kind > WBC_POSTURE) {
    *why = "task '" + name + "': unknown kind " + std::to_string(kind);
    return false;
  }
  t->name = name;
  t->kind = kind;
  t->level = level;
  t->gain = gain;
  t->max_rate = max_rate;
  t->frame = frame;
  t->has = false;
  if (kind == WBC_POSITION || kind == WBC_ORIENTATION || kind == WBC_POSE) {
    t->fid = frame_id(b, frame);
    if (t->fid < 0) {
      *why = "task '" + name + "': no frame '" + frame + "' in the body";
      return false;
    }
  }
  return true;
}

bool task_set_target(const Body &b, Task *t, const double *target, int n, std::string *why) {
  const int want = target_count(b, t->kind);
  if (!target || n != want) {
    *why = "task '" + t->name + "': a target of " + std::to_string(want) + " numbers, not " + std::to_string(n);
    return false;
  }
  for (int i = 0; i < n; i++)
    if (!std::isfinite(target[i])) {
      *why = "task '" + t->name + "': target[" + std::to_string(i + 1) + "] is not finite";
      return false;
    }
  switch (t->kind) {
    case WBC_POSITION: case WBC_COM: t->pos = Vector3d(target[0], target[1], target[2]); break;
    case WBC_COM_XY: t->pos = Vector3d(target[0], target[1], 0); break;
    case WBC_POSTURE: t->q = Eigen::Map<const VectorXd>(target, n); break;
    default: {
      const double *r = t->kind == WBC_POSE ? target + 3 : target;
      const Matrix3d R = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(r);
      if ((R * R.transpose() - Matrix3d::Identity()).norm() > 1e-6 || R.determinant() < 0) {
        *why = "task '" + t->name + "': the target orientation is not a rotation matrix";
        return false;
      }
      t->rot = R;
      if (t->kind == WBC_POSE) t->pos = Vector3d(target[0], target[1], target[2]);
    }
  }
  t->has = true;
  return true;
}

double task_rows(Body &b, const Task &t, MatrixXd *J, VectorXd *ref) {
  VectorXd e;
  switch (t.kind) {
    case WBC_POSITION: case WBC_ORIENTATION: case WBC_POSE: {
      const MatrixXd Jf = frame_jacobian(b, t.fid);
      Vector3d p;
      Matrix3d R;
      frame_pose(b, t.fid, &p, &R);
      if (t.kind == WBC_POSITION) {
        *J = Jf.topRows(3);
        e = t.pos - p;
      } else if (t.kind == WBC_ORIENTATION) {
        *J = Jf.bottomRows(3);
        e = rotation_error(t.rot, R);
      } else {
        *J = Jf;
        e.resize(6);
        e << t.pos - p, rotation_error(t.rot, R);
      }
      break;
    }
    case WBC_COM: case WBC_COM_XY: {
      Vector3d c;
      MatrixXd Jc;
      com(b, &c, &Jc);
      const int rows = t.kind == WBC_COM ? 3 : 2;
      *J = Jc.topRows(rows);
      e = (t.pos - c).head(rows);
      break;
    }
    case WBC_POSTURE: {
      *J = MatrixXd::Zero(b.nj, b.nv);
      J->rightCols(b.nj).setIdentity();
      e = t.q - b.q;
      break;
    }
  }
  *ref = t.gain * e;
  const double n = ref->norm();
  if (t.max_rate > 0 && n > t.max_rate) *ref *= t.max_rate / n;
  return t.kind == WBC_POSTURE ? e.norm() / std::sqrt((double)b.nj) : e.norm();
}

Level vstack(const std::vector<MatrixXd> &Js, const std::vector<VectorXd> &refs) {
  Eigen::Index rows = 0;
  for (auto &J : Js) rows += J.rows();
  Level L{ MatrixXd(rows, Js.empty() ? 0 : Js[0].cols()), VectorXd(rows) };
  Eigen::Index r = 0;
  for (size_t i = 0; i < Js.size(); i++) {
    L.J.middleRows(r, Js[i].rows()) = Js[i];
    L.ref.segment(r, refs[i].size()) = refs[i];
    r += Js[i].rows();
  }
  return L;
}

}  // namespace wholebody
