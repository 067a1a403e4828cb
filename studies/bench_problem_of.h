// A bench problem (bench_problems.h) from a Hamiltonian problem type: its
// methods, invariants and the measurement of one configuration, the
// reference computed on first use and kept. Instantiates the stepper
// templates for the type: include it only where a problem type is made into
// a bench problem once (bench_oscillators.cc, bench_orbits.cc,
// bench_nldnls.cc, bench_lagrangian_impl.h).
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/phase_space.h"
#include "studies/bench_problems.h"
#include "studies/work_precision.h"

namespace vivp::studies::detail {

template <class Problem>
BenchProblem MakeBenchProblem(std::string name, std::string description,
                              Problem problem, double t_end, long first_steps,
                              std::string reference,
                              std::function<std::vector<double>()> exact) {
  BenchProblem b;
  b.name = name;
  b.description = std::move(description);
  b.reference = std::move(reference);
  b.t_end = t_end;
  b.first_steps = first_steps;
  b.methods = WorkPrecisionMethods<Problem>();
  std::erase_if(b.methods, [&](const std::string& m) {
    return !ExternalMethodApplies(m, name);
  });
  b.invariant_names = problems::InvariantNames<Problem>();
  // The reference is computed on first use and kept.
  auto cache = std::make_shared<std::vector<double>>();
  b.measure = [=](const std::string& method, double knob, int repeats) {
    if (cache->empty()) *cache = exact();
    return Measure(name, problem, method, problems::InitialState(problem),
                   *cache, t_end, knob, repeats);
  };
  return b;
}

// Gauss–Legendre s = 3 with n steps: the reference for problems without a
// closed form.
template <class Problem>
std::vector<double> GaussReference(const Problem& problem, double t_end,
                                   long n) {
  using System = steppers::HamiltonianSystem<Problem>;
  const System system(problem);
  steppers::RungeKutta<Problem> stepper(system, steppers::Gauss3());
  const auto init = problems::InitialState(problem);
  typename System::Vector y = System::Vector::Map(init.data());
  const steppers::RunReport r = Integrate(stepper, y, t_end / n, n);
  if (r.status != steppers::StepOutcome::kOk)
    throw std::runtime_error("reference run failed: " + ToString(r.status));
  return std::vector<double>(y.data(), y.data() + y.size());
}

}  // namespace vivp::studies::detail
