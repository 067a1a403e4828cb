// Electromagnetism from its potentials, as a density of densities.h with
// the d + 1 components (A_0, A_1, …, A_d): A_0 the scalar potential, A_i the
// vector potential. Heaviside–Lorentz units, c = 1:
//
//   ℒ = ½ Σ_i E_i² − ½ Σ_{i<j} F_ij²,   E_i = −∂_i A_0 − ∂_t A_i,
//                                       F_ij = ∂_i A_j − ∂_j A_i,
//
// which is −¼ F_μν F^μν (in 2 + 1 D, F_12 is the magnetic field B; in 3 + 1 D
// the F_ij are B's components). A_0 has no time derivative: its
// Euler–Lagrange equation is Gauss's law ∇·E = 0, a constraint at every
// time, and nothing in the density fixes a gauge. The transformation
// A_0 → A_0 − ∂_t χ, A_i → A_i + ∂_i χ leaves E and F, and so ℒ, unchanged;
// docs/gauge.md shows which discrete operators keep that exactly.
#pragma once

namespace vivp::fields {

template <int d>
struct MaxwellIn {
  static_assert(d >= 1 && d <= 3, "Maxwell in 1, 2 or 3 space dimensions");
  static constexpr int kDim = d + 1, kSpaceDim = d;
  // A_0 enters without a time derivative: no initial data, no end
  // connection (core/action/field_point.h).
  static constexpr unsigned kWithoutTimeDerivative = 1u;
  // ∂_b A_a as the density receives it (densities.h): ∂_b's components.
  template <class T>
  static const T& Grad(const T* a_x, int b, int a) {
    return a_x[b * kDim + a];
  }
  template <class T>
  T operator()(const T*, const T* a_t, const T* a_x) const {
    T l(0.0);
    for (int i = 1; i <= d; ++i) {
      const T e = -Grad(a_x, i - 1, 0) - a_t[i];
      l += 0.5 * e * e;
    }
    for (int i = 1; i <= d; ++i)
      for (int j = i + 1; j <= d; ++j) {
        const T f = Grad(a_x, i - 1, j) - Grad(a_x, j - 1, i);
        l -= 0.5 * f * f;
      }
    return l;
  }
};

}  // namespace vivp::fields
