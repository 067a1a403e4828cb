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
//   static constexpr bool kConstantMass = true;  // L = ½vᵀMv + c·v − V(x)
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
#include <type_traits>
#include <utility>

#include "core/action/density_terms.h"
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

// kConstantMass declares L = ½vᵀMv + c·v − V(x) with M and c constant:
// ∂²L/∂v² = M and ∂²L/∂x∂v = 0 at every point, so that the equation of
// motion is ẍ = M⁻¹ ∂L/∂x (euler_lagrange.h, Accelerator) and
// needs only first derivatives over x. Ignored with Λ or kOrder = 1. The
// solvers check it wherever they evaluate ∂²L (reduced_system.h) and fail
// with an error naming it when it does not hold.
template <class P>
constexpr bool DeclaredConstantMass() {
  if constexpr (requires { P::kConstantMass; })
    return P::kConstantMass && DeclaredOrder<P>() != 1 && !HasLambda<P>;
  else
    return false;
}

// A problem whose pointwise derivatives were compiled once, elsewhere
// (erased_problem.h): every function below asks its model instead of
// differentiating it, so the solvers compile once per dimension, not once per
// Lagrangian.
template <class P>
concept Precompiled = requires(const P& p) {
  p.pointwise();
};

// Whether P's Lagrangian declares kConstantMass (for a precompiled problem,
// whether its model's does; a problem composed at run time may say so through
// a member ConstantMass(), problems/composed.h).
template <class P>
bool ConstantMass(const P& problem) {
  if constexpr (Precompiled<P>)
    return problem.pointwise().ConstantMass();
  else if constexpr (requires { problem.ConstantMass(); })
    return problem.ConstantMass();
  else
    return DeclaredConstantMass<P>();
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
  return LambdaTermPlusMinus<P::kDim>(
      [&](const T* x1, const T* v1, const T* x2, const T* v2) {
        return Density(problem, x1, v1, x2, v2);
      },
      xp, vp, xm, vm);
}

// A problem may differentiate itself term by term (problems/composed.h) by
// providing AddDiagonalDerivatives(p, out) and AddDiagonalGradient(p, out);
// otherwise L and Λ are each differentiated whole.
template <class P, class Real>
concept DifferentiatesByTerms = requires(const P& problem, const Real* p,
                                         Diagonal<Real, P::kDim>& dd,
                                         DiagonalVector<Real, P::kDim>& g) {
  problem.AddDiagonalDerivatives(p, dd);
  problem.AddDiagonalGradient(p, g);
};

// ∂f/∂m and ∂²f/∂m∂p of the ± density at m = 0, p = (x₊, v₊): ∇L(p) and
// ∇²L(p) (see AddLagrangianTerm) plus Λ's own mixed derivatives.
template <class Real, class P>
Diagonal<Real, P::kDim> DiagonalDerivatives(const P& problem, const Real* p) {
  constexpr int d = P::kDim;
  Diagonal<Real, d> out{DiagonalVector<Real, d>::Zero(),
                        Eigen::Matrix<Real, 2 * d, 2 * d>::Zero()};
  if constexpr (Precompiled<P>) {
    out = problem.pointwise().DiagonalDerivatives(p);
  } else if constexpr (DifferentiatesByTerms<P, Real>) {
    problem.AddDiagonalDerivatives(p, out);
  } else {
    AddLagrangianTerm<Depends::kBoth, d>(problem, p, out);
    if constexpr (HasLambda<P>)
      AddLambdaTerm<d>([&](const auto*... a) { return problem.Lambda(a...); },
                       p, out);
  }
  return out;
}

// ∂f/∂m of the ± density at m = 0 (the residual's pointwise part).
template <class Real, class P>
DiagonalVector<Real, P::kDim> DiagonalGradient(const P& problem,
                                               const Real* p) {
  constexpr int d = P::kDim;
  DiagonalVector<Real, d> g = DiagonalVector<Real, d>::Zero();
  if constexpr (Precompiled<P>) {
    g = problem.pointwise().DiagonalGradient(p);
  } else if constexpr (DifferentiatesByTerms<P, Real>) {
    problem.AddDiagonalGradient(p, g);
  } else {
    AddLagrangianTermGradient<Depends::kBoth, d>(problem, p, g);
    if constexpr (HasLambda<P>)
      AddLambdaTermGradient<d>(
          [&](const auto*... a) { return problem.Lambda(a...); }, p, g);
  }
  return g;
}

// DiagonalDerivatives at n points, p[k·2d …] ↦ out[k]: the Jacobian's
// sweep over the nodes. A precompiled problem makes one call for all n (one
// virtual call per block, not per node); the numbers are those of the
// single-point function. (The residual's sweep: gradient_sweep.h.)
template <class Real, class P>
void DiagonalDerivativesAt(const P& problem, const Real* p, int n,
                           Diagonal<Real, P::kDim>* out) {
  constexpr int d = P::kDim;
  if constexpr (Precompiled<P>) {
    problem.pointwise().DiagonalDerivativesAt(p, n, out);
  } else {
    for (int k = 0; k < n; ++k)
      out[k] = DiagonalDerivatives<Real>(problem, p + 2 * d * k);
  }
}

// L and its gradient at z = (x, v) (first-order AD).
template <class Real, class P>
std::pair<Real, Eigen::Matrix<Real, 2 * P::kDim, 1>> LagrangianGradient(
    const P& problem, const Real* z) {
  constexpr int d = P::kDim;
  if constexpr (Precompiled<P>)
    return problem.pointwise().LagrangianGradient(z);
  else
    return autodiff::Gradient<Real, 2 * d>(
        [&](const auto* s) { return problem(s, s + d); }, z);
}

