// Lagrangian densities of field theories in 1+1 dimensions, for the
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
// without it d = 1, as for every density below. Each one below is L = ½|φ_t|² −
// ½c²|φ_x|² − V(φ); the Euler–Lagrange equation is φ_tt = c²φ_xx − V′(φ).
#pragma once

#include <cmath>

namespace vivp::fields {

// The wave equation, V = 0.
struct Wave {
  static constexpr int kDim = 1;
  double c = 1.0;
  template <class T>
  T operator()(const T* phi, const T* phi_t, const T* phi_x) const {
    (void)phi;
    return T(0.5) * phi_t[0] * phi_t[0] - T(0.5 * c * c) * phi_x[0] * phi_x[0];
  }
};

// Klein–Gordon, V = ½m²φ².
struct KleinGordon {
  static constexpr int kDim = 1;
  double mass = 1.0, c = 1.0;
  template <class T>
  T operator()(const T* phi, const T* phi_t, const T* phi_x) const {
    return T(0.5) * phi_t[0] * phi_t[0] - T(0.5 * c * c) * phi_x[0] * phi_x[0] -
           T(0.5 * mass * mass) * phi[0] * phi[0];
  }
};

// Sine-Gordon, V = 1 − cos φ (units with m = c = 1).
struct SineGordon {
  static constexpr int kDim = 1;
  template <class T>
  T operator()(const T* phi, const T* phi_t, const T* phi_x) const {
    using std::cos;
    return T(0.5) * phi_t[0] * phi_t[0] - T(0.5) * phi_x[0] * phi_x[0] -
           (T(1.0) - cos(phi[0]));
  }
};

// φ⁴ theory, V = ¼λ(φ² − v²)²: kinks between the vacua ±v.
struct Phi4 {
  static constexpr int kDim = 1;
  double lambda = 2.0, v = 1.0;
  template <class T>
  T operator()(const T* phi, const T* phi_t, const T* phi_x) const {
    const T w = phi[0] * phi[0] - T(v * v);
    return T(0.5) * phi_t[0] * phi_t[0] - T(0.5) * phi_x[0] * phi_x[0] -
           T(0.25 * lambda) * w * w;
  }
};

// A complex field φ = φ₀ + iφ₁ with V = ½m²|φ|² + ¼λ|φ|⁴, invariant under
// φ → e^{iα}φ; its Noether charge is Q = ∫ (φ₀ ∂_tφ₁ − φ₁ ∂_tφ₀) dx.
struct ComplexPhi4 {
  static constexpr int kDim = 2;
  double mass = 1.0, lambda = 1.0;
  template <class T>
  T operator()(const T* phi, const T* phi_t, const T* phi_x) const {
    const T r2 = phi[0] * phi[0] + phi[1] * phi[1];
    return T(0.5) * (phi_t[0] * phi_t[0] + phi_t[1] * phi_t[1]) -
           T(0.5) * (phi_x[0] * phi_x[0] + phi_x[1] * phi_x[1]) -
           T(0.5 * mass * mass) * r2 - T(0.25 * lambda) * r2 * r2;
  }
};

}  // namespace vivp::fields
