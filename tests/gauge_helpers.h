// What the gauge-field tests share: a window's Jacobian as a dense matrix
// (tests on a few hundred unknowns; the solves never form it).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "solvers/spacetime/assembly.h"

namespace gauge_test {

template <class System>
Eigen::MatrixXd DenseJacobian(const System& sys, const std::vector<double>& y) {
  vivp::spacetime::PatternedMatrix jac;
  jac.Assemble(sys.size(), [&](auto& sink) { sys.Jacobian(y.data(), sink); });
  return Eigen::MatrixXd(jac.matrix());
}

}  // namespace gauge_test
