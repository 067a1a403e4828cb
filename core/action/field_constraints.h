// The equations of a field's components without a time derivative at one
// slice (docs/gauge.md §3), from the density alone. Such a component a
// (A₀ of electromagnetism) has no momentum, so its node row of the window
// (core/action/field_system.h) involves the slice alone; divided by the
// weights Hᵗ_i Hˣ_j it reads
//
//   G_a(j) = ∂ℒ/∂φ_a + (Σ_b D_bᵀ Hˣ q_b)_j / Hˣ_j,   q_b = ∂ℒ/∂(∂_bφ_a),
//
// for electromagnetism −(D·E)_j + ρ_j: the action's Gauss law. Its size is
// judged against the terms that cancel in it,
//
//   scale = max_j |∂ℒ/∂φ_a| + Σ_b ‖D_b‖_∞ max_j |q_b|,
//
// so that a relative residual of 1e-16 is round-off whatever the grid.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "core/action/field_point.h"
#include "core/autodiff/pointwise.h"
#include "core/sbp/space_grid.h"

namespace vivp::action {

struct ConstraintResidual {
  double largest = 0;  // max over the slice's points and constraint components
  double scale = 0;    // the size of the terms (above)
  double relative() const { return scale > 0 ? largest / scale : largest; }
};

// ‖D_b‖_∞: the largest absolute row sum of axis b's derivative.
inline double RowSumNorm(const sbp::SpaceDerivative<double>& axis) {
  double norm = 0;
  for (int j = 0; j < axis.points(); ++j) {
    double sum = 0;
    axis.ForRow(j, [&](int, double c) { sum += std::abs(c); });
    norm = std::max(norm, sum);
  }
  return norm;
}

// phi, phi_t: one slice, value j·m + a. out (optional, size points·m):
// G_a(j) at j·m + a for the constraint components, 0 for the others.
template <class Density>
ConstraintResidual ConstraintsOfSlice(const Density& density,
                                      const sbp::SpaceGrid<double>& grid,
                                      std::span<const double> phi,
                                      std::span<const double> phi_t,
                                      std::span<double> out = {}) {
  constexpr int m = Density::kDim, d = SpaceDimOf<Density>(), K = (2 + d) * m;
  constexpr unsigned mask = ConstraintMaskOf<Density>();
  ConstraintResidual r;
  if constexpr (mask == 0u) {
    std::fill(out.begin(), out.end(), 0.0);
    return r;
  } else {
    const int n = grid.points();
    std::vector<double> phi_x(phi.size() * d), drive(std::size_t(n) * m),
        flux(phi.size() * d), q(n), div(n), work;
    sbp::SpaceGrid<double>::GradientWork<double> gw;
    grid.Gradient<double>(m, phi, phi_x, gw);
    for (int j = 0; j < n; ++j) {
      double z[K];
      SliceArguments<m, d>(j, phi.data(), phi_t.data(), phi_x.data(), z);
      const auto g =
          autodiff::Gradient<double, K>(
              [&](const auto* w) { return density(w, w + m, w + 2 * m); }, z)
              .second;
      for (int a = 0; a < m; ++a) drive[j * m + a] = g[a];
      for (int k = 0; k < d * m; ++k) flux[j * d * m + k] = g[2 * m + k];
    }
    std::fill(out.begin(), out.end(), 0.0);
    for (int a = 0; a < m; ++a) {
      if (!((mask >> a) & 1u)) continue;
      std::fill(div.begin(), div.end(), 0.0);
      double source = 0, terms = 0;
      for (int b = 0; b < d; ++b) {
        double qmax = 0;
        for (int j = 0; j < n; ++j) {
          q[j] = flux[(j * d + b) * m + a];
          qmax = std::max(qmax, std::abs(q[j]));
        }
        grid.AddTransposeH<double>(b, q, div, work);
        terms += RowSumNorm(grid.axis(b)) * qmax;
      }
      for (int j = 0; j < n; ++j) {
        const double f = drive[j * m + a];
        const double gj = f + div[j] / grid.NormWeight(j);
        source = std::max(source, std::abs(f));
        // A non-finite residual stays visible (std::max would drop a NaN).
        r.largest = std::isnan(gj) || std::isnan(r.largest)
                        ? NAN
                        : std::max(r.largest, std::abs(gj));
        if (!out.empty()) out[j * m + a] = gj;
      }
      r.scale = std::max(r.scale, source + terms);
    }
    return r;
  }
}

}  // namespace vivp::action
