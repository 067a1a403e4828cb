// What accuracy costs in time: one configuration (method, steps or tolerance)
// run on one problem, measured. A row holds the final-time error against the
// problem's reference, the maximum energy error and the maximum error of the
// problem's other invariants over the run, the wall time (median of repeats,
// at least 5), function evaluations and implicit iterations. No printing:
// the bench program, the CLI and the figures format rows.
//
// Methods are the stepper family (methods.h), the Boost.Odeint peers
// (odeint_rk4, odeint_velocity_verlet, odeint_mclachlan and the adaptive
// odeint_dopri5, whose knob is a tolerance), and any ExternalMethod
// registered by name: the hook by which the variational solver (SBP21/42/63/
// 84) joins the same table. An external method gets the problem name, the
// initial state (q, p), t_end and the step count and returns the states at
// the step times and its counts.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/phase_space.h"
#include "solvers/steppers/integrate.h"
#include "solvers/steppers/methods.h"
#include "solvers/steppers/odeint_peers.h"
#include "studies/work_point.h"

namespace vivp::studies {

template <class Problem>
std::vector<std::string> WorkPrecisionMethods() {
  std::vector<std::string> out = steppers::MethodsFor<Problem>();
  for (const auto& p : PeerNames())
    if (Problem::kSeparable || p == "odeint_rk4" || p == "odeint_dopri5")
      out.push_back(p);
  for (const auto& [name, fn] : ExternalMethods()) out.push_back(name);
  return out;
}

template <class Problem>
steppers::AnyStepper<Problem> MakeAnyStepper(
    const std::string& name,
    const steppers::HamiltonianSystem<Problem>& system) {
  if (name == "odeint_rk4")
    return steppers::AnyStepper<Problem>(
        steppers::odeint_peers::Rk4<Problem>(system));
  if constexpr (Problem::kSeparable) {
    if (name == "odeint_velocity_verlet")
      return steppers::AnyStepper<Problem>(
          steppers::odeint_peers::VelocityVerlet<Problem>(system));
    if (name == "odeint_mclachlan")
      return steppers::AnyStepper<Problem>(
          steppers::odeint_peers::McLachlan<Problem>(system));
  }
  try {
    return MakeStepper<Problem>(name, system);
  } catch (const std::invalid_argument&) {
    std::string valid;
    for (const auto& n : WorkPrecisionMethods<Problem>()) {
      valid += valid.empty() ? "" : ", ";
      valid += n;
    }
    throw std::invalid_argument("unknown or inapplicable method '" + name +
                                "'; valid for this problem: " + valid);
  }
}

// Measures one configuration. `reference` is the state at t_end; `knob` is
// the step count (fixed-step) or the tolerance (adaptive).
template <class Problem>
WorkPoint Measure(const std::string& problem_name, const Problem& problem,
                  const std::string& method, const std::vector<double>& y0,
                  const std::vector<double>& reference, double t_end,
                  double knob, int repeats = 5) {
  using System = steppers::HamiltonianSystem<Problem>;
  using Vector = typename System::Vector;
  if (repeats < 5)
    throw std::invalid_argument("repeats must be at least 5, got " +
                                std::to_string(repeats));
  const System system(problem);
  const Vector start = Vector::Map(y0.data());
  const double e0 = system.Energy(start);
  const double e_scale = e0 != 0 ? std::fabs(e0) : 1.0;
  const auto i0 = problems::InvariantValues(problem, start.data(),
                                            start.data() + System::kDim);
  WorkPoint w;
  w.method = method;
  double energy = 0, invariant = 0;
  auto observe = [&](const Vector& y) {
    energy = std::max(energy, std::fabs(system.Energy(y) - e0));
    const auto i =
        problems::InvariantValues(problem, y.data(), y.data() + System::kDim);
    for (std::size_t k = 0; k < i.size(); ++k)
      invariant = std::max(invariant, std::fabs(i[k] - i0[k]));
  };
  Vector y = start;
  std::function<void(bool)> run;  // one run; observe or not
  if (ExternalMethods().count(method)) {
    const bool adaptive = IsAdaptive(method);
    if (adaptive) {
      w.tolerance = knob;
    } else {
      w.steps = static_cast<long>(knob);
      w.h = t_end / w.steps;
    }
    // `adaptive` by value: the run is called after this block ends.
    run = [&, adaptive](bool with_observer) {
      const ExternalRun r = ExternalMethods().at(method)(
          problem_name, y0, t_end, knob, with_observer);
      w.evaluations = r.evaluations;
      w.iterations = r.iterations;
      w.status = r.status;
      if (adaptive) w.steps = r.steps;
      if (r.states.empty()) return;
      y = Vector::Map(r.states.back().data());
      if (with_observer)
        for (const auto& s : r.states) observe(Vector::Map(s.data()));
    };
  } else if (IsAdaptive(method)) {
    w.tolerance = knob;
    run = [&](bool with_observer) {
      y = start;
      System counted(problem);
      const steppers::RunReport r =
          steppers::odeint_peers::Dopri5(counted, y, t_end, knob);
      w.steps = r.steps;
      w.evaluations = r.evaluations;
      w.status = ToString(r.status);
      if (with_observer) observe(y);  // endpoint only: no dense output
    };
  } else {
    w.steps = static_cast<long>(knob);
    w.h = t_end / w.steps;
    steppers::CheckRunArguments(w.h, w.steps);
    run = [&](bool with_observer) {
      auto stepper = MakeAnyStepper<Problem>(method, system);
      y = start;
      const steppers::RunReport r =
          with_observer
              ? Integrate(stepper, y, w.h, w.steps,
                          [&](double, const Vector& x) { observe(x); })
              : Integrate(stepper, y, w.h, w.steps);
      w.evaluations = r.evaluations;
      w.iterations = r.iterations;
      w.iterations_per_step = r.iterations_per_step();
      w.status = ToString(r.status);
    };
  }
  run(true);
  w.energy_error = energy / e_scale;
  w.invariant_error = i0.empty() ? NAN : invariant;
  w.error = 0;
  for (int i = 0; i < y.size(); ++i)
    w.error = std::max(w.error, std::fabs(y[i] - reference[i]));
  if (w.status != "ok") w.error = NAN;
  // Timing without the observer, so invariants are not charged to a method.
  std::vector<double> t;
  for (int r = 0; r < repeats; ++r) {
    const auto begin = std::chrono::steady_clock::now();
    run(false);
    t.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin)
            .count());
  }
  std::nth_element(t.begin(), t.begin() + repeats / 2, t.end());
  w.seconds = t[repeats / 2];
  return w;
}

}  // namespace vivp::studies
