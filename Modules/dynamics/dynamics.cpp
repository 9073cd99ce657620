// dynamics.h over Pinocchio: the state, and each query computed once per state in the caller's
// joint order.
#include "dynamics/dyn_model.hpp"

#include <pinocchio/algorithm/center-of-mass.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/frames.hpp>
#include <pinocchio/algorithm/jacobian.hpp>
#include <pinocchio/algorithm/rnea.hpp>

#include <cmath>
#include <exception>

namespace {

using Eigen::Map;
using Eigen::MatrixXd;
using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

int nv(const dyn_model *m) { return m->model.nv; }

// Runs f, turning an exception from Pinocchio into DYN_EFAIL with its message.
template <class F> int guarded(dyn_model *m, const char *what, F f) {
  if (!m) return DYN_EINVAL;
  try {
    return f();
  } catch (const std::exception &e) {
    return dyn_fail(m, DYN_EFAIL, std::string(what) + ": " + e.what());
  }
}

bool bad_frame(dyn_model *m, int frame) {
  if (frame >= 0 && frame < (int)m->model.nframes) return false;
  dyn_fail(m, DYN_EINVAL, "no frame with id " + std::to_string(frame));
  return true;
}

// The name of entry k of a velocity-sized vector, for messages.
std::string v_name(const dyn_model *m, int k) {
  static const char *base[6] = {"vx", "vy", "vz", "wx", "wy", "wz"};
  return k < 6 ? std::string("base ") + base[k] : "joint " + m->joints[k - 6];
}

// A velocity-sized vector in Pinocchio's order from one in ours.
void to_pin(const dyn_model *m, const double *ours, Eigen::VectorXd &pin) {
  for (int c = 0; c < nv(m); c++) pin[m->vcol[c]] = ours[c];
}

void from_pin(const dyn_model *m, const Eigen::VectorXd &pin, double *ours) {
  for (int c = 0; c < nv(m); c++) ours[c] = pin[m->vcol[c]];
}

// Columns of a Pinocchio-ordered matrix (rows x nv) into a row-major one in our order.
void cols_from_pin(const dyn_model *m, const MatrixXd &pin, int rows, double *out) {
  Map<RowMat> o(out, rows, nv(m));
  for (int c = 0; c < nv(m); c++) o.col(c) = pin.block(0, m->vcol[c], rows, 1);
}

// Runs compute once per state (flag: its DONE_* bit).
template <class F> void once(dyn_model *m, unsigned flag, F compute) {
  if (m->done & flag) return;
  compute();
  m->done |= flag;
}

void ensure_kin(dyn_model *m) {
  once(m, DONE_KIN, [&] {
    pinocchio::computeJointJacobians(m->model, m->kin, m->q);   // forward kinematics too
    pinocchio::updateFramePlacements(m->model, m->kin);
  });
}

// A generalized-force query: compute once per state into the dynamics data's member res, copied
// out in the caller's order.
template <class F>
int force_query(dyn_model *m, const char *what, double *out, unsigned flag, Eigen::VectorXd pinocchio::Data::*res,
                F compute) {
  return guarded(m, what, [&]() -> int {
    if (!out) return DYN_EINVAL;
    once(m, flag, compute);
    from_pin(m, m->dyn.*res, out);
    return 0;
  });
}

}  // namespace

