#include "report/field_plots.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "report/plot.h"

namespace vivp::report {

namespace fs = std::filesystem;

namespace {

void CheckSeries(const FieldSeries& f, int component) {
  if (f.components < 1 || component < 0 || component >= f.components)
    throw std::invalid_argument("field plot: component " +
                                std::to_string(component) + " of " +
                                std::to_string(f.components));
  if (f.t.empty() || f.x.empty() ||
      f.phi.size() != f.t.size() * f.x.size() * std::size_t(f.components))
    throw std::invalid_argument(
        "field plot: " + std::to_string(f.phi.size()) + " values for " +
        std::to_string(f.t.size()) + " slices × " + std::to_string(f.x.size()) +
        " points × " + std::to_string(f.components) + " components");
}

// The thinned rows (x, t, φ) of a heat map and the largest |φ| among them.
std::vector<std::vector<double>> HeatRows(const FieldSeries& f,
                                          const HeatMapStyle& style,
                                          double& top) {
  CheckSeries(f, style.component);
  const auto slices = Thin(f.t.size(), style.max_slices);
  const auto points = Thin(f.x.size(), style.max_points);
  std::vector<std::vector<double>> rows;
  rows.reserve(slices.size() * points.size());
  for (std::size_t s : slices)
    for (std::size_t j : points) {
      const double v = f.At(s, j, style.component);
      if (std::isfinite(v)) top = std::max(top, std::abs(v));
      rows.push_back({f.x[j], f.t[s], v});
    }
  return rows;
}

// The colour range and palette: ±top around white, or viridis.
void Palette(std::ostream& gp, const HeatMapStyle& style, double top) {
  gp << "set cblabel " << Quoted(style.label) << "\n";
  if (style.symmetric && top > 0)
    gp << "set cbrange [" << -top << ":" << top << "]\n" << kDivergingPalette;
  else
    gp << kViridisPalette;
}

// One panel: axes, title and the image of rows written as STEM_NAME.dat.
void HeatPanel(Figure& fig, const std::string& name, const FieldSeries& f,
               const std::vector<std::vector<double>>& rows,
               const HeatMapStyle& style) {
  const auto data = fig.Data(name, rows, "x t " + style.label);
  auto& gp = fig.script();
  gp << "set title " << Quoted(style.title) << "\n"
     << "set xlabel 'x'\nset ylabel 't'\n"
     << "set xrange [" << rows.front()[0] << ":" << rows.back()[0] << "]\n"
     << "set yrange [" << f.t.front() << ":" << f.t.back() << "]\n"
     << "plot '" << data << "' using 1:2:3 with image notitle\n";
}

// One panel of named curves y(t): axes, scale and plot command.
// x0, x1: the horizontal range.
void CurvesPanel(
    Figure& fig, const std::string& prefix, const std::vector<double>& t,
    const std::vector<std::pair<std::string, std::vector<double>>>& curves,
    const CurveStyle& style, double x0, double x1) {
  if (curves.empty()) throw std::invalid_argument("curves: nothing to plot");
  auto& gp = fig.script();
  gp << "set title " << Quoted(style.title) << "\n"
     << "set xlabel " << Quoted(style.xlabel) << "\n"
     << "set ylabel " << Quoted(style.ylabel) << "\n";
  if (style.log_y)
    gp << "set logscale y\nset format y '10^{%T}'\n";
  else
    gp << "unset logscale y\nset format y '% h'\n";
  gp << "set key " << style.key << "\nset grid\n";
  gp << "set xrange [" << x0 << ":" << x1 << "]\n";
  gp << "plot ";
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const auto& [name, y] = curves[k];
    if (y.size() != t.size())
      throw std::invalid_argument("curves: '" + name + "' has " +
                                  std::to_string(y.size()) + " values for " +
                                  std::to_string(t.size()) + " times");
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double v = style.log_y ? std::abs(y[i]) : y[i];
      if (std::isfinite(v) && (!style.log_y || v > 0))
        rows.push_back({t[i], v});
    }
    const auto data = fig.Data(prefix + std::to_string(k), rows, "t y");
    gp << (k ? ", " : "") << "'" << data << "' using 1:2 with "
       << (k < style.with.size() ? style.with[k] : "lines lw 2") << " title "
       << Quoted(name);
  }
  gp << "\n";
}

}  // namespace

fs::path HeatMap(const fs::path& dir, const std::string& stem,
                 const FieldSeries& f, const HeatMapStyle& style) {
  double top = 0;
  const auto rows = HeatRows(f, style, top);
  Figure fig(dir, stem, style.width, style.height);
  Palette(fig.script(), style, top);
  HeatPanel(fig, "field", f, rows, style);
  return fig.Render();
}

