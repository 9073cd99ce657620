// Strict task priorities for whole-body control (the stanford-wbc formulation: Khatib's operational
// space, Sentis' prioritized hierarchy). A level is a task Jacobian J (m x n) and what it asks for;
// each level acts only in the null space of the levels above it.
//
//   Velocity (kinematic mode, position servos): qdot from xdot_k = J_k qdot, level by level,
//     qdot_k = qdot_{k-1} + (J_k P_{k-1})^#  (xdot_k - J_k qdot_{k-1}),   P_k = P_{k-1} - V_k V_k^T
//   where ^# is a damped pseudo-inverse and V_k spans the directions level k takes (the right singular
//   vectors of J_k P_{k-1} above the rank tolerance), so P_k is an exact orthogonal projector and no
//   lower level moves a higher one, damped or not.
//
//   Torque (Sentis): with the mass matrix A, the task's projected Jacobian J_k|p = J_k N_{k-1}, its
//   inertia Lambda_k|p = (J_k|p A^-1 J_k|p^T)^+, its dynamically consistent inverse
//   Jbar_k|p = A^-1 J_k|p^T Lambda_k|p, and N_k = N_{k-1} - Jbar_k|p J_k|p; the force of level k
//   F_k = Lambda_k|p (xddot_k - J_k A^-1 tau_{k-1}) and tau_k = tau_{k-1} + J_k|p^T F_k, so that
//   J_i A^-1 N_k^T = 0 for every level i <= k: torques of lower levels accelerate no higher task.
//   The caller adds gravity and Coriolis terms (and subtracts Jdot qdot from xddot).
//
// Damping (both modes): the smallest singular value sigma_min of a level's projected Jacobian against
// `epsilon`: above it no damping (the exact pseudo-inverse); below it lambda^2 = (1 - (sigma_min /
// epsilon)^2) lambda_max^2 (Nakamura and Hanafusa's variable damping, as in Maciejewski and Klein),
// so the solution stays bounded at a singularity and exact away from one. Directions with a singular
// value under `rank_tol` are not the task's to take (a conflict with a higher level, or a singular
// pose): they are reported, and the level is flagged infeasible.
#ifndef HRP_WBC_PRIORITY_HPP
#define HRP_WBC_PRIORITY_HPP

#include <Eigen/Dense>
#include <vector>

namespace wholebody {

using Eigen::MatrixXd;
using Eigen::VectorXd;

struct Damping {
  double epsilon = 0.02;     // sigma_min below which damping sets in (units of the task's J)
  double lambda_max = 0.05;  // the damping at sigma_min = 0
  double rank_tol = 1e-6;    // a singular value under this is no direction at all
};

// A level: its Jacobian and its reference (a velocity in velocity mode, an acceleration in torque mode).
struct Level {
  MatrixXd J;
  VectorXd ref;
};

// What each level got: its singular values in the null space of the levels above, whether every
// direction it asks for was available (feasible), and how much of its reference is left undone.
struct LevelReport {
  int rows = 0, rank = 0;
  double sigma_min = 0, sigma_max = 0;   // of J_k P_{k-1} (velocity) or J_k|p (torque), the rank's range
  double damping = 0;                    // lambda applied
  double residual = 0;                   // |ref - achieved| after all levels
  bool feasible = false;                 // rank == rows and sigma_min >= epsilon
};

// Velocity mode. qdot (n) out; reports one per level. P (n x n) out, optional: the projector left
// for anything below the last level.
VectorXd solve_velocity(const std::vector<Level> &levels, int n, const Damping &d,
                        std::vector<LevelReport> *reports = nullptr, MatrixXd *P = nullptr);

// Torque mode. A (n x n, symmetric positive definite) and its inverse; tau (n) out: the task
// torques only (no gravity or Coriolis). N (n x n) out, optional: the dynamically consistent null
// space left below the last level (a posture torque tau0 goes in as N^T tau0).
VectorXd solve_torque(const std::vector<Level> &levels, const MatrixXd &A, const MatrixXd &Ainv,
                      const Damping &d, std::vector<LevelReport> *reports = nullptr, MatrixXd *N = nullptr);

// The damped pseudo-inverse of M (m x n) described above; sigma out (optional): M's singular values,
// rank out (optional). The damping used is returned in *lambda (optional).
MatrixXd damped_pinv(const MatrixXd &M, const Damping &d, VectorXd *sigma = nullptr, int *rank = nullptr,
                     double *lambda = nullptr);

}  // namespace wholebody

#endif
