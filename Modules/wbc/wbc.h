/* wbc: whole-body control of a floating-base body in kinematic mode (position servos), behind a C
 * ABI for LuaJIT (Lib/wbc.lua). Tasks (a frame's position, orientation or pose, the centre of mass,
 * a joint posture) sit in strict priority levels (Modules/wbc/priority.hpp); the feet (the
 * contacts) are held as the level above every task; joint position limits are kept by locking a
 * joint that would cross one as a constraint above everything (and solving again), joint speed
 * limits by scaling the whole step. Each step integrates the joint rates (and the floating base's
 * twist the contacts imply) over dt into the angles to command.
 *
 * Frames and units: the model's world is the stance frame, set by wbc_reset from the present
 * joint angles: on the ground midway between the contact frames (the soles), x along their mean
 * heading, z up (the contacts' mean orientation made level). Metres, radians; orientations as
 * 3x3 row-major matrices (columns: the frame's axes in the stance frame).
 *
 * Errors: every function returns >= 0 on success and < 0 on failure with a message naming the
 * thing (task, frame, joint, the bad number) in wbc_error(). A refused call changes nothing.
 */
#ifndef HRP_WBC_H
#define HRP_WBC_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* task kinds, with the target each takes (n numbers to wbc_task_target) */
enum {
  WBC_POSITION = 0,     /* a frame's origin: 3 */
  WBC_ORIENTATION = 1,  /* a frame's axes: 9 (row-major rotation) */
  WBC_POSE = 2,         /* both: 12 (position, then rotation) */
  WBC_COM = 3,          /* the centre of mass: 3 */
  WBC_COM_XY = 4,       /* the centre of mass over the ground: 2 (x, y) */
  WBC_POSTURE = 5       /* every joint's angle: njoint (robot order); its level is the lowest */
};

typedef struct wbc wbc;

typedef struct {
  int kind, level, rows, rank, feasible, enabled;
  double error;                 /* |target - present| (m, rad; a posture's RMS rad) */
  double sigma_min, sigma_max;  /* of the task's level in the null space of the levels above */
  double damping;
} wbc_task_status;

/* A controller of the body in `urdf` with its joints in robot order (njoint names; NULL: the URDF's
 * order), stepping by dt s. */
int wbc_new(const char *urdf, int njoint, const char *const *joints, double dt, wbc **out, char *err, size_t errlen);
void wbc_free(wbc *w);
const char *wbc_error(const wbc *w);
int wbc_njoint(const wbc *w);
const char *wbc_joint_name(const wbc *w, int j);   /* NULL if out of range */

/* Joint limits (njoint each, robot order): position lo, hi (rad) and speed (rad/s). */
int wbc_set_limits(wbc *w, const double *lo, const double *hi, const double *speed);
/* The frames in contact with the ground (the soles), held where they are at wbc_reset; after it, a
 * frame that stays a contact keeps its anchor and a new one is held where the model has it now. */
int wbc_set_contacts(wbc *w, int n, const char *const *frames);
/* Starts from the present joint angles (njoint): the stance frame, the contacts' anchors. */
int wbc_reset(wbc *w, const double *q);

/* A task: returns its id. gain: 1/s (the reference rate is gain * error); max_rate: the largest
 * reference speed (m/s or rad/s; <= 0: none). A task starts without a target (disabled). */
int wbc_task_add(wbc *w, const char *name, int kind, const char *frame, int level, double gain, double max_rate);
int wbc_task_id(const wbc *w, const char *name);
int wbc_task_target(wbc *w, int id, const double *target, int n);   /* n: the kind's count */
int wbc_task_clear(wbc *w, int id);                                    /* no target: the task rests */
int wbc_task_gain(wbc *w, int id, double gain);
/* The task's reference changes by at most max_accel per second (m/s^2 or rad/s^2; 0: no bound): a
 * new target starts it moving smoothly. */
int wbc_task_accel(wbc *w, int id, double max_accel);
int wbc_task_level(wbc *w, int id, int level);
int wbc_task_status_of(wbc *w, int id, wbc_task_status *out);
int wbc_ntask(const wbc *w);
const char *wbc_task_name(const wbc *w, int id);

/* The floating base (the torso) may lean at most `rad` from upright (0: no bound): a step that would
 * tilt it further stops its tilting (a constraint above every task, as a joint limit). A body leaning
 * after a target it cannot reach would otherwise tip over. */
int wbc_set_max_lean(wbc *w, double rad);
/* 1 if the last step held the base at max_lean. */
int wbc_leaning(const wbc *w);

/* One step: q_out (njoint) the angles to command. Returns the number of joints (and the lean) a limit
 * held. */
int wbc_step(wbc *w, double *q_out);

/* The model's pose of a frame (or 'com': position only) in the stance frame: pos 3, rot 9 (NULL ok). */
int wbc_frame_pose(wbc *w, const char *frame, double *pos, double *rot);
/* The floating base's pose in the stance frame: x y z qx qy qz qw. */
int wbc_base(const wbc *w, double *base7);
/* Microseconds of CPU the last step took. */
double wbc_step_us(const wbc *w);

#ifdef __cplusplus
}
#endif

#endif /* HRP_WBC_H */
