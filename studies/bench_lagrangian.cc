// The stepper templates for registered Lagrangians, compiled once per
// (d, separable) (bench_lagrangian.h).
#include "studies/bench_lagrangian.h"

#include <sstream>

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

#define VIVP_BENCH_LAGRANGIAN_INSTANCE(d, s)          \
  template BenchProblem LagrangianBenchProblem<d, s>( \
      const std::string&, ErasedHamiltonian<d, s>, double);
VIVP_BENCH_LAGRANGIAN_SHAPES(VIVP_BENCH_LAGRANGIAN_INSTANCE)
#undef VIVP_BENCH_LAGRANGIAN_INSTANCE

}  // namespace vivp::studies
