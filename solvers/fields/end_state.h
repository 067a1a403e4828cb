// The multiplier-corrected end state of a field solve, per spatial point, as
// in point mechanics (solvers/variational/end_state.h; docs/method.md §7):
// the multipliers of the field system carry the spatial weight Hˣ_j
// (core/action/field_system.h), so −λ3(j) is the momentum density
// ∂L/∂φ_t at t = T and φ_N + M⁻¹λ4 the quadrature of the integral form of
// φ, one order better than φ_N; M = ∂²L/∂φ_t². It is the state a march hands
// from one window to the next.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/action/field_system.h"

namespace vivp::fields {

struct FieldEnd {
  std::vector<double> phi, phi_t;  // corrected, value j·m + a
  // max_j |M⁻¹λ4| and max_j |(D_t φ)_N − φ_t|: the embedded error
  // estimates of φ_N and of the end velocity.
  double phi_estimate = 0, phi_t_estimate = 0;
};

template <class Density>
FieldEnd CorrectFieldEnd(const action::FieldSystem<Density>& system,
                         const double* y) {
  constexpr int m = Density::kComponents;
  constexpr int K = 3 * m;
  using Mat = Eigen::Matrix<double, m, m>;
  using Vec = Eigen::Matrix<double, m, 1>;
  const int nt = system.time_points(), nx = system.space_points();
  action::FieldValues<double> v;
  system.Fields(y, v);
  FieldEnd e;
  e.phi.resize(static_cast<std::size_t>(nx) * m);
  e.phi_t.resize(e.phi.size());
  for (int j = 0; j < nx; ++j) {
    const auto h = system.PointHessian(v, nt - 1, j);
    const Mat mass = h.template block<m, m>(m, m);
    const auto lu = mass.fullPivLu();
    Vec l3, l4;
    for (int a = 0; a < m; ++a) {
      l3[a] = y[system.Lambda3(j, a)];
      l4[a] = y[system.Lambda4(j, a)];
    }
    const Vec shift = lu.solve(l4);
    // −λ3 moved to the corrected position along ∂²L/∂φ∂φ_t (zero unless the
    // density couples φ and φ_t).
    const Vec momentum = -l3 + Mat(h.template block<m, m>(0, m)) * shift;
    // The velocity of that momentum: Newton on ∂L/∂φ_t(φ, u, φ_x) = p from
    // u = M⁻¹p, exact for a density quadratic in φ_t.
    Vec u = lu.solve(momentum);
    double z[K];
    for (int a = 0; a < m; ++a) {
      z[a] = v.phi[system.At(nt - 1, j, a)] + shift[a];
      z[2 * m + a] = v.phi_x[system.At(nt - 1, j, a)];
    }
    for (int step = 0; step < 4; ++step) {
      for (int a = 0; a < m; ++a) z[m + a] = u[a];
      const auto d = autodiff::Hessian<double, K>(
          [&](const auto* w) { return system.density()(w, w + m, w + 2 * m); },
          z);
      const Vec r = momentum - d.gradient.template segment<m>(m);
      const double scale =
          std::max(momentum.cwiseAbs().maxCoeff(),
                   d.gradient.template segment<m>(m).cwiseAbs().maxCoeff());
      if (r.cwiseAbs().maxCoeff() <=
          16 * std::numeric_limits<double>::epsilon() * scale)
        break;
      u += Mat(d.hessian.template block<m, m>(m, m)).fullPivLu().solve(r);
    }
    for (int a = 0; a < m; ++a) {
      e.phi[j * m + a] = z[a];
      e.phi_t[j * m + a] = u[a];
      e.phi_estimate = std::max(e.phi_estimate, std::abs(shift[a]));
      e.phi_t_estimate = std::max(
          e.phi_t_estimate, std::abs(v.phi_t[system.At(nt - 1, j, a)] - u[a]));
    }
  }
  return e;
}

}  // namespace vivp::fields
