// Strict task priorities in velocity and torque modes (priority.hpp says the formulation).
#include "wbc/priority.hpp"

#include <algorithm>
#include <cmath>

namespace wholebody {

namespace {

// The rank of a singular value list (descending) at the tolerance.
int rank_of(const VectorXd &s, double tol) {
  int r = 0;
  while (r < s.size() && s(r) > tol) r++;
  return r;
}

double damping_for(double sigma_min, const Damping &d) {
  if (sigma_min >= d.epsilon) return 0;
  const double q = sigma_min / d.epsilon;
  return std::sqrt(std::max(0.0, 1 - q * q)) * d.lambda_max;
}

void fill_report(LevelReport *r, int rows, const VectorXd &s, int rank, double lambda, const Damping &d) {
  r->rows = rows;
  r->rank = rank;
  r->sigma_max = s.size() ? s(0) : 0;
  r->sigma_min = rank ? s(rank - 1) : 0;
  r->damping = lambda;
  r->feasible = rank == rows && r->sigma_min >= d.epsilon;
}

// The SVD of M with its rank and damping: V diag(inv) U^T is M's damped pseudo-inverse.
struct DampedSvd {
  Eigen::JacobiSVD<MatrixXd> svd;
  int rank;
  double lambda;
  VectorXd inv;
  DampedSvd(const MatrixXd &M, const Damping &d) : svd(M, Eigen::ComputeThinU | Eigen::ComputeThinV) {
    const VectorXd &s = svd.singularValues();
    rank = rank_of(s, d.rank_tol);
    // sigma_min among the directions that exist: a conflict (rank < rows) is not a singularity to damp
    lambda = rank ? damping_for(s(rank - 1), d) : 0;
    inv = VectorXd::Zero(s.size());
    for (int i = 0; i < rank; i++) inv(i) = s(i) / (s(i) * s(i) + lambda * lambda);
  }
  MatrixXd pinv() const { return svd.matrixV() * inv.asDiagonal() * svd.matrixU().transpose(); }
};

}  // namespace

MatrixXd damped_pinv(const MatrixXd &M, const Damping &d, VectorXd *sigma, int *rank, double *lambda) {
  const DampedSvd ds(M, d);
  if (sigma) *sigma = ds.svd.singularValues();
  if (rank) *rank = ds.rank;
  if (lambda) *lambda = ds.lambda;
  return ds.pinv();
}

VectorXd solve_velocity(const std::vector<Level> &levels, int n, const Damping &d, std::vector<LevelReport> *reports,
                        MatrixXd *P_out) {
  VectorXd qdot = VectorXd::Zero(n);
  MatrixXd P = MatrixXd::Identity(n, n);
  std::vector<LevelReport> rep(levels.size());
  for (size_t k = 0; k < levels.size(); k++) {
    const Level &L = levels[k];
    const DampedSvd ds(L.J * P, d);
    const int r = ds.rank;
    qdot += ds.pinv() * (L.ref - L.J * qdot);
    // the directions this level took leave the projector: exact, whatever the damping
    const MatrixXd &V = ds.svd.matrixV();
    if (r) P -= V.leftCols(r) * V.leftCols(r).transpose();
    fill_report(&rep[k], (int)L.J.rows(), ds.svd.singularValues(), r, ds.lambda, d);
  }
  for (size_t k = 0; k < levels.size(); k++) rep[k].residual = (levels[k].ref - levels[k].J * qdot).norm();
  if (reports) *reports = rep;
  if (P_out) *P_out = P;
  return qdot;
}

VectorXd solve_torque(const std::vector<Level> &levels, const MatrixXd &A, const MatrixXd &Ainv, const Damping &d,
                      std::vector<LevelReport> *reports, MatrixXd *N_out) {
  const int n = (int)A.rows();
  VectorXd tau = VectorXd::Zero(n);
  MatrixXd N = MatrixXd::Identity(n, n);
  std::vector<LevelReport> rep(levels.size());
  for (size_t k = 0; k < levels.size(); k++) {
    const Level &L = levels[k];
    const MatrixXd Jp = L.J * N;
    // Lambda = (Jp A^-1 Jp^T)^+, damped on the singular values of Jp's inverse inertia, whose square
    // roots are the "velocity-like" singular values compared with epsilon
    const MatrixXd inv_inertia = Jp * Ainv * Jp.transpose();
    Eigen::SelfAdjointEigenSolver<MatrixXd> eig(0.5 * (inv_inertia + inv_inertia.transpose()));
    VectorXd ev = eig.eigenvalues().reverse().cwiseMax(0.0);      // descending
    MatrixXd U = eig.eigenvectors().rowwise().reverse();
    VectorXd s = ev.cwiseSqrt();
    const int r = rank_of(s, d.rank_tol);
    const double lam = r ? damping_for(s(r - 1), d) : 0;
    // the force from the damped inertia; the null space from the exact one (rank directions only), so
    // that lower levels stay dynamically consistent with this one, damped or not
    VectorXd inv = VectorXd::Zero(ev.size()), inv_exact = VectorXd::Zero(ev.size());
    for (int i = 0; i < r; i++) {
      inv(i) = 1.0 / (ev(i) + lam * lam);
      inv_exact(i) = 1.0 / ev(i);
    }
    const MatrixXd Lambda = U * inv.asDiagonal() * U.transpose();
    const MatrixXd Jbar = Ainv * Jp.transpose() * (U * inv_exact.asDiagonal() * U.transpose());
    const VectorXd F = Lambda * (L.ref - L.J * Ainv * tau);
    tau += Jp.transpose() * F;
    N -= Jbar * Jp;
    fill_report(&rep[k], (int)L.J.rows(), s, r, lam, d);
  }
  for (size_t k = 0; k < levels.size(); k++) rep[k].residual = (levels[k].ref - levels[k].J * Ainv * tau).norm();
  if (reports) *reports = rep;
  if (N_out) *N_out = N;
  return tau;
}

}  // namespace wholebody
