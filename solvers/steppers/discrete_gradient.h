// The discrete-gradient method of LeMesurier 2012, §5.2 (docs/steppers.md §3),
// for a Hamiltonian written through quadratic invariants, H(y) = Ĥ(ŷ(y)),
// ŷ_k(y) = ½yᵀA_k y + b_kᵀy + c_k:
//   (y⁺ − y)/h = J D̃_ŷĤ(ŷ, ŷ⁺) · D̃_y ŷ(y, y⁺)                        (90)
// D̃_y ŷ is the exact gradient of ŷ at the midpoint ȳ = (y + y⁺)/2 (exact for
// quadratics: ŷ(y⁺) − ŷ(y) = ∇ŷ(ȳ)·(y⁺ − y)). D̃_ŷĤ is the symmetric
// (Gonzalez) discrete gradient in ŷ-space,
//   g = ∇Ĥ(m) + [Ĥ(ŷ⁺) − Ĥ(ŷ) − ∇Ĥ(m)·Δ] Δ/|Δ|²,  m = (ŷ + ŷ⁺)/2, Δ = ŷ⁺ − ŷ,
// which for Ĥ quadratic in ŷ (the NLDNLS) is the time-symmetric product rule
// of (90) (the bracket vanishes) and for other Ĥ (Kepler, pendulum) still
// gives ΔH = g·Δŷ, so H is conserved exactly. Every quadratic invariant that
// all the ŷ_k share is conserved too (91).
//
// Solution by the linearly implicit iteration (92): freeze g at the previous
// iterate, then y^{(k+1)} solves the LINEAR system
//   (I − (h/2) J M) y^{(k+1)} = (I + (h/2) J M) y + h J v,  M = Σ g_k A_k, v =
//   Σ g_k b_k,
// a Cayley map, so every iterate keeps the quadratic invariants; energy holds
// in the limit. Iterated to round-off (increment at round-off or stagnating).
//
// The problem supplies kInvariantCount, QuadraticInvariants(q, p, ŷ) and
// HamiltonianOfInvariants(ŷ), templated on the scalar. A_k, b_k are read off
// once by automatic differentiation (∇ŷ at 0 and at the unit vectors).
#pragma once

#include <ceres/jet.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <vector>

#include "solvers/steppers/hamiltonian_system.h"
#include "solvers/steppers/step_result.h"

namespace vivp::steppers {

template <class Problem>
class DiscreteGradient {
 public:
  using System = HamiltonianSystem<Problem>;
  using Vector = typename System::Vector;
  using Matrix = typename System::Matrix;
  static constexpr int kN = System::kN;
  static constexpr int kDim = System::kDim;
  static constexpr int kK = Problem::kInvariantCount;
  using Invariants = Eigen::Matrix<double, kK, 1>;

  explicit DiscreteGradient(const System& system, int max_iterations = 100)
      : system_(system), max_iterations_(max_iterations) {
    // Row k of ∇ŷ at y is (A_k y + b_k)ᵀ.
    const auto jac0 = InvariantJacobian(Vector::Zero());
    b_ = jac0;
    for (int j = 0; j < kN; ++j) {
      const auto jac = InvariantJacobian(Vector::Unit(j));
      for (int k = 0; k < kK; ++k)
        for (int i = 0; i < kN; ++i) {
          const double a = jac(k, i) - jac0(k, i);
          if (a != 0) entries_.push_back({k, i, j, a});
        }
    }
  }

  std::string name() const { return "discrete_gradient"; }
  int order() const { return 2; }
  const System& system() const { return system_; }
  long evaluations() const { return evaluations_ + system_.evaluations(); }

