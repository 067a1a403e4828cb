// Gauss's law of electromagnetism marched from its action with the gauge
// free (docs/gauge.md §6): a plane wave k = (1, 2) on the periodic
// [0, 2π)², central differences of order 8, to t = 4. Two tables:
//
//   1. the action's Gauss law (A₀'s equation) at every slice, for SBP21,
//      SBP42 and SBP63 in time, windows of 8 to 64 points and Δt from the
//      resolution limit down to 1/16 of it; beside it the same law at the
//      corrected end state the march hands on, and E's error at t = 4;
//   2. the textbook law ∇·E with the exact derivative against Δx (orders 4
//      and 8 in space): the stencil's error, with its fitted order;
//   3. how the gauge (A₀ and D·A, zero in the data) moves over a march to
//      t = 40;
//   4. one window solved by Newton with the Fourier window solve and by
//      Ceres Levenberg–Marquardt from the same start: iterations, time,
//      Gauss's law, and the gauge each one picks.
//
// Usage: gauge_bench [--markdown] [--quick]
//   --quick   SBP42 and windows of 16 only
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/linalg/fit.h"
#include "studies/charged_waves.h"
#include "studies/gauge_waves.h"

namespace {

void Row(const vivp::studies::GaussRun& r, bool markdown) {
  if (!r.failure.empty()) {
    std::printf("%s, window %d, Δt/Δt_lim = 1/%g: not run: %s\n", r.op.c_str(),
                r.window, 1 / r.fraction, r.failure.c_str());
    return;
  }
  if (markdown)
    std::printf(
        "| %s | %d | 1/%g | %.4f | %d | %.1e | %.1e | %.1e | %.1e | %.2f |\n",
        r.op.c_str(), r.window, 1 / r.fraction, r.dt, r.windows, r.gauss,
        r.handoff, r.textbook, r.error_e, r.seconds);
  else
    std::printf(
        "%-6s %3d %6s %8.4f %7d %10.1e %10.1e %10.1e %10.1e %7.2f\n",
        r.op.c_str(), r.window,
        ("1/" + std::to_string(int(std::lround(1 / r.fraction)))).c_str(), r.dt,
        r.windows, r.gauss, r.handoff, r.textbook, r.error_e, r.seconds);
}

// Table 1: the action's Gauss law over operators, windows and steps.
void GaussTable(bool markdown, bool quick) {
  const double t_end = 4;
  std::printf(
      "The action's Gauss law, max over every slice, relative to its terms "
      "(16² points, order 8, t = 4):\n\n");
  if (markdown)
    std::printf(
        "| time | window | Δt/Δt_lim | Δt | windows | Gauss (action) | at "
        "hand-off | textbook | E error | s |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n");
  else
    std::printf("%-6s %3s %6s %8s %7s %10s %10s %10s %10s %7s\n", "time", "W",
                "Δt/lim", "Δt", "windows", "gauss", "hand-off", "textbook",
                "E error", "seconds");
  const auto [ops, windows] = vivp::studies::GaussSweepOf(quick);
  double worst = 0;
  bool failed = false;
  for (const auto& op : ops)
    for (int w : windows)
      for (double f : {1.0, 1 / 2.0, 1 / 4.0, 1 / 8.0, 1 / 16.0}) {
        const auto r = vivp::studies::RunGauss(op, w, f, 16, 8, t_end);
        Row(r, markdown);
        if (r.failure.empty())
          worst = std::max(worst, r.gauss);
        else
          failed = true;
      }
  std::printf("\nlargest: %.1e%s\n", worst,
              failed ? " (some configurations did not run)" : "");
}

// Table 2: the textbook law against Δx, with its fitted order.
void TextbookTable() {
  std::printf(
      "\nThe textbook law ∇·E (exact derivative) against Δx, SBP42, "
      "windows of 16, Δt at 1/4 of the limit:\n\n");
  for (int order : {4, 8}) {
    std::vector<double> h, e;
    for (int n : {12, 16, 24, 32, 48}) {
      const auto r = vivp::studies::RunGauss("sbp42", 16, 0.25, n, order, 1.0);
      if (!r.failure.empty()) continue;
      h.push_back(2 * 3.141592653589793 / n);
      e.push_back(r.textbook);
      std::printf("order %d, n = %2d: textbook %.2e, action %.1e\n", order, n,
                  r.textbook, r.gauss);
    }
    std::printf("order %d: fitted order in Δx %.2f\n\n", order,
                vivp::linalg::FitPowerLaw(h, e).order);
  }
}

// Table 4: how the gauge moves over a long march.
void DriftTable() {
  std::printf(
      "\nThe gauge over a long march (16², order 8, windows of 16, Δt at 1/4 "
      "of the limit; A₀ and D·A are 0 in the data):\n\n");
  for (const std::string op : {"sbp21", "sbp42"})
    for (const auto& r : vivp::studies::GaugeDrift(op, 16, {4, 10, 20, 40}))
      std::printf("%s t = %5.1f: max |A₀| %.1e, max |D·A| %.1e, Gauss %.1e\n",
                  op.c_str(), r.t, r.a0, r.divergence, r.gauss);
}

// Table 3: one window by the Fourier solve and by Ceres LM.
void SolverTable(bool markdown) {
  std::printf(
      "\nOne window from the same start (A₀ = 0, A(0) + t∂_tA(0)): Newton "
      "with the Fourier window solve against Ceres Levenberg–Marquardt "
      "(order 2 in space):\n\n");
  if (markdown)
    std::printf(
        "| time | window | grid | unknowns | solver | iterations | seconds | "
        "residual | Gauss | correction |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string op : {"sbp21", "sbp42"})
    for (const auto& [w, n] : {std::pair{8, 6}, {12, 6}, {8, 8}}) {
      const auto c = vivp::studies::CompareWindowSolves(op, w, n);
      for (const auto* side : {&c.fourier, &c.lm}) {
        const char* name = side == &c.fourier ? "fourier" : "ceres-lm";
        if (markdown)
          std::printf(
              "| %s | %d | %d² | %d | %s | %d | %.3f | %.1e | %.1e | %.2e |\n",
              op.c_str(), w, n, c.unknowns, name, side->iterations,
              side->seconds, side->residual, side->gauss, side->correction);
        else
          std::printf(
              "%-6s W=%-3d %2d² %6d %-9s %4d it %8.3f s  residual %.1e  "
              "gauss %.1e  correction %.2e%s%s\n",
              op.c_str(), w, n, c.unknowns, name, side->iterations,
              side->seconds, side->residual, side->gauss, side->correction,
              side->converged ? "" : "  not converged: ",
              side->converged ? "" : side->message.c_str());
      }
      std::printf("  E differs by %.1e relative, A₀ by %.1e\n", c.e_difference,
                  c.a0_difference);
    }
}

}  // namespace

int main(int argc, char** argv) {
  bool markdown = false, quick = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--markdown")) {
      markdown = true;
    } else if (!std::strcmp(argv[i], "--quick")) {
      quick = true;
    } else {
      std::fprintf(stderr, "usage: gauge_bench [--markdown] [--quick]\n");
      return 2;
    }
  }
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  GaussTable(markdown, quick);
  TextbookTable();
  DriftTable();
  SolverTable(markdown);
  return 0;
}