// L, its gradient and its Hessian at z = (x, v): ∂²L/∂x∂x top left, the mass
// matrix ∂²L/∂v∂v bottom right.
template <class Real, class P>
autodiff::ValueGradientHessian<Real, 2 * P::kDim> LagrangianDerivatives(
    const P& problem, const Real* z) {
  constexpr int d = P::kDim;
  if constexpr (Precompiled<P>)
    return problem.pointwise().LagrangianDerivatives(z);
  else
    return autodiff::Hessian<Real, 2 * d>(
        [&](const auto* s) { return problem(s, s + d); }, z);
}

// The density f at z = (x1, v1, x2, v2) and its gradient: the full system's
// residual (full_system.h). L(x1, v1) − L(x2, v2) is differentiated as two
// evaluations in 2d variables and only Λ in all 4d: the derivatives are
// the same numbers as those of f differentiated whole (AD adds the parts'
// derivatives component by component), at a fraction of the compiled code.
template <class Real, class P>
std::pair<Real, Eigen::Matrix<Real, 4 * P::kDim, 1>> DensityGradient(
    const P& problem, const Real* z) {
  constexpr int d = P::kDim;
  if constexpr (Precompiled<P>) {
    return problem.pointwise().DensityGradient(z);
  } else {
    const auto a = LagrangianGradient<Real>(problem, z);
    const auto b = LagrangianGradient<Real>(problem, z + 2 * d);
    std::pair<Real, Eigen::Matrix<Real, 4 * d, 1>> f;
    f.first = a.first - b.first;
    f.second << a.second, -b.second;
    if constexpr (HasLambda<P>) {
      const auto lambda = autodiff::Gradient<Real, 4 * d>(
          [&](const auto* y) {
            return problem.Lambda(y, y + d, y + 2 * d, y + 3 * d);
          },
          z);
      f.first += lambda.first;
      f.second += lambda.second;
    }
    return f;
  }
}

// The same with the Hessian: the full system's Jacobian (L's part is block
// diagonal).
template <class Real, class P>
autodiff::ValueGradientHessian<Real, 4 * P::kDim> DensityDerivatives(
    const P& problem, const Real* z) {
  constexpr int d = P::kDim;
  if constexpr (Precompiled<P>) {
    return problem.pointwise().DensityDerivatives(z);
  } else {
    const auto a = LagrangianDerivatives<Real>(problem, z);
    const auto b = LagrangianDerivatives<Real>(problem, z + 2 * d);
    autodiff::ValueGradientHessian<Real, 4 * d> f;
    f.value = a.value - b.value;
    f.gradient << a.gradient, -b.gradient;
    f.hessian.setZero();
    f.hessian.template topLeftCorner<2 * d, 2 * d>() = a.hessian;
    f.hessian.template bottomRightCorner<2 * d, 2 * d>() = -b.hessian;
    if constexpr (HasLambda<P>) {
      const auto lambda = autodiff::Hessian<Real, 4 * d>(
          [&](const auto* y) {
            return problem.Lambda(y, y + d, y + 2 * d, y + 3 * d);
          },
          z);
      f.value += lambda.value;
      f.gradient += lambda.gradient;
      f.hessian += lambda.hessian;
    }
    return f;
  }
}

// The Hessian of L in (x, v) at (x, v) (see LagrangianDerivatives).
template <class Real, class P>
Eigen::Matrix<Real, 2 * P::kDim, 2 * P::kDim> LagrangianHessian(
    const P& problem, const Real* x, const Real* v) {
  constexpr int d = P::kDim;
  Real z[2 * d];
  for (int c = 0; c < d; ++c) {
    z[c] = x[c];
    z[d + c] = v[c];
  }
  return LagrangianDerivatives<Real>(problem, z).hessian;
}

// The mass matrix ∂²L/∂v∂v at (x, v).
template <class Real, class P>
Eigen::Matrix<Real, P::kDim, P::kDim> MassMatrix(const P& problem,
                                                 const Real* x, const Real* v) {
  return LagrangianHessian(problem, x, v)
      .template bottomRightCorner<P::kDim, P::kDim>();
}

// ∂²f/∂x₋∂v₊ at (x, v) on the diagonal x1 = x2: the coefficient of ẋ in a
// first-order system's equation (Λ = ẋ₊x₋ gives 1).
template <class Real, class P>
Eigen::Matrix<Real, P::kDim, P::kDim> FirstOrderCoefficient(const P& problem,
                                                            const Real* x,
                                                            const Real* v) {
  constexpr int d = P::kDim;
  if constexpr (Precompiled<P>) {
    return problem.pointwise().FirstOrderCoefficient(x, v);
  } else {
    Real p[2 * d], m[2 * d];
    for (int c = 0; c < d; ++c) {
      p[c] = x[c];
      p[d + c] = v[c];
      m[c] = m[d + c] = Real(0);
    }
    const auto mixed = autodiff::Mixed<Real, 2 * d, 2 * d>(
        [&](const auto* pv, const auto* mv) {
          return DensityPlusMinus(problem, pv, pv + d, mv, mv + d);
        },
        p, m);
    return mixed.dmp.template block<d, d>(0, d);
  }
}

// 2 for a second-order system (∂²L/∂v² ≠ 0 at the given point), 1 otherwise,
// unless the problem declares kOrder.
template <class Real, class P>
int SystemOrder(const P& problem, const Real* x, const Real* v) {
  if constexpr (Precompiled<P>) {
    if (const int k = problem.pointwise().DeclaredOrder(); k != 0) return k;
  } else if constexpr (DeclaredOrder<P>() != 0) {
    return DeclaredOrder<P>();
  }
  return MassMatrix<Real>(problem, x, v).cwiseAbs().maxCoeff() > Real(0) ? 2
                                                                         : 1;
}

}  // namespace vivp::action
