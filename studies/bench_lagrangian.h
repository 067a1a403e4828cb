// A registered Lagrangian as a bench problem (bench_problems.h): the
// steppers on its Legendre form (legendre.h), the variational solver on the
// Lagrangian itself, measured against the registry's closed form or
// reference at t_end. The stepper templates are compiled once per
// (d, separable) in bench_lagrangian.cc for d = 1, 2, 3.
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

// The (d, separable) shapes compiled, as an X-macro so that the declarations
// here and the instantiations in bench_lagrangian.cc name the same list.
#define VIVP_BENCH_LAGRANGIAN_SHAPES(X) \
  X(1, true) X(1, false) X(2, true) X(2, false) X(3, true) X(3, false)

#define VIVP_BENCH_LAGRANGIAN_EXTERN(d, s)                   \
  extern template BenchProblem LagrangianBenchProblem<d, s>( \
      const std::string&, ErasedHamiltonian<d, s>, double);
VIVP_BENCH_LAGRANGIAN_SHAPES(VIVP_BENCH_LAGRANGIAN_EXTERN)
#undef VIVP_BENCH_LAGRANGIAN_EXTERN

}  // namespace vivp::studies
