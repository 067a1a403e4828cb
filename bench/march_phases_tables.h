// The runs, medians and tables of march_phases_bench: a march's phases per
// node, and the untimed cost per node of each march of a row with its
// ratios.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "solvers/variational/march_types.h"
#include "studies/registry.h"

namespace vivp::bench {

using variational::MarchPhases;
using variational::MarchResult;

struct Run {
  MarchResult result;
  double seconds = 0;
};

// A row's cost per node without the phase clocks, µs: adaptive, uniform;
// and the share of the adaptive march's time (from its timed run) that went
// into whole spectral elements.
struct Cost {
  std::string row;
  double adaptive = NAN, uniform = NAN;  // uniform: on the same nodes
  double whole_share = 0;
  // A uniform march that ends within the tolerance, where that on the same
  // nodes does not: its cost per node and its nodes over the adaptive's.
  double resolved = NAN, resolved_nodes = 1;
  double same_windows = NAN;  // on the adaptive march's windows
};

// The medians of `repeats` untimed runs of the marches, interleaved, per
// node of each: the adaptive one and the others of its row.
template <class A, class U>
std::vector<double> Untimed(A&& adaptive, const std::vector<U>& uniform,
                            int repeats) {
  std::vector<std::vector<double>> t(1 + uniform.size());
  for (int r = 0; r < repeats; ++r)
    for (std::size_t k = 0; k < t.size(); ++k) {
      const MarchResult m = k == 0 ? adaptive() : uniform[k - 1]();
      t[k].push_back(1e6 * m.seconds /
                     double(std::max<long long>(m.points, 1)));
    }
  std::vector<double> median;
  for (auto& v : t) {
    std::sort(v.begin(), v.end());
    median.push_back(v[v.size() / 2]);
  }
  return median;
}

// The run with the median total of `repeats`.
template <class F>
Run Median(F&& march, int repeats) {
  std::vector<Run> runs;
  for (int r = 0; r < repeats; ++r) {
    Run run;
    run.result = march();
    run.seconds = run.result.phases.total;
    runs.push_back(std::move(run));
  }
  std::sort(runs.begin(), runs.end(),
            [](const Run& a, const Run& b) { return a.seconds < b.seconds; });
  return std::move(runs[runs.size() / 2]);
}

// The end state's error: the largest over components of the handed-off
// position's and velocity's distance from the exact (or reference) state.
inline double EndError(const studies::NamedProblem& problem, double t_end,
                       const MarchResult& m) {
  const studies::ExactState e = problem.exact(t_end);
  double err = 0;
  for (std::size_t c = 0; c < e.x.size(); ++c)
    err = std::max({err, std::abs(m.end_position[c] - e.x[c]),
                    std::abs(m.end_velocity[c] - e.v[c])});
  return err;
}

inline void Print(const char* kind, double tol, const Run& run, double error) {
  const MarchResult& m = run.result;
  const MarchPhases& p = m.phases;
  const double nodes = double(std::max<long long>(m.points, 1));
  const double us = 1e6 / nodes;
  const double other =
      p.total - (p.predictor + p.setup + p.residual + p.assembly +
                 p.factorization + p.solve + p.end + p.checks);
  if (!m.status.converged) {
    std::printf("| %-8s | %7.0e | not converged: %s |\n", kind, tol,
                m.status.reason.c_str());
    return;
  }
  std::printf(
      "| %-8s | %7.0e | %8.2e | %7lld | %5lld | %4d | %5.1f | %4.2f | "
      "%6.3f | %5.3f | %5.3f | %5.3f | %5.3f | %5.3f | %5.3f | %5.3f | "
      "%5.3f | %5.3f |\n",
      kind, tol, error, m.points, m.window_count, m.rejected,
      double(m.corrections) / double(std::max<long long>(m.window_count, 1)),
      double(m.iterations) / double(std::max<long long>(m.window_count, 1)),
      p.total * us, p.predictor * us, p.setup * us, p.residual * us,
      p.assembly * us, p.factorization * us, p.solve * us, p.end * us,
      p.checks * us, other * us);
}

// The table of per-node costs and their ratios.
inline void PrintCosts(const std::vector<Cost>& costs, int repeats) {
  std::printf(
      "\nCost per node without the phase clocks, µs (median of %d runs of "
      "each march, interleaved), and its ratio. A spectral "
      "element's march solves, besides the halves it keeps, the whole "
      "element for their estimate (step doubling): its share of the timed "
      "adaptive march, and the ratio with that share taken out. Against the "
      "resolved uniform march (its nodes over the adaptive's), the ratio "
      "per node and the ratio of the two marches' times. Last, the march "
      "without error control on the adaptive march's own windows, and the "
      "ratio to it: the machinery's price on the same nodes and solution:\n\n"
      "| row | adaptive | uniform | ratio | whole elements | ratio without "
      "them | resolved uniform (its nodes) | ratio to it | time ratio | "
      "same windows | ratio to them |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n",
      repeats);
  for (const Cost& c : costs) {
    if (std::isnan(c.uniform))
      std::printf("| %s | %.3f | not converged | | %.0f %% | |", c.row.c_str(),
                  c.adaptive, 100 * c.whole_share);
    else
      std::printf("| %s | %.3f | %.3f | %.2f | %.0f %% | %.2f |", c.row.c_str(),
                  c.adaptive, c.uniform, c.adaptive / c.uniform,
                  100 * c.whole_share,
                  c.adaptive * (1 - c.whole_share) / c.uniform);
    if (std::isnan(c.resolved))
      std::printf(" the same | | |");
    else
      std::printf(" %.3f (×%.1f) | %.2f | %.2f |", c.resolved, c.resolved_nodes,
                  c.adaptive / c.resolved,
                  c.adaptive / (c.resolved * c.resolved_nodes));
    if (std::isnan(c.same_windows))
      std::printf(" not converged | |\n");
    else
      std::printf(" %.3f | %.2f |\n", c.same_windows,
                  c.adaptive / c.same_windows);
  }
}

}  // namespace vivp::bench
