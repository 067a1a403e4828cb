// The Courant-like resolution limit of the space-time discretization.
//
// In point mechanics the discrete critical point stays bounded only while
// Δt·ω is below a limit of the time operator (solvers/variational/
// resolution.h: SBP21 0.70, SBP42 1.00, SBP63 0.95, SBP84 0.90). A field
// discretized in space is a system of coupled oscillators: linearized about
// a state, φ_tt = −M⁻¹(C·(−D_x²) + K)φ with M = ∂²L/∂φ_t², C = −∂²L/∂φ_x²
// and K = −∂²L/∂φ² per spatial point, so its fastest frequency is
//
//   ω_max² ≈ max_j [λ_max(M⁻¹C)·ρ(D_x)² + λ_max(M⁻¹K)],
//
// ρ(D_x) the spectral radius of the spatial derivative (for periodic
// differences of order 2q the largest |Σ 2c_k sin kθ|/Δx: 1.00, 1.37, 1.59,
// 1.73 over Δx for orders 2, 4, 6, 8). The limit is the point-mechanics one
// for this ω: measured for the Klein–Gordon field, whose spatial Fourier
// modes are exactly independent oscillators (tests/fields_orders_test.cc,
// `resolution_limit_is_the_modes`).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "core/action/field_point.h"
#include "core/autodiff/pointwise.h"
#include "core/linalg/small_eigen.h"
#include "core/sbp/space.h"
#include "core/sbp/space_grid.h"

