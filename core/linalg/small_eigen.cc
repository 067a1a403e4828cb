#include "core/linalg/small_eigen.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace vivp::linalg {

namespace {

// Two coordinates (a plane orbit), in closed form: the step control asks
// once per window, and the general path (a full-pivoting LU, a Hessenberg
// reduction and a real Schur form, with their allocations) cost 3 % of a
// Kepler march's instructions. A = M⁻¹K = adj(M) K / det M; its eigenvalues
// are tr/2 ± √((a00 − a11)²/4 + a01 a10), complex (real part tr/2) when the
// root's argument is negative. False when M is too close to singular for
// the adjugate (|det M| ≤ 1e-12 max|M|²): the general path then.
bool LargestOfTwo(const Eigen::MatrixXd& k, const Eigen::MatrixXd& m,
                  double& largest) {
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

}  // namespace

double LargestGeneralizedEigenvalue(const Eigen::MatrixXd& k,
                                    const Eigen::MatrixXd& m) {
  if (k.rows() == 1 && m(0, 0) != 0.0) return std::max(0.0, k(0, 0) / m(0, 0));
  if (double largest; k.rows() == 2 && LargestOfTwo(k, m, largest))
    return largest;
  const Eigen::MatrixXd a = m.fullPivLu().solve(k);
  const Eigen::VectorXcd ev = a.eigenvalues();
  double largest = 0;
  for (Eigen::Index i = 0; i < ev.size(); ++i)
    largest = std::max(largest, ev[i].real());
  return largest;
}

}  // namespace vivp::linalg
