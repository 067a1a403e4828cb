// What a user writes, and the pointwise density of the doubled action built
// from it (Rothkopf & Nordström 2023, eq. 34; Galley's non-conservative form).
//
//   // ẍ + κx³ = 0 from L = ½ẋ² − ¼κx⁴
//   struct Anharmonic {
//     static constexpr int kDim = 1;
//     double kappa = 20.0;
//     template <class T> T operator()(const T* x, const T* v) const {
//       return T(0.5) * v[0] * v[0] - 0.25 * kappa * x[0] * x[0] * x[0] * x[0];
//     }
//   };
//
// Optional members (a problem states only what it has):
//   template <class T> T Lambda(const T* x1, const T* v1,
//                               const T* x2, const T* v2) const;  // Λ
//   static constexpr int kOrder = 1;  // or 2; otherwise detected from ∂²L/∂v²
//
// Warnings:
//  1. operator() and Lambda are called with nested automatic-differentiation
//     scalars. Write constants as T(0.5) or 0.5 * x, and call math functions
//     unqualified after `using std::sin;` etc. so the AD overloads are found.
//  2. Λ must vanish at x1 = x2, v1 = v2 (it is a function of the difference
//     path x₋ to first order); otherwise x1 = x2 is not the critical point.
#pragma once

#include <Eigen/Core>
#include <concepts>

#include "core/autodiff/pointwise.h"

