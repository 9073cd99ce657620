// The C ABI of wbc_torque.h over priority.hpp's solve_torque.
#include "wbc/wbc_torque.h"
#include "wbc/priority.hpp"

#include <cmath>
#include <cstdio>

using wholebody::Level;
using wholebody::LevelReport;
using wholebody::MatrixXd;
using wholebody::VectorXd;

namespace {

bool finite(const double *x, int n) {
  for (int i = 0; i < n; i++)
    if (!std::isfinite(x[i])) return false;
  return true;
}

int fail(char *err, size_t errlen, const char *msg) {
  if (err && errlen) snprintf(err, errlen, "wbc_solve_torque: %s", msg);
  return -1;
}

}  // namespace

extern "C" int wbc_solve_torque(int n, const double *A, int nlevel, const int *rows, const double *J,
                                const double *ref, const double *tau0, double *tau, wbc_torque_level *report,
                                char *err, size_t errlen) {
  if (n < 1 || n > 64 || nlevel < 1 || nlevel > 8 || !A || !rows || !J || !ref || !tau)
    return fail(err, errlen, "1..64 joints, 1..8 levels and every array are needed");
  int total = 0;
  for (int k = 0; k < nlevel; k++) {
    if (rows[k] < 1 || rows[k] > n) return fail(err, errlen, "a level has 1..n rows");
    total += rows[k];
  }
  if (!finite(A, n * n)) return fail(err, errlen, "the mass matrix is not finite");
  if (!finite(J, total * n)) return fail(err, errlen, "a task Jacobian is not finite");
  if (!finite(ref, total)) return fail(err, errlen, "a task's acceleration is not finite");
  if (tau0 && !finite(tau0, n)) return fail(err, errlen, "the posture torque is not finite");
  const MatrixXd Am = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(A, n, n);
  const MatrixXd As = 0.5 * (Am + Am.transpose());
  Eigen::LLT<MatrixXd> llt(As);
  if (llt.info() != Eigen::Success) return fail(err, errlen, "the mass matrix is not positive definite");
  const MatrixXd Ainv = llt.solve(MatrixXd::Identity(n, n));
  std::vector<Level> levels((size_t)nlevel);
  int r0 = 0;
  for (int k = 0; k < nlevel; k++) {
    levels[k].J = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        J + (size_t)r0 * n, rows[k], n);
    levels[k].ref = Eigen::Map<const VectorXd>(ref + r0, rows[k]);
    r0 += rows[k];
  }
  std::vector<LevelReport> rep;
  MatrixXd N;
  VectorXd t = wholebody::solve_torque(levels, As, Ainv, wholebody::Damping(), &rep, &N);
  if (tau0) t += N.transpose() * Eigen::Map<const VectorXd>(tau0, n);
  if (!t.allFinite()) return fail(err, errlen, "the torques are not finite");
  for (int i = 0; i < n; i++) tau[i] = t(i);
  if (report)
    for (int k = 0; k < nlevel; k++) {
      report[k].rows = rep[k].rows;
      report[k].rank = rep[k].rank;
      report[k].feasible = rep[k].feasible ? 1 : 0;
      report[k].sigma_min = rep[k].sigma_min;
      report[k].damping = rep[k].damping;
    }
  return 0;
}
