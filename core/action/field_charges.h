// Conserved quantities of a field slice, from the density alone (Noether;
// nothing is written per problem): with π = ∂L/∂φ_t,
//
//   energy    E = Σ_j Hˣ_j (π·φ_t − L)            (time translation)
//   momentum  P = −Σ_j Hˣ_j π·φ_x                  (space translation;
//             in d dimensions one per axis, π·∂_bφ)
//   charge    Q = Σ_j Hˣ_j (φ_0 π_1 − φ_1 π_0)     (rotation of two
//             components, the U(1) charge of a complex field; 0 for one)
//
// evaluated with φ_x = D_x φ and the quadrature Hˣ of the spatial operator
// (on a grid of d axes, ∇φ and the product norm H: space_grid.h).
// Whether a quantity is conserved depends on the density (and, for P, on the
// spatial operator: a bounded interval breaks translations).
#pragma once

#include <array>
#include <span>
#include <vector>

#include "core/action/field_point.h"
#include "core/autodiff/pointwise.h"
#include "core/sbp/space.h"
#include "core/sbp/space_grid.h"

namespace vivp::action {

struct FieldCharges {
  double energy = 0, momentum = 0, charge = 0;
  // In d dimensions P_b = −Σ_j H_j π·∂_bφ along each axis b; momentum is
  // momenta[0].
  std::array<double, 3> momenta{};
};

// phi, phi_t: one slice, value j·m + a, on a grid of d axes (the density's
// kSpaceDim), H its norm.
template <class Density>
FieldCharges ChargesOfSlice(const Density& density,
                            const sbp::SpaceGrid<double>& grid,
                            std::span<const double> phi,
                            std::span<const double> phi_t) {
  constexpr int m = Density::kDim, d = SpaceDimOf<Density>(), K = (2 + d) * m;
  const int n = grid.points();
  std::vector<double> phi_x(phi.size() * d);
  sbp::SpaceGrid<double>::GradientWork<double> work;
  grid.Gradient<double>(m, phi, phi_x, work);
  FieldCharges q;
  for (int j = 0; j < n; ++j) {
    double z[K];
    SliceArguments<m, d>(j, phi.data(), phi_t.data(), phi_x.data(), z);
    const auto [value, g] = autodiff::Gradient<double, K>(
        [&](const auto* w) { return density(w, w + m, w + 2 * m); }, z);
    double e = -value, p[d] = {};
    for (int a = 0; a < m; ++a) {
      e += g[m + a] * z[m + a];
      for (int b = 0; b < d; ++b) p[b] -= g[m + a] * z[(2 + b) * m + a];
    }
    const double h = grid.NormWeight(j);
    q.energy += h * e;
    for (int b = 0; b < d; ++b) q.momenta[b] += h * p[b];
    if constexpr (m == 2) q.charge += h * (z[0] * g[m + 1] - z[1] * g[m]);
  }
  q.momentum = q.momenta[0];
  return q;
}

// A field of one spatial axis.
template <class Density>
FieldCharges ChargesOfSlice(const Density& density,
                            const sbp::SpaceDerivative<double>& dx,
                            std::span<const double> phi,
                            std::span<const double> phi_t) {
  return ChargesOfSlice(density, sbp::SpaceGrid<double>(dx), phi, phi_t);
}

}  // namespace vivp::action
