// The model behind dynamics.h: Pinocchio's model and data, the map between the caller's joint
// order and Pinocchio's, the frame names, the state and which results of it are computed.
#ifndef HRP_DYN_MODEL_HPP
#define HRP_DYN_MODEL_HPP

#include "dynamics/dynamics.h"

#include <pinocchio/multibody.hpp>

#include <string>
#include <utility>
#include <unordered_map>
#include <vector>

struct dyn_model {
  // The data are built in place from the model (never copied: a copy of Pinocchio's data reads
  // Eigen solvers' fields that were never set).
  explicit dyn_model(pinocchio::Model &&m) : model(std::move(m)), kin(model), dyn(model) {}
  pinocchio::Model model;
  // Two data sets: the kinematic queries (joint Jacobians, frames, COM) and the dynamic ones
  // (CRBA, RNEA) each fill Pinocchio's work arrays their own way, so neither spoils the other's.
  pinocchio::Data kin, dyn;
  std::vector<std::string> joints;   // the caller's joint order
  std::vector<int> vcol;             // velocity index: ours -> Pinocchio's (nv)
  std::vector<int> qidx;             // configuration index of joint j (njoint)
  std::unordered_map<std::string, int> frames;   // name -> frame id
  Eigen::VectorXd q, v, acc;         // Pinocchio's order (acc: inverse dynamics' input)
  unsigned done = 0;                 // DONE_* of the current state
  Eigen::MatrixXd work;              // 6 x nv, Pinocchio's column order
  std::string err;
};

enum : unsigned { DONE_KIN = 1, DONE_COM = 2, DONE_CRBA = 4, DONE_GRAVITY = 8, DONE_NLE = 16 };

// Sets m->err and returns code.
int dyn_fail(dyn_model *m, int code, const std::string &msg);

#endif
