// The two-degree-of-freedom problems of the work–precision comparison
// (bench_problems.h): kepler, kepler_e09, henon_heiles.
#include <cmath>
#include <vector>

#include "problems/henon_heiles.h"
#include "problems/kepler.h"
#include "studies/bench_problem_of.h"
#include "studies/bench_problems.h"

namespace vivp::studies {

std::vector<BenchProblem> OrbitBenchProblems() {
  using detail::MakeBenchProblem;
  std::vector<BenchProblem> r;
  const double orbit = 2 * M_PI;
  r.push_back(MakeBenchProblem(
      "kepler", "Kepler e = 0.6, 10 orbits", problems::Kepler{}, 10 * orbit,
      1000, "exact (Kepler's equation)",
      [=] { return problems::Kepler{}.Exact(10 * orbit); }));
  problems::Kepler hard;
  hard.e = 0.9;
  r.push_back(MakeBenchProblem("kepler_e09", "Kepler e = 0.9, 3 orbits", hard,
                               3 * orbit, 1000, "exact (Kepler's equation)",
                               [=] { return hard.Exact(3 * orbit); }));
  r.push_back(MakeBenchProblem(
      "henon_heiles", "Hénon–Heiles, q = p = (0.18, 0.18), t = 100",
      problems::HenonHeiles{}, 100.0, 100, "Gauss–Legendre s = 3, h = 0.005",
      [] {
        return detail::GaussReference(problems::HenonHeiles{}, 100.0, 20000);
      }));
  return r;
}

}  // namespace vivp::studies
