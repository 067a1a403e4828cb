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
// Then the textbook law's order, of its largest |(D⁻·E)/e² − ρ| over the
// nodes (a charge density, not relative): in Δt on 32 points, and in Δx on
// 32, 64 and 128 points at one Δt.
//
// Usage: charged_bench [--markdown] [--quick] [--orders]
//   --quick   SBP42 and windows of 16 only
//   --orders  the orders only (windows of 16, SBP21 and SBP42)
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/linalg/fit.h"
#include "solvers/variational/resolution.h"
#include "studies/charged_waves.h"

namespace {

// The textbook law against Δt (n = 32) and against Δx at Δt = 0.02, windows
// of 16: the action's law and the textbook one differ in how the time
// difference of φ enters ρ, so their difference falls with Δt, and with Δx
// only as far as the solution changes.
void Orders() {
  std::printf("\nThe textbook law's order (windows of 16, t = 6):\n");
  for (const char* op : {"sbp21", "sbp42"}) {
    std::vector<double> dt, tb;
    for (double f : {1 / 2.0, 1 / 4.0, 1 / 8.0, 1 / 16.0}) {
      const auto r = vivp::studies::RunChargedGauss(op, 16, f, 32, 6.0);
      dt.push_back(r.dt);
      tb.push_back(r.textbook_absolute);
      std::printf("  %s, 32 points, Δt = %.4f: |textbook| %.2e\n", op, r.dt,
                  r.textbook_absolute);
    }
    std::printf("  %s: order in Δt %.2f\n", op,
                vivp::linalg::FitPowerLaw(dt, tb).order);
    std::vector<double> h, tx;
    for (int n : {32, 64, 128}) {
      const double hx = 20.0 / n, omega = std::sqrt(1 + 4 / (hx * hx));
      const double f = 0.02 / (vivp::variational::StabilityLimit(op) / omega);
      const auto r = vivp::studies::RunChargedGauss(op, 16, f, n, 6.0);
      h.push_back(hx);
      tx.push_back(r.textbook_absolute);
      std::printf("  %s, %d points, Δt = %.4f: |textbook| %.2e\n", op, n, r.dt,
                  r.textbook_absolute);
    }
    std::printf("  %s: order in Δx %.2f\n", op,
                vivp::linalg::FitPowerLaw(h, tx).order);
  }
}

}  // namespace

int main(int argc, char** argv) {
  bool markdown = false, quick = false;
  for (int a = 1; a < argc; ++a) {
    if (!std::strcmp(argv[a], "--markdown")) {
      markdown = true;
    } else if (!std::strcmp(argv[a], "--quick")) {
      quick = true;
    } else if (!std::strcmp(argv[a], "--orders")) {
      Orders();
      return 0;
    } else {
      std::fprintf(stderr,
                   "usage: charged_bench [--markdown] [--quick] [--orders]\n");
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
  Orders();
  return 0;
}
