/* dynamics: the rigid-body model of a body with a floating base, from its URDF, through
 * Pinocchio (the libpinocchio wheel in the project's .venv), behind a plain C ABI for LuaJIT
 * (Lib/dynamics.lua). Frame poses and Jacobians, the centre of mass and its Jacobian, the
 * joint-space mass matrix (CRBA), gravity torques, nonlinear effects and inverse dynamics (RNEA).
 *
 * The model: the URDF's root link is the base, joined to the world by a free-flyer joint; every
 * other movable joint of the URDF is one of the body's joints (1-DoF: revolute or prismatic).
 * Fixed joints are merged; their child links stay as frames (l_sole, r_palm, camera_link ...).
 *
 * Orders and layouts:
 *   joint order   the caller's (robot.lua `joints`, the shm order); NULL at load: the URDF's order
 *                 as Pinocchio reads it (depth first).
 *   base pose     7 numbers: position x y z (m, world) then the orientation quaternion x y z w
 *                 (normalised here); NULL = at the origin, upright.
 *   velocities    nv = 6 + njoint numbers: the base twist (linear then angular, in the base link's
 *                 frame: Pinocchio's free-flyer convention), then the joint rates in joint order.
 *                 Jacobian columns, mass-matrix rows and columns and generalized forces (gravity,
 *                 nonlinear effects, torques) are in this order too; their first 6 entries are the
 *                 base's (a force and a moment on the base, in its frame).
 *   matrices      row-major: a 6 x nv Jacobian is J[r * nv + c].
 *   frame pose    position (3, world) and rotation (9, row-major: columns = the frame's axes in the
 *                 world).
 *   Jacobians     a frame's 6 x nv Jacobian maps velocities to the frame's linear velocity (rows
 *                 0-2: of its origin) and angular velocity (rows 3-5), expressed either in world-
 *                 aligned axes at the frame's origin (DYN_WORLD_ALIGNED, Pinocchio's
 *                 LOCAL_WORLD_ALIGNED: what task-space control needs) or in the frame's own axes
 *                 (DYN_LOCAL).
 *   gravity       -9.81 m/s^2 along the world's z.
 *
 * A model holds a state (base pose, joint angles, velocities) set by dyn_set_state; every query is
 * of that state and computes what it needs once (the next dyn_set_state invalidates it). A model is
 * not thread-safe: one per thread.
 *
 * Errors: every function returns 0 (or a count or id >= 0) on success and a negative DYN_E* code on
 * failure, with a message naming the thing (frame, joint, file) in dyn_error(). A refused state
 * leaves the previous one in place. Nothing throws across the ABI.
 */
#ifndef HRP_DYNAMICS_H
#define HRP_DYNAMICS_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Jacobian reference frames */
enum { DYN_WORLD_ALIGNED = 0, DYN_LOCAL = 1 };

/* Return codes */
enum {
  DYN_EINVAL = -1,     /* bad argument: NULL pointer, index out of range, unknown reference frame */
  DYN_ENOFRAME = -2,   /* no frame of that name */
  DYN_EBADINPUT = -3,  /* a NaN or infinite input, a zero quaternion */
  DYN_EMODEL = -4,     /* the URDF or the joint order is not usable */
  DYN_EFAIL = -5       /* Pinocchio failed (its message in dyn_error) */
};

typedef struct dyn_model dyn_model;

/* Builds a model from a URDF (path) and a joint order (njoint names, each a movable joint of the
 * URDF, every movable joint once; joints NULL: the URDF's order, njoint ignored). On failure
 * returns DYN_EMODEL and writes a message naming the file and the joint into err. */
int dyn_model_load(const char *urdf, int njoint, const char *const *joints, dyn_model **out, char *err,
                   size_t errlen);

void dyn_model_destroy(dyn_model *m);   /* NULL is fine */

/* The message of the last failed call ("" if none). */
const char *dyn_error(const dyn_model *m);

int dyn_njoint(const dyn_model *m);     /* joints of the body (without the base) */
int dyn_nq(const dyn_model *m);         /* Pinocchio's configuration size: 7 + njoint */
int dyn_nv(const dyn_model *m);         /* velocity size: 6 + njoint */
const char *dyn_joint_name(const dyn_model *m, int j);   /* j in joint order; NULL if out of range */
double dyn_total_mass(const dyn_model *m);               /* kg */

int dyn_nframe(const dyn_model *m);
const char *dyn_frame_name(const dyn_model *m, int frame);   /* NULL if out of range */
/* A frame's id: a link (its body frame), else a joint's frame. DYN_ENOFRAME if the URDF has none. */
int dyn_frame_id(dyn_model *m, const char *name);

/* Sets the state: base (7 or NULL), q (njoint, joint order), v (nv or NULL: at rest). */
int dyn_set_state(dyn_model *m, const double *base, const double *q, const double *v);

/* World pose of a frame: pos (3), rot (9, may be NULL). */
int dyn_frame_pose(dyn_model *m, int frame, double *pos, double *rot);

/* A frame's Jacobian, 6 x nv, in DYN_WORLD_ALIGNED or DYN_LOCAL axes. */
int dyn_frame_jacobian(dyn_model *m, int frame, int ref, double *J);

/* Whole-body centre of mass (3, world) and its Jacobian (3 x nv, world axes; may be NULL). */
int dyn_com(dyn_model *m, double *com, double *J);

/* Joint-space mass matrix (nv x nv, symmetric), CRBA. */
int dyn_mass_matrix(dyn_model *m, double *M);

/* Gravity torques g(q) (nv): the generalized forces that hold the body still against gravity. */
int dyn_gravity(dyn_model *m, double *g);

/* Nonlinear effects h(q, v) = C(q, v) v + g(q) (nv), RNEA with zero acceleration. */
int dyn_nonlinear(dyn_model *m, double *h);

/* Inverse dynamics (RNEA): tau = M(q) a + h(q, v) for an acceleration a (nv). */
int dyn_inverse_dynamics(dyn_model *m, const double *a, double *tau);

#ifdef __cplusplus
}
#endif

#endif /* HRP_DYNAMICS_H */
