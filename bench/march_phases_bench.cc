// Where a point-mechanics march spends its time, per node: the predictor,
// the operators rebuilt for a new step, Newton's residuals, assemblies,
// factorizations and solves, the end state and estimates, the a-posteriori
// checks, and the rest (step control, acceptance, allocation). Each row
// under error control is followed by a uniform march of the same operator
// over the same span with the same number of nodes, and where those end
// further off than the tolerance by the fewest nodes that do not; and by
// a march without error control on the adaptive march's own windows
// (MarchOptions::given_windows): the same nodes, the same solution to
// round-off, the machinery that chose them apart. The price of the
// adaptive machinery per node is the ratio to that march; the ratio to a
// uniform march that meets the tolerance is what a user without error
// control would pay per node, on more nodes, for the same end error.
//
// The phases need a clock read around each of them, which costs most where
// the phases are short and many: an lgl8 march of the anharmonic oscillator
// at 1e-8 took 0.67 µs per node timed so and 0.55 µs untimed, its uniform
// march 0.42 and 0.36 (ratios 1.59 and 1.53). So the cost per node, and the
// ratio, come from marches without the phase clocks, the two marches of a
// row interleaved run by run (a drift of the machine falls on both), and
// the phases from the timed runs beside them.
//
// A spectral element under error control by its halves keeps two halves
// and solves the whole element besides, for their estimate and their
// Newton start (element_halves.h): three element solves per two kept,
// where the finite-difference windows' estimates come with the window's
// own solve. The last table gives that whole element's share of the
// (timed) adaptive march and the ratio without it, which separates the
// estimator's own solve from the rest of the machinery (predictor,
// rejections, checks). An OP of lgl8_halves (lgl12_, lgl16_) marches the
// element so at every tolerance, lgl8_embedded by its own end-node
// estimates (one solve per element, as a finite-difference window), lgl8
// as the march does by default (ElementEstimate).
//
// Usage: march_phases_bench [--repeats R] [--window W] [--trajectory]
// [PROBLEM T_END OP TOL ...]
// Default rows: Kepler e = 0.9 over 3 orbits and the anharmonic oscillator
// to t = 10, SBP42/63/84, tolerances 1e-5 … 1e-8 (the comparison of
// `vivp bench`), in windows of W points (default: the march's default
// under error control, DefaultWindowPoints), both marches. Times are
// the median of R runs (default 5); the phases come from the run with the
// median total. The marches keep no trajectory (the solver's cost alone);
// --trajectory keeps every node in both, as a caller that stores them does
// (its allocations and page faults fall into "other").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bench/march_phases_tables.h"
#include "solvers/variational/solver_choice.h"
#include "studies/registry.h"

using namespace vivp;
using namespace vivp::variational;
using namespace vivp::bench;

