// Error control of time-slab marching, two figures:
//  fig_error_control_wp_PROBLEM (Kepler e = 0.9 over 3 orbits, the
//    anharmonic oscillator to t = 10): error at t_end against the median
//    wall time of 5 runs, for the variational solver under error control
//    (SBP42, SBP63, SBP84; tolerances 1e-3 … 1e-10), SBP84 on uniform grids,
//    odeint's tolerance-driven dopri5, and the fixed-step stepper that
//    reaches 1e-8 fastest on that problem (chosen by measurement here);
//  fig_error_control_steps: the step each window of SBP42/63/84 chose at
//    tolerance 1e-6 along one Kepler e = 0.9 orbit, against the distance r
//    from the centre (the local time scale is r^{3/2}).
// Usage: fig_error_control [OUTPUT_DIR] [BUDGET_SECONDS]
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>

#include "report/plot.h"
#include "studies/bench_problems.h"
#include "studies/registry.h"

namespace {

using namespace vivp;
using namespace vivp::variational;
using studies::WorkPoint;

std::vector<std::vector<double>> Curve(const std::vector<WorkPoint>& sweep) {
  std::vector<std::vector<double>> rows;
  for (const auto& w : sweep)
    if (w.status == "ok" && w.error > 0) rows.push_back({w.seconds, w.error});
  return rows;
}

// Seconds to reach `target` (the first run at or below it), or infinity.
double TimeTo(const std::vector<WorkPoint>& sweep, double target) {
  for (const auto& w : sweep)
    if (w.status == "ok" && w.error <= target) return w.seconds;
  return std::numeric_limits<double>::infinity();
}

void WorkPrecision(const std::filesystem::path& dir,
                   const studies::BenchProblem& p, double budget) {
  report::Figure fig(dir, "fig_error_control_wp_" + p.name, 900, 700);
  std::string plots;
  auto add = [&](const std::string& method, const std::string& style,
                 const std::vector<WorkPoint>& sweep,
                 const std::string& note = "") {
    const auto rows = Curve(sweep);
    if (rows.empty()) return;
    plots += (plots.empty() ? "" : ", ") + std::string("'") +
             fig.Data(method, rows, "seconds error") + "' using 1:2 with " +
             style + " title '" + method + note + "' noenhanced";
  };
  int pt = 1;
  for (const char* m : {"variational_sbp42", "variational_sbp63",
                        "variational_sbp84", "variational_sbp84_uniform"})
    add(m, "linespoints lw 2 pt " + std::to_string(pt++),
        studies::Sweep(p, m, 5, budget));
  add("odeint_dopri5", "linespoints lw 2 dt 2 pt 6",
      studies::Sweep(p, "odeint_dopri5", 5, budget));
  std::string best;
  std::vector<WorkPoint> best_sweep;
  double best_time = std::numeric_limits<double>::infinity();
  for (const auto& m : p.methods) {
    if (studies::IsAdaptive(m) || m.rfind("variational_", 0) == 0) continue;
    auto sweep = studies::Sweep(p, m, 5, budget);
    const double t = TimeTo(sweep, 1e-8);
    if (t < best_time) {
      best_time = t;
      best = m;
      best_sweep = std::move(sweep);
    }
  }
  if (!best.empty())
    add(best, "linespoints lw 2 dt 3 pt 8", best_sweep,
        " (the fastest fixed-step method to 1e-8)");
  fig.script() << "set logscale xy\nset format xy '10^{%L}'\n"
               << "set xlabel 'wall time of one run [s]'\n"
               << "set ylabel 'max-norm error at t_{end}'\n"
               << "set title '" << p.description
               << ": error control' noenhanced\n"
               << "set key outside below maxrows 3\nset grid\n"
               << "plot " << plots << "\n";
  std::cout << fig.Render().string() << "\n";
}

void Steps(const std::filesystem::path& dir) {
  report::Figure fig(dir, "fig_error_control_steps", 900, 650);
  const vivp::studies::NamedProblem& p =
      vivp::studies::FindProblem("kepler_e09");
  std::string plots;
  int pt = 1;
  std::vector<std::vector<double>> rows;  // of the last operator, for r
  for (const char* op : {"sbp42", "sbp63", "sbp84"}) {
    MarchOptions o;
    o.tolerance = {1e-6, 1e-6};
    const Grid g{.op = op, .t_end = 2 * M_PI};
    const MarchResult m = p.march(g, o, {});
    rows.clear();
    for (const auto& w : m.windows) {
      const auto s = p.exact(0.5 * (w.t_start + w.t_end));
      rows.push_back(
          {0.5 * (w.t_start + w.t_end), w.dt, std::hypot(s.x[0], s.x[1])});
    }
    plots += (plots.empty() ? "" : ", ") + std::string("'") +
             fig.Data(op, rows, "t dt r") +
             "' using 1:2 with linespoints lw 2 pt " + std::to_string(pt++) +
             " ps 0.6 title '" + op + ", " + std::to_string(m.points) +
             " nodes'";
  }
  plots += ", '" + fig.Data("r", rows, "t dt r") +
           "' using 1:3 axes x1y2 with lines lw 1 lc rgb 'gray' "
           "title 'r = |x| (right axis)'";
  fig.script() << "set logscale y\nset format y '10^{%L}'\n"
               << "set xlabel 't'\nset ylabel 'window step {/Symbol D}t'\n"
               << "set y2label 'r'\nset y2tics\nset ytics nomirror\n"
               << "set title 'Kepler e = 0.9, one orbit, tolerance 1e-6: the "
                  "step follows r^{3/2}'\n"
               << "set key outside below\nset grid\n"
               << "plot " << plots << "\n";
  std::cout << fig.Render().string() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  const double budget = argc > 2 ? std::atof(argv[2]) : 0.5;
  for (const char* name : {"kepler_e09", "anharmonic"})
    WorkPrecision(dir, studies::FindBenchProblem(name), budget);
  Steps(dir);
}
