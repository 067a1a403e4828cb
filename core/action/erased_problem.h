// A Lagrangian behind a fixed set of pointwise derivatives, so that the
// solvers compile once per dimension d instead of once per Lagrangian.
//
// Everything the solvers, marches, predictors and references need from a
// problem is a derivative of L or of the doubled density f at one point
// (density.h): the residual's ∂f/∂x₋ at x₋ = 0, its Jacobian's mixed block,
// the full density's gradient and Hessian, ∇L and ∇²L for momenta, masses
// and the corrected end state. PointwiseModel<d> is that list as virtual
// functions; ModelOf<P> implements it with automatic differentiation of P,
// in whichever translation unit names P; ErasedProblem<d> carries a model
// and satisfies Precompiled, so density.h's functions ask the model
// instead of differentiating.
//
// The arithmetic is the same: each virtual calls the density.h function it
// stands for on P. What changes is that the solve loop calls through a
// pointer once per node instead of inlining L — a few nanoseconds against the
// nested-Jet Hessian it calls.
//
//   const auto erased = vivp::action::Erase(vivp::problems::Anharmonic{});
//   vivp::variational::Solve(erased, initial, grid);  // compiled for d = 1
#pragma once

#include <Eigen/Core>
#include <memory>
#include <utility>

#include "core/action/density.h"
#include "core/action/euler_lagrange.h"
#include "core/action/gradient_sweep.h"
// VIVP_PRECOMPILED_DIMS(X): the dimensions for which the solvers, marches
// and scene runners are compiled into the libraries (explicit
// instantiations; extern templates in their headers). A problem of another
// dimension compiles them where it is solved. Written by CMake from VIVP_DIMS.
#include "core/action/precompiled_dims.h"

namespace vivp::action {

// True when the solvers for d coordinates are compiled into the libraries.
constexpr bool IsPrecompiledDim(int d) {
#define VIVP_IS_DIM(D) d == D ||
  return VIVP_PRECOMPILED_DIMS(VIVP_IS_DIM) false;
#undef VIVP_IS_DIM
}

template <int d>
class PointwiseModel {
 public:
  using Vector2 = Eigen::Matrix<double, 2 * d, 1>;
  using Vector4 = Eigen::Matrix<double, 4 * d, 1>;
  using Matrix = Eigen::Matrix<double, d, d>;

  virtual ~PointwiseModel() = default;

  // L(x, v).
  virtual double Value(const double* x, const double* v) const = 0;
  // P::kOrder, or 0 when P does not declare it.
  virtual int DeclaredOrder() const = 0;
  // The functions of density.h of the same names, at z = (x, v), at the
  // ± point p = (x₊, v₊), or at z = (x1, v1, x2, v2).
  virtual std::pair<double, Vector2> LagrangianGradient(
      const double* z) const = 0;
  virtual autodiff::ValueGradientHessian<double, 2 * d> LagrangianDerivatives(
      const double* z) const = 0;
  virtual Diagonal<double, d> DiagonalDerivatives(const double* p) const = 0;
  virtual DiagonalVector<double, d> DiagonalGradient(const double* p) const = 0;
  // The residual evaluated again in extended precision (ivp_types.h).
  virtual DiagonalVector<long double, d> DiagonalGradient(
      const long double* p) const = 0;
  // The residual's sweep over the nodes (gradient_sweep.h) and the
  // Jacobian's derivatives at n points (density.h: DiagonalDerivativesAt):
  // one call per sweep or block, not per node.
  virtual void SweepDiagonalGradient(
      const GradientSweep<double, d>& s) const = 0;
  virtual void SweepDiagonalGradient(
      const GradientSweep<long double, d>& s) const = 0;
  virtual void DiagonalDerivativesAt(const double* p, int n,
                                     Diagonal<double, d>* out) const = 0;
  virtual std::pair<double, Vector4> DensityGradient(const double* z) const = 0;
  virtual autodiff::ValueGradientHessian<double, 4 * d> DensityDerivatives(
      const double* z) const = 0;
  virtual Matrix FirstOrderCoefficient(const double* x,
                                       const double* v) const = 0;
  // ẍ(x, ẋ) of a second-order problem (euler_lagrange.h).
  virtual Eigen::Matrix<double, d, 1> Acceleration(const double* x,
                                                   const double* v) const = 0;
  // Whether L declares kConstantMass (density.h), and ∂L/∂x alone.
  virtual bool ConstantMass() const = 0;
  virtual Eigen::Matrix<double, d, 1> PositionGradient(
      const double* x, const double* v) const = 0;
};

// The model of one problem type: each function differentiates P as
// density.h does.
template <LagrangianProblem P>
class ModelOf final : public PointwiseModel<P::kDim> {
  static constexpr int d = P::kDim;
  using Base = PointwiseModel<d>;

