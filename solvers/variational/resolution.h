// Is the time step fine enough for the fastest oscillation of the problem?
//
// The variational SBP discretization is not unconditionally stable: for the
// harmonic oscillator ẍ = −ω²x its discrete critical point grows without
// bound once Δt·ω exceeds a limit that depends on the operator, measured
// per operator (core/sbp, Measured::stability_limit; reproduce with
// tests/variational_resolution_test). A Newton solve that converges to such a
// critical point has solved the discrete equations but not the problem, so
// SolveIvp reports it as not converged. ω is estimated from the Lagrangian: ω²
// = the largest eigenvalue of M⁻¹K with M = ∂²L/∂v², K = −∂²L/∂x², at the
// initial and final states.
#pragma once

#include <cmath>
#include <string_view>

#include "core/action/density.h"
#include "core/linalg/small_eigen.h"
#include "core/sbp/builder.h"

namespace vivp::variational {

// The limit of Δt·ω of an operator; an unknown operator is
// std::invalid_argument naming the valid ones.
inline double StabilityLimit(std::string_view op) {
  return sbp::Table(op).measured.stability_limit;
}

// The largest ω with ω² an eigenvalue of M⁻¹K, from the Hessian of L in
// (x, v) at a point (M its velocity block, K minus its position block); 0
// when the problem has no oscillation there (K ≤ 0, or a first-order system
// with M = 0). One and two coordinates in closed form on the blocks as they
// are (linalg::LargestOfFew), without the heap.
template <class Hessian>
double FastestFrequencyOf(const Hessian& h) {
  constexpr int d = Hessian::RowsAtCompileTime / 2;
  const Eigen::Matrix<double, d, d> m = h.template bottomRightCorner<d, d>();
  const Eigen::Matrix<double, d, d> k = -h.template topLeftCorner<d, d>();
  if (m.cwiseAbs().maxCoeff() == 0.0) return 0.0;
  if (double largest; linalg::LargestOfFew(k, m, largest))
    return std::sqrt(largest);
  return std::sqrt(linalg::LargestGeneralizedEigenvalue(k, m));
}

// The same at (x, v).
template <class P>
double FastestFrequency(const P& problem, const double* x, const double* v) {
  return FastestFrequencyOf(action::LagrangianHessian(problem, x, v));
}

}  // namespace vivp::variational
