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
#include <stdexcept>
#include <string>
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

namespace detail {

// ∂ℒ/∂φ and q = ∂ℒ/∂(∇φ) at every point of a slice: drive at j·m + a,
// flux at (j·d + b)·m + a.
template <class Density>
void SliceDerivatives(const Density& density,
                      const sbp::SpaceGrid<double>& grid,
                      std::span<const double> phi,
                      std::span<const double> phi_t, std::vector<double>& drive,
                      std::vector<double>& flux) {
  constexpr int m = Density::kDim, d = SpaceDimOf<Density>(), K = (2 + d) * m;
  const int n = grid.points();
  std::vector<double> phi_x(phi.size() * d);
  sbp::SpaceGrid<double>::GradientWork<double> gw;
  grid.Gradient<double>(m, phi, phi_x, gw);
  drive.resize(std::size_t(n) * m);
  flux.resize(phi.size() * d);
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
}

// G_a = ∂ℒ/∂φ_a + Σ_b div_b(q_b) for the constraint components, with
// div_b(q, out) adding axis b's divergence of q (one value per point) to
// out and returning the size of that term for the scale.
template <class Density, class Divergence>
ConstraintResidual Constraints(const Density& density,
                               const sbp::SpaceGrid<double>& grid,
                               std::span<const double> phi,
                               std::span<const double> phi_t,
                               std::span<double> out, Divergence&& div_b) {
  constexpr int m = Density::kDim, d = SpaceDimOf<Density>();
  constexpr unsigned mask = ConstraintMaskOf<Density>();
  ConstraintResidual r;
  std::fill(out.begin(), out.end(), 0.0);
  if constexpr (mask != 0u) {
    const int n = grid.points();
    std::vector<double> drive, flux, q(n), div(n);
    SliceDerivatives(density, grid, phi, phi_t, drive, flux);
    for (int a = 0; a < m; ++a) {
      if (!((mask >> a) & 1u)) continue;
      std::fill(div.begin(), div.end(), 0.0);
      double source = 0, terms = 0;
      for (int b = 0; b < d; ++b) {
        for (int j = 0; j < n; ++j) q[j] = flux[(j * d + b) * m + a];
        terms += div_b(b, q, div);
      }
      for (int j = 0; j < n; ++j) {
        const double f = drive[j * m + a];
        const double gj = f + div[j];
        source = std::max(source, std::abs(f));
        // A non-finite residual stays visible (std::max would drop a NaN).
        r.largest = std::isnan(gj) || std::isnan(r.largest)
                        ? NAN
                        : std::max(r.largest, std::abs(gj));
        if (!out.empty()) out[j * m + a] = gj;
      }
      r.scale = std::max(r.scale, source + terms);
    }
  }
  return r;
}

// The derivative matrix of the trigonometric interpolant on n periodic
// points of spacing h: ½(−1)^(i−l) cot((i−l)π/n) for even n, csc for odd,
// times 2π/(n h) (row-major).
inline std::vector<double> SpectralDerivative(int n, double h) {
  constexpr double pi = 3.14159265358979323846;
  std::vector<double> m(std::size_t(n) * n, 0.0);
  const double scale = 2 * pi / (n * h);
  for (int i = 0; i < n; ++i)
    for (int l = 0; l < n; ++l) {
      if (i == l) continue;
      const double x = (i - l) * pi / n, sign = (i - l) % 2 ? -1.0 : 1.0;
      m[std::size_t(i) * n + l] =
          scale * 0.5 * sign * (n % 2 == 0 ? 1 / std::tan(x) : 1 / std::sin(x));
    }
  return m;
}

}  // namespace detail

// phi, phi_t: one slice, value j·m + a. out (optional, size points·m):
// G_a(j) at j·m + a for the constraint components, 0 for the others.
template <class Density>
ConstraintResidual ConstraintsOfSlice(const Density& density,
                                      const sbp::SpaceGrid<double>& grid,
                                      std::span<const double> phi,
                                      std::span<const double> phi_t,
                                      std::span<double> out = {}) {
  std::vector<double> work;
  return detail::Constraints(
      density, grid, phi, phi_t, out,
      [&](int b, std::span<const double> q, std::span<double> div) {
        // (D_bᵀ Hˣ q)_j / Hˣ_j.
        std::vector<double> acc(div.size(), 0.0);
        grid.AddTransposeH<double>(b, q, acc, work);
        double qmax = 0;
        for (std::size_t j = 0; j < div.size(); ++j) {
          div[j] += acc[j] / grid.NormWeight(int(j));
          qmax = std::max(qmax, std::abs(q[j]));
        }
        return RowSumNorm(grid.axis(b)) * qmax;
      });
}

// The textbook law beside it: the same constraint with the exact derivative
// of the grid's trigonometric interpolant in place of the stencil,
// G_a = ∂ℒ/∂φ_a − Σ_b ∂_b q_b (for electromagnetism −∇·E + ρ with the
// discrete solution's E). It measures a truncation error, not round-off,
// so its scale is the size of its terms, max_j |∂ℒ/∂φ_a| + Σ_b max_j
// |∂_b q_b|, each axis's term at least (2π/L_b) max_j |q_b| (L_b the
// period). Every axis periodic, else std::invalid_argument; O(N Σ_b N_b)
// per slice.
template <class Density>
ConstraintResidual TextbookConstraintsOfSlice(
    const Density& density, const sbp::SpaceGrid<double>& grid,
    std::span<const double> phi, std::span<const double> phi_t,
    std::span<double> out = {}) {
  std::vector<std::vector<double>> spectral;
  for (int b = 0; b < grid.dim(); ++b) {
    if (!grid.axis(b).periodic())
      throw std::invalid_argument(
          "the textbook constraint takes the exact derivative of a periodic "
          "grid; axis " +
          std::to_string(b) + " is an interval");
    spectral.push_back(
        detail::SpectralDerivative(grid.points(b), grid.axis(b).dx()));
  }
  return detail::Constraints(
      density, grid, phi, phi_t, out,
      [&](int b, std::span<const double> q, std::span<double> div) {
        const int nb = grid.points(b);
        const auto& dm = spectral[b];
        double size = 0, qmax = 0;
        // Along each line of axis b: stride and the line's first points.
        int stride = 1;
        for (int c = 0; c < b; ++c) stride *= grid.points(c);
        const int n = grid.points();
        for (int j = 0; j < n; ++j) {
          const int i = (j / stride) % nb, base = j - i * stride;
          double sum = 0;
          for (int l = 0; l < nb; ++l)
            sum += dm[std::size_t(i) * nb + l] * q[base + l * stride];
          div[j] -= sum;
          size = std::max(size, std::abs(sum));
          qmax = std::max(qmax, std::abs(q[j]));
        }
        // Floored by the flux at the box's longest wavelength: a field
        // constant along the axis has no divergence terms to compare with.
        const double k_min =
            2 * 3.14159265358979323846 / (nb * grid.axis(b).dx());
        return std::max(size, k_min * qmax);
      });
}

}  // namespace vivp::action
