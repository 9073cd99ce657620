// Unit tests of Modules/wbc's strict priorities (TAP): random Jacobians and mass matrices; each level
// met where it is feasible, no lower level moving a higher one, conflicts and singularities flagged,
// dynamic consistency J_i A^-1 N^T = 0.
#include "wbc/priority.hpp"
#include "tap.h"

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

namespace {

using wholebody::Level;
using wholebody::LevelReport;
using wholebody::MatrixXd;
using wholebody::VectorXd;

std::mt19937 rng(7);

MatrixXd random_matrix(int r, int c) {
  std::normal_distribution<double> g(0, 1);
  MatrixXd m(r, c);
  for (int i = 0; i < r; i++)
    for (int j = 0; j < c; j++) m(i, j) = g(rng);
  return m;
}

VectorXd random_vector(int n) { return random_matrix(n, 1).col(0); }

// symmetric positive definite, with a spread of eigenvalues like a robot's (light hands, heavy legs)
MatrixXd random_spd(int n) {
  const MatrixXd Q = random_matrix(n, n).householderQr().householderQ();
  VectorXd ev(n);
  for (int i = 0; i < n; i++) ev(i) = std::pow(10.0, -2.0 + 3.0 * i / (n - 1));
  return Q * ev.asDiagonal() * Q.transpose();
}

std::string fmt(const char *f, double v) {
  char b[96];
  snprintf(b, sizeof b, f, v);
  return b;
}

void velocity_tests() {
  const int n = 14;
  const wholebody::Damping d;
  for (int trial = 0; trial < 20; trial++) {
    std::vector<Level> levels = { { random_matrix(6, n), random_vector(6) }, { random_matrix(3, n), random_vector(3) },
                                  { random_matrix(3, n), random_vector(3) } };
    std::vector<LevelReport> rep;
    MatrixXd P;
    const VectorXd qdot = wholebody::solve_velocity(levels, n, d, &rep, &P);
    double worst = 0;
    for (auto &r : rep) worst = std::max(worst, r.residual);
    const bool feasible = rep[0].feasible && rep[1].feasible && rep[2].feasible;
    if (trial == 0 || worst > 1e-9 || !feasible) {
      tap_ok(worst < 1e-9 && feasible, "velocity: 12 task rows in 14 joints: every level met exactly",
             fmt("worst residual %.2e", worst).c_str());
      if (worst > 1e-9 || !feasible) break;
    }
    // the levels' directions leave the projector: J_k P = 0 for every level, P a projector
    double leak = 0;
    for (auto &L : levels) leak = std::max(leak, (L.J * P).cwiseAbs().maxCoeff());
    const double idem = (P * P - P).cwiseAbs().maxCoeff();
    if (trial == 0 || leak > 1e-9 || idem > 1e-9) {
      tap_ok(leak < 1e-9 && idem < 1e-9, "velocity: the remaining projector is exact (J_k P = 0, P^2 = P)",
             (fmt("max |J P| %.2e", leak) + fmt(", |P^2 - P| %.2e", idem)).c_str());
      if (leak > 1e-9 || idem > 1e-9) break;
    }
  }

  // a lower level that asks for more than is left: the higher ones unchanged, the lower flagged
  {
    std::vector<Level> high = { { random_matrix(6, n), random_vector(6) }, { random_matrix(6, n), random_vector(6) } };
    const VectorXd q_high = wholebody::solve_velocity(high, n, d);
    std::vector<Level> all = high;
    all.push_back({ random_matrix(6, n), random_vector(6) });   // 18 rows in 14 joints
    std::vector<LevelReport> rep;
    const VectorXd q_all = wholebody::solve_velocity(all, n, d, &rep);
    const double moved = (high[0].J * (q_all - q_high)).norm() + (high[1].J * (q_all - q_high)).norm();
    tap_ok(moved < 1e-9 && rep[0].feasible && rep[1].feasible, "velocity: an over-demanding third level moves no higher one",
           fmt("higher tasks moved by %.2e", moved).c_str());
    tap_ok(!rep[2].feasible && rep[2].rank == 2 && rep[2].residual > 1e-3,
           "velocity: it is flagged infeasible with the 2 directions left to it",
           (fmt("rank %.0f", rep[2].rank) + fmt(", residual %.3f", rep[2].residual)).c_str());
  }

  // a level that repeats a higher one: no direction left (a conflict), its reference ignored
  {
    const MatrixXd J = random_matrix(3, n);
    std::vector<Level> levels = { { J, random_vector(3) }, { J, random_vector(3) } };
    std::vector<LevelReport> rep;
    const VectorXd qdot = wholebody::solve_velocity(levels, n, d, &rep);
    tap_ok(rep[1].rank == 0 && !rep[1].feasible && (J * qdot - levels[0].ref).norm() < 1e-9,
           "velocity: a task in conflict with a higher one has rank 0 and changes nothing", "");
  }

  // near a singularity: damped, bounded, flagged; exact (undamped) away from one
  {
    MatrixXd J = random_matrix(3, n);
    J.row(2) = J.row(1) + 1e-4 * random_matrix(1, n);   // two rows nearly parallel: sigma_min ~ 1e-4
    VectorXd ref(3);
    ref << 1, 1, -1;                                     // the nearly parallel rows asked opposite ways
    std::vector<Level> levels = { { J, ref } };
    std::vector<LevelReport> rep;
    const VectorXd qdot = wholebody::solve_velocity(levels, n, d, &rep);
    const double undamped = (J.completeOrthogonalDecomposition().pseudoInverse() * levels[0].ref).norm();
    tap_ok(rep[0].damping > 0.9 * d.lambda_max && !rep[0].feasible && qdot.norm() < 1e-2 * undamped,
           "velocity: near a singularity the solution is damped and bounded, the task flagged",
           (fmt("|qdot| %.1f", qdot.norm()) + fmt(" against %.0f undamped", undamped) +
            fmt(", sigma_min %.1e", rep[0].sigma_min)).c_str());
    levels[0].J = random_matrix(3, n);
    wholebody::solve_velocity(levels, n, d, &rep);
    tap_ok(rep[0].damping == 0 && rep[0].feasible, "velocity: away from singularities no damping at all", "");
  }
}

void torque_tests() {
  const int n = 14;
  const wholebody::Damping d;
  double worst_consistency = 0, worst_residual = 0, worst_posture = 0;
  for (int trial = 0; trial < 20; trial++) {
    const MatrixXd A = random_spd(n);
    const MatrixXd Ainv = A.inverse();
    std::vector<Level> levels = { { random_matrix(6, n), random_vector(6) }, { random_matrix(3, n), random_vector(3) },
                                  { random_matrix(3, n), random_vector(3) } };
    std::vector<LevelReport> rep;
    MatrixXd N;
    const VectorXd tau = wholebody::solve_torque(levels, A, Ainv, d, &rep, &N);
    for (auto &r : rep) worst_residual = std::max(worst_residual, r.residual);
    // dynamic consistency: no torque left in N^T accelerates any task
    for (auto &L : levels) worst_consistency = std::max(worst_consistency, (L.J * Ainv * N.transpose()).cwiseAbs().maxCoeff());
    // a posture torque through N^T leaves every task's acceleration as it was
    const VectorXd tau0 = random_vector(n);
    const VectorXd tau_all = tau + N.transpose() * tau0;
    for (auto &L : levels) worst_posture = std::max(worst_posture, (L.J * Ainv * (tau_all - tau)).norm());
  }
  tap_ok(worst_residual < 1e-8, "torque: 12 task rows in 14 joints: every level's acceleration met",
         fmt("worst residual %.2e", worst_residual).c_str());
  tap_ok(worst_consistency < 1e-9, "torque: dynamic consistency, J_k A^-1 N^T = 0 for every level",
         fmt("max %.2e", worst_consistency).c_str());
  tap_ok(worst_posture < 1e-9, "torque: a posture torque through N^T accelerates no task",
         fmt("max %.2e", worst_posture).c_str());

  // the levels below a higher one: its acceleration is the same with or without them
  {
    const MatrixXd A = random_spd(n), Ainv = A.inverse();
    std::vector<Level> high = { { random_matrix(6, n), random_vector(6) } };
    const VectorXd t1 = wholebody::solve_torque(high, A, Ainv, d);
    std::vector<Level> all = high;
    all.push_back({ random_matrix(6, n), random_vector(6) });
    all.push_back({ random_matrix(6, n), random_vector(6) });   // 18 rows: the last one cannot be met
    std::vector<LevelReport> rep;
    const VectorXd t3 = wholebody::solve_torque(all, A, Ainv, d, &rep);
    const double moved = (high[0].J * Ainv * (t3 - t1)).norm();
    tap_ok(moved < 1e-9 && !rep[2].feasible, "torque: lower levels, one over-demanding, move no higher one",
           fmt("moved %.2e", moved).c_str());
  }
}

}  // namespace

int main() {
  velocity_tests();
  torque_tests();
  return tap_done();
}
