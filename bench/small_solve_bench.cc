// What a small marched solve costs: the anharmonic oscillator to t = 10 on
// uniform grids of 256 … 8192 steps, SBP42 and SBP84, in the default windows
// (the variational rows of the work–precision comparison). Per run: the
// median wall time of 7, the windows, Jacobian factorizations and Newton or
// chord corrections, the time per window and per node, and the end error of
// the handed-off state. A cost that is fixed per run shows as a time per
// window that falls with the number of windows.
//
// Uses only what the march has offered since time-slab marching began
// (registry, MarchOptions, MarchResult), so the same file measures an older
// build for a before/after table.
#include <cmath>
#include <cstdio>

#include "bench/timing.h"
#include "studies/registry.h"

using namespace vivp;
using namespace vivp::variational;

int main() {
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
      const Grid g{.op = op, .points = steps + 1, .t_end = t_end};
      MarchOptions o;
      o.stabilize = false;
      o.keep_trajectory = false;
      MarchResult m;
      const double s = bench::MedianSeconds([&] { m = p.march(g, o, {}); }, 7);
      std::printf("%-6s %6ld %9.3f %8lld %7d %7d %12.2f %10.1f %10.2e %s\n", op,
                  steps, 1e3 * s, m.window_count, m.iterations, m.corrections,
                  1e6 * s / double(m.window_count), 1e9 * s / double(steps + 1),
                  std::abs(m.end_position[0] - exact),
                  m.status.converged ? "ok" : "not converged");
    }
  }
}