 public:
  explicit ModelOf(P problem) : problem_(std::move(problem)) {}

  double Value(const double* x, const double* v) const override {
    return problem_(x, v);
  }
  int DeclaredOrder() const override { return action::DeclaredOrder<P>(); }
  std::pair<double, typename Base::Vector2> LagrangianGradient(
      const double* z) const override {
    return action::LagrangianGradient<double>(problem_, z);
  }
  autodiff::ValueGradientHessian<double, 2 * d> LagrangianDerivatives(
      const double* z) const override {
    return action::LagrangianDerivatives<double>(problem_, z);
  }
  Diagonal<double, d> DiagonalDerivatives(const double* p) const override {
    return action::DiagonalDerivatives<double>(problem_, p);
  }
  DiagonalVector<double, d> DiagonalGradient(const double* p) const override {
    return action::DiagonalGradient<double>(problem_, p);
  }
  DiagonalVector<long double, d> DiagonalGradient(
      const long double* p) const override {
    return action::DiagonalGradient<long double>(problem_, p);
  }
  void SweepDiagonalGradient(const GradientSweep<double, d>& s) const override {
    action::SweepDiagonalGradient<double>(problem_, s);
  }
  void SweepDiagonalGradient(
      const GradientSweep<long double, d>& s) const override {
    action::SweepDiagonalGradient<long double>(problem_, s);
  }
  void DiagonalDerivativesAt(const double* p, int n,
                             Diagonal<double, d>* out) const override {
    action::DiagonalDerivativesAt<double>(problem_, p, n, out);
  }
  std::pair<double, typename Base::Vector4> DensityGradient(
      const double* z) const override {
    return action::DensityGradient<double>(problem_, z);
  }
  autodiff::ValueGradientHessian<double, 4 * d> DensityDerivatives(
      const double* z) const override {
    return action::DensityDerivatives<double>(problem_, z);
  }
  typename Base::Matrix FirstOrderCoefficient(const double* x,
                                              const double* v) const override {
    return action::FirstOrderCoefficient<double>(problem_, x, v);
  }
  Eigen::Matrix<double, d, 1> Acceleration(const double* x,
                                           const double* v) const override {
    return action::Acceleration(problem_, x, v);
  }
  bool ConstantMass() const override { return action::ConstantMass(problem_); }
  Eigen::Matrix<double, d, 1> PositionGradient(const double* x,
                                               const double* v) const override {
    return action::PositionGradient(problem_, x, v);
  }

  const P& problem() const { return problem_; }

 private:
  P problem_;
};

// A problem of d coordinates known only through its model. Copies share the
// model (it is immutable).
template <int d>
class ErasedProblem {
 public:
  static constexpr int kDim = d;

  explicit ErasedProblem(std::shared_ptr<const PointwiseModel<d>> model)
      : model_(std::move(model)) {}

  double operator()(const double* x, const double* v) const {
    return model_->Value(x, v);
  }
  const PointwiseModel<d>& pointwise() const { return *model_; }
  const std::shared_ptr<const PointwiseModel<d>>& model() const {
    return model_;
  }

 private:
  std::shared_ptr<const PointwiseModel<d>> model_;
};

// L = L_a + L_b (and Λ = Λ_a + Λ_b): every quantity of the model is linear
// in the density, so the sum's derivatives are the sums of the parts'. A
// scene's registered Lagrangian plus its built-in effects is such a sum; the
// parts are each compiled once. Neither part's kOrder is carried over: the
// sum's order is read off its mass matrix.
template <int d>
class SumModel final : public PointwiseModel<d> {
  using Base = PointwiseModel<d>;

 public:
  SumModel(std::shared_ptr<const Base> a, std::shared_ptr<const Base> b)
      : a_(std::move(a)), b_(std::move(b)) {}