fs::path HeatMaps(const fs::path& dir, const std::string& stem,
                  const std::vector<FieldSeries>& fields,
                  const std::vector<HeatMapStyle>& styles,
                  const std::string& title, int width, int height) {
  if (fields.empty() || fields.size() != styles.size())
    throw std::invalid_argument("heat maps: " + std::to_string(fields.size()) +
                                " fields and " + std::to_string(styles.size()) +
                                " styles");
  double top = 0;
  std::vector<std::vector<std::vector<double>>> rows;
  for (std::size_t k = 0; k < fields.size(); ++k)
    rows.push_back(HeatRows(fields[k], styles[k], top));
  Figure fig(dir, stem, width, height);
  auto& gp = fig.script();
  Palette(gp, styles.front(), top);
  gp << "set multiplot layout 1," << fields.size();
  if (!title.empty()) gp << " title " << Quoted(title);
  gp << "\n";
  for (std::size_t k = 0; k < fields.size(); ++k)
    HeatPanel(fig, "field" + std::to_string(k), fields[k], rows[k], styles[k]);
  gp << "unset multiplot\n";
  return fig.Render();
}

FieldSeries Crop(const FieldSeries& f, double x0, double x1, double t0,
                 double t1) {
  CheckSeries(f, 0);
  FieldSeries c;
  c.components = f.components;
  std::vector<std::size_t> js;
  for (std::size_t j = 0; j < f.x.size(); ++j)
    if (f.x[j] >= x0 && f.x[j] <= x1) {
      js.push_back(j);
      c.x.push_back(f.x[j]);
    }
  for (std::size_t s = 0; s < f.t.size(); ++s) {
    if (f.t[s] < t0 || f.t[s] > t1) continue;
    c.t.push_back(f.t[s]);
    for (std::size_t j : js)
      for (int a = 0; a < f.components; ++a) c.phi.push_back(f.At(s, j, a));
  }
  if (c.t.empty() || c.x.empty())
    throw std::invalid_argument("crop: no slice or point in the window");
  return c;
}

fs::path Snapshots(const fs::path& dir, const std::string& stem,
                   const FieldSeries& f, const std::vector<double>& times,
                   const std::string& title, int component) {
  CheckSeries(f, component);
  if (times.empty())
    throw std::invalid_argument("snapshots: no times requested");
  Figure fig(dir, stem);
  auto& gp = fig.script();
  if (!title.empty()) gp << "set title " << Quoted(title) << "\n";
  gp << "set xlabel 'x'\nset ylabel 'φ'\nset key outside right\nplot ";
  for (std::size_t k = 0; k < times.size(); ++k) {
    const auto near =
        std::min_element(f.t.begin(), f.t.end(), [&](double a, double b) {
          return std::abs(a - times[k]) < std::abs(b - times[k]);
        });
    const std::size_t s = std::size_t(near - f.t.begin());
    std::vector<std::vector<double>> rows;
    for (std::size_t j = 0; j < f.x.size(); ++j)
      rows.push_back({f.x[j], f.At(s, j, component)});
    const auto data = fig.Data("t" + std::to_string(k), rows, "x phi");
    gp << (k ? ", " : "") << "'" << data << "' using 1:2 with lines lw 2 "
       << "title 't = " << f.t[s] << "'";
  }
  gp << "\n";
  return fig.Render();
}

fs::path Curves(
    const fs::path& dir, const std::string& stem, const std::vector<double>& t,
    const std::vector<std::pair<std::string, std::vector<double>>>& curves,
    const CurveStyle& style) {
  if (t.empty()) throw std::invalid_argument("curves: no times");
  Figure fig(dir, stem);
  CurvesPanel(fig, "c", t, curves, style, t.front(), t.back());
  return fig.Render();
}

fs::path CurvePanels(const fs::path& dir, const std::string& stem,
                     const std::vector<double>& t,
                     const std::vector<CurvePanel>& panels,
                     const std::string& title, int width, int height) {
  if (panels.empty() || t.empty())
    throw std::invalid_argument("curve panels: no panel or no times");
  Figure fig(dir, stem, width, height);
  auto& gp = fig.script();
  gp << "set multiplot layout " << panels.size() << ",1";
  if (!title.empty()) gp << " title " << Quoted(title);
  gp << "\n";
  for (std::size_t k = 0; k < panels.size(); ++k)
    CurvesPanel(fig, "p" + std::to_string(k) + "c",
                panels[k].t.empty() ? t : panels[k].t, panels[k].curves,
                panels[k].style, t.front(), t.back());
  gp << "unset multiplot\n";
  return fig.Render();
}

}  // namespace vivp::report
