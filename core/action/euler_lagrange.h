// The equation of motion a problem's action implies, evaluated pointwise by
// automatic differentiation of the same density the solver uses. The
// variational solver never needs it; it serves reference solutions and
// checks (a scene's `reference = "ode"`, conserved quantities).
//
// With (g_x, g_v) = ∂f/∂(x₋, v₋) at x₋ = 0 and G = ∂(g_x, g_v)/∂(x₊, v₊)
// (DiagonalDerivatives), the Euler–Lagrange equation ∂f/∂x₋ − d/dt ∂f/∂v₋ = 0
// of the doubled action (Galley's form, Rothkopf & Nordström 2023, eq. 34)
// reads
//   g_x − G_vx ẋ − G_vv ẍ = 0.
// Second order (G_vv = ∂²L/∂v² invertible): ẍ = G_vv⁻¹(g_x − G_vx ẋ).
// First order (L linear in v): g_x(x, ẋ) − G_vx ẋ = 0 is solved for ẋ.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

#include "core/action/density.h"
#include "core/action/precompiled_dims.h"

namespace vivp::action {

template <class P>
using StateVector = Eigen::Matrix<double, P::kDim, 1>;

// ẍ = G_vv⁻¹(g_x − G_vx ẋ) from g_x and the velocity rows [G_vx G_vv].
template <int d>
Eigen::Matrix<double, d, 1> AccelerationFrom(
    const Eigen::Matrix<double, d, 1>& gx,
    const Eigen::Matrix<double, d, 2 * d>& velocity_rows, const double* v) {
  const Eigen::Map<const Eigen::Matrix<double, d, 1>> vel(v);
  const Eigen::Matrix<double, d, 1> rhs =
      gx - velocity_rows.template leftCols<d>() * vel;
  return velocity_rows.template rightCols<d>().partialPivLu().solve(rhs);
}

// ẍ at (x, ẋ) from the diagonal derivatives g at p = (x, ẋ).
template <int d>
Eigen::Matrix<double, d, 1> AccelerationFrom(const Diagonal<double, d>& g,
                                             const double* v) {
  return AccelerationFrom<d>(
      Eigen::Matrix<double, d, 1>(g.dm.template head<d>()),
      Eigen::Matrix<double, d, 2 * d>(g.dmp.template bottomRows<d>()), v);
}

// ẍ at (x, ẋ) of a second-order problem. (A precompiled problem evaluates
// it in its model, where P is known: the predictor calls it at every step
// and uses only part of the Hessian.)
template <class P>
StateVector<P> Acceleration(const P& problem, const double* x,
                            const double* v) {
  constexpr int d = P::kDim;
  if constexpr (Precompiled<P>) {
    return problem.pointwise().Acceleration(x, v);
  } else {
    double p[2 * d];
    for (int c = 0; c < d; ++c) {
      p[c] = x[c];
      p[d + c] = v[c];
    }
    if constexpr (!DifferentiatesByTerms<P, double> && !HasLambda<P>) {
      // A Lagrangian alone: g = ∇L and G = ∇²L (density_terms.h), of which
      // the acceleration reads ∂L/∂x and the velocity rows only. The
      // predictor evaluates this at every stage of every step: with the
      // whole Hessian it was 7.7 % of a march under error control (Kepler
      // e = 0.9, SBP84, callgrind).
      const auto g = autodiff::GradientAndLastRows<double, 2 * d, d>(
          [&](const auto* z) { return problem(z, z + d); }, p);
      return AccelerationFrom<d>(
          Eigen::Matrix<double, d, 1>(g.gradient.template head<d>()), g.rows,
          v);
    } else {
      return AccelerationFrom<d>(DiagonalDerivatives<double>(problem, p), v);
    }
  }
}

// ∂L/∂x at (x, ẋ), first derivatives over x only: the force of a Lagrangian
// that declares kConstantMass (density.h).
template <class P>
StateVector<P> PositionGradient(const P& problem, const double* x,
                                const double* v) {
  constexpr int d = P::kDim;
  if constexpr (Precompiled<P>) {
    return problem.pointwise().PositionGradient(x, v);
  } else {
    using Scalar = autodiff::First<double, d>;
    using Vector = Eigen::Matrix<double, d, 1>;
    Scalar xs[d], vs[d];
    for (int c = 0; c < d; ++c) {
      xs[c] = Scalar(x[c], Vector::Unit(c));
      vs[c] = Scalar(v[c], Vector::Zero());
    }
    return problem(xs, vs).derivatives();
  }
}

// ẍ(x, ẋ) as Acceleration computes it, but for a Lagrangian that declares
// kConstantMass as M⁻¹ ∂L/∂x, with M⁻¹ formed at the first point asked and
// kept: first derivatives over x instead of the velocity rows of ∇²L and a
// d × d solve at every call (the right-hand side of a march's predictor:
// about 9 % of a uniform SBP84 march of the anharmonic oscillator, perf).
// `constant_mass` false: Acceleration at every call whatever L declares (a
// caller that has no check of the declaration along its path).
template <class P>
class Accelerator {
 public:
  static constexpr int d = P::kDim;
  explicit Accelerator(const P& problem, bool constant_mass = true)
      : problem_(problem),
        constant_mass_(constant_mass && ConstantMass(problem)) {}

