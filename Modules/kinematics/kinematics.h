/* kinematics: forward and inverse kinematics and centre of mass of a small humanoid
 * (OP3 / DARwIn-OP class), a plain C ABI over C++/Eigen, used from LuaJIT (Lib/kinematics.lua).
 *
 * The robot is data, not code (kin_desc): every joint is a revolute axis given in the
 * "reference frame" = the robot at its zero pose (all joints 0), soles on z = 0, x forward,
 * y left, z up, metres. Joint angles follow the right-hand rule about the axis as given (so
 * mirrored left/right axes give mirrored signs). Link masses and centres of mass are given
 * at the zero pose too. Forward kinematics is the product of exponentials of these axes.
 *
 * Frames used by the functions:
 *   torso frame  axes of the reference frame carried by the torso; origin at kin_desc.origin
 *                (a reference-frame point). Foot, hand, COM and camera poses are in it.
 *   foot frame   origin at the sole point below the ankle (kin_desc.sole), axes parallel to
 *                the torso frame at the zero pose (x forward, z up out of the sole).
 *   camera frame origin at the optical centre, x along the optical axis, y left, z = image up.
 *   level frame  origin at the torso origin, z against gravity, x = torso heading (torso
 *                roll and pitch removed, yaw kept at 0); used by kin_camera_pose.
 * Poses as 6 numbers: x y z roll pitch yaw with R = Rz(yaw) Ry(pitch) Rx(roll).
 * Rotations as 9 numbers: row-major 3x3.
 *
 * Errors: functions return 0 (or a flag set >= 0) on success and a negative code on a caller
 * mistake; kin_model_create writes a message into the caller's buffer. No output is ever NaN:
 * non-finite inputs are replaced (see KIN_BAD_INPUT) and counted in the flags.
 */
#ifndef HRP_KINEMATICS_H
#define HRP_KINEMATICS_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- model description */

#define KIN_LEFT 0
#define KIN_RIGHT 1

/* Everything the model needs, in plain arrays (copied by kin_model_create). */
typedef struct kin_desc {
  int njoint;                 /* number of joints (20 for OP3 / DARwIn-OP) */
  const int *parent;          /* (njoint) parent joint index, -1 = the torso */
  const double *axis;         /* (njoint x 3) joint axis, reference frame (normalised here) */
  const double *anchor;       /* (njoint x 3) m, a point on the axis, reference frame */
  const double *mass;         /* (njoint) kg, link moved by the joint */
  const double *com;          /* (njoint x 3) m, that link's centre of mass at the zero pose */
  const double *qmin;         /* (njoint) rad, lower joint limits; NULL = none */
  const double *qmax;         /* (njoint) rad, upper joint limits; NULL = none */
  double torso_mass;          /* kg */
  double torso_com[3];        /* m, reference frame */
  double origin[3];           /* m, torso-frame origin in the reference frame */
  int leg[2][6];              /* joint indices: hip yaw, roll, pitch, knee, ankle pitch, roll */
  double sole[2][3];          /* m, foot-frame origin (sole point below the ankle), reference */
  int arm[2][3];              /* joint indices: shoulder pitch, shoulder roll, elbow */
  double hand[2][3];          /* m, hand point on the last arm link, reference frame */
  int head[2];                /* joint indices: pan, tilt */
  double camera[3];           /* m, optical centre on the head's last link, reference frame */
} kin_desc;

typedef struct kin_model kin_model;

/* Flags returned by the inverse kinematics (bit set; 0 = exact solution). */
#define KIN_OK 0
#define KIN_UNREACHABLE 1     /* target out of reach: nearest reachable solution returned */
#define KIN_JOINT_LIMIT 2     /* an angle was clamped to its joint limit */
#define KIN_BAD_INPUT 4       /* a NaN or infinite input was replaced by the zero-pose value */

#define KIN_EINVAL (-1)       /* bad argument (NULL pointer, side not 0/1) */
#define KIN_EMODEL (-2)       /* description not usable (message in err) */

/* ---------------------------------------------------------------- model */

/* Builds a model from a description; checks that each leg has the structure the analytic
 * solver needs (yaw axis along z; roll and pitch axes meeting at the hip; knee and ankle pitch
 * parallel to the hip pitch; ankle pitch and roll meeting at the ankle, below the hip). */
int kin_model_create(const kin_desc *d, kin_model **out, char *err, size_t errlen);

/* Frees a model (NULL is fine). */
void kin_model_destroy(kin_model *m);

/* Number of joints of the model. */
int kin_njoint(const kin_model *m);

/* Whole-body mass, kg. */
double kin_total_mass(const kin_model *m);

/* ---------------------------------------------------------------- forward kinematics */

/* Pose of every link: out (njoint x 12) = rotation (9, row-major) then position (3) of the
 * link frame in the torso frame (link frame = torso-aligned at the zero pose, origin at the
 * reference origin carried along). q (njoint) rad. Returns a flag set (KIN_BAD_INPUT). */
int kin_link_poses(const kin_model *m, const double *q, double *out);

/* Foot pose of one leg from its 6 angles (leg order): pose (6) x y z roll pitch yaw,
 * torso frame. rot (9) may be NULL. Returns a flag set or KIN_EINVAL. */
int kin_leg_fk(const kin_model *m, int side, const double *q6, double *pose, double *rot);

/* Hand position (3) of one arm from its 3 angles, torso frame; rot (9) may be NULL. */
int kin_arm_fk(const kin_model *m, int side, const double *q3, double *pos, double *rot);

/* Camera pose from the 2 head angles: pos (3) and rot (9), torso frame. */
int kin_head_fk(const kin_model *m, const double *q2, double *pos, double *rot);

/* Camera pose in the level frame from all joint angles q (njoint) and the torso's roll,
 * pitch (rpy (3), yaw ignored): pos (3), rot (9); *height (may be NULL) = camera height
 * above the lower sole (the ground under the support foot). */
int kin_camera_pose(const kin_model *m, const double *q, const double *rpy,
                    double *pos, double *rot, double *height);

/* Whole-body centre of mass (3), torso frame, from all joint angles q (njoint). */
int kin_com(const kin_model *m, const double *q, double *com);

/* ---------------------------------------------------------------- inverse kinematics */

/* Analytic 6-joint leg IK: foot pose (6: x y z roll pitch yaw, torso frame) -> q6 (leg order).
 * Out of reach: the foot orientation is kept and the foot goes as near as it can along the
 * line from the hip (KIN_UNREACHABLE). Angles are clamped to the limits (KIN_JOINT_LIMIT). */
int kin_leg_ik(const kin_model *m, int side, const double *pose, double *q6);

/* Arm IK for a hand position (3, torso frame) -> q3 (arm order). q3 holds the starting guess
 * (e.g. the current angles) on entry; damped least squares on the exact chain. KIN_UNREACHABLE
 * when the hand stays more than 1e-4 m from the target (the closest point found is returned). */
int kin_arm_ik(const kin_model *m, int side, const double *pos, double *q3);

/* Head angles (2: pan, tilt) that point the camera's optical axis at a point (3, torso
 * frame). KIN_UNREACHABLE if the point is too close to the camera or a limit binds. */
int kin_head_look_at(const kin_model *m, const double *target, double *q2);

#ifdef __cplusplus
}
#endif

#endif /* HRP_KINEMATICS_H */
