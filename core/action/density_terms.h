// The derivatives of the doubled density one term at a time (density.h):
// what a problem summed from terms (problems/composed.h) adds up, each term
// in the variables it depends on, and the types they are added into.
#pragma once

#include <Eigen/Core>
#include <type_traits>

#include "core/autodiff/pointwise.h"

namespace vivp::action {

// A term λ(x1, v1, x2, v2) of Λ in average/difference variables.
template <int d, class F, class T>
T LambdaTermPlusMinus(const F& lambda, const T* xp, const T* vp, const T* xm,
                      const T* vm) {
  T x1[d], v1[d], x2[d], v2[d];
  for (int c = 0; c < d; ++c) {
    x1[c] = xp[c] + T(0.5) * xm[c];
    x2[c] = xp[c] - T(0.5) * xm[c];
    v1[c] = vp[c] + T(0.5) * vm[c];
    v2[c] = vp[c] - T(0.5) * vm[c];
  }
  return lambda(x1, v1, x2, v2);
}

// What a term of L depends on: a potential sees only x, a kinetic energy only
// v. A problem summed from terms (problems/composed.h) differentiates each
// term in the d variables it depends on instead of all 2d.
enum class Depends { kPosition, kVelocity, kBoth };

// ∂f/∂m and ∂²f/∂m∂p of the ± density f at m = 0, p = (x₊, v₊), m = (x₋, v₋).
template <class Real, int d>
using Diagonal = autodiff::MixedDerivatives<Real, 2 * d, 2 * d>;
template <class Real, int d>
using DiagonalVector = Eigen::Matrix<Real, 2 * d, 1>;

// Adds one term ℓ(x, v) of L. Because ℓ(p + m/2) − ℓ(p − m/2) is odd in m,
// its part of ∂f/∂m and ∂²f/∂m∂p is exactly ∇ℓ(p) and ∇²ℓ(p): one
// evaluation with second-order AD. A term declared kPosition (kVelocity) is
// called with a null velocity (position) pointer, which it must not read.
template <Depends kDep, int d, class Real, class F>
void AddLagrangianTerm(const F& term, const Real* p, Diagonal<Real, d>& out) {
  if constexpr (kDep == Depends::kBoth) {
    const auto h = autodiff::Hessian<Real, 2 * d>(
        [&](const auto* z) { return term(z, z + d); }, p);
    out.dm += h.gradient;
    out.dmp += h.hessian;
  } else {
    constexpr int off = kDep == Depends::kPosition ? 0 : d;
    const auto h = autodiff::Hessian<Real, d>(
        [&](const auto* z) {
          using T = std::remove_cvref_t<decltype(*z)>;
          const T* none = nullptr;
          return kDep == Depends::kPosition ? term(z, none) : term(none, z);
        },
        p + off);
    out.dm.template segment<d>(off) += h.gradient;
    out.dmp.template block<d, d>(off, off) += h.hessian;
  }
}

// The same for the residual alone (first derivatives).
template <Depends kDep, int d, class Real, class F>
void AddLagrangianTermGradient(const F& term, const Real* p,
                               DiagonalVector<Real, d>& out) {
  if constexpr (kDep == Depends::kBoth) {
    out += autodiff::Gradient<Real, 2 * d>(
               [&](const auto* z) { return term(z, z + d); }, p)
               .second;
  } else {
    constexpr int off = kDep == Depends::kPosition ? 0 : d;
    out.template segment<d>(off) +=
        autodiff::Gradient<Real, d>(
            [&](const auto* z) {
              using T = std::remove_cvref_t<decltype(*z)>;
              const T* none = nullptr;
              return kDep == Depends::kPosition ? term(z, none) : term(none, z);
            },
            p + off)
            .second;
  }
}

// Adds one term λ(x1, v1, x2, v2) of Λ: its mixed derivatives at m = 0.
template <int d, class Real, class F>
void AddLambdaTerm(const F& lambda, const Real* p, Diagonal<Real, d>& out) {
  const Real m[2 * d] = {};
  const auto lam = autodiff::Mixed<Real, 2 * d, 2 * d>(
      [&](const auto* pv, const auto* mv) {
        return LambdaTermPlusMinus<d>(lambda, pv, pv + d, mv, mv + d);
      },
      p, m);
  out.dm += lam.dm;
  out.dmp += lam.dmp;
}

template <int d, class Real, class F>
void AddLambdaTermGradient(const F& lambda, const Real* p,
                           DiagonalVector<Real, d>& out) {
  const Real m[2 * d] = {};
  out += autodiff::MinusGradient<Real, 2 * d, 2 * d>(
      [&](const auto* pv, const auto* mv) {
        return LambdaTermPlusMinus<d>(lambda, pv, pv + d, mv, mv + d);
      },
      p, m);
}

}  // namespace vivp::action
