// What accuracy costs in time: for each problem the work–precision sweep of
// every applicable method (stepper family and Boost.Odeint peers, median of 5
// runs), then for target errors 1e-4, 1e-8 and 1e-12 the cheapest configuration
// of each method that reaches the target, its time and the ratio to the fastest
// method at that target (all measured in this run), and last the same as one
// Markdown table per problem (methods by row, targets by column: the tables
// of docs/performance.md §4 are pasted from it). Usage:
// steppers_work_precision [BUDGET_SECONDS] [PROBLEM...]; the budget caps the
// slowest run of a sweep (default 0.5).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "studies/bench_problems.h"

using namespace vivp::studies;

namespace {

constexpr double kTargets[] = {1e-4, 1e-8, 1e-12};

// Per target (kTargets order): the cheapest converged run of each method
// that reaches it, fastest first.
using Cheapest = std::vector<std::vector<WorkPoint>>;

Cheapest Table(const vivp::studies::BenchProblem& p, double budget) {
  Cheapest all;
  std::printf("\n## %s (reference: %s)\n", p.description.c_str(),
              p.reference.c_str());
  std::printf("%-23s %9s %9s %10s %10s %10s %10s %9s %6s %s\n", "method",
              "steps", "tol", "error", "max|dH|/H", "max|dI|", "seconds",
              "evals", "it/st", "status");
  std::map<std::string, std::vector<WorkPoint>> sweeps;
  for (const auto& m : p.methods) {
    sweeps[m] = Sweep(p, m, 5, budget);
    for (const auto& w : sweeps[m])
      std::printf(
          "%-23s %9ld %9.1e %10.3e %10.3e %10.3e %10.3e %9ld %6.2f %s\n",
          w.method.c_str(), w.steps, w.tolerance, w.error, w.energy_error,
          w.invariant_error, w.seconds, w.evaluations, w.iterations_per_step,
          w.status.c_str());
  }
  for (double target : kTargets) {
    std::vector<vivp::studies::WorkPoint> best;
    for (const auto& [m, rows] : sweeps) {
      const vivp::studies::WorkPoint* cheapest = nullptr;
      for (const auto& w : rows)
        if (w.status == "ok" && w.error <= target &&
            (!cheapest || w.seconds < cheapest->seconds))
          cheapest = &w;
      if (cheapest) best.push_back(*cheapest);
    }
    std::sort(best.begin(), best.end(), [](const auto& a, const auto& b) {
      return a.seconds < b.seconds;
    });
    std::printf(
        "\n# %s, target error %.0e: cheapest configuration per method\n",
        p.name.c_str(), target);
    all.push_back(best);
    if (best.empty()) {
      std::printf("  (no method reached it within the budget)\n");
      continue;
    }
    for (const auto& w : best)
      std::printf("  %-23s %9ld %9.1e  error %9.2e  %10.3e s  x%.1f\n",
                  w.method.c_str(), w.steps, w.tolerance, w.error, w.seconds,
                  w.seconds / best.front().seconds);
  }
  return all;
}

// One Markdown table: a row per method, a column per target; a cell is the
// cheapest configuration (steps, or tolerance for adaptive methods), its
// median time and its ratio to the fastest method at that target.
void Markdown(const vivp::studies::BenchProblem& p, const Cheapest& all) {
  std::printf("\n%s (reference: %s)\n\n| method |", p.description.c_str(),
              p.reference.c_str());
  for (double t : kTargets) std::printf(" error %.0e |", t);
  std::printf("\n|---|");
  for (std::size_t k = 0; k < std::size(kTargets); ++k) std::printf("---|");
  std::printf("\n");
  for (const auto& m : p.methods) {
    std::printf("| %s |", m.c_str());
    for (const auto& best : all) {
      const auto w = std::find_if(best.begin(), best.end(),
                                  [&](const auto& b) { return b.method == m; });
      if (w == best.end()) {
        std::printf(" — |");
        continue;
      }
      const double ratio = w->seconds / best.front().seconds;
      const char* bold = w == best.begin() ? "**" : "";
      if (std::isfinite(w->tolerance))
        std::printf(" %stol %.0e: %.2g s, ×%.1f%s |", bold, w->tolerance,
                    w->seconds, ratio, bold);
      else
        std::printf(" %s%ld steps: %.2g s, ×%.1f%s |", bold, w->steps,
                    w->seconds, ratio, bold);
    }
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  const double budget = argc > 1 ? std::atof(argv[1]) : 0.5;
  std::vector<std::string> names;
  for (int i = 2; i < argc; ++i) names.push_back(argv[i]);
  if (names.empty())
    names = {"anharmonic", "damped",   "kepler",
             "nldnls",     "pendulum", "henon_heiles"};
  std::printf(
      "# What accuracy costs in time: work–precision, median of 5 runs,"
      " sweeps stop after a run slower than %.2f s\n",
      budget);
  std::vector<Cheapest> results;
  for (const auto& n : names)
    results.push_back(Table(vivp::studies::FindBenchProblem(n), budget));
  std::printf(
      "\n# Markdown: cheapest configuration per method and target"
      " (\"—\": not reached within the budget)\n");
  for (std::size_t i = 0; i < names.size(); ++i)
    Markdown(vivp::studies::FindBenchProblem(names[i]), results[i]);
}
