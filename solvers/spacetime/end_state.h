// The multiplier-corrected end state of a field solve, per spatial point:
// the point-mechanics correction (solvers/variational/end_state.h;
// docs/method.md §7) applied to the Lagrangian L(φ, φ_t) = density(φ, φ_t,
// φ_x) of each spatial point at its φ_x at t = T. The multipliers of the field
// system carry the spatial weight Hˣ_j (core/action/field_system.h), so
// −λ3(j) is the momentum density ∂L/∂φ_t at t = T and φ_N + M⁻¹λ4 the
// quadrature of the integral form of φ, one order better than φ_N;
// M = ∂²L/∂φ_t². It is the state a march hands from one window to the next.
#pragma once

#include <algorithm>
#include <bit>
#include <span>
#include <vector>

#include "core/action/field_system.h"
#include "core/autodiff/pointwise.h"
#include "core/sbp/space_grid.h"
#include "solvers/variational/end_state.h"

namespace vivp::spacetime {

struct FieldEnd {
  std::vector<double> phi, phi_t;  // corrected, value j·m + a
  // max_j |M⁻¹λ4| and max_j |(D_t φ)_N − φ_t|: the embedded error
  // estimates of φ_N and of the end velocity.
  double phi_estimate = 0, phi_t_estimate = 0;
};

namespace detail {

// The density at one spatial point with ∇φ held fixed, as a point-mechanics
// Lagrangian in (φ, φ_t) of the components with a time derivative; those
// without one (A₀ of a gauge field, docs/gauge.md §2) carry no momentum and
// no end multipliers, so they are held at their last node's value.
template <class Density>
struct PointLagrangian {
  static constexpr int m = Density::kDim;
  static constexpr unsigned kConstraints = action::ConstraintMaskOf<Density>();
  static constexpr int kDim = m - std::popcount(kConstraints);
  static constexpr int kGrad = action::SpaceDimOf<Density>() * m;
  static constexpr bool Dynamic(int a) { return !((kConstraints >> a) & 1u); }
  const Density* density;
  double phi_x[kGrad];  // ∇φ, as the density receives it
  double held[m];       // the constraint components' values
  template <class T>
  T operator()(const T* x, const T* v) const {
    T px[kGrad], fx[m], fv[m];
    for (int a = 0; a < kGrad; ++a) px[a] = T(phi_x[a]);
    for (int a = 0, k = 0; a < m; ++a) {
      fx[a] = Dynamic(a) ? x[k] : T(held[a]);
      fv[a] = Dynamic(a) ? v[k++] : T(0);
    }
    return (*density)(fx, fv, px);
  }
};

}  // namespace detail

// The state (x, v) of a slice moved to the gauge in which the components
// without a time derivative vanish (A₀ = 0, temporal gauge): those set to
// 0 with their gradient, the others' velocities those of the same momenta
// π = ∂ℒ/∂φ_t (for electromagnetism ∂_tA_b − E_b … = ∂_tA_b + ∂_bA₀).
// A window's Newton start built from it carries no gauge velocity from the
// window before: extrapolating A₀ and its stencil derivative from one window
// to the next amplified the gauge directions (which no equation damps) by a
// fixed factor per window — |A₀| from 1e-11 at t = 4 to 1e+29 at t = 40 in
// 160 windows (docs/gauge.md §5). Fields without such a component are
// returned unchanged.
template <class Density>
void ToTemporalGauge(const Density& density, const sbp::SpaceGrid<double>& grid,
                     std::span<double> x, std::span<double> v) {
  constexpr int m = Density::kDim, d = action::SpaceDimOf<Density>();
  constexpr int K = (2 + d) * m;
  using Point = detail::PointLagrangian<Density>;
  if constexpr (Point::kConstraints != 0u) {
    const int n = grid.points();
    std::vector<double> gx(x.size() * d);
    sbp::SpaceGrid<double>::GradientWork<double> w;
    grid.Gradient<double>(m, x, gx, w);
    using Vec = Eigen::Matrix<double, Point::kDim, 1>;
    for (int j = 0; j < n; ++j) {
      double z[K];
      action::SliceArguments<m, d>(j, x.data(), v.data(), gx.data(), z);
      const auto g =
          autodiff::Gradient<double, K>(
              [&](const auto* q) { return density(q, q + m, q + 2 * m); }, z)
              .second;
      Point lagrangian{&density, {}, {}};
      Vec p, guess;
      double xd[Point::kDim];
      for (int a = 0, c = 0; a < m; ++a) {
        for (int b = 0; b < d; ++b)
          lagrangian.phi_x[b * m + a] =
              Point::Dynamic(a) ? gx[(j * d + b) * m + a] : 0.0;
        lagrangian.held[a] = 0;
        if (!Point::Dynamic(a)) continue;
        p[c] = g[m + a];
        guess[c] = v[j * m + a];
        xd[c++] = x[j * m + a];
      }
      const Vec u = variational::VelocityOfMomentum(lagrangian, xd, guess, p);
      for (int a = 0, c = 0; a < m; ++a) {
        if (Point::Dynamic(a)) {
          v[j * m + a] = u[c++];
        } else {
          x[j * m + a] = 0;
          v[j * m + a] = 0;
        }
      }
    }
  }
}

// v: the system's fields at y (FieldSystem::Fields). With a range, only the
// points [begin, end) (one rank's of a distributed window, whose other
// points are its halo), value (j − begin)·m + a.
template <class Density>
FieldEnd CorrectFieldEnd(const action::FieldSystem<Density>& system,
                         const double* y, const action::FieldValues<double>& v,
                         int begin = 0, int end = -1) {
  constexpr int m = Density::kDim;
  const int last = system.time_points() - 1;
  if (end < 0) end = system.space_points();
  FieldEnd e;
  e.phi.resize(static_cast<std::size_t>(end - begin) * m);
  e.phi_t.resize(e.phi.size());
  for (int j = begin; j < end; ++j) {
    const int k = (j - begin) * m;
    if (system.Fixed(j)) {
      // A Dirichlet point's column is the data (field_boundary.h): its end
      // state is the last node and D̄_t there; no multipliers to correct by.
      for (int a = 0; a < m; ++a) {
        e.phi[k + a] = v.phi[system.At(last, j, a)];
        e.phi_t[k + a] = v.phi_t[system.At(last, j, a)];
      }
      continue;
    }
    using Point = detail::PointLagrangian<Density>;
    constexpr int md = Point::kDim;
    Point lagrangian{&system.density(), {}, {}};
    double lambda3[md], lambda4[md], xn[md], vn[md];
    for (int b = 0; b < action::SpaceDimOf<Density>(); ++b)
      for (int a = 0; a < m; ++a)
        lagrangian.phi_x[b * m + a] = v.phi_x[system.Grad(last, j, b, a)];
    for (int a = 0, c = 0; a < m; ++a) {
      const int at = system.At(last, j, a);
      e.phi[k + a] = lagrangian.held[a] = v.phi[at];
      e.phi_t[k + a] = v.phi_t[at];
      if (!Point::Dynamic(a)) continue;
      lambda3[c] = y[system.Lambda3(j, a)];
      lambda4[c] = y[system.Lambda4(j, a)];
      xn[c] = v.phi[at];
      vn[c++] = v.phi_t[at];
    }
    const auto c = variational::CorrectEnd<double>(lagrangian, 2, xn, vn,
                                                   lambda3, lambda4);
    for (int a = 0, q = 0; a < m; ++a)
      if (Point::Dynamic(a)) {
        e.phi[k + a] = c.position[q];
        e.phi_t[k + a] = c.velocity[q++];
      }
    e.phi_estimate = std::max(e.phi_estimate, c.position_error_estimate);
    e.phi_t_estimate = std::max(e.phi_t_estimate, c.velocity_error_estimate);
  }
  return e;
}

}  // namespace vivp::spacetime
