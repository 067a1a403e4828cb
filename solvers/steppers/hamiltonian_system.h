// A Hamiltonian system y = (q, p), ẏ = J∇H(y), J = [0 I; −I 0], built from a
// problem functor with `template <class T> T Hamiltonian(const T* q,
// const T* p) const` and `static constexpr int kDim`.
//
// A problem may instead supply its own derivatives (ErasedHamiltonian in
// studies/erased_hamiltonian.h does, to compile the steppers once for many
// problems): `double Value(const double* y)`, `Gradient(y)` and `Hessian(y)`
// as Eigen vectors and matrices of size 2d.
//
// The gradient comes from one forward pass with ceres::Jet<double, 2d>; the
// Newton Jacobian J∇²H from nested Eigen AutoDiffScalars, one Hessian column
// per pass (outer derivative along e_j, inner gradient), so each scalar
// carries 2(2d+1) numbers instead of (2d+1)². Warnings:
//   1. Nested ceres::Jets do not accept T(0.5) in a problem functor; the
//      nested AutoDiffScalar used here does, so problems may write T(c).
//   2. Function evaluations are counted in the system (one per ∇H), so a
//      stepper's cost is read off the system it was given.
#pragma once

#include <ceres/jet.h>

#include <Eigen/Core>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>

namespace vivp::steppers {

template <class P>
concept SuppliesDerivatives = requires(const P& p, const double* y) {
  p.Value(y);
  p.Gradient(y);
  p.Hessian(y);
};

template <class Problem>
class HamiltonianSystem {
 public:
  static constexpr int kDim = Problem::kDim;  // degrees of freedom d
  static constexpr int kN = 2 * kDim;         // state size
  using Vector = Eigen::Matrix<double, kN, 1>;
  using Matrix = Eigen::Matrix<double, kN, kN>;

  explicit HamiltonianSystem(Problem problem = {}) : problem_(problem) {}

  const Problem& problem() const { return problem_; }

  double Energy(const Vector& y) const {
    if constexpr (SuppliesDerivatives<Problem>)
      return problem_.Value(y.data());
    else
      return problem_.Hamiltonian(y.data(), y.data() + kDim);
  }

  // ∇H(y) = (∂H/∂q, ∂H/∂p).
  Vector Gradient(const Vector& y) const {
    ++evaluations_;
    if constexpr (SuppliesDerivatives<Problem>) {
      return problem_.Gradient(y.data());
    } else {
      using Jet = ceres::Jet<double, kN>;
      Jet x[kN];
      for (int i = 0; i < kN; ++i) x[i] = Jet(y[i], i);
      const Jet h = problem_.Hamiltonian(x, x + kDim);
      return h.v;
    }
  }

  // f(y) = J∇H(y): q̇ = ∂H/∂p, ṗ = −∂H/∂q.
  Vector Field(const Vector& y) const { return ApplyJ(Gradient(y)); }

  static Vector ApplyJ(const Vector& g) {
    Vector f;
    f.template head<kDim>() = g.template tail<kDim>();
    f.template tail<kDim>() = -g.template head<kDim>();
    return f;
  }

  // ∇²H(y) column by column (see the header comment).
  Matrix Hessian(const Vector& y) const {
    ++jacobians_;
    if constexpr (SuppliesDerivatives<Problem>) {
      return problem_.Hessian(y.data());
    } else {
      using Inner = Eigen::AutoDiffScalar<Eigen::Matrix<double, kN, 1>>;
      using Outer = Eigen::AutoDiffScalar<Eigen::Matrix<Inner, 1, 1>>;
      Matrix hess;
      Outer x[kN];
      for (int j = 0; j < kN; ++j) {
        for (int i = 0; i < kN; ++i) {
          Inner value(y[i], kN, i);
          Inner seed(i == j ? 1.0 : 0.0, Eigen::Matrix<double, kN, 1>::Zero());
          x[i] = Outer(value, Eigen::Matrix<Inner, 1, 1>(seed));
        }
        const Outer h = problem_.Hamiltonian(x, x + kDim);
        hess.col(j) = h.derivatives()(0).derivatives();
      }
      return hess;
    }
  }

  // Df(y) = J∇²H(y).
  Matrix FieldJacobian(const Vector& y) const {
    const Matrix hess = Hessian(y);
    Matrix df;
    df.template topRows<kDim>() = hess.template bottomRows<kDim>();
    df.template bottomRows<kDim>() = -hess.template topRows<kDim>();
    return df;
  }

  long evaluations() const { return evaluations_; }
  long jacobians() const { return jacobians_; }
  void ResetCounts() const { evaluations_ = jacobians_ = 0; }

 private:
  Problem problem_;
  mutable long evaluations_ = 0;
  mutable long jacobians_ = 0;
};

}  // namespace vivp::steppers
