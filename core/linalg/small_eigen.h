// The largest real part among the eigenvalues of M⁻¹K for small dense M, K
// (a problem's d × d mass and stiffness). Compiled once for every size: the
// fixed-size Eigen eigensolver, instantiated for each problem's d, was the
// largest single template cost of a solver's translation unit.
#pragma once

#include <Eigen/Core>

namespace vivp::linalg {

// NaN-free for singular M only if the caller excludes M = 0 first.
double LargestGeneralizedEigenvalue(const Eigen::MatrixXd& k,
                                    const Eigen::MatrixXd& m);

}  // namespace vivp::linalg
