// The plots of `vivp run`: the trajectory and one figure per diagnostic.
#include <cmath>
#include <iomanip>
#include <utility>

#include "apps/run_output.h"
#include "report/plot.h"

namespace vivp::apps {
namespace {

using PlotCurves = std::vector<std::pair<std::string, std::string>>;

// What the plots of a run share: where they go, the scene, the columns and
// their statistics, and the lists of PNGs drawn and of plots that failed.
struct RunPlots {
  const std::filesystem::path& dir;
  const scene::Scene& s;
  const scene::RunLayout& layout;
  const std::vector<ColumnStats>& stats;
  std::vector<std::string>& files;
  std::vector<std::string>& warnings;
  std::string title;

  void Render(report::Figure& fig, const std::string& png) {
    try {
      fig.Render();
      files.push_back(png);
    } catch (const std::exception& e) {
      warnings.push_back(e.what());
    }
  }
  int Column(const std::string& name) const {
    for (std::size_t k = 0; k < layout.columns.size(); ++k)
      if (layout.columns[k] == name) return int(k) + 2;  // after t
    return 0;
  }
  void Header(report::Figure& fig) const {
    fig.script() << "set datafile separator ','\nset title \"" << title
                 << "\" noenhanced\n"
                    "set key outside below horizontal maxrows 2\nset grid\n";
  }
  // Time axes span exactly the scene's interval (gnuplot would round it up).
  void TimeAxis(report::Figure& fig) const {
    fig.script() << std::setprecision(17) << "set xrange [" << s.t_start << ":"
                 << s.t_end << "]\n";
  }
};

void PlotTrajectory(RunPlots& p) {
  const int d = p.layout.dof;
  report::Figure fig(p.dir, "trajectory");
  p.Header(fig);
  auto& g = fig.script();
  if (d == 2) {
    g << "set size ratio -1\nset xlabel 'x_0'\nset ylabel 'x_1'\nplot "
         "'trajectory.csv' using 2:3 with lines lw 2 title 'vivp'";
    if (p.layout.reference_x >= 0)
      g << ", 'diagnostics.csv' using " << p.layout.reference_x + 2 << ":"
        << p.layout.reference_x + 3
        << " with lines dt 2 lc rgb 'black' title 'reference'";
  } else {
    p.TimeAxis(fig);
    g << "set xlabel 't'\nset ylabel 'x'\n";
    if (d > 8) g << "unset key\n";
    g << "plot ";
    for (int c = 0; c < d; ++c)
      g << (c ? ", " : "") << "'trajectory.csv' using 1:" << c + 2
        << " with lines lw 2 title 'x_" << c << "'";
    if (p.layout.reference_x >= 0)
      for (int c = 0; c < d; ++c)
        g << ", 'diagnostics.csv' using 1:" << p.layout.reference_x + 2 + c
          << " with lines dt 2 lc rgb 'black' title 'reference x_" << c << "'";
  }
  g << "\n";
  p.Render(fig, "trajectory.png");
}

void PlotSeries(RunPlots& p, const std::string& stem, const std::string& ylabel,
                const PlotCurves& curves, bool log) {
  report::Figure fig(p.dir, stem);
  p.Header(fig);
  p.TimeAxis(fig);
  // A quantity that stays within 1e-3 (relative) of its initial value is
  // plotted as its change q(t) − q(0): the conservation error is what a
  // reader wants to see, and tick labels could not resolve it otherwise.
  bool deviation = !log;
  for (const auto& curve : curves) {
    const ColumnStats& c = p.stats[p.Column(curve.first) - 2];
    deviation = deviation && std::isfinite(c.first) &&
                std::max(c.max - c.first, c.first - c.min) <=
                    1e-3 * std::max(std::abs(c.first), 1e-300);
  }
  fig.script() << "set xlabel 't'\nset ylabel '" << ylabel
               << (deviation ? ": change since the start" : "") << "'\n"
               << (log || deviation ? "set format y '%.1e'\n" : "")
               << (log ? "set logscale y\n" : "") << "plot "
               << std::setprecision(17);
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const int col = p.Column(curves[k].first);
    fig.script() << (k ? ", " : "") << "'diagnostics.csv' using 1:";
    if (deviation)
      fig.script() << "($" << col << " - (" << p.stats[col - 2].first << "))";
    else
      fig.script() << col;
    fig.script() << " with lines lw 2 title '" << curves[k].second << "'";
  }
  fig.script() << "\n";
  p.Render(fig, stem + ".png");
}

// The figure of one entry of the scene's output.diagnostics.
void PlotDiagnostic(RunPlots& p, const std::string& diag) {
  const int d = p.layout.dof;
  if (diag == "energy") {
    PlotCurves c = {{"energy", "vivp"}};
    if (p.Column("energy_reference"))
      c.push_back({"energy_reference", "reference"});
    PlotSeries(p, "energy", "energy v·∂L/∂v − L", c, false);
  } else if (diag == "momentum") {
    PlotCurves c;
    for (int k = 0; k < d; ++k)
      c.push_back({"p" + std::to_string(k), "p_" + std::to_string(k)});
    PlotSeries(p, "momentum", "momentum ∂L/∂v", c, false);
  } else if (diag == "angular_momentum") {
    PlotCurves c;
    if (d == 2)
      c.push_back({"angular_momentum", "x × p"});
    else
      for (const char* a : {"x", "y", "z"})
        c.push_back(
            {std::string("angular_momentum_") + a, std::string("L_") + a});
    PlotSeries(p, "angular_momentum", "angular momentum", c, false);
  } else if (diag == "error") {
    PlotSeries(p, "error", "error against the reference",
               {{"error_x", "max_i |x_i − x_i^{ref}|"},
                {"error_v", "max_i |v_i − v_i^{ref}|"}},
               true);
  }
}

}  // namespace

std::vector<std::string> WritePlots(const std::filesystem::path& dir,
                                    const scene::Scene& s,
                                    const scene::RunLayout& layout,
                                    const std::vector<ColumnStats>& stats,
                                    std::vector<std::string>& warnings) {
  std::vector<std::string> files;
  RunPlots p{dir,
             s,
             layout,
             stats,
             files,
             warnings,
             s.title.empty() ? s.source : s.title};
  PlotTrajectory(p);
  for (const auto& diag : s.output.diagnostics) PlotDiagnostic(p, diag);
  return files;
}

}  // namespace vivp::apps
