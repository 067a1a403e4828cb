// Work–precision of the sine-Gordon breather: the space-time solve against
// the method of lines on the same spatial operator (studies/
// field_work_precision.h says how the grids and step counts are chosen).
// One run measures everything; the ratios are of times from this run.
//
// Usage: fields_work_precision [--quick] [--markdown] [--verbose]
//   --quick     the 1e-4 target only
//   --markdown  the cheapest configurations as Markdown (docs/fields.md §9)
//   --verbose   every run of every search on stderr
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>

#include "studies/field_work_precision.h"

namespace {

void Print(const std::string& line) {
  std::fprintf(stderr, "  %s\n", line.c_str());
}

// The second table: a window's cost per time step against Gauss4's.
void PrintStepCosts(const vivp::studies::FieldWorkReport& r, bool markdown) {
  std::printf(
      "\nA window's cost per time step against one Gauss4 step at the same "
      "Δt on the same grid:\n\n");
  if (markdown)
    std::printf(
        "| target | Nx | variational | steps | per step | gauss4 per step | "
        "ratio |\n|---|---|---|---|---|---|---|\n");
  else
    std::printf("%-7s %5s %-22s %7s %11s %15s %6s\n", "target", "Nx",
                "variational", "steps", "per step", "gauss4 per step", "ratio");
  for (const auto& c : r.step_costs) {
    const double ratio = c.seconds_per_step / c.gauss4_seconds_per_step;
    if (markdown)
      std::printf("| %.0e | %d | %s | %lld | %.1f µs | %.1f µs%s | %.1f |\n",
                  c.target, c.space_points, c.config.c_str(), c.steps,
                  1e6 * c.seconds_per_step, 1e6 * c.gauss4_seconds_per_step,
                  c.gauss4_converged ? "" : " (not converged)", ratio);
    else
      std::printf("%-7.0e %5d %-22s %7lld %8.1f µs %12.1f µs%s %6.1f\n",
                  c.target, c.space_points, c.config.c_str(), c.steps,
                  1e6 * c.seconds_per_step, 1e6 * c.gauss4_seconds_per_step,
                  c.gauss4_converged ? "" : " (not converged)", ratio);
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace vivp::studies;
  FieldWorkOptions o;
  bool markdown = false, verbose = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick"))
      o.targets = {1e-4};
    else if (!std::strcmp(argv[i], "--markdown"))
      markdown = true;
    else if (!std::strcmp(argv[i], "--verbose"))
      verbose = true;
    else {
      std::fprintf(stderr,
                   "fields_work_precision: unknown argument '%s' (--quick, "
                   "--markdown, --verbose)\n",
                   argv[i]);
      return 2;
    }
  }
  const auto r = BreatherWorkPrecision(o, verbose ? Print : nullptr);
  std::printf(
      "Sine-Gordon breather ω = %g on [−%g, %g), order-8 periodic "
      "differences, T = %.4f;\nerror = max |φ − exact| over the grid at "
      "t = T·k/8, k = 1…8. Cheapest configuration per target (%zu runs):\n\n",
      o.omega, o.half_length, o.half_length, o.t_end, r.runs.size());
  std::map<double, double> variational_seconds;
  for (const auto& b : r.cheapest)
    if (b.family == "variational" && b.found)
      variational_seconds[b.target] = b.run.seconds;
  if (markdown)
    std::printf(
        "| target | Nx (floor) | method | configuration | steps | error | "
        "time | variational / this |\n|---|---|---|---|---|---|---|---|\n");
  else
    std::printf("%-7s %-15s %-12s %-22s %7s %9s %9s %8s\n", "target",
                "Nx (floor)", "method", "configuration", "steps", "error",
                "seconds", "var/this");
  for (const auto& b : r.cheapest) {
    char grid[64], steps[32], err[32], sec[32], ratio[32];
    std::snprintf(grid, sizeof grid, "%d (%.1e)", b.space_points, b.floor);
    const std::string config =
        !b.found ? "— " + b.why
        : b.family == "dopri5"
            ? "tol " +
                  [&] {
                    char t[32];
                    std::snprintf(t, sizeof t, "%.1e", b.run.tolerance);
                    return std::string(t);
                  }()
            : b.run.config;
    std::snprintf(steps, sizeof steps, "%lld", b.found ? b.run.steps : 0LL);
    std::snprintf(err, sizeof err, "%.2e", b.found ? b.run.error : NAN);
    std::snprintf(sec, sizeof sec, "%.3f", b.found ? b.run.seconds : NAN);
    const auto v = variational_seconds.find(b.target);
    std::snprintf(ratio, sizeof ratio, "%.1f",
                  b.found && v != variational_seconds.end()
                      ? v->second / b.run.seconds
                      : NAN);
    if (markdown)
      std::printf("| %.0e | %s | %s | %s | %s | %s | %s s | %s |\n", b.target,
                  grid, b.family.c_str(), config.c_str(), b.found ? steps : "—",
                  b.found ? err : "—", b.found ? sec : "—",
                  b.found ? ratio : "—");
    else
      std::printf("%-7.0e %-15s %-12s %-22s %7s %9s %9s %8s\n", b.target, grid,
                  b.family.c_str(), config.c_str(), b.found ? steps : "—",
                  b.found ? err : "—", b.found ? sec : "—",
                  b.found ? ratio : "—");
  }
  PrintStepCosts(r, markdown);
  return 0;
}
