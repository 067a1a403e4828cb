// Work–precision diagrams (docs/steppers.md): final-time error against wall
// time (median of 5 runs, log–log) for every applicable method on every problem
// of the work–precision harness (harmonic, pendulum, anharmonic, damped —
// variational solver only —, Kepler e = 0.6 and e = 0.9, Hénon–Heiles,
// NLDNLS); one PNG per problem. The variational solver's curves
// (variational_sbpXX) are solid like the stepper family, the peers dashed.
// Usage: fig_steppers_work_precision [OUTPUT_DIR] [BUDGET_SECONDS]
#include <cstdlib>
#include <iostream>

#include "report/plot.h"
#include "studies/bench_problems.h"

int main(int argc, char** argv) {
  using namespace vivp::studies;
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  const double budget = argc > 2 ? std::atof(argv[2]) : 0.1;
  for (const vivp::studies::BenchProblem& p : vivp::studies::BenchProblems()) {
    vivp::report::Figure fig(dir, "fig_steppers_wp_" + p.name);
    std::string plots;
    int style = 1;
    for (const auto& m : p.methods) {
      std::vector<std::vector<double>> rows;
      for (const auto& w : Sweep(p, m, 5, budget))
        if (w.status == "ok" && w.error > 0)
          rows.push_back({w.seconds, w.error});
      if (rows.empty()) continue;
      const std::string file = fig.Data(m, rows, "seconds error");
      // Peers dashed, so the two families read apart.
      const bool peer = m.rfind("odeint_", 0) == 0;
      plots += plots.empty() ? "" : ", ";
      plots += std::string("'") + file +
               "' using 1:2 with linespoints lw 2 pt " + std::to_string(style) +
               (peer ? " dt 2" : "") + " title '" + m + "' noenhanced";
      ++style;
    }
    fig.script() << "set logscale xy\nset format xy '10^{%L}'\n"
                 << "set xlabel 'wall time of one run [s]'\n"
                 << "set ylabel 'max-norm error at t_{end}'\n"
                 << "set title '" << p.description << "' noenhanced\n"
                 << "set key outside right\nset grid\n"
                 << "plot " << plots << "\n";
    std::cout << fig.Render().string() << "\n";
  }
}