  StateVector<P> operator()(const double* x, const double* v) {
    if (!constant_mass_) return Acceleration(problem_, x, v);
    if (!have_mass_) LearnMass(x, v);
    return inverse_mass_ * PositionGradient(problem_, x, v);
  }

 private:
  // M from ∇²L at (x, ẋ) (LagrangianHessian), where ∂²L/∂x∂ẋ must vanish
  // too; std::invalid_argument when the declaration visibly does not hold
  // there or M is singular.
  void LearnMass(const double* x, const double* v) {
    const auto h = LagrangianHessian(problem_, x, v);
    const Eigen::Matrix<double, d, d> mass =
        h.template bottomRightCorner<d, d>();
    if (!(h.template bottomLeftCorner<d, d>().array() == 0.0).all())
      throw std::invalid_argument(
          "the Lagrangian declares kConstantMass, but ∂²L/∂x∂ẋ ≠ 0 at its "
          "first point: it is not ½ẋᵀMẋ + c·ẋ − V(x); remove kConstantMass");
    const Eigen::FullPivLU<Eigen::Matrix<double, d, d>> lu(mass);
    if (!mass.allFinite() || lu.rank() < d)
      throw std::invalid_argument(
          "the Lagrangian declares kConstantMass, but its mass matrix "
          "∂²L/∂ẋ² is singular or not finite at its first point");
    inverse_mass_ = lu.inverse();
    have_mass_ = true;
  }

  const P& problem_;
  bool constant_mass_;
  bool have_mass_ = false;
  Eigen::Matrix<double, d, d> inverse_mass_;
};

// ẋ at x of a first-order problem: Newton on F(ẋ) = g_x − G_vx ẋ from
// `guess`, with Jacobian ∂g_x/∂v₊ − G_vx (exact when L and Λ are linear in
// the velocity, as for every first-order system of Rothkopf & Nordström
// 2023). Throws std::runtime_error when F has no zero there (the equation is
// singular).
template <class P>
StateVector<P> FirstOrderVelocity(const P& problem, const double* x,
                                  StateVector<P> guess) {
  constexpr int d = P::kDim;
  double p[2 * d];
  for (int c = 0; c < d; ++c) p[c] = x[c];
  for (int it = 0; it < 50; ++it) {
    for (int c = 0; c < d; ++c) p[d + c] = guess[c];
    const auto g = DiagonalDerivatives<double>(problem, p);
    const Eigen::Matrix<double, d, d> gvx = g.dmp.template block<d, d>(d, 0);
    const StateVector<P> f = g.dm.template head<d>() - gvx * guess;
    const Eigen::Matrix<double, d, d> jac =
        g.dmp.template block<d, d>(0, d) - gvx;
    const StateVector<P> step = jac.fullPivLu().solve(f);
    if (!step.allFinite())
      throw std::runtime_error(
          "the first-order equation g_x(x, ẋ) = 0 cannot be solved for ẋ");
    guess -= step;
    if (step.template lpNorm<Eigen::Infinity>() <=
        4e-16 * (1 + guess.template lpNorm<Eigen::Infinity>()))
      break;
  }
  return guess;
}

// The equations of motion as a first-order system: y = (x, ẋ) ↦ (ẋ, ẍ) for a
// second-order problem, y = x ↦ ẋ (the velocity part of dy zero) for a
// first-order one; y and dy hold 2d values. `velocity` is the first-order
// velocity of the last call, the Newton start of the next.
template <class P>
void EquationsOfMotion(const P& problem, int order, const double* y, double* dy,
                       StateVector<P>& velocity) {
  constexpr int d = P::kDim;
  if (order == 2) {
    const StateVector<P> a = Acceleration(problem, y, y + d);
    for (int c = 0; c < d; ++c) {
      dy[c] = y[d + c];
      dy[d + c] = a[c];
    }
  } else {
    velocity = FirstOrderVelocity(problem, y, velocity);
    for (int c = 0; c < d; ++c) {
      dy[c] = velocity[c];
      dy[d + c] = 0.0;
    }
  }
}

// The d × d solve of AccelerationFrom compiled once per dimension
// (euler_lagrange.cc), not in every file that erases a Lagrangian.
#define VIVP_EXTERN_ACCELERATION(D)                                \
  extern template Eigen::Matrix<double, D, 1> AccelerationFrom<D>( \
      const Eigen::Matrix<double, D, 1>&,                          \
      const Eigen::Matrix<double, D, 2 * D>&, const double*);      \
  extern template Eigen::Matrix<double, D, 1> AccelerationFrom<D>( \
      const Diagonal<double, D>&, const double*);
VIVP_PRECOMPILED_DIMS(VIVP_EXTERN_ACCELERATION)
#undef VIVP_EXTERN_ACCELERATION

}  // namespace vivp::action