namespace {

struct Row {
  std::string problem;
  double t_end;
  std::string op;
  double tol;
};

// Prints the marches of a row; their untimed cost where they converged.
std::optional<Cost> Measure(const Row& row, int repeats, long long chosen,
                            bool trajectory) {
  const studies::NamedProblem& problem = studies::FindProblem(row.problem);
  // OP_embedded, OP_halves: a spectral element under error control by its
  // own end-node estimates, one solve each, or by its halves, at every
  // tolerance (MarchOptions::element_estimate; OP alone: the default).
  std::string op = row.op;
  const bool embedded = op.ends_with("_embedded");
  const bool halves = op.ends_with("_halves");
  if (embedded) op.resize(op.size() - std::string("_embedded").size());
  if (halves) op.resize(op.size() - std::string("_halves").size());
  // A spectral element's window is the element.
  const long long window =
      sbp::IsElement(op) ? DefaultWindowPoints(Path::kReducedNewton, op, true)
                         : chosen;
  Grid grid{.op = op, .t_start = 0.0, .t_end = row.t_end};
  MarchOptions o;
  if (embedded) o.element_estimate = ElementEstimate::kEmbedded;
  if (halves) o.element_estimate = ElementEstimate::kHalves;
  o.window_points = window;
  o.phase_timings = true;
  o.keep_trajectory = trajectory;
  o.tolerance = {row.tol, row.tol};
  const Run adaptive =
      Median([&] { return problem.march(grid, o, {}); }, repeats);
  std::printf("| %s, t = %.4g, %s |||||||||||||||||\n", row.problem.c_str(),
              row.t_end, row.op.c_str());
  Print("adaptive", row.tol, adaptive,
        adaptive.result.status.converged
            ? EndError(problem, row.t_end, adaptive.result)
            : NAN);
  if (!adaptive.result.status.converged) return std::nullopt;
  // The same nodes on a uniform grid: no predictor tolerance to meet, no
  // rejections, one step.
  MarchOptions u;
  u.window_points = window;
  u.phase_timings = true;
  u.keep_trajectory = trajectory;
  u.stabilize = false;
  // The price of the machinery is the ratio on the same nodes. Where those
  // do not resolve the problem to the tolerance (a window fails check 3,
  // or the march ends further off: Kepler e = 0.9 on the nodes an element
  // placed for pericentre ended up to 4.5 off, with more Newton work per
  // window than a resolved march), also the fewest nodes, up to 64 times
  // as many, that end within it: the price per node of a uniform march
  // that does the job, whose windows are easier than the adaptive march's
  // where the orbit is slow.
  const Grid adaptive_grid = grid;
  grid.points = adaptive.result.points;
  const Run same = Median([&] { return problem.march(grid, u, {}); }, repeats);
  const auto error = [&](const Run& run) {
    return run.result.status.converged
               ? EndError(problem, row.t_end, run.result)
               : NAN;
  };
  Print("uniform", row.tol, same, error(same));
  // The adaptive march's own windows without error control.
  MarchOptions w = u;
  {
    MarchOptions keep = o;  // the window reports come with the trajectory
    keep.phase_timings = false;
    keep.keep_trajectory = true;
    const MarchResult m = problem.march(adaptive_grid, keep, {});
    if (m.status.converged) w.given_windows = AcceptedWindows(m, adaptive_grid);
  }
  std::optional<Run> windows;
  if (!w.given_windows.empty()) {
    windows =
        Median([&] { return problem.march(adaptive_grid, w, {}); }, repeats);
    Print("windows", row.tol, *windows, error(*windows));
    if (!windows->result.status.converged) windows.reset();
  }
  // The fewest nodes that do, in whole windows: doubled until a march ends
  // within the tolerance, then bisected between the last count that did
  // not and the first that did, to a sixteenth. Doubling alone overshot:
  // SBP84 at 10⁻⁵ resolved at 8 times the nodes with an end error of
  // 5.7e-7, a twentieth of the tolerance, on windows easier than needed.
  Grid resolved_grid = grid;
  bool resolved = error(same) <= row.tol;
  if (!resolved) {
    const long long step = window - 1;
    MarchOptions quiet = u;
    quiet.phase_timings = false;
    const auto ends_within = [&](long long windows) {
      Grid g = grid;
      g.points = 1 + windows * step;
      const MarchResult m = problem.march(g, quiet, {});
      return m.status.converged && EndError(problem, row.t_end, m) <= row.tol;
    };
    long long lo = (grid.points - 1 + step - 1) / step, hi = 2 * lo;
    const long long most = 64 * lo;
    while (hi <= most && !ends_within(hi)) {
      lo = hi;
      hi *= 2;
    }
    resolved = hi <= most;
    while (resolved && hi - lo > std::max(1LL, hi / 16)) {
      const long long mid = (lo + hi) / 2;
      (ends_within(mid) ? hi : lo) = mid;
    }
    if (resolved) {
      resolved_grid.points = 1 + hi * step;
      const Run r =
          Median([&] { return problem.march(resolved_grid, u, {}); }, repeats);
      Print("resolved", row.tol, r, error(r));
    }
  }
  if (!same.result.status.converged && !resolved && !windows)
    return std::nullopt;
  MarchOptions oa = o, ou = u, ow = w;
  oa.phase_timings = ou.phase_timings = ow.phase_timings = false;
  using March = std::function<MarchResult()>;
  std::vector<March> uniform;
  if (same.result.status.converged)
    uniform.push_back([&] { return problem.march(grid, ou, {}); });
  if (resolved && resolved_grid.points != grid.points)
    uniform.push_back([&] { return problem.march(resolved_grid, ou, {}); });
  if (windows)
    uniform.push_back([&] { return problem.march(adaptive_grid, ow, {}); });
  const std::vector<double> t = Untimed(
      [&] { return problem.march(adaptive_grid, oa, {}); }, uniform, repeats);
  Cost cost;
  char name[160];
  std::snprintf(name, sizeof name, "%s, t = %.4g, %s, %.0e",
                row.problem.c_str(), row.t_end, row.op.c_str(), row.tol);
  cost.row = name;
  cost.adaptive = t[0];
  std::size_t k = 1;
  if (same.result.status.converged) cost.uniform = t[k++];
  if (resolved && resolved_grid.points != grid.points) {
    cost.resolved = t[k++];
    cost.resolved_nodes =
        double(resolved_grid.points) / double(adaptive.result.points);
  }
  if (windows) cost.same_windows = t[k];
  const MarchPhases& p = adaptive.result.phases;
  cost.whole_share = p.total > 0 ? p.whole_elements / p.total : 0.0;
  return cost;
}

}  // namespace

