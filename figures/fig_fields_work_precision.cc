// Work–precision of the sine-Gordon breather (docs/fields.md §9): error
// against wall time for the space-time solve and the method of lines on the
// same spatial operator, from one run of the study in
// studies/field_work_precision.h. Lines join each method's cheapest run per
// target (1e-4, 1e-6, 1e-8, on the spatial grid of that target); the small
// points are every converged run of the searches.
// Usage: fig_fields_work_precision [OUTPUT_DIR] [--quick]
#include <cstring>
#include <iostream>
#include <map>

#include "report/plot.h"
#include "studies/field_work_precision.h"

int main(int argc, char** argv) {
  using namespace vivp::studies;
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  FieldWorkOptions o;
  if (argc > 2 && !std::strcmp(argv[2], "--quick")) o.targets = {1e-4};
  const auto r = BreatherWorkPrecision(o);
  vivp::report::Figure fig(dir, "fig_fields_work_precision", 900, 600);
  std::string plots;
  int style = 1;
  for (const auto& family : FieldWorkFamilies()) {
    std::vector<std::vector<double>> best, all;
    for (const auto& b : r.cheapest)
      if (b.family == family && b.found)
        best.push_back({b.run.seconds, b.run.error, double(b.space_points)});
    for (const auto& run : r.runs)
      if (run.family == family && run.converged && run.error < 1)
        all.push_back({run.seconds, run.error, double(run.space_points)});
    if (all.empty()) continue;
    const auto runs = fig.Data(family + "_runs", all, "seconds error Nx");
    plots += (plots.empty() ? "" : ", ") + std::string("'") + runs +
             "' using 1:2 with points pt 7 ps 0.5 lc " + std::to_string(style) +
             " notitle";
    if (!best.empty()) {
      const auto file = fig.Data(family, best, "seconds error Nx");
      plots += ", '" + file + "' using 1:2 with linespoints lw 2 pt 5 lc " +
               std::to_string(style) +
               (family == "variational" ? "" : " dt 2") + " title '" + family +
               "' noenhanced";
    }
    ++style;
  }
  fig.script() << "set logscale xy\nset format xy '10^{%L}'\n"
               << "set xlabel 'wall time of one run [s]'\n"
               << "set ylabel 'max |φ − exact| at t = kT/8'\n"
               << "set title \"sine-Gordon breather ω = 0.5, [−30, 30), "
                  "order-8 differences, T = 4π\\ncheapest run per target "
                  "(Nx 300 / 600 / 900) and every run of the searches\"\n"
               << "set key outside right\nset grid\n"
               << "plot " << plots << "\n";
  std::cout << fig.Render().string() << "\n";
}
