// The largest real part among the eigenvalues of M⁻¹K for small dense M, K
// (a problem's d × d mass and stiffness). Compiled once for every size: the
// fixed-size Eigen eigensolver, instantiated for each problem's d, was the
// largest single template cost of a solver's translation unit.
#pragma once

#include <Eigen/Core>

namespace vivp::linalg {

// M = 0 (a first-order system, no oscillation) is the caller's case to
// handle; a singular nonzero M is solved by full-pivoting LU.
double LargestGeneralizedEigenvalue(const Eigen::MatrixXd& k,
                                    const Eigen::MatrixXd& m);

}  // namespace vivp::linalg