namespace vivp::spacetime {

// ρ(D_x): exact for periodic differences (the symbol's maximum over a fine
// θ grid including the modes of the grid), by power iteration on
// H⁻¹DᵀHD = −D·D through the SBP property for an SBP operator.
inline double SpectralRadius(const sbp::SpaceDerivative<double>& dx) {
  if (const auto* p = dx.periodic_operator()) {
    double best = 0;
    const int n = p->points();
    for (int k = 0; k <= n / 2; ++k) {
      const double theta = 2 * std::numbers::pi * k / n;
      double s = 0;
      for (int l = 1; l <= p->half_width(); ++l)
        s += 2 * p->coefficient(l) * std::sin(l * theta);
      best = std::max(best, std::abs(s));
    }
    return best * p->inv_dx();
  }
  // The largest eigenvalue of DᵀHD in the H inner product is ρ(D)² for the
  // singular values; power iteration on it.
  const int n = dx.points();
  std::vector<double> u(n), du(n), w(n, 0.0), scratch(n);
  for (int j = 0; j < n; ++j) u[j] = std::cos(2.9 * j) + 0.1;
  double lambda = 0;
  for (int it = 0; it < 200; ++it) {
    dx.Apply<double>(u, du);
    std::fill(w.begin(), w.end(), 0.0);
    dx.AddTransposeH<double>(du, scratch, w);  // w = DᵀH D u
    double num = 0, den = 0;
    for (int j = 0; j < n; ++j) {
      w[j] /= dx.NormWeight(j);
      num += dx.NormWeight(j) * u[j] * w[j];
      den += dx.NormWeight(j) * u[j] * u[j];
    }
    lambda = num / den;
    double norm = 0;
    for (double x : w) norm = std::max(norm, std::abs(x));
    for (int j = 0; j < n; ++j) u[j] = w[j] / norm;
  }
  return std::sqrt(std::max(lambda, 0.0));
}

// On a grid of d axes the stiffness Σ_a D_aᵀ H D_a is a sum of commuting
// terms, so its largest eigenvalue is the sum of the axes': ρ² = Σ_a ρ_a².
inline double SpectralRadius(const sbp::SpaceGrid<double>& grid) {
  if (grid.dim() == 1) return SpectralRadius(grid.axis(0));
  double r2 = 0;
  for (int a = 0; a < grid.dim(); ++a) {
    const double r = SpectralRadius(grid.axis(a));
    r2 += r * r;
  }
  return std::sqrt(r2);
}

// ω_max of the linearization about the state (φ, φ_t) on the grid; rho is
// SpectralRadius(grid), a property of the grid computed once per solve. In
// d dimensions C is the largest of the axes' blocks −∂²L/∂(∂_bφ)², exact
// for an isotropic density without mixed gradient blocks. With a range, the
// largest over the points [begin, end) (one rank's of a distributed march).
template <class Density>
double FastestFieldFrequency(const Density& density,
                             const sbp::SpaceGrid<double>& grid, double rho,
                             std::span<const double> phi,
                             std::span<const double> phi_t, int begin = 0,
                             int end = -1) {
  constexpr int m = Density::kDim;
  constexpr int d = action::SpaceDimOf<Density>();
  constexpr int K = (2 + d) * m;
  const int n = end < 0 ? grid.points() : end;
  std::vector<double> phi_x(phi.size() * d);
  sbp::SpaceGrid<double>::GradientWork<double> work;
  grid.Gradient<double>(m, phi, phi_x, work);
  double omega2 = 0;
  // One component: the eigenvalues are quotients; more: the small dense
  // solver (its allocations were a tenth of this check's time for m = 1).
  Eigen::MatrixXd mass(m, m), c(m, m), k(m, m);
  std::vector<int> dynamic;
  for (int a = 0; a < m; ++a)
    if (!((action::ConstraintMaskOf<Density>() >> a) & 1u))
      dynamic.push_back(a);
  for (int j = begin; j < n; ++j) {
    double z[K];
    action::SliceArguments<m, d>(j, phi.data(), phi_t.data(), phi_x.data(), z);
    const auto h = autodiff::Hessian<double, K>(
        [&](const auto* w) { return density(w, w + m, w + 2 * m); }, z);
    double wc, wk;
    if constexpr (m == 1) {
      // As LargestGeneralizedEigenvalue: the largest of 0 and the quotient.
      const double mj = h.hessian(1, 1);
      double cmax = -h.hessian(2, 2);
      for (int b = 1; b < d; ++b)
        cmax = std::max(cmax, -h.hessian(2 + b, 2 + b));
      wc = mj != 0 ? std::max(0.0, cmax / mj) : 0.0;
      wk = mj != 0 ? std::max(0.0, -h.hessian(0, 0) / mj) : 0.0;
    } else {
      // A component without a time derivative (A₀) is a constraint, not an
      // oscillator: the frequencies are those of the others.
      // (Returned as a matrix: an indexed view of the temporary block
      // would outlive it.)
      auto block = [&](int r, int col) -> Eigen::MatrixXd {
        const Eigen::MatrixXd full = h.hessian.template block<m, m>(r, col);
        return full(dynamic, dynamic);
      };
      mass = block(m, m);
      k = -block(0, 0);
      wc = 0;
      for (int b = 0; b < d; ++b) {
        c = -block((2 + b) * m, (2 + b) * m);
        wc = std::max(wc, linalg::LargestGeneralizedEigenvalue(c, mass));
      }
      wk = linalg::LargestGeneralizedEigenvalue(k, mass);
    }
    omega2 = std::max(omega2, std::max(wc, 0.0) * rho * rho + wk);
  }
  return std::sqrt(std::max(omega2, 0.0));
}

// The one-dimensional field's grid.
template <class Density>
double FastestFieldFrequency(const Density& density,
                             const sbp::SpaceDerivative<double>& dx, double rho,
                             std::span<const double> phi,
                             std::span<const double> phi_t) {
  return FastestFieldFrequency(density, sbp::SpaceGrid<double>(dx), rho, phi,
                               phi_t);
}

// Why Δt·ω at time t is beyond the time operator's limit (empty if it is
// not), with the time points a grid over t_span needs; the check of every
// field solve, before it starts and at every window's ends.
inline std::string UnderResolved(const std::string& op, double limit, double dt,
                                 double omega, double t, double t_span) {
  const double od = dt * omega;
  if (!(od > limit)) return "";
  const long long need =
      static_cast<long long>(std::ceil(t_span * omega / limit)) + 1;
  std::ostringstream msg;
  msg << "under-resolved: Δt·ω_max = " << od << " at t = " << t
      << " exceeds the " << op << " limit " << limit << " (ω_max = " << omega
      << " from the spatial grid and the potential); use at least " << need
      << " time points";
  return msg.str();
}

}  // namespace vivp::spacetime