  double Value(const double* x, const double* v) const override {
    return a_->Value(x, v) + b_->Value(x, v);
  }
  int DeclaredOrder() const override { return 0; }
  std::pair<double, typename Base::Vector2> LagrangianGradient(
      const double* z) const override {
    return Add(a_->LagrangianGradient(z), b_->LagrangianGradient(z));
  }
  autodiff::ValueGradientHessian<double, 2 * d> LagrangianDerivatives(
      const double* z) const override {
    return Add(a_->LagrangianDerivatives(z), b_->LagrangianDerivatives(z));
  }
  Diagonal<double, d> DiagonalDerivatives(const double* p) const override {
    const auto a = a_->DiagonalDerivatives(p), b = b_->DiagonalDerivatives(p);
    return {a.dm + b.dm, a.dmp + b.dmp};
  }
  DiagonalVector<double, d> DiagonalGradient(const double* p) const override {
    return a_->DiagonalGradient(p) + b_->DiagonalGradient(p);
  }
  DiagonalVector<long double, d> DiagonalGradient(
      const long double* p) const override {
    return a_->DiagonalGradient(p) + b_->DiagonalGradient(p);
  }
  // The sweeps as the single-point sums, point by point (the sum is not
  // on the fast path: a scene's registered L with built-in effects).
  void SweepDiagonalGradient(const GradientSweep<double, d>& s) const override {
    SweepPoints(s, [&](const double* q) { return DiagonalGradient(q); });
  }
  void SweepDiagonalGradient(
      const GradientSweep<long double, d>& s) const override {
    SweepPoints(s, [&](const long double* q) { return DiagonalGradient(q); });
  }
  void DiagonalDerivativesAt(const double* p, int n,
                             Diagonal<double, d>* out) const override {
    for (int k = 0; k < n; ++k) out[k] = DiagonalDerivatives(p + 2 * d * k);
  }
  std::pair<double, typename Base::Vector4> DensityGradient(
      const double* z) const override {
    return Add(a_->DensityGradient(z), b_->DensityGradient(z));
  }
  autodiff::ValueGradientHessian<double, 4 * d> DensityDerivatives(
      const double* z) const override {
    return Add(a_->DensityDerivatives(z), b_->DensityDerivatives(z));
  }
  typename Base::Matrix FirstOrderCoefficient(const double* x,
                                              const double* v) const override {
    return a_->FirstOrderCoefficient(x, v) + b_->FirstOrderCoefficient(x, v);
  }
  // Not the sum of the parts' accelerations: ẍ solves the summed equations.
  Eigen::Matrix<double, d, 1> Acceleration(const double* x,
                                           const double* v) const override {
    double p[2 * d];
    for (int c = 0; c < d; ++c) {
      p[c] = x[c];
      p[d + c] = v[c];
    }
    return AccelerationFrom<d>(DiagonalDerivatives(p), v);
  }
  // ½vᵀ(M_a + M_b)v − V_a − V_b when both parts are of that form.
  bool ConstantMass() const override {
    return a_->ConstantMass() && b_->ConstantMass();
  }
  Eigen::Matrix<double, d, 1> PositionGradient(const double* x,
                                               const double* v) const override {
    return a_->PositionGradient(x, v) + b_->PositionGradient(x, v);
  }

 private:
  template <class V>
  static std::pair<double, V> Add(const std::pair<double, V>& a,
                                  const std::pair<double, V>& b) {
    return {a.first + b.first, a.second + b.second};
  }
  template <int K>
  static autodiff::ValueGradientHessian<double, K> Add(
      const autodiff::ValueGradientHessian<double, K>& a,
      const autodiff::ValueGradientHessian<double, K>& b) {
    return {a.value + b.value, a.gradient + b.gradient, a.hessian + b.hessian};
  }

  std::shared_ptr<const Base> a_, b_;
};

template <int d>
ErasedProblem<d> operator+(const ErasedProblem<d>& a,
                           const ErasedProblem<d>& b) {
  return ErasedProblem<d>(
      std::make_shared<const SumModel<d>>(a.model(), b.model()));
}

// The erased form of `problem` (a copy of it lives in the model).
template <LagrangianProblem P>
ErasedProblem<P::kDim> Erase(P problem) {
  return ErasedProblem<P::kDim>(
      std::make_shared<const ModelOf<P>>(std::move(problem)));
}

}  // namespace vivp::action