  StepReport Step(Vector& y, double h) {
    constexpr double kEps = std::numeric_limits<double>::epsilon();
    StepReport report;
    const Invariants yhat = InvariantValues(y);
    const double h0 = Hhat(yhat);
    Vector next = y + h * system_.Field(y);  // explicit Euler predictor
    double previous = std::numeric_limits<double>::infinity();
    for (int it = 1; it <= max_iterations_; ++it) {
      const Eigen::Matrix<double, kK, 1> g =
          HatGradient(yhat, h0, InvariantValues(next));
      Matrix m = Matrix::Zero();
      for (const auto& e : entries_) m(e.i, e.j) += g[e.k] * e.a;
      const Vector v = b_.transpose() * g;
      Matrix jm;
      jm.template topRows<kDim>() = m.template bottomRows<kDim>();
      jm.template bottomRows<kDim>() = -m.template topRows<kDim>();
      const Matrix lhs = Matrix::Identity() - 0.5 * h * jm;
      const Vector rhs = y + 0.5 * h * (jm * y) + h * System::ApplyJ(v);
      const Vector candidate = lhs.partialPivLu().solve(rhs);
      if (!candidate.allFinite()) {
        report.status = StepOutcome::kNewtonFailed;
        return report;
      }
      const double size = (candidate - next).template lpNorm<Eigen::Infinity>();
      const double scale = y.template lpNorm<Eigen::Infinity>() +
                           std::numeric_limits<double>::min();
      report.iterations = it;
      if (size >= previous) {
        if (size > 1e4 * kEps * scale) {
          report.status = StepOutcome::kNewtonFailed;
          return report;
        }
        break;  // stagnated at round-off: keep the better iterate
      }
      next = candidate;
      if (size <= 4 * kEps * scale) break;
      previous = size;
    }
    if (report.iterations >= max_iterations_) {
      report.status = StepOutcome::kNewtonFailed;
      return report;
    }
    y = next;
    return report;
  }

 private:
  struct Entry {
    int k, i, j;
    double a;
  };

  Eigen::Matrix<double, kK, kN> InvariantJacobian(const Vector& y) const {
    using Jet = ceres::Jet<double, kN>;
    Jet x[kN], out[kK];
    for (int i = 0; i < kN; ++i) x[i] = Jet(y[i], i);
    system_.problem().QuadraticInvariants(x, x + kDim, out);
    Eigen::Matrix<double, kK, kN> jac;
    for (int k = 0; k < kK; ++k) jac.row(k) = out[k].v.transpose();
    return jac;
  }

  Invariants InvariantValues(const Vector& y) const {
    Invariants out;
    system_.problem().QuadraticInvariants(y.data(), y.data() + kDim,
                                          out.data());
    return out;
  }

  double Hhat(const Invariants& yhat) const {
    return system_.problem().HamiltonianOfInvariants(yhat.data());
  }

  Invariants HatGradientAt(const Invariants& yhat) const {
    ++evaluations_;
    using Jet = ceres::Jet<double, kK>;
    Jet x[kK];
    for (int k = 0; k < kK; ++k) x[k] = Jet(yhat[k], k);
    return system_.problem().HamiltonianOfInvariants(x).v;
  }

  // Gonzalez discrete gradient of Ĥ between ŷ and ŷ⁺. The bracket is the
  // midpoint-rule error of ΔĤ; below the round-off of the terms that form it
  // it is noise, and dividing it by |Δ|² would amplify that noise.
  //
  // A problem may say that Ĥ does not depend on some ŷ_k (InvariantActive):
  // the correction then stays off those, which keeps ΔĤ = g·Δŷ and leaves
  // symmetries that the inactive invariants would break (composed
  // Hamiltonians with radial potentials keep ℓ = q × p).
  Invariants HatGradient(const Invariants& yhat, double h0,
                         const Invariants& yplus) const {
    constexpr double kEps = std::numeric_limits<double>::epsilon();
    Invariants delta = yplus - yhat;
    if constexpr (requires { system_.problem().InvariantActive(0); })
      for (int k = 0; k < kK; ++k)
        if (!system_.problem().InvariantActive(k)) delta[k] = 0;
    const Invariants g = HatGradientAt(0.5 * (yhat + yplus));
    const double h1 = Hhat(yplus);
    const double defect = h1 - h0 - g.dot(delta);
    const double noise =
        64 * kEps *
        (std::fabs(h0) + std::fabs(h1) + g.cwiseAbs().dot(delta.cwiseAbs()));
    const double d2 = delta.squaredNorm();
    if (std::fabs(defect) <= noise || d2 == 0) return g;
    return g + (defect / d2) * delta;
  }

  System system_;
  int max_iterations_;
  Eigen::Matrix<double, kK, kN> b_;
  std::vector<Entry> entries_;
  mutable long evaluations_ = 0;
};

}  // namespace vivp::steppers
