// Plots of a 1+1-dimensional field: the space-time heat map, snapshots at
// chosen times, and quantities against time (energy, charge, error). They
// take plain arrays, so a scene run, a figure program and a user's own
// solve draw the same pictures.
//
//   vivp::report::FieldSeries f{.t = s.t, .x = xs, .phi = s.phi,
//                               .components = 1};
//   vivp::report::HeatMap(dir, "breather", f, {.title = "sine-Gordon"});
//   vivp::report::Snapshots(dir, "breather_snapshots", f, {0.0, 1.0, 2.0});
//   vivp::report::Curves(dir, "breather_energy", t, {{"E(t) - E(0)", dE}},
//                        {.ylabel = "energy drift"});
//
// Several heat maps side by side (HeatMaps) and curves in stacked panels
// (CurvePanels) make one PNG of a comparison.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace vivp::report {

// Slices of a field: φ at (t[s], x[j], component a) is
// phi[(s·x.size() + j)·components + a].
struct FieldSeries {
  std::vector<double> t, x;
  std::vector<double> phi;
  int components = 1;
  double At(std::size_t s, std::size_t j, int a = 0) const {
    return phi[(s * x.size() + j) * components + a];
  }
};

struct HeatMapStyle {
  std::string title;
  std::string label = "φ";  // the colour bar
  int component = 0;
  // The data file is thinned to at most this many slices and points (every
  // k-th, the last one kept), so a 512 × 512 field plots from a small file.
  int max_slices = 400, max_points = 400;
  bool symmetric = true;  // colour range ±max|φ|, zero in the middle
  int width = 900, height = 650;
};

// x horizontally, t upwards. Writes STEM_field.dat, STEM.gp and STEM.png in
// dir; returns the PNG. Throws std::invalid_argument on a series whose sizes
// do not agree and std::runtime_error if the plot cannot be written.
std::filesystem::path HeatMap(const std::filesystem::path& dir,
                              const std::string& stem, const FieldSeries& f,
                              const HeatMapStyle& style = {});

// The slices with t in [t0, t1] and the points with x in [x0, x1]: a heat
// map of a localized field need not show the empty rest of the domain.
FieldSeries Crop(const FieldSeries& f, double x0, double x1, double t0,
                 double t1);

// Heat maps side by side in one PNG, with one colour range for all (the
// first style's `symmetric` and `label` apply to every panel; each style's
// title is its panel's). Same files and errors as HeatMap.
std::filesystem::path HeatMaps(const std::filesystem::path& dir,
                               const std::string& stem,
                               const std::vector<FieldSeries>& fields,
                               const std::vector<HeatMapStyle>& styles,
                               const std::string& title = "", int width = 1500,
                               int height = 620);

// φ(x) at the slices nearest to each requested time, one curve each.
std::filesystem::path Snapshots(const std::filesystem::path& dir,
                                const std::string& stem, const FieldSeries& f,
                                const std::vector<double>& times,
                                const std::string& title = "",
                                int component = 0);

struct CurveStyle {
  std::string title;
  std::string xlabel = "t", ylabel;
  bool log_y = false;            // plots |y|; zeros are left out
  std::string key = "top left";  // gnuplot's key position
  // gnuplot's "with" clause per curve ("lines lw 2" where absent): curves
  // that coincide stay visible as a thin line on a thick one.
  std::vector<std::string> with;
};

// Named curves y(t) on the same axes.
std::filesystem::path Curves(
    const std::filesystem::path& dir, const std::string& stem,
    const std::vector<double>& t,
    const std::vector<std::pair<std::string, std::vector<double>>>& curves,
    const CurveStyle& style = {});

// Panels of curves against t, stacked one above the other (an error above
// an energy drift, say), all over the range of t; each panel has its own
// style, and its own times where `t` is not empty (a quantity sampled once
// per window, say).
struct CurvePanel {
  std::vector<std::pair<std::string, std::vector<double>>> curves;
  CurveStyle style;
  std::vector<double> t;
};
std::filesystem::path CurvePanels(const std::filesystem::path& dir,
                                  const std::string& stem,
                                  const std::vector<double>& t,
                                  const std::vector<CurvePanel>& panels,
                                  const std::string& title = "",
                                  int width = 900, int height = 800);

}  // namespace vivp::report
