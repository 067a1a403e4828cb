// A registered Lagrangian as a bench problem (bench_problems.h): the
// steppers on its Legendre form (legendre.h), the variational solver on the
// Lagrangian itself, measured against the registry's closed form or
// reference at t_end. The stepper templates are compiled once per
// (d, separable) in bench_lagrangian.cc for d = 1, 2, 3.
#pragma once

#include <string>

#include "studies/bench_problems.h"
#include "studies/erased_hamiltonian.h"

namespace vivp::steppers {

// The largest number of coordinates the bench is compiled for.
inline constexpr int kMaxBenchDim = 3;

// `name` must be in the registry (studies/registry.h).
template <int d, bool Separable>
BenchProblem LagrangianBenchProblem(const std::string& name,
                                    ErasedHamiltonian<d, Separable> h,
                                    double t_end);

#define VIVP_BENCH_LAGRANGIAN(d, s)                          \
  extern template BenchProblem LagrangianBenchProblem<d, s>( \
      const std::string&, ErasedHamiltonian<d, s>, double);
VIVP_BENCH_LAGRANGIAN(1, true)
VIVP_BENCH_LAGRANGIAN(1, false)
VIVP_BENCH_LAGRANGIAN(2, true)
VIVP_BENCH_LAGRANGIAN(2, false)
VIVP_BENCH_LAGRANGIAN(3, true)
VIVP_BENCH_LAGRANGIAN(3, false)
#undef VIVP_BENCH_LAGRANGIAN

}  // namespace vivp::steppers
