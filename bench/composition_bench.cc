// Composition must not cost at run time (docs/performance.md §1): a Lagrangian
// composed of effects chosen at run time (problems/composed.h) against the
// hand-written functor of the same system, same solve, same run: reduced
// Newton, SBP42, Nt = 2^16, median of 7 runs each (interleaved). Also prints
// the largest difference of the two trajectories.
#include <cmath>
#include <cstdio>

#include "bench/timing.h"
#include "problems/anharmonic.h"
#include "problems/composed.h"
#include "problems/damped_oscillator.h"
#include "solvers/variational/solve_ivp.h"

using namespace vivp;
using namespace vivp::variational;
using namespace vivp::problems;

namespace {

template <class A, class B>
void Compare(const char* name, const A& hand, const B& composed,
             const vivp::variational::InitialData& init, double t_end) {
  const Grid g{
      .op = "sbp42", .points = 1 << 16, .t_start = 0.0, .t_end = t_end};
  vivp::variational::IvpSolution<double> a, b;
  std::vector<double> ta, tb;
  for (int r = 0; r < 7; ++r) {
    ta.push_back(bench::MedianSeconds([&] { a = SolveIvp(hand, init, g); }, 1));
    tb.push_back(
        bench::MedianSeconds([&] { b = SolveIvp(composed, init, g); }, 1));
  }
  std::nth_element(ta.begin(), ta.begin() + 3, ta.end());
  std::nth_element(tb.begin(), tb.begin() + 3, tb.end());
  const double diff = (a.x1 - b.x1).cwiseAbs().maxCoeff();
  std::printf("%-34s %10.4f %10.4f %8.3f %10.1e %s\n", name, ta[3], tb[3],
              tb[3] / ta[3], diff,
              a.status.converged && b.status.converged ? "" : "NOT CONVERGED");
}

}  // namespace

int main() {
  std::printf(
      "# composed effects vs hand-written functor: reduced Newton, SBP42, "
      "Nt = 2^16, median of 7\n");
  std::printf("%-34s %10s %10s %8s %10s\n", "system", "hand [s]", "composed",
              "ratio", "max|dx|");
  Compare("kinetic + spring + damping", DampedOscillator{},
          Composed<1>{{effects::Kinetic{0.5, {}}, effects::Spring{1.0, {}},
                       effects::Damping{0.00071}}},
          {{1.0}, {0.0}}, 204.8);
  Compare("kinetic + quartic (anharmonic)", Anharmonic{},
          Composed<1>{{effects::Kinetic{1.0, {}}, effects::Quartic{20.0}}},
          {{1.0}, {0.3}}, 1.0);
}
