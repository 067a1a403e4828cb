// Plotting glue for the solver figures of Rothkopf & Nordström (2023),
// Figs. 2 and 5-15: panels of marker/line series drawn side by side, the
// paths x1, x2 of a solve against the exact solution, and convergence plots
// of the deviation at t_end against Δt = 1/Nt with power-law fits.
//
//   auto sbp21 = vivp::figures::PaperStudy("damped", "sbp21");
//   auto sbp42 = vivp::figures::PaperStudy("damped", "sbp42");
//   vivp::figures::ConvergenceFigure(dir, "fig13_damped_convergence", "...",
//                                    {{"SBP21", sbp21}, {"SBP42", sbp42}},
//                                    {Quantity::kValue,
//                                    Quantity::kDerivative});
//
// Nothing here computes what the solver library does not: the solves, the
// errors and the fitted orders come from solvers/variational.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "studies/registry.h"

namespace vivp::figures {

// gnuplot "with ..." clauses in the paper's colours.
inline constexpr const char* kRedCircles = "points pt 6 ps 1.4 lc rgb 'red'";
inline constexpr const char* kRedDots = "points pt 7 ps 0.5 lc rgb 'red'";
inline constexpr const char* kBlueCrosses = "points pt 2 ps 1.4 lc rgb 'blue'";
inline constexpr const char* kGreenCrosses =
    "points pt 2 ps 1.4 lc rgb '#009900'";
inline constexpr const char* kGrayLine = "lines lw 2 lc rgb 'gray60'";
inline constexpr const char* kGrayDashed = "lines lw 2 dt 2 lc rgb 'gray60'";
inline constexpr const char* kBlackLine = "lines lw 2 lc rgb 'black'";

// One curve of a panel: rows of (x, y) drawn `with` a gnuplot style.
struct Series {
  std::string title;
  std::vector<std::vector<double>> rows;
  std::string with;
};

struct Panel {
  std::string title, xlabel, ylabel;
  std::vector<Series> series;
  std::string settings;  // further gnuplot lines (ranges, logscale, key)
};

// Draws the panels side by side (multiplot), data and script next to the PNG.
std::filesystem::path PanelFigure(const std::filesystem::path& dir,
                                  const std::string& stem,
                                  const std::vector<Panel>& panels);

// f sampled on [t0, t1], for the continuum solutions drawn as lines.
Series Curve(const std::string& title, const std::function<double(double)>& f,
             double t0, double t1, const std::string& with, int samples = 600);

// Component c of a path (x1 or x2 of the solution) against t.
Series PathSeries(const std::string& title,
                  const variational::IvpSolution<double>::Matrix& path,
                  const std::vector<double>& t, const std::string& with,
                  int c = 0);

// x1 (red circles), x2 (blue crosses) and the exact x (gray line).
Panel PathsPanel(const studies::NamedProblem& problem,
                 const variational::IvpSolution<double>& s,
                 const std::string& title);

// The paper's path figures (5, 8, 10, 12): regularized SBP21, Nt = 32 on
// [0, 1] (doubled until resolved for a problem that needs more), the full
// doubled system so that x1 and x2 are solved separately.
std::filesystem::path PathsFigure(const std::filesystem::path& dir,
                                  const std::string& stem,
                                  const std::string& problem_name,
                                  const std::string& title);

// The paper's convergence study: Nt = 16, 32, ..., 512 on [0, 1].
studies::ConvergenceStudy PaperStudy(const std::string& problem_name,
                                     const std::string& op);

enum class Quantity { kValue, kDerivative };

struct ConvergenceSeries {
  std::string label;  // "SBP21": blue crosses; the second series red circles
  studies::ConvergenceStudy study;
  bool fit = true;  // draw the power-law fit (gray) with its slope in the key
};

// One log-log panel per quantity: |x_N − x(t_end)| or |(Dx)_N − ẋ(t_end)|
// against Δt = 1/Nt; fitted slopes are study.orders.
std::filesystem::path ConvergenceFigure(
    const std::filesystem::path& dir, const std::string& stem,
    const std::string& title, const std::vector<ConvergenceSeries>& series,
    const std::vector<Quantity>& quantities);

// The late-time damped oscillator of Figs. 14-15: SBP42 on [0, 204.8], the
// full doubled system (x1 = x2 is then measured, not imposed).
variational::IvpSolution<double> LateTimeDamped(long long points);

// Figs. 9, 11, 13: value and derivative for SBP21 and SBP42, with fits.
std::filesystem::path OperatorPairConvergenceFigure(
    const std::filesystem::path& dir, const std::string& stem,
    const std::string& problem_name, const std::string& title);

}  // namespace vivp::figures
