#include "figures/solver_figures.h"

#include <algorithm>
#include <cstdio>

#include "core/linalg/fit.h"
#include "report/plot.h"

namespace vivp::figures {
namespace {

// Fixed-precision text for slopes in keys.
std::string Fixed(double v, int digits = 2) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

double Error(const studies::ConvergenceRow& r, Quantity q) {
  return q == Quantity::kValue ? r.err_x : r.err_v;
}

double Order(const studies::ConvergenceStudy& s, Quantity q) {
  return q == Quantity::kValue ? s.orders.x : s.orders.v;
}

}  // namespace

std::filesystem::path PanelFigure(const std::filesystem::path& dir,
                                  const std::string& stem,
                                  const std::vector<Panel>& panels) {
  const int n = static_cast<int>(panels.size());
  report::Figure fig(dir, stem, n == 1 ? 900 : 750 * n, 600);
  auto& s = fig.script();
  s << "set multiplot\n";
  for (int p = 0; p < n; ++p) {
    const Panel& panel = panels[p];
    // reset keeps each panel's settings from leaking into the next one.
    s << "reset\nset origin " << double(p) / n << ",0\nset size " << 1.0 / n
      << ",1\nset grid\nset key box opaque below horizontal\n"
      << "set bmargin 6\nset autoscale fix\n"
      << "set offsets graph 0.02, graph 0.02, graph 0.05, graph 0.05\n"
      << "set title '" << panel.title << "'\nset xlabel '" << panel.xlabel
      << "'\nset ylabel '" << panel.ylabel << "'\n"
      << panel.settings << "\nplot ";
    bool first = true;
    for (std::size_t k = 0; k < panel.series.size(); ++k) {
      const Series& c = panel.series[k];
      if (c.rows.empty()) continue;  // gnuplot refuses empty data files
      // Built by append: GCC 12 warns falsely (-Wrestrict, bug 105329) on
      // chains of std::string operator+.
      std::string name = "p";
      name.append(std::to_string(p)).append("_").append(std::to_string(k));
      const auto file = fig.Data(name, c.rows, "x y");
      s << (first ? "" : ", \\\n     ") << "'" << file << "' using 1:2 with "
        << c.with << " title '" << c.title << "'";
      first = false;
    }
    s << "\n";
  }
  s << "unset multiplot\n";
  return fig.Render();
}

Series Curve(const std::string& title, const std::function<double(double)>& f,
             double t0, double t1, const std::string& with, int samples) {
  Series c{title, {}, with};
  for (int i = 0; i < samples; ++i) {
    const double t = t0 + (t1 - t0) * i / (samples - 1);
    c.rows.push_back({t, f(t)});
  }
  return c;
}

Series PathSeries(const std::string& title,
                  const variational::IvpSolution<double>::Matrix& path,
                  const std::vector<double>& t, const std::string& with,
                  int c) {
  Series out{title, {}, with};
  for (std::size_t i = 0; i < t.size(); ++i)
    out.rows.push_back({t[i], path(static_cast<Eigen::Index>(i), c)});
  return out;
}

Panel PathsPanel(const studies::NamedProblem& problem,
                 const variational::IvpSolution<double>& s,
                 const std::string& title) {
  Panel panel{title, "t", "x(t)", {}, ""};
  panel.series.push_back(Curve(
      "exact", [&](double t) { return problem.exact(t).x[0]; }, s.t.front(),
      s.t.back(), kGrayLine));
  panel.series.push_back(PathSeries("x_1", s.x1, s.t, kRedCircles));
  panel.series.push_back(PathSeries("x_2", s.x2, s.t, kBlueCrosses));
  return panel;
}

std::filesystem::path PathsFigure(const std::filesystem::path& dir,
                                  const std::string& stem,
                                  const std::string& problem_name,
                                  const std::string& title) {
  const studies::NamedProblem& problem = studies::FindProblem(problem_name);
  variational::SolveOptions options;
  options.path = variational::Path::kFullNewton;
  // The paper's Nt = 32; a problem whose interval or frequencies need more
  // (Kepler e = 0.9 over an orbit) gets the first doubling that resolves it.
  long long points = 32;
  auto s = problem.solve({.op = "sbp21", .points = points}, options);
  while (!s.status.converged &&
         s.status.reason.rfind("under-resolved", 0) == 0 && points < 8192) {
    points *= 2;
    s = problem.solve({.op = "sbp21", .points = points}, options);
  }
  if (!s.status.converged)
    throw std::runtime_error(problem_name + ": " + s.status.reason);
  return PanelFigure(dir, stem, {PathsPanel(problem, s, title)});
}

studies::ConvergenceStudy PaperStudy(const std::string& problem_name,
                                     const std::string& op) {
  return RunConvergence(studies::FindProblem(problem_name),
                        {.op = op, .points = 16}, {16, 32, 64, 128, 256, 512},
                        {});
}

std::filesystem::path ConvergenceFigure(
    const std::filesystem::path& dir, const std::string& stem,
    const std::string& title, const std::vector<ConvergenceSeries>& series,
    const std::vector<Quantity>& quantities) {
  static const char* const kStyles[] = {kBlueCrosses, kRedCircles,
                                        kGreenCrosses};
  std::vector<Panel> panels;
  for (Quantity q : quantities) {
    Panel panel{
        title + (q == Quantity::kValue ? ": value" : ": derivative"),
        "{/Symbol D}t = 1/N_t",
        q == Quantity::kValue ? "|x_N - x(t_2)|" : "|(Dx)_N - dx/dt(t_2)|",
        {},
        "set logscale xy\nset format y '10^{%L}'\n"};
    // Tics at the grids of the study, labelled 1/Nt.
    std::string tics;
    for (const auto& r : series.front().study.rows)
      tics += (tics.empty() ? "'1/" : ", '1/") + std::to_string(r.points) +
              "' " + Fixed(r.dt, 17);
    panel.settings += "set xtics (" + tics + ")\n";
    for (std::size_t k = 0; k < series.size(); ++k) {
      const ConvergenceSeries& cs = series[k];
      // Exact zeros (round-off cancelled completely) have no logarithm.
      Series points{cs.label, {}, kStyles[k % 3]};
      std::vector<double> dt, err;
      for (const auto& r : cs.study.rows) {
        dt.push_back(r.dt);
        err.push_back(Error(r, q));
        if (Error(r, q) > 0) points.rows.push_back({r.dt, Error(r, q)});
      }
      panel.series.push_back(points);
      if (!cs.fit) continue;
      // Same fit and round-off floor as RunConvergence, for the prefactor.
      const linalg::PowerLawFit fit = linalg::FitPowerLaw(dt, err, 1e-13);
      if (!(fit.points_used >= 2)) continue;
      Series line{
          cs.label + " fit {/Symbol D}t^{" + Fixed(Order(cs.study, q)) + "}",
          {},
          k == 0 ? kGrayLine : kGrayDashed};
      for (double h : {dt.front(), dt.back()})
        line.rows.push_back({h, fit.prefactor * std::pow(h, fit.order)});
      panel.series.push_back(line);
    }
    panels.push_back(panel);
  }
  return PanelFigure(dir, stem, panels);
}

variational::IvpSolution<double> LateTimeDamped(long long points) {
  variational::SolveOptions options;
  options.path = variational::Path::kFullNewton;
  auto s = studies::FindProblem("damped").solve(
      {.op = "sbp42", .points = points, .t_end = 204.8}, options);
  if (!s.status.converged)
    throw std::runtime_error("late-time damped oscillator, Nt = " +
                             std::to_string(points) + ": " + s.status.reason);
  return s;
}

std::filesystem::path OperatorPairConvergenceFigure(
    const std::filesystem::path& dir, const std::string& stem,
    const std::string& problem_name, const std::string& title) {
  return ConvergenceFigure(dir, stem, title,
                           {{"SBP21", PaperStudy(problem_name, "sbp21")},
                            {"SBP42", PaperStudy(problem_name, "sbp42")}},
                           {Quantity::kValue, Quantity::kDerivative});
}

}  // namespace vivp::figures
