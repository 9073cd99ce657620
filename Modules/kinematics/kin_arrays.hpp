// The per-joint arrays of a kin_desc in std::vector storage, for the C++ that builds descriptions
// (kin_load.cpp from a URDF; the tree tests joint by joint). Internal to Modules/kinematics.
#ifndef HRP_KIN_ARRAYS_HPP
#define HRP_KIN_ARRAYS_HPP

#include "kinematics/kinematics.h"

#include <vector>

struct KinArrays {
  std::vector<int> parent;                                       // (n)
  std::vector<double> axis, anchor, com;                         // (3n)
  std::vector<double> mass, qmin, qmax;                          // (n)

  KinArrays() = default;
  explicit KinArrays(int n)
      : parent(n), axis(3 * n), anchor(3 * n), com(3 * n), mass(n), qmin(n), qmax(n) {}

  // Points d's joint arrays at these (valid while the vectors are not resized); njoint = their size.
  void describe(kin_desc &d) const {
    d.njoint = (int)parent.size();
    d.parent = parent.data();
    d.axis = axis.data();
    d.anchor = anchor.data();
    d.mass = mass.data();
    d.com = com.data();
    d.qmin = qmin.data();
    d.qmax = qmax.data();
  }
};

#endif
