// The stepper family by name, for the bench harness, the CLI and tests:
//   rk4, midpoint, verlet, gauss2, gauss3, triple_jump, suzuki, triple_jump6,
//   discrete_gradient.
// Compositions use Störmer–Verlet as the symmetric base when H is separable
// and implicit midpoint otherwise. Methods that do not apply to a problem
// (Verlet for non-separable H, the discrete gradient without quadratic
// invariants) are refused with an error naming the valid ones.
//
//   auto stepper = MakeStepper<problems::Kepler>("gauss2", system);
//   Vector y = ...;  RunReport r = Integrate(stepper, y, h, n);
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "solvers/steppers/composition.h"
#include "solvers/steppers/discrete_gradient.h"
#include "solvers/steppers/runge_kutta.h"
#include "solvers/steppers/stormer_verlet.h"

namespace vivp::steppers {

template <class P>
concept HasQuadraticInvariants = requires {
  P::kInvariantCount;
};

// A stepper behind a uniform interface (type erasure), for runtime names.
template <class Problem>
class AnyStepper {
 public:
  using System = HamiltonianSystem<Problem>;
  using Vector = typename System::Vector;

  template <class S>
  explicit AnyStepper(S stepper)
      : name_(stepper.name()), order_(stepper.order()) {
    auto shared = std::make_shared<S>(std::move(stepper));
    step_ = [shared](Vector& y, double h) { return shared->Step(y, h); };
    evaluations_ = [shared] { return shared->evaluations(); };
  }

  StepReport Step(Vector& y, double h) { return step_(y, h); }
  long evaluations() const { return evaluations_(); }
  const std::string& name() const { return name_; }
  int order() const { return order_; }

 private:
  std::string name_;
  int order_;
  std::function<StepReport(Vector&, double)> step_;
  std::function<long()> evaluations_;
};

inline const std::vector<std::string>& MethodNames() {
  static const std::vector<std::string> names = {
      "rk4",         "midpoint", "verlet",       "gauss2",           "gauss3",
      "triple_jump", "suzuki",   "triple_jump6", "discrete_gradient"};
  return names;
}

template <class Problem>
std::vector<std::string> MethodsFor() {
  std::vector<std::string> out;
  for (const auto& n : MethodNames()) {
    if (n == "verlet" && !Problem::kSeparable) continue;
    if (n == "discrete_gradient" && !HasQuadraticInvariants<Problem>) continue;
    out.push_back(n);
  }
  return out;
}

template <class Problem>
AnyStepper<Problem> MakeStepper(const std::string& name,
                                const HamiltonianSystem<Problem>& system) {
  using S = AnyStepper<Problem>;
  auto composed = [&](CompositionCoefficients c) {
    if constexpr (Problem::kSeparable)
      return S(Composition(StormerVerlet<Problem>(system), std::move(c)));
    else
      return S(Composition(RungeKutta<Problem>(system, ImplicitMidpoint()),
                           std::move(c)));
  };
  if (name == "rk4") return S(RungeKutta<Problem>(system, ClassicalRk4()));
  if (name == "midpoint")
    return S(RungeKutta<Problem>(system, ImplicitMidpoint()));
  if (name == "gauss2") return S(RungeKutta<Problem>(system, Gauss2()));
  if (name == "gauss3") return S(RungeKutta<Problem>(system, Gauss3()));
  if constexpr (Problem::kSeparable)
    if (name == "verlet") return S(StormerVerlet<Problem>(system));
  if (name == "triple_jump") return composed(TripleJump4());
  if (name == "suzuki") return composed(Suzuki4());
  if (name == "triple_jump6") return composed(TripleJump6());
  if constexpr (HasQuadraticInvariants<Problem>)
    if (name == "discrete_gradient")
      return S(DiscreteGradient<Problem>(system));
  std::string valid;
  for (const auto& n : MethodsFor<Problem>()) {
    valid += valid.empty() ? "" : ", ";
    valid += n;
  }
  throw std::invalid_argument("unknown or inapplicable method '" + name +
                              "'; valid for this problem: " + valid);
}

}  // namespace vivp::steppers
