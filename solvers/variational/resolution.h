// Is the time step fine enough for the fastest oscillation of the problem?
//
// The variational SBP discretization is not unconditionally stable: for the
// harmonic oscillator ẍ = −ω²x its discrete critical point grows without
// bound once Δt·ω exceeds a limit that depends on the operator. Measured
// (global solve over 400 steps, max|x| < 1.5 as "bounded"; reproduce with
// tests/variational_resolution_test):
//   SBP21 0.70, SBP42 1.00, SBP63 0.95, SBP84 0.90.
// A Newton solve that converges to such a critical point has solved the
// discrete equations but not the problem, so SolveIvp reports it as not
// converged. ω is estimated from the Lagrangian: ω² = the largest eigenvalue
// of M⁻¹K with M = ∂²L/∂v², K = −∂²L/∂x², at the initial and final states.
#pragma once

#include <cmath>
#include <string_view>

#include "core/action/density.h"
#include "core/linalg/small_eigen.h"

namespace vivp::variational {

inline double StabilityLimit(std::string_view op) {
  if (op == "sbp21") return 0.70;
  if (op == "sbp42") return 1.00;
  if (op == "sbp63") return 0.95;
  if (op == "sbp84") return 0.90;
  return 0.70;
}

// The largest ω with ω² an eigenvalue of M⁻¹K at (x, v); 0 when the problem
// has no oscillation there (K ≤ 0, or a first-order system with M = 0).
template <class P>
double FastestFrequency(const P& problem, const double* x, const double* v) {
  constexpr int d = P::kDim;
  const auto h = action::LagrangianHessian(problem, x, v);
  const Eigen::MatrixXd m = h.template bottomRightCorner<d, d>();
  const Eigen::MatrixXd k = -h.template topLeftCorner<d, d>();
  if (m.cwiseAbs().maxCoeff() == 0.0) return 0.0;
  return std::sqrt(linalg::LargestGeneralizedEigenvalue(k, m));
}

}  // namespace vivp::variational
