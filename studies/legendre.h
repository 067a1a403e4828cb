// The Hamiltonian form of a Lagrangian quadratic in the velocities (the
// Legendre transform), for the steppers of `vivp bench`:
//
//   L(q, ẋ) = ½ẋᵀMẋ + b(q)·ẋ − V(q),   M constant and invertible,
//   p = Mẋ + b(q),   H(q, p) = ½(p − b(q))ᵀM⁻¹(p − b(q)) + V(q).
//
// b and V are read off L itself, exactly for such an L: V(q) = −L(q, 0),
// b_i(q) = ½[L(q, e_i) − L(q, −e_i)]; M from second differences in ẋ. H is
// separable (Störmer–Verlet applies) when b vanishes.
//
// Whether L has this form is checked numerically, at the initial data and at
// eight nearby points (q, ẋ): L must match the quadratic to 1e-9 relative,
// M must be the same everywhere and invertible. A check at points cannot
// prove it everywhere; a Lagrangian that is quadratic in ẋ only near these
// points (or whose b vanishes only there) would be misread.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/action/precompiled_dims.h"
#include "solvers/variational/ivp_types.h"

namespace vivp::studies {

template <int d>
struct LegendreForm {
  Eigen::Matrix<double, d, d> mass, inverse_mass;
  bool separable = true;
};

namespace detail {

// L(q, ẋ) at ẋ = s·e_i + t·e_j (i, j < 0: that term absent).
template <class L, class T>
T AtUnitVelocity(const L& l, const T* q, int i, double s, int j, double t) {
  T v[L::kDim];
  for (int c = 0; c < L::kDim; ++c) v[c] = T(0.0);
  if (i >= 0) v[i] = v[i] + T(s);
  if (j >= 0) v[j] = v[j] + T(t);
  return l(q, v);
}

// M⁻¹ into *inverse, or false when M is singular (full-pivoting LU's rank).
// Compiled once per dimension (legendre.cc), not per Lagrangian.
template <int d>
bool InvertMass(const Eigen::Matrix<double, d, d>& m,
                Eigen::Matrix<double, d, d>* inverse) {
  const Eigen::FullPivLU<Eigen::Matrix<double, d, d>> lu(m);
  if (lu.rank() < d) return false;
  *inverse = lu.inverse();
  return true;
}

#define VIVP_EXTERN_INVERT_MASS(D)                                       \
  extern template bool InvertMass<D>(const Eigen::Matrix<double, D, D>&, \
                                     Eigen::Matrix<double, D, D>*);
VIVP_PRECOMPILED_DIMS(VIVP_EXTERN_INVERT_MASS)
#undef VIVP_EXTERN_INVERT_MASS

}  // namespace detail

// b(q) of the form above, at any scalar type.
template <class L, class T>
void VectorPotential(const L& l, const T* q, T* b) {
  for (int i = 0; i < L::kDim; ++i)
    b[i] = T(0.5) * (detail::AtUnitVelocity(l, q, i, 1, -1, 0) -
                     detail::AtUnitVelocity(l, q, i, -1, -1, 0));
}

// Throws std::domain_error naming what fails.
template <class L>
LegendreForm<L::kDim> FindLegendreForm(const L& l,
                                       const variational::InitialData& init) {
  constexpr int d = L::kDim;
  using detail::AtUnitVelocity;
  auto mass_at = [&](const double* q) {
    Eigen::Matrix<double, d, d> m;
    const double l0 = AtUnitVelocity(l, q, -1, 0, -1, 0);
    for (int i = 0; i < d; ++i)
      m(i, i) = AtUnitVelocity(l, q, i, 1, -1, 0) +
                AtUnitVelocity(l, q, i, -1, -1, 0) - 2 * l0;
    for (int i = 0; i < d; ++i)
      for (int j = i + 1; j < d; ++j)
        m(i, j) = m(j, i) = 0.25 * (AtUnitVelocity(l, q, i, 1, j, 1) -
                                    AtUnitVelocity(l, q, i, 1, j, -1) -
                                    AtUnitVelocity(l, q, i, -1, j, 1) +
                                    AtUnitVelocity(l, q, i, -1, j, -1));
    return m;
  };
  double q0[d], v0[d];
  for (int c = 0; c < d; ++c) {
    q0[c] = init.x.at(c);
    v0[c] = init.v.empty() ? 0.0 : init.v.at(c);
  }
  LegendreForm<d> f;
  f.mass = mass_at(q0);
  if (!detail::InvertMass<d>(f.mass, &f.inverse_mass))
    throw std::domain_error(
        "M = ∂²L/∂ẋ² is singular (L is not quadratic in every velocity, "
        "e.g. a first-order system)");
  const double mscale = f.mass.cwiseAbs().maxCoeff();
  for (int k = 0; k < 9; ++k) {
    // The initial point, then eight points around it (fixed offsets).
    double q[d], v[d];
    for (int c = 0; c < d; ++c) {
      const double u = k == 0 ? 0 : std::sin(1.7 * k + 2.3 * c);
      q[c] = q0[c] + 0.1 * u * (1 + std::abs(q0[c]));
      v[c] = v0[c] + 0.5 * std::cos(1.3 * k + 0.7 * c) * (1 + std::abs(v0[c]));
    }
    if ((mass_at(q) - f.mass).cwiseAbs().maxCoeff() > 1e-9 * mscale)
      throw std::domain_error(
          "M = ∂²L/∂ẋ² depends on the position (a position-dependent mass "
          "has no Hamiltonian form here)");
    double b[d];
    VectorPotential(l, q, b);
    const double l0 = AtUnitVelocity(l, q, -1, 0, -1, 0);
    double quadratic = l0, bscale = 0;
    for (int i = 0; i < d; ++i) {
      quadratic += b[i] * v[i];
      for (int j = 0; j < d; ++j) quadratic += 0.5 * v[i] * f.mass(i, j) * v[j];
      bscale = std::max(bscale, std::abs(b[i]));
    }
    const double lv = l(q, v);
    if (std::abs(lv - quadratic) >
        1e-9 * std::max({std::abs(lv), std::abs(l0), mscale}))
      throw std::domain_error(
          "L is not quadratic in the velocities (L(q, ẋ) differs from "
          "½ẋᵀMẋ + b·ẋ + L(q, 0) by " +
          std::to_string(std::abs(lv - quadratic)) + ")");
    if (bscale > 1e-13 * std::max(1.0, mscale)) f.separable = false;
  }
  return f;
}

// H(q, p) of the form above, at any scalar type.
template <bool Separable, class L, class T>
T LegendreHamiltonian(const L& l, const LegendreForm<L::kDim>& f, const T* q,
                      const T* p) {
  constexpr int d = L::kDim;
  T r[d];
  if constexpr (Separable) {
    for (int i = 0; i < d; ++i) r[i] = p[i];
  } else {
    T b[d];
    VectorPotential(l, q, b);
    for (int i = 0; i < d; ++i) r[i] = p[i] - b[i];
  }
  T h = -detail::AtUnitVelocity(l, q, -1, 0, -1, 0);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j)
      h = h + T(0.5 * f.inverse_mass(i, j)) * r[i] * r[j];
  return h;
}

}  // namespace vivp::studies
