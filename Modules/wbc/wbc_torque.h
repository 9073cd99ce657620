/* wbc_torque: the operational-space torques of strict task priorities (Modules/wbc/priority.hpp's
 * solve_torque, Sentis' formulation) behind a C ABI for LuaJIT (Lib/wbc_torque.lua): for a mass
 * matrix A (n x n) and levels of task Jacobians with the accelerations each asks for, the joint
 * torques tau = sum_k J_k|p^T Lambda_k|p (xddot_k - J_k A^-1 tau_{k-1}) + N^T tau0, where N is the
 * dynamically consistent null space left below the last level (tau0: a posture's torque, which then
 * accelerates no task). Gravity, Coriolis and friction terms are the caller's to add.
 *
 * Layouts: matrices row-major; the levels' Jacobians stacked (sum of rows x n) in level order, their
 * references likewise (sum of rows). Returns 0, or -1 with a message in err (a NaN or infinite input,
 * a size out of range); tau is then left untouched.
 */
#ifndef HRP_WBC_TORQUE_H
#define HRP_WBC_TORQUE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* What each level got: sigma_min of its projected inverse inertia's square roots, feasible (every
 * direction it asks for available and none near singular), the damping used. */
typedef struct {
  int rows, rank, feasible;
  double sigma_min, damping;
} wbc_torque_level;

/* n: joints (1..64); nlevel levels (1..8) of rows[k] rows (1..n) each; J and ref stacked; tau0 (n or
 * NULL: none); tau out (n); report out (nlevel or NULL). */
int wbc_solve_torque(int n, const double *A, int nlevel, const int *rows, const double *J, const double *ref,
                     const double *tau0, double *tau, wbc_torque_level *report, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif /* HRP_WBC_TORQUE_H */
