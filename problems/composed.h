// A Lagrangian composed of effects (effects.h) chosen at run time, e.g. from
// a scene file:
//
//   using namespace vivp::problems;
//   Composed<1> damped{{effects::Kinetic{0.5}, effects::Spring{1.0},
//                       effects::Damping{0.00071}}};
//   auto sol = vivp::variational::SolveIvp(damped, {{1.0}, {0.0}}, grid);
//
// L is the sum of the effects' Lagrangian terms and Λ the sum of their Λ
// terms. The solver differentiates a composition term by term
// (AddDiagonalDerivatives), each effect in the variables it depends on — a
// potential in x, a kinetic energy in v: d instead of 2d AD variables — and
// Λ only for the effects that have one. So an absent effect costs nothing
// and a composition is not slower than the hand-written functor of the same
// system (bench/composition_bench). Only the full doubled system (full Newton,
// Ceres) evaluates the (possibly empty) Λ sum as a whole.
#pragma once

#include <type_traits>
#include <variant>
#include <vector>

#include "problems/effects.h"

namespace vivp::problems {

template <class E>
concept HasLagrangian = requires(const E& e, const double* p) {
  e.template Lagrangian<1>(p, p);
};
template <class E>
concept HasLambdaTerm = requires(const E& e, const double* p) {
  e.template Lambda<1>(p, p, p, p);
};

// Does this effect contribute to Λ?
inline bool IsDissipative(const Effect& e) {
  return std::visit([](const auto& t) { return HasLambdaTerm<decltype(t)>; },
                    e);
}

template <int D>
struct Composed {
  static constexpr int kDim = D;
  std::vector<Effect> effects;

  template <class T>
  T operator()(const T* x, const T* v) const {
    T sum = T(0.0);
    for (const Effect& e : effects)
      std::visit(
          [&](const auto& t) {
            if constexpr (HasLagrangian<decltype(t)>)
              sum += t.template Lagrangian<D>(x, v);
          },
          e);
    return sum;
  }

  // L = ½ẋᵀMẋ − V(x) with M constant (action::ConstantMass): no Λ, and
  // every effect a kinetic energy or a function of x alone. M may be zero
  // (potentials only): such a composition is a part of a sum whose other
  // part carries the kinetic energy (a scene's registered Lagrangian,
  // action::SumModel). The predictor of a second-order march then integrates
  // ẍ = M⁻¹ ∂L/∂x (core/action/euler_lagrange.h).
  bool ConstantMass() const {
    for (const Effect& e : effects) {
      const bool ok = std::visit(
          [](const auto& t) {
            using E = std::remove_cvref_t<decltype(t)>;
            if constexpr (HasLambdaTerm<E>)
              return false;
            else if constexpr (std::is_same_v<E, effects::Kinetic>)
              return true;
            else
              return E::kDepends == action::Depends::kPosition;
          },
          e);
      if (!ok) return false;
    }
    return true;
  }

  template <class T>
  T Lambda(const T* x1, const T* v1, const T* x2, const T* v2) const {
    T sum = T(0.0);
    for (const Effect& e : effects)
      std::visit(
          [&](const auto& t) {
            if constexpr (HasLambdaTerm<decltype(t)>)
              sum += t.template Lambda<D>(x1, v1, x2, v2);
          },
          e);
    return sum;
  }

  // The pointwise derivatives of the doubled density, term by term
  // (core/action/density.h): each effect in the variables it depends on.
  template <class Real>
  void AddDiagonalDerivatives(const Real* p,
                              action::Diagonal<Real, D>& out) const {
    for (const Effect& e : effects)
      std::visit(
          [&](const auto& t) {
            using E = std::remove_cvref_t<decltype(t)>;
            if constexpr (HasLagrangian<E>)
              action::AddLagrangianTerm<E::kDepends, D>(
                  [&](const auto* x, const auto* v) {
                    return t.template Lagrangian<D>(x, v);
                  },
                  p, out);
            if constexpr (HasLambdaTerm<E>)
              action::AddLambdaTerm<D>(
                  [&](const auto*... a) { return t.template Lambda<D>(a...); },
                  p, out);
          },
          e);
  }

  template <class Real>
  void AddDiagonalGradient(const Real* p,
                           action::DiagonalVector<Real, D>& out) const {
    for (const Effect& e : effects)
      std::visit(
          [&](const auto& t) {
            using E = std::remove_cvref_t<decltype(t)>;
            if constexpr (HasLagrangian<E>)
              action::AddLagrangianTermGradient<E::kDepends, D>(
                  [&](const auto* x, const auto* v) {
                    return t.template Lagrangian<D>(x, v);
                  },
                  p, out);
            if constexpr (HasLambdaTerm<E>)
              action::AddLambdaTermGradient<D>(
                  [&](const auto*... a) { return t.template Lambda<D>(a...); },
                  p, out);
          },
          e);
  }
};

}  // namespace vivp::problems
