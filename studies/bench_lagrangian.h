// A registered Lagrangian as a bench problem (bench_problems.h): the
// steppers on its Legendre form (legendre.h), the variational solver on the
// Lagrangian itself, measured against the registry's closed form or
// reference at t_end. The stepper templates are compiled once per
// (d, separable) for d = 1, 2, 3 (bench_lagrangian_impl.h).
#pragma once

#include <string>

#include "studies/bench_problems.h"
#include "studies/erased_hamiltonian.h"

namespace vivp::studies {

// The largest number of coordinates the bench is compiled for.
inline constexpr int kMaxBenchDim = 3;

// `name` must be in the registry (studies/registry.h).
template <int d, bool Separable>
BenchProblem LagrangianBenchProblem(const std::string& name,
                                    ErasedHamiltonian<d, Separable> h,
                                    double t_end);

// The numbers of coordinates compiled, each with both separable forms in a
// translation unit of its own (generated from bench_lagrangian_dim.cc.in by
// studies/CMakeLists.txt, whose list of d must match this one).
#define VIVP_BENCH_LAGRANGIAN_DIMS(X) X(1) X(2) X(3)

#define VIVP_BENCH_LAGRANGIAN_EXTERN(d)                          \
  extern template BenchProblem LagrangianBenchProblem<d, true>(  \
      const std::string&, ErasedHamiltonian<d, true>, double);   \
  extern template BenchProblem LagrangianBenchProblem<d, false>( \
      const std::string&, ErasedHamiltonian<d, false>, double);
VIVP_BENCH_LAGRANGIAN_DIMS(VIVP_BENCH_LAGRANGIAN_EXTERN)
#undef VIVP_BENCH_LAGRANGIAN_EXTERN

}  // namespace vivp::studies