int main(int argc, char** argv) {
  int repeats = 5;
  // Both marches of a row in the same windows: those of error control.
  long long window = DefaultWindowPoints(Path::kReducedNewton, "sbp84", true);
  bool trajectory = false;
  std::vector<Row> rows;
  std::vector<std::string> args(argv + 1, argv + argc);
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--repeats" && i + 1 < args.size()) {
      repeats = std::max(1, std::atoi(args[++i].c_str()));
    } else if (args[i] == "--window" && i + 1 < args.size()) {
      window = std::atoll(args[++i].c_str());
    } else if (args[i] == "--trajectory") {
      trajectory = true;
    } else if (i + 3 < args.size()) {
      rows.push_back({args[i], std::atof(args[i + 1].c_str()), args[i + 2],
                      std::atof(args[i + 3].c_str())});
      i += 3;
    } else {
      std::fprintf(stderr,
                   "usage: march_phases_bench [--repeats R] [--window W] "
                   "[--trajectory] [PROBLEM T_END OP TOL ...]\n");
      return 2;
    }
  }
  if (rows.empty())
    for (const auto& [problem, t_end] :
         {std::pair<std::string, double>{"kepler_e09", 6 * M_PI},
          {"anharmonic", 10.0}})
      for (const char* op : {"sbp42", "sbp63", "sbp84"})
        for (double tol : {1e-5, 1e-6, 1e-7, 1e-8})
          rows.push_back({problem, t_end, op, tol});
  std::printf(
      "Per node, µs (median of %d runs, windows of %lld points, %s): a march "
      "under error control at the tolerance, then a uniform march with the "
      "same nodes, and where those end further off than the tolerance "
      "(or fail) one with the fewest nodes that does not (resolved: found by "
      "doubling, then bisecting to a sixteenth). "
      "corr/w, fact/w: Newton corrections and Jacobian "
      "factorizations per accepted window; other: step "
      "control, acceptance, allocation.\n\n",
      repeats, window, trajectory ? "every node kept" : "no trajectory kept");
  std::printf(
      "| march | tol | end error | nodes | windows | rej | corr/w | fact/w | "
      "total | "
      "predictor | "
      "setup | residual | assembly | factor | solve | end | checks | other "
      "|\n"
      "|---|---|---|---|---|---|---|---|---|"
      "---|---|---|---|---|---|---|---|---|\n");
  std::vector<Cost> costs;
  for (const Row& row : rows) {
    try {
      if (auto c = Measure(row, repeats, window, trajectory))
        costs.push_back(*c);
    } catch (const std::exception& e) {
      std::printf("| %s: %s |\n", row.problem.c_str(), e.what());
    }
  }
  PrintCosts(costs, repeats);
  return 0;
}
