/* kinematics: forward and inverse kinematics and centre of mass of a humanoid over named chains
 * (legs, arms, head), a plain C ABI over C++/Eigen, used from LuaJIT (Lib/kinematics.lua).
 *
 * The robot is data, not code. kin_model_load builds a model from the robot's URDF (the same file
 * the simulator reads, parsed by Modules/description) plus the robot config's joint order and
 * chains; kin_model_create builds one from plain arrays (kin_desc), which is what the loader fills.
 *
 * Description (kin_desc): every joint is a revolute axis given in the "reference frame" = the
 * robot at its zero pose (all joints 0). Joint angles follow the right-hand rule about the axis as
 * given (so mirrored left/right axes give mirrored signs). Link masses and centres of mass are
 * given at the zero pose too. Forward kinematics is the product of exponentials of these axes.
 * Joints may come in any order (the bus order): each names its parent joint (-1 = the torso), and
 * chains name their joints from the base to the tip; a chain may hang from any link.
 *
 * Frames used by the functions:
 *   torso frame  axes of the reference frame carried by the torso (the URDF's root link); origin
 *                at kin_desc.origin (a reference-frame point; 0 for a URDF: its root link frame).
 *                Foot, hand, COM and camera poses are in it.
 *   tip frames   each chain ends in a frame fixed to its last link (the URDF frames l_sole,
 *                l_hand, camera_link ...): foot frame (origin on the sole below the ankle, x
 *                forward, z up out of the sole), hand frame, camera frame (origin at the optical
 *                centre, x along the optical axis, y left, z = image up).
 *   level frame  origin at the torso origin, z against gravity, x = torso heading (torso roll
 *                and pitch removed, yaw kept at 0); used by kin_camera_pose.
 * Poses as 6 numbers: x y z roll pitch yaw with R = Rz(yaw) Ry(pitch) Rx(roll).
 * Rotations as 9 numbers: row-major 3x3 (columns = the frame's axes in the torso frame).
 *
 * Whole-body angle arrays q (njoint) are in the model's joint order. The chain functions take the
 * chain's own angles; `qbase` (njoint, may be NULL = all 0) gives the angles of the joints between
 * the torso and the chain (a waist), which place the chain's base.
 *
 * Errors: functions return 0 (or a flag set >= 0) on success and a negative code on a caller
 * mistake; model creation writes a message into the caller's buffer. No output is ever NaN:
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

/* Chain kinds, and what each needs. */
#define KIN_LEG 0    /* 6 joints: hip yaw, hip roll, hip pitch, knee, ankle pitch, ankle roll, with
                        axes along z, x, y, y, y, x (either sense); hip roll/pitch axes meeting,
                        ankle pitch/roll axes meeting below the hip. Tip: the foot frame. */
#define KIN_ARM 1    /* 1..16 joints, any axes. Tip: the hand frame. */
#define KIN_HEAD 2   /* 2 joints: pan (axis along z), tilt (along y), the optical axis (the tip's
                        x) perpendicular to the tilt axis. Tip: the camera frame. */
/* A tip is a frame on the chain's last link or, for an arm or a head, on a link below it (a neck
 * roll between the tilt and the camera): the joints between the chain and its tip then take their
 * angles from qbase, as those above the chain do. A leg's tip is on its last link. */

#define KIN_MAXJ 64          /* joints of a model at most */
#define KIN_MAXARM 16        /* joints of an arm at most */

typedef struct kin_chain {
  const char *name;          /* for messages (e.g. "lleg"); may be NULL */
  int kind;                  /* KIN_LEG, KIN_ARM, KIN_HEAD */
  int side;                  /* KIN_LEFT / KIN_RIGHT for legs and arms; 0 for the head */
  int n;                     /* number of joints */
  const int *joints;         /* (n) joint indices from the base to the tip */
  double tip[3];             /* m, tip frame origin at the zero pose, reference frame */
  double tip_rot[9];         /* tip frame axes at the zero pose, reference frame (row-major) */
  int tip_below;             /* 0: the tip is on the last joint's link; else 1 + the index of the joint
                                whose link carries it, a joint below the last one (arm, head) */
} kin_chain;

/* Everything the model needs, in plain arrays (copied by kin_model_create). */
typedef struct kin_desc {
  int njoint;                 /* number of joints, 1..KIN_MAXJ */
  const int *parent;          /* (njoint) parent joint index, -1 = the torso; any order, no cycle */
  const double *axis;         /* (njoint x 3) joint axis, reference frame (normalised here) */
  const double *anchor;       /* (njoint x 3) m, a point on the axis, reference frame */
  const double *mass;         /* (njoint) kg, link moved by the joint */
  const double *com;          /* (njoint x 3) m, that link's centre of mass at the zero pose */
  const double *qmin;         /* (njoint) rad, lower joint limits; NULL = none */
  const double *qmax;         /* (njoint) rad, upper joint limits; NULL = none */
  const char *const *names;   /* (njoint) joint names for messages; NULL = indices */
  double torso_mass;          /* kg */
  double torso_com[3];        /* m, reference frame */
  double origin[3];           /* m, torso-frame origin in the reference frame */
  int nchain;                 /* number of chains; at most one per kind and side */
  const kin_chain *chains;    /* (nchain) */
} kin_desc;

/* What kin_model_load reads besides the URDF: the robot config's joint order and chains. */
typedef struct kin_chain_spec {
  const char *name;          /* e.g. "lleg" (messages) */
  int kind, side;            /* as in kin_chain */
  int n;
  const char *const *joints; /* (n) joint names from the base to the tip */
  const char *tip;           /* a frame (massless fixed link) or link of the URDF */
} kin_chain_spec;

