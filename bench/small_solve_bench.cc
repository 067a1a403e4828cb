// What a small marched solve costs: the anharmonic oscillator to t = 10 on
// uniform grids of 256 … 8192 steps, SBP42 and SBP84, in the default windows
// (the variational rows of the work–precision comparison). Per run: the
// median wall time of 7, the windows, Jacobian factorizations and Newton or
// chord corrections, the time per window and per node, and the end error of
// the handed-off state. A cost that is fixed per run shows as a time per
// window that falls with the number of windows.
//
// Usage: small_solve_bench [--repeats R PROBLEM T_END OP STEPS ...]
// With rows given, each is marched R times (default 1) with default options
// and reported with its predictor steps but without the end error: the mode for
// counting instructions (valgrind --tool=callgrind --toggle-collect=main),
// where the anharmonic oscillator's reference, long double Jacobi functions,
// does not terminate.
//
// Uses only what the march has offered since time-slab marching began
// (registry, MarchOptions, MarchResult), so the same file measures an older
// build for a before/after table.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "bench/timing.h"
#include "studies/registry.h"

using namespace vivp;
using namespace vivp::variational;

namespace {

// `stabilize` off: the rows of the work–precision comparison; on (the
// default) for the command line's rows, the march a caller gets.
MarchResult March(const vivp::studies::NamedProblem& p, const char* op,
                  long steps, double t_end, bool stabilize) {
  const Grid g{.op = op, .points = steps + 1, .t_end = t_end};
  MarchOptions o;
  o.stabilize = stabilize;
  o.keep_trajectory = false;
  return p.march(g, o, {});
}

// The rows of the command line, `repeats` runs each.
int Rows(int argc, char** argv) {
  int first = 1, repeats = 1;
  if (argc > 2 && std::string(argv[1]) == "--repeats") {
    repeats = std::atoi(argv[2]);
    first = 3;
  }
  if (repeats < 1 || (argc - first) % 4 != 0) {
    std::fprintf(stderr,
                 "usage: small_solve_bench [--repeats R PROBLEM T_END OP "
                 "STEPS ...] (R >= 1)\n");
    return 2;
  }
  std::printf("%-12s %8s %-6s %7s %10s %8s %7s %7s %9s %s\n", "problem",
              "t_end", "op", "steps", "ms", "windows", "fact.", "corr.",
              "predictor", "status");
  for (int a = first; a < argc; a += 4) {
    const auto& p = vivp::studies::FindProblem(argv[a]);
    const double t_end = std::atof(argv[a + 1]);
    const long steps = std::atol(argv[a + 3]);
    MarchResult m;
    const double s = bench::MedianSeconds(
        [&] { m = March(p, argv[a + 2], steps, t_end, true); }, repeats);
    std::printf("%-12s %8.4g %-6s %7ld %10.3f %8lld %7d %7d %9ld %s\n", argv[a],
                t_end, argv[a + 2], steps, 1e3 * s, m.window_count,
                m.iterations, m.corrections, m.predictor_steps,
                m.status.converged ? "ok" : m.status.reason.c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) {
    try {
      return Rows(argc, argv);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "small_solve_bench: %s\n", e.what());
      return 2;
    }
  }
  const vivp::studies::NamedProblem& p =
      vivp::studies::FindProblem("anharmonic");
  const double t_end = 10.0;
  const double exact = p.exact(t_end).x[0];
  std::printf(
      "# anharmonic oscillator to t = 10, uniform grids, default windows;\n"
      "# median of 7 runs\n");
  std::printf("%-6s %6s %9s %8s %7s %7s %12s %10s %10s %s\n", "op", "steps",
              "ms", "windows", "fact.", "corr.", "us/window", "ns/node",
              "err x(T)", "status");
  for (const char* op : {"sbp42", "sbp84"}) {
    for (long steps = 256; steps <= 8192; steps *= 2) {
      MarchResult m;
      const double s = bench::MedianSeconds(
          [&] { m = March(p, op, steps, t_end, false); }, 7);
      std::printf("%-6s %6ld %9.3f %8lld %7d %7d %12.2f %10.1f %10.2e %s\n", op,
                  steps, 1e3 * s, m.window_count, m.iterations, m.corrections,
                  1e6 * s / double(m.window_count), 1e9 * s / double(steps + 1),
                  std::abs(m.end_position[0] - exact),
                  m.status.converged ? "ok" : "not converged");
    }
  }
}
