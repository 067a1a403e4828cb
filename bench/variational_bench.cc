// Cost of the variational solver against Nt (docs/method.md §5):
//  1. the three paths to the critical point (reduced Newton, full Newton,
//     Ceres LM) on the anharmonic problem, Nt = 2^5 ... 2^20 (LM until it
//     stops converging): iterations, seconds, attained error at t = 1;
//  2. linear cost: reduced Newton on the damped oscillator (one iteration) and
//     the anharmonic problem (seconds per iteration), with the ratio
//     t(Nt)/t(2^16), median of 5 runs.
#include <cstdio>

#include "bench/timing.h"
#include "studies/registry.h"

using namespace vivp;
using namespace vivp::variational;

namespace {

void PathTable() {
  const vivp::studies::NamedProblem& p =
      vivp::studies::FindProblem("anharmonic");
  const double exact = p.exact(1.0).x[0];
  std::printf(
      "# anharmonic, SBP42, t in [0, 1]: the three paths (median of 3 runs)\n");
  std::printf("%-12s %9s %5s %10s %10s %10s %s\n", "path", "Nt", "it",
              "seconds", "err x_N", "|grad S|", "status");
  for (Path path : {Path::kReducedNewton, Path::kFullNewton, Path::kCeresLm}) {
    for (long long n = 32; n <= (1 << 20); n *= 2) {
      Grid g;
      g.op = "sbp42";
      g.points = n;
      SolveOptions o;
      o.path = path;
      IvpSolution<double> s;
      const int repeats = n <= (1 << 14) ? 3 : 1;
      const double t =
          bench::MedianSeconds([&] { s = p.solve(g, o); }, repeats);
      std::printf("%-12s %9lld %5d %10.4f %10.2e %10.2e %s\n", PathName(path),
                  n, s.iterations, t, std::abs(s.x1(n - 1, 0) - exact),
                  s.gradient_norm,
                  s.status.converged ? "converged" : "NOT CONVERGED");
      if (!s.status.converged || t > 20) break;  // LM stalls; stop that path
    }
  }
}

void LinearCost() {
  std::printf(
      "\n# reduced Newton, SBP42: cost against Nt (median of 5 runs)\n");
  std::printf("%-10s %9s %5s %10s %12s %14s\n", "problem", "Nt", "it",
              "seconds", "s/iteration", "t/t(2^16)");
  for (const char* name : {"damped", "anharmonic"}) {
    const vivp::studies::NamedProblem& p = vivp::studies::FindProblem(name);
    double t16 = 0;
    for (long long n = 1 << 10; n <= (1 << 20); n *= 4) {
      Grid g;
      g.op = "sbp42";
      g.points = n;
      g.t_end = 1.0;
      IvpSolution<double> s;
      const double t = bench::MedianSeconds([&] { s = p.solve(g, {}); }, 5);
      if (n == (1 << 16)) t16 = t;
      std::printf("%-10s %9lld %5d %10.4f %12.4f %14s\n", name, n, s.iterations,
                  t, t / s.iterations,
                  t16 > 0 ? std::to_string(t / t16).substr(0, 6).c_str() : "-");
    }
  }
}

}  // namespace

int main() {
  LinearCost();
  PathTable();
}
