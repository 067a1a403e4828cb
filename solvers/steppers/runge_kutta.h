// Generic Runge–Kutta engine for ẏ = J∇H(y): a method is a Tableau.
// Explicit tableaus (RK4) evaluate stages in order. Implicit ones (implicit
// midpoint, Gauss–Legendre) solve the stage equations
//   Z_i = h Σ_j a_ij f(y + Z_j)                        (Hairer–Lubich–Wanner
//   VIII.6)
// by simplified Newton with the matrix I − h A⊗Df(y*), iterated to round-off:
// the iteration stops when the increment is at the round-off level of the
// state or stops shrinking there (stagnation), never on a residual threshold.
// Df is re-evaluated only when the contraction rate gets poor, so a smooth run
// pays one Jacobian per many steps; the fixed point is the same either way.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <optional>

#include "core/linalg/dense_lu.h"
#include "solvers/steppers/hamiltonian_system.h"
#include "solvers/steppers/step_result.h"
#include "solvers/steppers/tableau.h"

namespace vivp::steppers {

struct NewtonOptions {
  int max_iterations = 100;
  // Re-evaluate Df when the contraction rate of a solve exceeds this.
  double refresh_rate = 0.5;
};

template <class Problem>
class RungeKutta {
 public:
  using System = HamiltonianSystem<Problem>;
  using Vector = typename System::Vector;
  static constexpr int kN = System::kN;

  RungeKutta(const System& system, Tableau tableau, NewtonOptions options = {})
      : system_(system), tableau_(std::move(tableau)), options_(options) {}

  const std::string& name() const { return tableau_.name; }
  int order() const { return tableau_.order; }
  const System& system() const { return system_; }
  long evaluations() const { return system_.evaluations(); }

  StepReport Step(Vector& y, double h) {
    return tableau_.explicit_method() ? ExplicitStep(y, h) : ImplicitStep(y, h);
  }

 private:
  StepReport ExplicitStep(Vector& y, double h) {
    const int s = tableau_.stages();
    k_.resize(kN, s);
    for (int i = 0; i < s; ++i) {
      Vector yi = y;
      for (int j = 0; j < i; ++j)
        if (tableau_.a(i, j) != 0) yi += h * tableau_.a(i, j) * k_.col(j);
      k_.col(i) = system_.Field(yi);
    }
    y += h * (k_ * tableau_.b);
    return {};
  }

  // Df is kept across steps and step sizes (compositions change h every
  // substep); only the cheap LU of I − h A⊗Df is redone when h changes.
  void Factor(double h) {
    const int s = tableau_.stages();
    Eigen::MatrixXd m = Eigen::MatrixXd::Identity(s * kN, s * kN);
    for (int i = 0; i < s; ++i)
      for (int j = 0; j < s; ++j)
        m.block<kN, kN>(i * kN, j * kN) -= h * tableau_.a(i, j) * *df_;
    lu_.emplace(m);
    lu_h_ = h;
  }

  StepReport ImplicitStep(Vector& y, double h) {
    constexpr double kEps = std::numeric_limits<double>::epsilon();
    const int s = tableau_.stages();
    StepReport report;
    bool fresh = false;  // Df was evaluated at this y
    if (!df_ || refresh_) {
      df_ = system_.FieldJacobian(y);
      fresh = true;
      lu_.reset();
    }
    if (!lu_ || lu_h_ != h) Factor(h);
    refresh_ = false;
    // Start from the explicit Euler guess Z_i = c_i h f(y).
    const Vector f0 = system_.Field(y);
    Eigen::MatrixXd z(kN, s), f(kN, s);
    for (int i = 0; i < s; ++i) z.col(i) = tableau_.c[i] * h * f0;
    double previous = std::numeric_limits<double>::infinity();
    double worst_rate = 0;
    for (int it = 1;; ++it) {
      if (it > options_.max_iterations) {
        report.status = StepOutcome::kNewtonFailed;
        return report;
      }
      for (int i = 0; i < s; ++i) f.col(i) = system_.Field(y + z.col(i));
      const Eigen::MatrixXd g = z - h * f * tableau_.a.transpose();
      // solve(−g) as −solve(g): the same numbers (rounding is symmetric
      // under negation), and g is passed as a map, not copied.
      Eigen::VectorXd& dz = dz_;
      lu_->Solve(Eigen::Map<const Eigen::VectorXd>(g.data(), s * kN), dz);
      dz = -dz;
      if (!dz.allFinite()) {
        report.status = StepOutcome::kNewtonFailed;
        return report;
      }
      const double size = dz.lpNorm<Eigen::Infinity>();
      const double scale = y.template lpNorm<Eigen::Infinity>() +
                           z.lpNorm<Eigen::Infinity>() +
                           std::numeric_limits<double>::min();
      const double rate = size / previous;
      report.iterations = it;
      if (rate >= 1 && size > 1e4 * kEps * scale) {
        // Diverging, not stagnating: refresh Df at y once and start again.
        if (fresh) {
          report.status = StepOutcome::kNewtonFailed;
          return report;
        }
        df_ = system_.FieldJacobian(y);
        Factor(h);
        fresh = true;
        for (int i = 0; i < s; ++i) z.col(i) = tableau_.c[i] * h * f0;
        previous = std::numeric_limits<double>::infinity();
        continue;
      }
      if (rate < 1) {
        z += Eigen::Map<const Eigen::MatrixXd>(dz.data(), kN, s);
        if (it > 1) worst_rate = std::max(worst_rate, rate);
        // Slow contraction with a Df from an earlier step: refresh it now and
        // continue from the current iterate.
        if (!fresh && it > 1 && rate > options_.refresh_rate &&
            size > 4 * kEps * scale) {
          df_ = system_.FieldJacobian(y);
          Factor(h);
          fresh = true;
          previous = std::numeric_limits<double>::infinity();
          continue;
        }
      }
      // Round-off reached: the increment no longer changes the state, or it
      // stagnated at the round-off level.
      if (size <= 4 * kEps * scale || rate >= 1) break;
      previous = size;
    }
    if (worst_rate > options_.refresh_rate) refresh_ = true;
    for (int i = 0; i < s; ++i) f.col(i) = system_.Field(y + z.col(i));
    y += h * (f * tableau_.b);
    return report;
  }

  System system_;
  Tableau tableau_;
  NewtonOptions options_;
  Eigen::MatrixXd k_;
  std::optional<typename System::Matrix> df_;
  std::optional<linalg::DenseLu> lu_;
  Eigen::VectorXd dz_;  // the Newton correction, reused across iterations
  double lu_h_ = 0;
  bool refresh_ = false;
};

}  // namespace vivp::steppers
