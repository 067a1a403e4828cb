// The node terms of the reduced residual (reduced_system.h) in one sweep:
// at every node i the point p = (x₊, v₊)ᵢ, the diagonal gradient
// g = ∂f/∂(x₋, v₋) there (density.h), the row Hᵢ·∂f/∂x₋ and the
// momentum-like wᵢ = ∂f/∂v₋ that D̄ᵀH is applied to afterwards.
//
// One function for the whole sweep, so that a precompiled problem
// (erased_problem.h) makes one virtual call per residual and still streams
// the path arrays: gathering blocks of points into a buffer and scattering
// the gradients back cost 2–5 % of a march for the anharmonic oscillator,
// whose gradient is only a few dozen flops.
#pragma once

#include <array>

#include "core/action/density.h"
#include "core/sbp/operator.h"

namespace vivp::action {

template <class Real, int d>
struct GradientSweep {
  std::array<const Real*, d> x{}, v{};  // x₊, v₊ per component, n values
  const sbp::Operator<Real>* norm = nullptr;  // Hᵢ = norm->NormWeight(i)
  int n = 0;
  Real* rows = nullptr;      // rows[i·d + c] = Hᵢ·∂f/∂x₋_c
  std::array<Real*, d> w{};  // w[c][i] = ∂f/∂v₋_c
};

// The sweep with gradient(p) ↦ DiagonalVector<Real, d> at each node.
template <class Real, int d, class Gradient>
void SweepPoints(const GradientSweep<Real, d>& s, Gradient gradient) {
  for (int i = 0; i < s.n; ++i) {
    Real p[2 * d];
    for (int c = 0; c < d; ++c) {
      p[c] = s.x[c][i];
      p[d + c] = s.v[c][i];
    }
    const auto g = gradient(p);
    const Real h = s.norm->NormWeight(i);
    for (int c = 0; c < d; ++c) {
      s.rows[i * d + c] = h * g[c];
      s.w[c][i] = g[d + c];
    }
  }
}

template <class Real, class P>
void SweepDiagonalGradient(const P& problem,
                           const GradientSweep<Real, P::kDim>& s) {
  if constexpr (Precompiled<P>)
    problem.pointwise().SweepDiagonalGradient(s);
  else
    SweepPoints(
        s, [&](const Real* p) { return DiagonalGradient<Real>(problem, p); });
}

}  // namespace vivp::action
