// What accuracy costs in time (issue 6, acceptance 4): for each problem the
// work–precision sweep of every applicable method (stepper family and
// Boost.Odeint peers, median of 5 runs), then for target errors 1e-4, 1e-8
// and 1e-12 the cheapest configuration of each method that reaches the
// target, its time and the ratio to the fastest method at that target (all
// measured in this run). Usage: steppers_work_precision [BUDGET_SECONDS]
// [PROBLEM...]; the budget caps the slowest run of a sweep (default 0.5).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "solvers/steppers/bench_problems.h"

using namespace vivp::steppers;

namespace {

void Table(const BenchProblem& p, double budget) {
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
  for (double target : {1e-4, 1e-8, 1e-12}) {
    std::vector<WorkPoint> best;
    for (const auto& [m, rows] : sweeps) {
      const WorkPoint* cheapest = nullptr;
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
    if (best.empty()) {
      std::printf("  (no method reached it within the budget)\n");
      continue;
    }
    for (const auto& w : best)
      std::printf("  %-23s %9ld %9.1e  error %9.2e  %10.3e s  x%.1f\n",
                  w.method.c_str(), w.steps, w.tolerance, w.error, w.seconds,
                  w.seconds / best.front().seconds);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const double budget = argc > 1 ? std::atof(argv[1]) : 0.5;
  std::vector<std::string> names;
  for (int i = 2; i < argc; ++i) names.push_back(argv[i]);
  if (names.empty())
    names = {"anharmonic", "damped", "kepler", "nldnls", "pendulum",
             "henon_heiles"};
  std::printf(
      "# What accuracy costs in time: work–precision, median of 5 runs,"
      " sweeps stop after a run slower than %.2f s\n",
      budget);
  for (const auto& n : names) Table(FindBenchProblem(n), budget);
}
