// Lagrangian densities of field theories in d + 1 dimensions, for the
// space-time discretization of the action (Rothkopf & Nordström 2023 name
// partial differential equations as the extension of the method; Rothkopf,
// Horowitz & Nordström, "Exact symmetry conservation and automatic mesh
// refinement in discrete initial boundary value problems", 2024).
//
// A density is a functor templated on the scalar, like a point-mechanics
// Lagrangian, with kDim field components:
//
//   template <class T>
//   T operator()(const T* phi, const T* phi_t, const T* phi_x) const;
//
// so that its derivatives come from automatic differentiation and no field
// equation is written by hand. A density in d spatial dimensions declares
// `static constexpr int kSpaceDim = d` and receives the gradient as its
// third argument, d·kDim values (∂_0 φ's components, then ∂_1 φ's, …);
// without it d = 1. Each density below is written once for any d (its
// template argument; the plain name is d = 1): L = ½|φ_t|² − ½c²|∇φ|² −
// V(φ), whose Euler–Lagrange equation is φ_tt = c²Δφ − V′(φ).
#pragma once

#include <cmath>

namespace vivp::fields {

// |∇φ_a|² = Σ_b (∂_b φ_a)² of component a among m, the gradient as the
// density receives it; d = 1 is the single square (no sum with zero).
template <int d, int m = 1, class T>
T GradientSquared(const T* phi_x, int a = 0) {
  T s = phi_x[a] * phi_x[a];
  for (int b = 1; b < d; ++b) s += phi_x[b * m + a] * phi_x[b * m + a];
  return s;
}

// The wave equation, V = 0.
template <int d>
struct WaveIn {
  static constexpr int kDim = 1, kSpaceDim = d;
  double c = 1.0;
  template <class T>
  T operator()(const T* phi, const T* phi_t, const T* phi_x) const {
    (void)phi;
    return T(0.5) * phi_t[0] * phi_t[0] -
           T(0.5 * c * c) * GradientSquared<d>(phi_x);
  }
};
using Wave = WaveIn<1>;

// Klein–Gordon, V = ½m²φ².
template <int d>
struct KleinGordonIn {
  static constexpr int kDim = 1, kSpaceDim = d;
  double mass = 1.0, c = 1.0;
  template <class T>
  T operator()(const T* phi, const T* phi_t, const T* phi_x) const {
    return T(0.5) * phi_t[0] * phi_t[0] -
           T(0.5 * c * c) * GradientSquared<d>(phi_x) -
           T(0.5 * mass * mass) * phi[0] * phi[0];
  }
};
using KleinGordon = KleinGordonIn<1>;

// Sine-Gordon, V = 1 − cos φ (units with m = c = 1).
template <int d>
struct SineGordonIn {
  static constexpr int kDim = 1, kSpaceDim = d;
  template <class T>
  T operator()(const T* phi, const T* phi_t, const T* phi_x) const {
    using std::cos;
    return T(0.5) * phi_t[0] * phi_t[0] - T(0.5) * GradientSquared<d>(phi_x) -
           (T(1.0) - cos(phi[0]));
  }
};
using SineGordon = SineGordonIn<1>;

// φ⁴ theory, V = ¼λ(φ² − v²)²: kinks between the vacua ±v.
template <int d>
struct Phi4In {
  static constexpr int kDim = 1, kSpaceDim = d;
  double lambda = 2.0, v = 1.0;
  template <class T>
  T operator()(const T* phi, const T* phi_t, const T* phi_x) const {
    const T w = phi[0] * phi[0] - T(v * v);
    return T(0.5) * phi_t[0] * phi_t[0] - T(0.5) * GradientSquared<d>(phi_x) -
           T(0.25 * lambda) * w * w;
  }
};
using Phi4 = Phi4In<1>;

// A complex field φ = φ₀ + iφ₁ with V = ½m²|φ|² + ¼λ|φ|⁴, invariant under
// φ → e^{iα}φ; its Noether charge is Q = ∫ (φ₀ ∂_tφ₁ − φ₁ ∂_tφ₀) dx.
template <int d>
struct ComplexPhi4In {
  static constexpr int kDim = 2, kSpaceDim = d;
  double mass = 1.0, lambda = 1.0;
  template <class T>
  T operator()(const T* phi, const T* phi_t, const T* phi_x) const {
    const T r2 = phi[0] * phi[0] + phi[1] * phi[1];
    return T(0.5) * (phi_t[0] * phi_t[0] + phi_t[1] * phi_t[1]) -
           T(0.5) * (GradientSquared<d, 2>(phi_x, 0) +
                     GradientSquared<d, 2>(phi_x, 1)) -
           T(0.5 * mass * mass) * r2 - T(0.25 * lambda) * r2 * r2;
  }
};
using ComplexPhi4 = ComplexPhi4In<1>;

}  // namespace vivp::fields
