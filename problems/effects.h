// Effects: the terms a physical system is composed of (README "Effects"). A
// scene lists effects; the Lagrangian is their sum and the non-conservative
// term Λ the sum of the dissipative ones, so an effect that is not listed costs
// nothing. Each effect is a small struct with defaults for every parameter and
// either
//   template <int D, class T> T Lagrangian(const T* x, const T* v) const
// (a term of L, D degrees of freedom) or
//   template <int D, class T> T Lambda(const T* x1, const T* v1,
//                                      const T* x2, const T* v2) const
// (a term of Galley's Λ in the doubled variables), or both. A Lagrangian term
// declares what it depends on (kDepends: the position, the velocity or
// both); the solver differentiates it in those variables only, and calls it
// with a null pointer for the other argument. Spec() is the effect's name,
// formula and parameter table (effect_parameters.h), from which the scene
// catalogue, reader and help are generated.
#pragma once

#include <cmath>
#include <variant>
#include <vector>

#include "core/action/density.h"
#include "core/autodiff/scalar.h"
#include "problems/effect_parameters.h"

namespace vivp::problems::effects {

namespace detail {
template <int D, class T>
T Dot(const T* a, const T* b) {
  T s = a[0] * b[0];
  for (int c = 1; c < D; ++c) s += a[c] * b[c];
  return s;
}
// (v1 + v2)·(x1 − x2) = 2 ẋ₊·x₋, the building block of linear Λ terms.
template <int D, class T>
T PlusDotMinus(const T* x1, const T* v1, const T* x2, const T* v2) {
  T s = (v1[0] + v2[0]) * (x1[0] - x2[0]);
  for (int c = 1; c < D; ++c) s += (v1[c] + v2[c]) * (x1[c] - x2[c]);
  return s;
}
}  // namespace detail

// Kinetic energy ½ m|ẋ|², or ½ ẋᵀMẋ with a symmetric mass matrix M
// (row-major D×D in `matrix`, used when non-empty).
struct Kinetic {
  static constexpr action::Depends kDepends = action::Depends::kVelocity;
  double mass = 1.0;
  std::vector<double> matrix;
  static EffectSpec<Kinetic> Spec() {
    using K = ParameterKind;
    return {"kinetic",
            "L += ½ m|ẋ|²  (or ½ ẋᵀMẋ with a mass matrix M)",
            {{"mass", K::kPositive, &Kinetic::mass, "scalar mass m"},
             {"matrix", K::kMatrix, &Kinetic::matrix,
              "symmetric positive definite M, dof rows (instead of mass)"}},
            /*kinetic=*/true,
            /*first_order=*/false,
            {"mass", "matrix"}};
  }
  template <int D, class T>
  T Lagrangian(const T*, const T* v) const {
    if (matrix.empty()) return T(0.5 * mass) * detail::Dot<D>(v, v);
    T s = T(0.0);
    for (int r = 0; r < D; ++r)
      for (int c = 0; c < D; ++c) s += T(0.5 * matrix[r * D + c]) * v[r] * v[c];
    return s;
  }
};

// Uniform gravity: V = m g x_axis, so L gets −m g x_axis (axis 0-based,
// default the last coordinate: "up").
struct Gravity {
  static constexpr action::Depends kDepends = action::Depends::kPosition;
  double mass = 1.0;
  double g = 1.0;
  int axis = -1;  // −1: the last coordinate
  static EffectSpec<Gravity> Spec() {
    using K = ParameterKind;
    return {"gravity",
            "L −= m g x_axis  (uniform field along −axis)",
            {{"mass", K::kPositive, &Gravity::mass, "mass m"},
             {"g", K::kReal, &Gravity::g, "field strength g"},
             {"axis", K::kAxis, &Gravity::axis, "coordinate index"}}};
  }
  template <int D, class T>
  T Lagrangian(const T* x, const T*) const {
    return T(-mass * g) * x[axis < 0 ? D - 1 : axis];
  }
};

// Linear spring to a centre: V = ½k|x − c|².
struct Spring {
  static constexpr action::Depends kDepends = action::Depends::kPosition;
  double k = 1.0;
  std::vector<double> centre;  // empty: the origin
  static EffectSpec<Spring> Spec() {
    using K = ParameterKind;
    return {"spring",
            "L −= ½ k|x − c|²",
            {{"k", K::kNonNegative, &Spring::k, "stiffness k"},
             {"centre", K::kVector, &Spring::centre, "rest point c"}}};
  }
  template <int D, class T>
  T Lagrangian(const T* x, const T*) const {
    if (centre.empty()) return T(-0.5 * k) * detail::Dot<D>(x, x);
    T dx[D];
    for (int c = 0; c < D; ++c) dx[c] = x[c] - T(centre[c]);
    return T(-0.5 * k) * detail::Dot<D>(dx, dx);
  }
  // The same as a function of r² = |x|² (only without a centre).
  bool radial() const {
    for (double c : centre)
      if (c != 0) return false;
    return true;
  }
  template <class T>
  T RadialLagrangian(const T& r2) const {
    return T(-0.5 * k) * r2;
  }
};

// Quartic (anharmonic) potential V = ¼κ|x|⁴ (Rothkopf & Nordström 2023,
// eq. 33, for D = 1).
struct Quartic {
  static constexpr action::Depends kDepends = action::Depends::kPosition;
  double kappa = 1.0;
  static EffectSpec<Quartic> Spec() {
    return {"quartic",
            "L −= ¼ κ|x|⁴  (anharmonic, Rothkopf & Nordström 2023, eq. 33)",
            {{"kappa", ParameterKind::kNonNegative, &Quartic::kappa,
              "strength κ"}}};
  }
  template <int D, class T>
  T Lagrangian(const T* x, const T*) const {
    return RadialLagrangian(detail::Dot<D>(x, x));
  }
  bool radial() const { return true; }
  template <class T>
  T RadialLagrangian(const T& r2) const {
    return T(-0.25 * kappa) * r2 * r2;
  }
};

// Pendulum in angle form: V = −s cos x_axis (s = m g ℓ, with m ℓ² = 1 in
// the kinetic term for the usual ẍ = −s sin x).
struct Pendulum {
  static constexpr action::Depends kDepends = action::Depends::kPosition;
  double strength = 1.0;
  int axis = 0;
  static EffectSpec<Pendulum> Spec() {
    using K = ParameterKind;
    return {"pendulum",
            "L += s cos x_axis  (ẍ = −(s/m) sin x)",
            {{"strength", K::kPositive, &Pendulum::strength, "s = m g ℓ"},
             {"axis", K::kAxis, &Pendulum::axis, "angle coordinate"}}};
  }
  template <int D, class T>
  T Lagrangian(const T* x, const T*) const {
    using std::cos;
    return T(strength) * cos(x[axis]);
  }
};

// Central attraction V = −k/|x| (Kepler).
struct Central {
  static constexpr action::Depends kDepends = action::Depends::kPosition;
  double k = 1.0;
  static EffectSpec<Central> Spec() {
    return {"central",
            "L += k/|x|  (Kepler attraction)",
            {{"k", ParameterKind::kPositive, &Central::k, "strength k"}}};
  }
  template <int D, class T>
  T Lagrangian(const T* x, const T*) const {
    return RadialLagrangian(detail::Dot<D>(x, x));
  }
  bool radial() const { return true; }
  template <class T>
  T RadialLagrangian(const T& r2) const {
    using std::sqrt;
    return T(k) / sqrt(r2);
  }
};

// Gaussian well (the experiment of McLachlan & Offen 2023 with a = 1): L
// gets +U with U = a·exp(−|x|²/2) (McLachlan & Offen write ẍ = ∇U,
// L = ½|ẋ|² + U: docs/bea.md §1), i.e. the potential energy −U, attractive
// for a > 0.
struct GaussianWell {
  static constexpr action::Depends kDepends = action::Depends::kPosition;
  double amplitude = 1.0;
  static EffectSpec<GaussianWell> Spec() {
    return {"gaussian_well",
            "L += a exp(−|x|²/2)  (McLachlan & Offen 2023: ẍ = ∇U)",
            {{"amplitude", ParameterKind::kReal, &GaussianWell::amplitude,
              "depth a"}}};
  }
  template <int D, class T>
  T Lagrangian(const T* x, const T*) const {
    return RadialLagrangian(detail::Dot<D>(x, x));
  }
  bool radial() const { return true; }
  template <class T>
  T RadialLagrangian(const T& r2) const {
    using std::exp;
    return T(amplitude) * exp(T(-0.5) * r2);
  }
};

// Nearest-neighbour chain (FPU type): V = Σ ½k(Δ)² + ¼β(Δ)⁴ over the bonds
// Δ = x_{i+1} − x_i, with x_{−1} = x_D = 0 when the ends are fixed.
struct Chain {
  static constexpr action::Depends kDepends = action::Depends::kPosition;
  double k = 1.0;
  double beta = 0.0;
  bool fixed_ends = true;
  static EffectSpec<Chain> Spec() {
    using K = ParameterKind;
    return {"chain",
            "L −= Σ_bonds ½ k Δ² + ¼ β Δ⁴, Δ = x_{i+1} − x_i  (FPU; walls "
            "x_{−1} = x_dof = 0 with fixed_ends)",
            {{"k", K::kNonNegative, &Chain::k, "bond stiffness k"},
             {"beta", K::kReal, &Chain::beta, "quartic bond part β"},
             {"fixed_ends", K::kBool, &Chain::fixed_ends,
              "bonds to walls at both ends"}}};
  }
  template <int D, class T>
  T Lagrangian(const T* x, const T*) const {
    T s = T(0.0);
    auto bond = [&](const T& d) {
      const T d2 = d * d;
      s += T(0.5 * k) * d2;
      if (beta != 0.0) s += T(0.25 * beta) * d2 * d2;
    };
    for (int i = 0; i + 1 < D; ++i) bond(T(x[i + 1] - x[i]));
    if (fixed_ends) {
      bond(x[0]);
      bond(x[D - 1]);
    }
    return -s;
  }
};

// Linear damping F = −ξẋ through Galley's Λ = −ξ ẋ₊·x₋ (Rothkopf &
// Nordström 2023, eq. 40).
struct Damping {
  double xi = 0.1;
  static EffectSpec<Damping> Spec() {
    return {"damping",
            "Λ = −ξ ẋ₊·x₋  (friction force −ξẋ, Rothkopf & Nordström 2023, "
            "eq. 40)",
            {{"xi", ParameterKind::kNonNegative, &Damping::xi,
              "friction coefficient ξ"}}};
  }
  template <int D, class T>
  T Lambda(const T* x1, const T* v1, const T* x2, const T* v2) const {
    return T(-0.5 * xi) * detail::PlusDotMinus<D>(x1, v1, x2, v2);
  }
};

// First-order growth ẋ = κx (Rothkopf & Nordström 2023, eqs. 37–38):
// L = −½κ|x|² with Λ = ẋ₊·x₋, which together give the first-order equation.
struct Growth {
  static constexpr action::Depends kDepends = action::Depends::kPosition;
  double kappa = 1.0;
  static EffectSpec<Growth> Spec() {
    return {"growth",
            "L −= ½ κ|x|², Λ = ẋ₊·x₋  (first order ẋ = κx, Rothkopf & "
            "Nordström 2023, eqs. 37–38)",
            {{"kappa", ParameterKind::kReal, &Growth::kappa, "rate κ"}},
            /*kinetic=*/false,
            /*first_order=*/true};
  }
  template <int D, class T>
  T Lagrangian(const T* x, const T*) const {
    return T(-0.5 * kappa) * detail::Dot<D>(x, x);
  }
  template <int D, class T>
  T Lambda(const T* x1, const T* v1, const T* x2, const T* v2) const {
    return T(0.5) * detail::PlusDotMinus<D>(x1, v1, x2, v2);
  }
};

}  // namespace vivp::problems::effects

namespace vivp::problems {

// Every effect a scene may list, in the catalogue's order: adding an effect
// is its struct above (terms, Spec()) and its name here.
using Effect = std::variant<effects::Kinetic, effects::Gravity, effects::Spring,
                            effects::Quartic, effects::Pendulum,
                            effects::Central, effects::GaussianWell,
                            effects::Chain, effects::Damping, effects::Growth>;

}  // namespace vivp::problems
