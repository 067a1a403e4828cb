// Conserved quantities of a field slice, from the density alone (Noether;
// nothing is written per problem): with π = ∂L/∂φ_t,
//
//   energy    E = Σ_j Hˣ_j (π·φ_t − L)            (time translation)
//   momentum  P = −Σ_j Hˣ_j π·φ_x                  (space translation)
//   charge    Q = Σ_j Hˣ_j (φ_0 π_1 − φ_1 π_0)     (rotation of two
//             components, the U(1) charge of a complex field; 0 for one)
//
// evaluated with φ_x = D_x φ and the quadrature Hˣ of the spatial operator.
// Whether a quantity is conserved depends on the density (and, for P, on the
// spatial operator: a bounded interval breaks translations).
#pragma once

#include <span>
#include <vector>

#include "core/autodiff/pointwise.h"
#include "core/sbp/space.h"

namespace vivp::action {

struct FieldCharges {
  double energy = 0, momentum = 0, charge = 0;
};

// phi, phi_t: one slice, value j·m + a.
template <class Density>
FieldCharges ChargesOfSlice(const Density& density,
                            const sbp::SpaceDerivative<double>& dx,
                            std::span<const double> phi,
                            std::span<const double> phi_t) {
  constexpr int m = Density::kDim;
  const int n = dx.points();
  std::vector<double> phi_x(phi.size());
  dx.ApplyComponents(m, phi, phi_x);
  FieldCharges q;
  for (int j = 0; j < n; ++j) {
    double z[3 * m];
    for (int a = 0; a < m; ++a) {
      z[a] = phi[j * m + a];
      z[m + a] = phi_t[j * m + a];
      z[2 * m + a] = phi_x[j * m + a];
    }
    const auto [value, g] = autodiff::Gradient<double, 3 * m>(
        [&](const auto* w) { return density(w, w + m, w + 2 * m); }, z);
    double e = -value, p = 0;
    for (int a = 0; a < m; ++a) {
      e += g[m + a] * z[m + a];
      p -= g[m + a] * z[2 * m + a];
    }
    const double h = dx.NormWeight(j);
    q.energy += h * e;
    q.momentum += h * p;
    if constexpr (m == 2) q.charge += h * (z[0] * g[m + 1] - z[1] * g[m]);
  }
  return q;
}

}  // namespace vivp::action
