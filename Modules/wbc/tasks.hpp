// The body the controller moves (the rigid-body model of Modules/dynamics with a floating base and
// its state) and the tasks on it: each kind's Jacobian rows and reference rate.
#ifndef HRP_WBC_TASKS_HPP
#define HRP_WBC_TASKS_HPP

#include "dynamics/dynamics.h"
#include "wbc/priority.hpp"

#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace wholebody {

struct Body {
  dyn_model *model = nullptr;
  int nj = 0, nv = 0;
  std::vector<std::string> joints;
  Eigen::VectorXd q;                  // joint angles, robot order
  Eigen::Vector3d base_p;             // the floating base in the stance frame
  Eigen::Quaterniond base_r;
  std::vector<double> buf;            // 6 x nv, row-major, for the C calls
  std::string err;
};

struct Task {
  std::string name, frame;
  int kind = 0, level = 0, fid = -1;
  double gain = 0, max_rate = 0;
  double max_accel = 0;               // the reference's largest change per second (<= 0: none)
  Eigen::VectorXd last_ref, next_ref; // the reference of the last step (empty: at rest), of this one
  bool has = false;                   // a target is set
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();      // POSITION, POSE, COM, COM_XY targets
  Eigen::Matrix3d rot = Eigen::Matrix3d::Identity();  // ORIENTATION, POSE
  Eigen::VectorXd q;                                   // POSTURE
  double error = 0;                   // at the last step
  LevelReport report;                 // the task's level at the last step
};

bool body_load(Body *b, const char *urdf, int nj, const char *const *joints, char *err, size_t errlen);
void body_free(Body *b);
// Sends the state to the model (false: b->err says why).
bool body_update(Body *b);
// Moves the state by velocities qd (nv: the base's twist in its own frame, then the joints) over dt.
void body_integrate(Body *b, const Eigen::VectorXd &qd, double dt);

int frame_id(Body &b, const std::string &name);
void frame_pose(Body &b, int fid, Eigen::Vector3d *p, Eigen::Matrix3d *R);
void com(Body &b, Eigen::Vector3d *c, Eigen::MatrixXd *J);

// A task of `kind` on `frame` (COM and POSTURE take none); false and *why on a bad name or kind.
bool task_init(Body &b, Task *t, const std::string &name, int kind, const std::string &frame, int level, double gain,
               double max_rate, std::string *why);
// Its target: n numbers, the kind's count (wbc.h); false and *why on a wrong count, a NaN or a
// matrix that is not a rotation.
bool task_set_target(const Body &b, Task *t, const double *target, int n, std::string *why);
// Its rows at the body's present state: J (rows x nv) and ref = gain * error (its norm at most
// max_rate). Returns the error's size.
double task_rows(Body &b, const Task &t, Eigen::MatrixXd *J, Eigen::VectorXd *ref);
// The rows of several tasks as one level.
Level vstack(const std::vector<Eigen::MatrixXd> &Js, const std::vector<Eigen::VectorXd> &refs);

}  // namespace wholebody

#endif