extern "C" {

const char *dyn_error(const dyn_model *m) { return m ? m->err.c_str() : "no model"; }
int dyn_njoint(const dyn_model *m) { return m ? (int)m->joints.size() : DYN_EINVAL; }
int dyn_nq(const dyn_model *m) { return m ? m->model.nq : DYN_EINVAL; }
int dyn_nv(const dyn_model *m) { return m ? m->model.nv : DYN_EINVAL; }
int dyn_nframe(const dyn_model *m) { return m ? (int)m->model.nframes : DYN_EINVAL; }

const char *dyn_joint_name(const dyn_model *m, int j) {
  return m && j >= 0 && j < (int)m->joints.size() ? m->joints[j].c_str() : nullptr;
}

const char *dyn_frame_name(const dyn_model *m, int frame) {
  return m && frame >= 0 && frame < (int)m->model.nframes ? m->model.frames[frame].name.c_str() : nullptr;
}

double dyn_total_mass(const dyn_model *m) { return m ? pinocchio::computeTotalMass(m->model) : 0.0; }

int dyn_frame_id(dyn_model *m, const char *name) {
  if (!m || !name) return DYN_EINVAL;
  auto it = m->frames.find(name);
  if (it == m->frames.end()) return dyn_fail(m, DYN_ENOFRAME, std::string("no frame '") + name + "' in the model");
  return it->second;
}

int dyn_set_state(dyn_model *m, const double *base, const double *q, const double *v) {
  if (!m || !q) return DYN_EINVAL;
  static const char *bname[7] = {"x", "y", "z", "qx", "qy", "qz", "qw"};
  Eigen::VectorXd nq = m->q;
  if (base) {
    for (int k = 0; k < 7; k++)
      if (!std::isfinite(base[k]))
        return dyn_fail(m, DYN_EBADINPUT, std::string("base ") + bname[k] + " is not finite");
    Eigen::Vector4d quat(base[3], base[4], base[5], base[6]);
    double n = quat.norm();
    if (n < 1e-9) return dyn_fail(m, DYN_EBADINPUT, "base quaternion is zero");
    nq.head<3>() = Eigen::Vector3d(base[0], base[1], base[2]);
    nq.segment<4>(3) = quat / n;
  } else {
    nq.head<7>() << 0, 0, 0, 0, 0, 0, 1;
  }
  for (size_t j = 0; j < m->joints.size(); j++) {
    if (!std::isfinite(q[j])) return dyn_fail(m, DYN_EBADINPUT, "joint " + m->joints[j] + " angle is not finite");
    nq[m->qidx[j]] = q[j];
  }
  if (v) {
    for (int c = 0; c < nv(m); c++)
      if (!std::isfinite(v[c])) return dyn_fail(m, DYN_EBADINPUT, v_name(m, c) + " velocity is not finite");
    to_pin(m, v, m->v);
  } else {
    m->v.setZero();
  }
  m->q = nq;
  m->done = 0;
  return 0;
}

int dyn_frame_pose(dyn_model *m, int frame, double *pos, double *rot) {
  return guarded(m, "frame pose", [&]() -> int {
    if (!pos || bad_frame(m, frame)) return DYN_EINVAL;
    ensure_kin(m);
    const pinocchio::SE3 &X = m->kin.oMf[frame];
    Map<Eigen::Vector3d>{pos} = X.translation();
    if (rot) Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>{rot} = X.rotation();
    return 0;
  });
}

int dyn_frame_jacobian(dyn_model *m, int frame, int ref, double *J) {
  return guarded(m, "frame Jacobian", [&]() -> int {
    if (!J || bad_frame(m, frame)) return DYN_EINVAL;
    if (ref != DYN_WORLD_ALIGNED && ref != DYN_LOCAL)
      return dyn_fail(m, DYN_EINVAL, "reference frame " + std::to_string(ref) + " is neither WORLD_ALIGNED nor LOCAL");
    ensure_kin(m);
    m->work.setZero();
    pinocchio::getFrameJacobian(m->model, m->kin, (pinocchio::FrameIndex)frame,
                                ref == DYN_LOCAL ? pinocchio::LOCAL : pinocchio::LOCAL_WORLD_ALIGNED, m->work);
    cols_from_pin(m, m->work, 6, J);
    return 0;
  });
}

int dyn_com(dyn_model *m, double *com, double *J) {
  return guarded(m, "centre of mass", [&]() -> int {
    if (!com) return DYN_EINVAL;
    once(m, DONE_COM, [&] { pinocchio::jacobianCenterOfMass(m->model, m->kin, m->q, true); });
    Map<Eigen::Vector3d>{com} = m->kin.com[0];
    if (J) cols_from_pin(m, m->kin.Jcom, 3, J);
    return 0;
  });
}

int dyn_mass_matrix(dyn_model *m, double *M) {
  return guarded(m, "mass matrix", [&]() -> int {
    if (!M) return DYN_EINVAL;
    once(m, DONE_CRBA, [&] {   // CRBA fills the upper triangle
      pinocchio::crba(m->model, m->dyn, m->q);
      m->dyn.M.triangularView<Eigen::StrictlyLower>() = m->dyn.M.transpose().triangularView<Eigen::StrictlyLower>();
    });
    Map<RowMat> o(M, nv(m), nv(m));
    for (int r = 0; r < nv(m); r++)
      for (int c = 0; c < nv(m); c++) o(r, c) = m->dyn.M(m->vcol[r], m->vcol[c]);
    return 0;
  });
}

int dyn_gravity(dyn_model *m, double *g) {
  return force_query(m, "gravity", g, DONE_GRAVITY, &pinocchio::Data::g,
                     [&] { pinocchio::computeGeneralizedGravity(m->model, m->dyn, m->q); });
}

int dyn_nonlinear(dyn_model *m, double *h) {
  return force_query(m, "nonlinear effects", h, DONE_NLE, &pinocchio::Data::nle,
                     [&] { pinocchio::nonLinearEffects(m->model, m->dyn, m->q, m->v); });
}

int dyn_inverse_dynamics(dyn_model *m, const double *a, double *tau) {
  return guarded(m, "inverse dynamics", [&]() -> int {
    if (!a || !tau) return DYN_EINVAL;
    for (int c = 0; c < nv(m); c++)
      if (!std::isfinite(a[c])) return dyn_fail(m, DYN_EBADINPUT, v_name(m, c) + " acceleration is not finite");
    to_pin(m, a, m->acc);
    pinocchio::rnea(m->model, m->dyn, m->q, m->v, m->acc);
    from_pin(m, m->dyn.tau, tau);
    return 0;
  });
}

}  // extern "C"
