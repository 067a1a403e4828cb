// Pointwise second-order automatic differentiation of a small density.
//
// The discrete action is a sum of densities f(z_i) over time nodes, each
// depending on a handful of variables z_i (positions and velocities of the two
// paths at node i). Its gradient and Hessian therefore only ever need
// derivatives of f with respect to those K variables: this header computes
// them with nested Eigen AutoDiffScalars of fixed size K, never with a
// derivative over all unknowns.
//
// Why Eigen's AutoDiffScalar and not ceres::Jet for the nesting: a user's
// Lagrangian writes constants the way the math reads, `T(0.5) * v[0] * v[0]`
// or `0.25 * kappa * x*x*x*x`. Nested AutoDiffScalars accept both (their Real
// is the bottom floating-point type); nested Jets accept neither (Ceres 2.1
// has no implicit conversion from double into Jet<Jet<double, N>, M>).
#pragma once

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

namespace vivp::autodiff {

template <class Real, int K>
using First = Eigen::AutoDiffScalar<Eigen::Matrix<Real, K, 1>>;
template <class Real, int K, int M = K>
using Second = Eigen::AutoDiffScalar<Eigen::Matrix<First<Real, K>, M, 1>>;

template <class Real, int K>
struct ValueGradientHessian {
  Real value;
  Eigen::Matrix<Real, K, 1> gradient;
  Eigen::Matrix<Real, K, K> hessian;
};

// Value, gradient and Hessian of f at z; f is called with an array of K
// Second<Real, K> scalars.
template <class Real, int K, class F>
ValueGradientHessian<Real, K> Hessian(const F& f, const Real* z) {
  using Inner = First<Real, K>;
  using Outer = Second<Real, K>;
  using InnerVec = Eigen::Matrix<Real, K, 1>;
  Outer vars[K];
  for (int k = 0; k < K; ++k) {
    vars[k].value() = Inner(z[k], InnerVec::Unit(k));
    for (int j = 0; j < K; ++j)
      vars[k].derivatives()[j] = Inner(Real(j == k), InnerVec::Zero());
  }
  const Outer r = f(vars);
  ValueGradientHessian<Real, K> out;
  out.value = r.value().value();
  out.gradient = r.value().derivatives();
  for (int a = 0; a < K; ++a)
    out.hessian.row(a) = r.derivatives()[a].derivatives();
  return out;
}

// Value and gradient of f at z (first order only).
template <class Real, int K, class F>
std::pair<Real, Eigen::Matrix<Real, K, 1>> Gradient(const F& f, const Real* z) {
  using Scalar = First<Real, K>;
  Scalar vars[K];
  for (int k = 0; k < K; ++k)
    vars[k] = Scalar(z[k], Eigen::Matrix<Real, K, 1>::Unit(k));
  const Scalar r = f(vars);
  return {r.value(), r.derivatives()};
}

// The gradient of f at z (K values) and the last R rows of its Hessian,
// ∂²f/∂z_r∂z for r ≥ K − R: the outer derivatives run over all K variables,
// the inner ones over the last R only. The Euler–Lagrange acceleration needs
// ∂L/∂x and the velocity rows ∂²L/∂ẋ∂(x, ẋ), not ∂²L/∂x²: at K = 2R this
// carries R + 1 inner values per outer one where Hessian carries K + 1.
// Each derivative is formed by the same operations as Hessian's.
template <class Real, int K, int R>
struct GradientRows {
  Eigen::Matrix<Real, K, 1> gradient;
  Eigen::Matrix<Real, R, K> rows;
};

template <class Real, int K, int R, class F>
GradientRows<Real, K, R> GradientAndLastRows(const F& f, const Real* z) {
  static_assert(R >= 1 && R <= K);
  using Inner = First<Real, R>;
  using Outer = Eigen::AutoDiffScalar<Eigen::Matrix<Inner, K, 1>>;
  using InnerVec = Eigen::Matrix<Real, R, 1>;
  Outer vars[K];
  for (int k = 0; k < K; ++k) {
    const InnerVec seed =
        k >= K - R ? InnerVec(InnerVec::Unit(k - (K - R))) : InnerVec::Zero();
    vars[k].value() = Inner(z[k], seed);
    for (int j = 0; j < K; ++j)
      vars[k].derivatives()[j] = Inner(Real(j == k), InnerVec::Zero());
  }
  const Outer r = f(vars);
  GradientRows<Real, K, R> out;
  for (int k = 0; k < K; ++k) {
    out.gradient[k] = r.derivatives()[k].value();
    out.rows.col(k) = r.derivatives()[k].derivatives();
  }
  return out;
}

// For f(p, m) with P "plus" and M "minus" variables, at m = m0:
//   dm  = ∂f/∂m            (M)
//   dmp = ∂²f/∂m∂p         (M x P), row j = d(∂f/∂m_j)/dp
// Inner derivatives run over m, outer over p. f is called with two arrays of
// Second scalars (p first, then m).
template <class Real, int P, int M>
struct MixedDerivatives {
  Eigen::Matrix<Real, M, 1> dm;
  Eigen::Matrix<Real, M, P> dmp;
};

template <class Real, int P, int M, class F>
MixedDerivatives<Real, P, M> Mixed(const F& f, const Real* p, const Real* m) {
  using Inner = First<Real, M>;
  using Outer = Eigen::AutoDiffScalar<Eigen::Matrix<Inner, P, 1>>;
  using InnerVec = Eigen::Matrix<Real, M, 1>;
  Outer pv[P], mv[M];
  for (int k = 0; k < P; ++k) {
    pv[k].value() = Inner(p[k], InnerVec::Zero());
    for (int j = 0; j < P; ++j)
      pv[k].derivatives()[j] = Inner(Real(j == k), InnerVec::Zero());
  }
  for (int k = 0; k < M; ++k) {
    mv[k].value() = Inner(m[k], InnerVec::Unit(k));
    for (int j = 0; j < P; ++j)
      mv[k].derivatives()[j] = Inner(Real(0), InnerVec::Zero());
  }
  const Outer r = f(pv, mv);
  MixedDerivatives<Real, P, M> out;
  out.dm = r.value().derivatives();
  for (int k = 0; k < P; ++k) out.dmp.col(k) = r.derivatives()[k].derivatives();
  return out;
}

// ∂f/∂m at (p, m) for the residual alone (first order over m).
template <class Real, int P, int M, class F>
Eigen::Matrix<Real, M, 1> MinusGradient(const F& f, const Real* p,
                                        const Real* m) {
  using Scalar = First<Real, M>;
  Scalar pv[P], mv[M];
  for (int k = 0; k < P; ++k)
    pv[k] = Scalar(p[k], Eigen::Matrix<Real, M, 1>::Zero());
  for (int k = 0; k < M; ++k)
    mv[k] = Scalar(m[k], Eigen::Matrix<Real, M, 1>::Unit(k));
  return f(pv, mv).derivatives();
}

}  // namespace vivp::autodiff
