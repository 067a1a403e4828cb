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
#include <vector>

#include "core/action/field_system.h"
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
