// Gauss's law of scalar electrodynamics marched from its action with A₀
// free at every node (docs/gauge.md §8): a particle and an antiparticle on
// the periodic [0, 20), 32 points, m² = 1, e = 0.7, to t = 6 (through their
// collision). For SBP21, SBP42 and SBP63 in time, windows of 8 to 64 points
// and Δt from the operator's resolution limit down to 1/16 of it: the
// action's Gauss law at every node (max, relative to the terms that cancel
// in it), the textbook law beside it, the energy of the handed states,
// Newton's iterations (and the windows solved again with full Newton
// steps) and the time.
//
// Usage: charged_bench [--markdown] [--quick]
//   --quick   SBP42 and windows of 16 only
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "studies/charged_waves.h"

int main(int argc, char** argv) {
  bool markdown = false, quick = false;
  for (int a = 1; a < argc; ++a) {
    if (!std::strcmp(argv[a], "--markdown"))
      markdown = true;
    else if (!std::strcmp(argv[a], "--quick"))
      quick = true;
    else {
      std::fprintf(stderr, "usage: charged_bench [--markdown] [--quick]\n");
      return 2;
    }
  }
  std::printf(
      "Scalar electrodynamics, the action's Gauss law at every node "
      "(32 points, t = 6):\n\n");
  if (markdown)
    std::printf(
        "| time | window | Δt/Δt_lim | Δt | windows | Newton | retried | Gauss "
        "(action) | textbook | energy | s |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n");
  else
    std::printf("%-6s %3s %6s %8s %7s %6s %7s %10s %10s %10s %7s\n", "time",
                "W", "Δt/lim", "Δt", "windows", "Newton", "retried", "gauss",
                "textbook", "energy", "seconds");
  const auto [ops, windows] = vivp::studies::GaussSweepOf(quick);
  double worst = 0;
  int failed = 0;
  for (const auto& op : ops)
    for (int w : windows)
      for (double f : {1.0, 1 / 2.0, 1 / 4.0, 1 / 8.0, 1 / 16.0}) {
        const auto r = vivp::studies::RunChargedGauss(op, w, f, 32, 6.0);
        const std::string frac = "1/" + std::to_string(int(std::lround(1 / f)));
        if (!r.failure.empty()) {
          std::printf("%s, window %d, Δt/Δt_lim = %s: not run: %s\n",
                      op.c_str(), w, frac.c_str(), r.failure.c_str());
          ++failed;
          continue;
        }
        worst = std::max(worst, r.gauss);
        // One window hands on one state: no drift to show.
        char energy[16] = "-";
        if (r.windows > 1)
          std::snprintf(energy, sizeof energy, "%.1e", r.energy);
        std::printf(markdown
                        ? "| %s | %d | %s | %.4f | %d | %lld | %d | %.1e | "
                          "%.1e | %s | %.2f |\n"
                        : "%-6s %3d %6s %8.4f %7d %6lld %7d %10.1e %10.1e "
                          "%10s %7.2f\n",
                    op.c_str(), w, frac.c_str(), r.dt, r.windows, r.newton,
                    r.retries, r.gauss, r.textbook, energy, r.seconds);
      }
  std::printf("\nlargest Gauss residual of the action: %.1e%s\n", worst,
              failed ? " (some configurations did not run)" : "");
  return 0;
}
