// A bench problem (bench_problems.h) from a Hamiltonian problem type: its
// methods, invariants and the measurement of one configuration, the
// reference computed on first use and kept. Instantiates the stepper
// templates for the type: include it only where a problem type is made into
// a bench problem once (bench_problems.cc, bench_lagrangian.cc).
#pragma once

#include <functional>
#include <memory>
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

}  // namespace vivp::studies::detail
