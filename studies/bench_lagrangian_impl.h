// The definition of LagrangianBenchProblem (bench_lagrangian.h), included
// only by the translation units generated from bench_lagrangian_dim.cc.in:
// one per d, so that the stepper templates for the three sizes compile in
// parallel.
#pragma once

#include <sstream>

#include "studies/bench_lagrangian.h"
#include "studies/bench_problem_of.h"
#include "studies/registry.h"

namespace vivp::studies {

template <int d, bool Separable>
BenchProblem LagrangianBenchProblem(const std::string& name,
                                    ErasedHamiltonian<d, Separable> h,
                                    double t_end) {
  const NamedProblem& p = FindProblem(name);
  std::ostringstream description;
  description << p.description << ", t = " << t_end;
  // (x, p) at t_end from the closed form or the reference integration.
  auto reference = [name, t_end] {
    const ExactState s = FindProblem(name).exact(t_end);
    std::vector<double> y = s.x;
    y.insert(y.end(), s.p.begin(), s.p.end());
    return y;
  };
  return detail::MakeBenchProblem(name, description.str(), std::move(h), t_end,
                                  64, p.reference, reference);
}

}  // namespace vivp::studies