namespace vivp::action {

template <class P>
concept LagrangianProblem = requires(const P& p, const double* x) {
  { P::kDim } -> std::convertible_to<int>;
  { p(x, x) } -> std::convertible_to<double>;
};

template <class P>
concept HasLambda = requires(const P& p, const double* x) {
  { p.Lambda(x, x, x, x) } -> std::convertible_to<double>;
};

template <class P>
constexpr int DeclaredOrder() {
  if constexpr (requires { P::kOrder; })
    return P::kOrder;
  else
    return 0;
}

// f = L(x1, v1) − L(x2, v2) + Λ(x1, v1, x2, v2): the density of eq. (34).
template <class P, class T>
T Density(const P& problem, const T* x1, const T* v1, const T* x2,
          const T* v2) {
  T f = problem(x1, v1) - problem(x2, v2);
  if constexpr (HasLambda<P>) f += problem.Lambda(x1, v1, x2, v2);
  return f;
}

// The same density in average/difference variables x± (x1,2 = x₊ ± x₋/2).
template <class P, class T>
T DensityPlusMinus(const P& problem, const T* xp, const T* vp, const T* xm,
                   const T* vm) {
  constexpr int d = P::kDim;
  T x1[d], v1[d], x2[d], v2[d];
  for (int c = 0; c < d; ++c) {
    x1[c] = xp[c] + T(0.5) * xm[c];
    x2[c] = xp[c] - T(0.5) * xm[c];
    v1[c] = vp[c] + T(0.5) * vm[c];
    v2[c] = vp[c] - T(0.5) * vm[c];
  }
  return Density(problem, x1, v1, x2, v2);
}

// Λ alone in average/difference variables (zero when the problem has none).
template <class P, class T>
T LambdaPlusMinus(const P& problem, const T* xp, const T* vp, const T* xm,
                  const T* vm) {
  constexpr int d = P::kDim;
  T x1[d], v1[d], x2[d], v2[d];
  for (int c = 0; c < d; ++c) {
    x1[c] = xp[c] + T(0.5) * xm[c];
    x2[c] = xp[c] - T(0.5) * xm[c];
    v1[c] = vp[c] + T(0.5) * vm[c];
    v2[c] = vp[c] - T(0.5) * vm[c];
  }
  return problem.Lambda(x1, v1, x2, v2);
}

// ∂f/∂m and ∂²f/∂m∂p of the ± density at m = 0, p = (x₊, v₊). Because
// L(p + m/2) − L(p − m/2) is odd in m, its part is exactly ∇L(p) and ∇²L(p):
// one evaluation of L with second-order AD instead of two. Λ, if present,
// adds its own mixed derivatives.
template <class Real, class P>
ad::MixedDerivatives<Real, 2 * P::kDim, 2 * P::kDim> DiagonalDerivatives(
    const P& problem, const Real* p) {
  constexpr int d = P::kDim;
  const auto h = ad::Hessian<Real, 2 * d>(
      [&](const auto* z) { return problem(z, z + d); }, p);
  ad::MixedDerivatives<Real, 2 * d, 2 * d> out{h.gradient, h.hessian};
  if constexpr (HasLambda<P>) {
    Real m[2 * d] = {};
    const auto lam = ad::Mixed<Real, 2 * d, 2 * d>(
        [&](const auto* pv, const auto* mv) {
          return LambdaPlusMinus(problem, pv, pv + d, mv, mv + d);
        },
        p, m);
    out.dm += lam.dm;
    out.dmp += lam.dmp;
  }
  return out;
}

// ∂f/∂m of the ± density at m = 0 (the residual's pointwise part).
template <class Real, class P>
Eigen::Matrix<Real, 2 * P::kDim, 1> DiagonalGradient(const P& problem,
                                                     const Real* p) {
  constexpr int d = P::kDim;
  Eigen::Matrix<Real, 2 * d, 1> g =
      ad::Gradient<Real, 2 * d>(
          [&](const auto* z) { return problem(z, z + d); }, p)
          .second;
  if constexpr (HasLambda<P>) {
    Real m[2 * d] = {};
    g += ad::MinusGradient<Real, 2 * d, 2 * d>(
        [&](const auto* pv, const auto* mv) {
          return LambdaPlusMinus(problem, pv, pv + d, mv, mv + d);
        },
        p, m);
  }
  return g;
}

// The mass matrix ∂²L/∂v∂v at (x, v).
template <class Real, class P>
Eigen::Matrix<Real, P::kDim, P::kDim> MassMatrix(const P& problem,
                                                 const Real* x, const Real* v) {
  constexpr int d = P::kDim;
  Real z[2 * d];
  for (int c = 0; c < d; ++c) {
    z[c] = x[c];
    z[d + c] = v[c];
  }
  const auto h = ad::Hessian<Real, 2 * d>(
      [&](const auto* s) { return problem(s, s + d); }, z);
  return h.hessian.template bottomRightCorner<d, d>();
}

// ∂²f/∂x₋∂v₊ at (x, v) on the diagonal x1 = x2: the coefficient of ẋ in a
// first-order system's equation (Λ = ẋ₊x₋ gives 1).
template <class Real, class P>
Eigen::Matrix<Real, P::kDim, P::kDim> FirstOrderCoefficient(const P& problem,
                                                            const Real* x,
                                                            const Real* v) {
  constexpr int d = P::kDim;
  Real p[2 * d], m[2 * d];
  for (int c = 0; c < d; ++c) {
    p[c] = x[c];
    p[d + c] = v[c];
    m[c] = m[d + c] = Real(0);
  }
  const auto mixed = ad::Mixed<Real, 2 * d, 2 * d>(
      [&](const auto* pv, const auto* mv) {
        return DensityPlusMinus(problem, pv, pv + d, mv, mv + d);
      },
      p, m);
  return mixed.dmp.template block<d, d>(0, d);
}

// 2 for a second-order system (∂²L/∂v² ≠ 0 at the given point), 1 otherwise,
// unless the problem declares kOrder.
template <class Real, class P>
int SystemOrder(const P& problem, const Real* x, const Real* v) {
  if constexpr (DeclaredOrder<P>() != 0) {
    return DeclaredOrder<P>();
  } else {
    return MassMatrix<Real>(problem, x, v).cwiseAbs().maxCoeff() > Real(0) ? 2
                                                                          : 1;
  }
}

}  // namespace vivp::action