typedef struct kin_spec {
  const char *urdf;          /* path of the robot's URDF */
  const char *config;        /* name of the robot config, for messages (e.g. its file) */
  int njoint;
  const char *const *joints; /* (njoint) the robot's joint order: every URDF joint exactly once */
  int nchain;
  const kin_chain_spec *chains;
} kin_spec;

typedef struct kin_model kin_model;

/* Flags returned by the inverse kinematics (bit set; 0 = exact solution). */
#define KIN_OK 0
#define KIN_UNREACHABLE 1     /* target out of reach: nearest reachable solution returned */
#define KIN_JOINT_LIMIT 2     /* an angle was clamped to its joint limit */
#define KIN_BAD_INPUT 4       /* a NaN or infinite input was replaced by the zero-pose value */

#define KIN_EINVAL (-1)       /* bad argument (NULL pointer, side not 0/1) */
#define KIN_EMODEL (-2)       /* description not usable (message in err) */
#define KIN_ENOCHAIN (-3)     /* the model has no such chain */

/* ---------------------------------------------------------------- model */

/* Builds a model from a description; checks the joint tree (no cycle), that each chain is a
 * path down the tree and that it has the structure its solver needs (see KIN_LEG ...). */
int kin_model_create(const kin_desc *d, kin_model **out, char *err, size_t errlen);

/* Builds a model from a URDF and the robot's joint order and chains. Refuses (message naming the
 * file and the element): an unreadable or invalid URDF, a URDF joint missing from the joint
 * order or the reverse, an unknown joint or tip in a chain, a chain that is not a path down the
 * tree or that its solver cannot serve. Torso = the URDF's root link; limits from the URDF. */
int kin_model_load(const kin_spec *s, kin_model **out, char *err, size_t errlen);

/* Frees a model (NULL is fine). */
void kin_model_destroy(kin_model *m);

/* Number of joints of the model. */
int kin_njoint(const kin_model *m);

/* Whole-body mass, kg. */
double kin_total_mass(const kin_model *m);

/* Joint j's axis in the torso frame at the zero pose (3, unit) and limits (rad; may be NULL). */
int kin_joint_info(const kin_model *m, int j, double *axis, double *qmin, double *qmax);

/* Number of joints of a chain (kind, side) and their indices (idx may be NULL), or KIN_ENOCHAIN. */
int kin_chain_joints(const kin_model *m, int kind, int side, int *idx);

/* ---------------------------------------------------------------- forward kinematics */

/* Pose of every link: out (njoint x 12) = rotation (9, row-major) then position (3) of the
 * link frame in the torso frame (link frame = torso-aligned at the zero pose, origin at the
 * torso origin carried along). q (njoint) rad. Returns a flag set (KIN_BAD_INPUT). */
int kin_link_poses(const kin_model *m, const double *q, double *out);

/* Foot pose of one leg from its 6 angles (leg order): pose (6) x y z roll pitch yaw,
 * torso frame. rot (9) may be NULL. Returns a flag set, KIN_EINVAL or KIN_ENOCHAIN. */
int kin_leg_fk(const kin_model *m, int side, const double *q6, const double *qbase, double *pose,
               double *rot);

/* Hand position (3) of one arm from its n angles, torso frame; rot (9) may be NULL. */
int kin_arm_fk(const kin_model *m, int side, const double *qn, const double *qbase, double *pos,
               double *rot);

/* Camera pose from the 2 head angles: pos (3) and rot (9), torso frame. */
int kin_head_fk(const kin_model *m, const double *q2, const double *qbase, double *pos, double *rot);

/* Camera pose in the level frame from all joint angles q (njoint) and the torso's roll,
 * pitch (rpy (3), yaw ignored): pos (3), rot (9); *height (may be NULL) = camera height
 * above the lower sole (the ground under the support foot; above the torso origin if the model
 * has no legs). */
int kin_camera_pose(const kin_model *m, const double *q, const double *rpy,
                    double *pos, double *rot, double *height);

/* Whole-body centre of mass (3), torso frame, from all joint angles q (njoint). */
int kin_com(const kin_model *m, const double *q, double *com);

/* ---------------------------------------------------------------- inverse kinematics */

/* Analytic 6-joint leg IK: foot pose (6: x y z roll pitch yaw, torso frame) -> q6 (leg order).
 * Out of reach: the foot orientation is kept and the foot goes as near as it can along the
 * line from the hip (KIN_UNREACHABLE). Angles are clamped to the limits (KIN_JOINT_LIMIT). */
int kin_leg_ik(const kin_model *m, int side, const double *pose, const double *qbase, double *q6);

/* Arm IK for a hand position (3, torso frame) -> qn (arm order). qn holds the starting guess
 * (e.g. the current angles) on entry; damped least squares on the exact chain. KIN_UNREACHABLE
 * when the hand stays more than 1e-4 m from the target (the closest point found is returned). */
int kin_arm_ik(const kin_model *m, int side, const double *pos, const double *qbase, double *qn);

/* Head angles (2: pan, tilt) that point the camera's optical axis at a point (3, torso
 * frame). KIN_UNREACHABLE if the point is too close to the camera or a limit binds. A head of two
 * horizontal tilt axes (the Hubo's NK1/NK2 at +-45 deg) is solved numerically (Gauss-Newton on the
 * direction, within the limits): it pitches and rolls the camera, so a point to the side is
 * reached only within what the two tilts allow (KIN_UNREACHABLE beyond: the nearest direction). */
int kin_head_look_at(const kin_model *m, const double *target, const double *qbase, double *q2);

#ifdef __cplusplus
}
#endif

#endif /* HRP_KINEMATICS_H */
