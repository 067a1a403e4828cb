// The plots of a field run: the space-time heat map (one per component),
// snapshots of φ(x), and each diagnostic against time, drawn by
// report/field_plots.h from every slice of the solve.
#include <functional>

#include "apps/run_field.h"
#include "report/field_plots.h"
#include "scene/charged_scene.h"

namespace vivp::apps {

namespace {

// The change since the first value: what a conservation plot shows.
std::vector<double> Drift(const std::vector<double>& v) {
  std::vector<double> d(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) d[i] = v[i] - v.front();
  return d;
}

struct CurveOf {
  std::string name, label, ylabel;
  bool drift, log;
};

CurveOf Describe(const std::string& column) {
  if (column == "energy")
    return {"E(t) - E(0)", "energy", "energy E = Σ Hx (π·φ_t − L), change",
            true, false};
  if (column.rfind("momentum", 0) == 0) {
    const std::string axis = column == "momentum" ? "x" : column.substr(9);
    return {"P(t) - P(0)", column,
            "momentum P_" + axis + " = −Σ H π·∂_" + axis + "φ, change", true,
            false};
  }
  if (column == "charge")
    return {"Q(t) - Q(0)", "charge",
            "U(1) charge Q = Σ Hx (φ_0 π_1 − φ_1 π_0), change", true, false};
  if (column == "gauss")
    return {"max_x |G| / terms", "gauss",
            "Gauss's law of the action (A₀'s equation), relative", false, true};
  if (column == "gauss_textbook")
    return {"max_x |∇·E| / terms", "gauss_textbook",
            "textbook Gauss law ∇·E (exact derivative), relative", false, true};
  return {"max_x |φ − φ_exact|", "error", "error against the exact solution",
          false, true};
}

}  // namespace

std::vector<std::string> WriteFieldPlots(const std::filesystem::path& dir,
                                         const scene::FieldScene& s,
                                         const scene::FieldRun& run,
                                         std::vector<std::string>& warnings) {
  std::vector<std::string> files;
  auto draw = [&](const std::string& png, const std::function<void()>& plot) {
    try {
      plot();
      files.push_back(png);
    } catch (const std::exception& e) {
      warnings.push_back("no " + png + ": " + e.what());
    }
  };
  const auto& sol = run.solution;
  const std::string title = s.title.empty() ? s.source : s.title;
  const report::FieldSeries series{
      .t = sol.t, .x = run.x, .phi = sol.phi, .components = s.components};
  // A field on a grid: its slices are drawn by WriteSlicePictures. A
  // charged field's values are |φ| (≥ 0, its own range), E and ρ.
  const auto charged = scene::ChargedValueLabels(s.Dim());
  for (int a = 0; a < s.components && s.Dim() == 1; ++a) {
    const std::string stem = a == 0 ? "field" : "field_" + std::to_string(a);
    const std::string label = s.Charged()         ? charged.at(std::size_t(a))
                              : s.components == 1 ? "φ"
                                                  : "φ_" + std::to_string(a);
    draw(stem + ".png", [&] {
      report::HeatMap(dir, stem, series,
                      {.title = title,
                       .label = label,
                       .component = a,
                       .symmetric = !(s.Charged() && a == 0)});
    });
  }
  std::vector<double> times;
  for (int k = 0; k <= 4; ++k) times.push_back(s.t_end * k / 4.0);
  // Snapshots share one axis: not for |φ|, E and ρ together.
  if (s.Dim() == 1 && !s.Charged())
    draw("snapshots.png",
         [&] { report::Snapshots(dir, "snapshots", series, times, title); });
  for (std::size_t c = 0; c < run.columns.size(); ++c) {
    const CurveOf curve = Describe(run.columns[c]);
    const auto& v = run.values[c];
    draw(curve.label + ".png", [&] {
      report::Curves(
          dir, curve.label, sol.t, {{curve.name, curve.drift ? Drift(v) : v}},
          {.title = title, .ylabel = curve.ylabel, .log_y = curve.log});
    });
  }
  return files;
}

}  // namespace vivp::apps
