// Störmer–Verlet for separable H = T(p) + V(q) (Hairer–Lubich–Wanner I.1.4,
// the "kick-drift-kick" form): explicit, symplectic, symmetric, order 2.
//   p½ = p − (h/2)∂H/∂q(q),  q⁺ = q + h ∂H/∂p(p½),  p⁺ = p½ − (h/2)∂H/∂q(q⁺).
// For a non-separable H this would be implicit; the problem must declare
// kSeparable = true (checked at compile time).
#pragma once

#include "solvers/steppers/hamiltonian_system.h"
#include "solvers/steppers/step_result.h"

namespace vivp::steppers {

template <class Problem>
class StormerVerlet {
 public:
  static_assert(Problem::kSeparable,
                "Störmer–Verlet here is the explicit form for separable H");
  using System = HamiltonianSystem<Problem>;
  using Vector = typename System::Vector;
  static constexpr int kDim = System::kDim;

  explicit StormerVerlet(const System& system) : system_(system) {}

  std::string name() const { return "verlet"; }
  int order() const { return 2; }
  const System& system() const { return system_; }
  long evaluations() const { return system_.evaluations(); }

  // One ∇H evaluation per step: the force at q⁺ is kept for the next kick
  // (FSAL) as long as the caller hands back the same state.
  StepReport Step(Vector& y, double h) {
    if (!(have_force_ && y == last_)) force_ = QGradient(y);
    y.template tail<kDim>() -= 0.5 * h * force_;
    const Vector g = system_.Gradient(y);
    y.template head<kDim>() += h * g.template tail<kDim>();
    force_ = QGradient(y);
    y.template tail<kDim>() -= 0.5 * h * force_;
    last_ = y;
    have_force_ = true;
    return {};
  }

 private:
  Eigen::Matrix<double, kDim, 1> QGradient(const Vector& y) const {
    return system_.Gradient(y).template head<kDim>();
  }

  System system_;
  Eigen::Matrix<double, kDim, 1> force_ =
      Eigen::Matrix<double, kDim, 1>::Zero();
  Vector last_ = Vector::Zero();
  bool have_force_ = false;
};

}  // namespace vivp::steppers
