// The largest real part among the eigenvalues of M⁻¹K for small dense M, K
// (a problem's d × d mass and stiffness). Compiled once for every size: the
// fixed-size Eigen eigensolver, instantiated for each problem's d, was the
// largest single template cost of a solver's translation unit.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace vivp::linalg {

// One and two coordinates (a line, a plane orbit) in closed form, for any
// Eigen matrix type, so that a caller holding fixed-size blocks asks without
// copying them to the heap (the step control asks once per window). Two:
// A = M⁻¹K = adj(M) K / det M; its eigenvalues are tr/2 ± √((a00 − a11)²/4 +
// a01 a10), complex (real part tr/2) when the root's argument is negative.
// False when there is no closed form: more coordinates, M(0,0) = 0 for one,
// or |det M| ≤ 1e-12 max|M|² for two (too close to singular for the
// adjugate); LargestGeneralizedEigenvalue then takes the general path.
template <class Mat>
bool LargestOfFew(const Mat& k, const Mat& m, double& largest) {
  if (k.rows() == 1) {
    if (m(0, 0) == 0.0) return false;
    largest = std::max(0.0, k(0, 0) / m(0, 0));
    return true;
  }
  if (k.rows() != 2) return false;
  const double det = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
  const double scale = m.cwiseAbs().maxCoeff();
  if (!(std::abs(det) > 1e-12 * scale * scale)) return false;
  const double a00 = (m(1, 1) * k(0, 0) - m(0, 1) * k(1, 0)) / det;
  const double a01 = (m(1, 1) * k(0, 1) - m(0, 1) * k(1, 1)) / det;
  const double a10 = (m(0, 0) * k(1, 0) - m(1, 0) * k(0, 0)) / det;
  const double a11 = (m(0, 0) * k(1, 1) - m(1, 0) * k(0, 1)) / det;
  const double half_trace = 0.5 * (a00 + a11);
  const double half_gap = 0.5 * (a00 - a11);
  const double disc = half_gap * half_gap + a01 * a10;
  largest =
      std::max(0.0, disc >= 0 ? half_trace + std::sqrt(disc) : half_trace);
  return true;
}

// M = 0 (a first-order system, no oscillation) is the caller's case to
// handle; a singular nonzero M is solved by full-pivoting LU.
double LargestGeneralizedEigenvalue(const Eigen::MatrixXd& k,
                                    const Eigen::MatrixXd& m);

}  // namespace vivp::linalg
