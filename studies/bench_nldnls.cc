// The NLDNLS chain of the work–precision comparison (bench_problems.h): 32
// sites, so state vectors and matrices of fixed size 64.
#include "problems/nldnls.h"
#include "studies/bench_problem_of.h"
#include "studies/bench_problems.h"

namespace vivp::studies {

BenchProblem NldnlsBenchProblem() {
  return detail::MakeBenchProblem(
      "nldnls",
      "NLDNLS eq. (6), 32 periodic sites, κ = 1, 2A sech(A n), A = 0.5, t = "
      "10",
      problems::Nldnls{}, 10.0, 50, "Gauss–Legendre s = 3, h = 0.001",
      [] { return detail::GaussReference(problems::Nldnls{}, 10.0, 10000); });
}

}  // namespace vivp::studies
