// The sine-Gordon breather ω = 0.5 (period 2π/ω ≈ 12.57) marched to
// T = 100 on [−20, 20): periodic order-8 differences in space, SBP42 in time
// in windows of 16 points (docs/fields.md §4, §7). Three runs, the grids of
// the second table of bench/fields_bench.cc: 200 points at Δt = 0.02 and
// 0.01, 400 points at Δt = 0.02.
//
// - fig_fields_breather_map: φ(t, x) over four periods (400 points).
// - fig_fields_breather: above, the largest |φ − φ_exact| of each slice
//   (log scale); below, |E(t) − E(0)|, the discrete energy of a slice
//   (core/action/field_charges.h) against that of the discrete initial
//   data, at every slice but the last.
//
// What it shows: the error of the two 200-point runs lies on one curve, so
// it is the spatial grid's, not the time step's; 400 points lower it 50-fold
// at T. The energy does not drift: its deviation is bounded, the same on
// both grids, and 8.4 times smaller at half the Δt (order 3, docs/fields.md
// §6).
//
// Usage: fig_fields_breather [OUTPUT_DIR]                     (about 30 s)
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "core/action/field_charges.h"
#include "figures/field_figures.h"
#include "problems/fields/densities.h"
#include "problems/fields/exact.h"
#include "report/field_plots.h"
#include "solvers/spacetime/solve.h"

using namespace vivp;

namespace {

// The error is drawn every kStep; the energy as its largest deviation in
// each half period kBin (it deviates in a burst once every half period,
// when the breather passes through φ = 0, and is flat in between). Every
// slice enters the maxima in the titles.
constexpr double kOmega = 0.5, kEnd = 100.0, kStep = 0.02,
                 kBin = std::numbers::pi / kOmega;
// Bin b is centred on the burst at t = b·kBin; the half period after the
// last burst before kEnd is left out of the curve (not of the maxima).
const int kBins = int(kEnd / kBin) + 1;

struct Curves {
  std::vector<double> error;     // at t = 0, kStep, 2kStep, …
  std::vector<double> envelope;  // max |E − E0| at interior slices per bin
  double end_error = 0, end_energy = 0;  // at the last slice
  double error50 = 0, error_end = 0;     // the error to t = 50 and at T
  double interior_energy = 0;            // max |E − E0| before it
  double e0 = 0;                         // energy of the initial data
  report::FieldSeries field;
  double seconds = 0;
};

// Solves one grid; error and energy drift at the times of kStep.
Curves Solve(const figures::FieldRun& run) {
  const fields::SineGordon sg;
  const fields::SineGordonBreather breather{kOmega};
  const auto dx = sbp::SpaceDerivative<double>::Periodic(8, run.nx, -20, 40);
  const auto [phi0, pi0] = fields::InitialData(breather, dx);
  const double e0 = action::ChargesOfSlice(sg, dx, phi0, pi0).energy;
  const auto s =
      spacetime::SolveField(sg, dx, {"sbp42", run.nt, kEnd, 16}, phi0, pi0);
  if (!s.status.converged) throw std::runtime_error(s.status.reason);
  Curves c;
  c.seconds = s.seconds_total;
  c.e0 = e0;
  const int nx = run.nx;
  const auto stride = std::size_t(std::lround(kStep / s.dt));
  c.envelope.assign(kBins, 0.0);
  // Every slice enters the maxima; every stride-th the curves.
  for (std::size_t k = 0; k < s.t.size(); ++k) {
    double worst = 0;
    for (int j = 0; j < nx; ++j)
      worst = std::max(worst,
                       std::abs(s.phi[k * nx + j] - breather(s.t[k], dx.x(j))));
    const std::span<const double> p(s.phi.data() + k * nx, nx);
    const std::span<const double> q(s.phi_t.data() + k * nx, nx);
    const double de = action::ChargesOfSlice(sg, dx, p, q).energy - e0;
    // The march's last slice has the closure row's φ_t, an order less
    // accurate than the others (docs/fields.md §6); where two windows meet
    // the slice is the corrected hand-off state (§4).
    const bool end = k + 1 == s.t.size();
    if (end) {
      c.end_error = std::max(c.end_error, worst);
      c.end_energy = std::max(c.end_energy, std::abs(de));
    } else {
      c.interior_energy = std::max(c.interior_energy, std::abs(de));
      const int b = int(s.t[k] / kBin + 0.5);
      if (b < kBins) c.envelope[b] = std::max(c.envelope[b], std::abs(de));
    }
    if (s.t[k] <= 50) c.error50 = std::max(c.error50, worst);
    c.error_end = worst;
    if (k % stride) continue;
    c.error.push_back(worst);
  }
  for (int j = 0; j < nx; ++j) c.field.x.push_back(dx.x(j));
  c.field.t = s.t;
  c.field.phi = s.phi;
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  const std::vector<figures::FieldRun> runs = {
      {200, 5001}, {400, 5001}, {200, 10001}};
  std::vector<double> t;
  for (int i = 0; i * kStep <= kEnd + 1e-9; ++i) t.push_back(i * kStep);
  std::vector<report::CurvePanel> panels(2);
  for (int b = 0; b < kBins; ++b) panels[1].t.push_back(b * kBin);
  std::vector<Curves> c;
  for (const figures::FieldRun& run : runs) {
    c.push_back(Solve(run));
    const std::string key = run.Key(kEnd);
    panels[0].curves.push_back({key, c.back().error});
    panels[1].curves.push_back({key, c.back().envelope});
    std::printf(
        "%-24s max error t ≤ 50: %.2e, at T: %.2e; max |E − E0| before the "
        "last slice %.2e, at it %.2e; %.1f s\n",
        key.c_str(), c.back().error50, c.back().error_end,
        c.back().interior_energy, c.back().end_energy, c.back().seconds);
  }
  char title[2][256];
  std::snprintf(title[0], sizeof title[0],
                "max_j |φ − φ_{exact}| per slice: ≤ %.1e on 200 points to "
                "t = 50;\nat T = 100 %.2f on 200 points (both Δt), %.1e on "
                "400 points",
                std::max(c[0].error50, c[2].error50), c[0].error_end,
                c[1].error_end);
  std::snprintf(title[1], sizeof title[1],
                "largest |E(t) − E(0)| in each half period (E(0) = %.2f):\n"
                "≤ %.1e at Δt = 0.02, ≤ %.1e at Δt = 0.01 (at the last "
                "slice, left out: %.1e, %.1e)",
                c[0].e0, c[0].interior_energy, c[2].interior_energy,
                c[0].end_energy, c[2].end_energy);
  panels[0].style = {.title = title[0],
                     .xlabel = "",
                     .ylabel = "error",
                     .log_y = true,
                     .with = figures::ThickUnderThin()};
  panels[1].style = {.title = title[1],
                     .ylabel = "|E(t) − E(0)|",
                     .log_y = true,
                     .key = "center right",
                     .with = figures::ThickUnderThin("linespoints pt 7")};
  const auto curves = report::CurvePanels(
      dir, "fig_fields_breather", t, panels,
      "sine-Gordon breather ω = 0.5 on [−20, 20), periodic order-8 "
      "differences, SBP42 in time (windows of 16)",
      900, 850);
  const double periods = 4 * 2 * std::numbers::pi / kOmega;
  const auto heat = report::HeatMap(
      dir, "fig_fields_breather_map",
      report::Crop(c[1].field, -10, 10, 0, periods),
      {.title = "sine-Gordon breather ω = 0.5, four periods: 400 points on "
                "[−20, 20) (|x| ≤ 10 shown), Δt = 0.02, SBP42"});
  std::printf("%s\n%s\n", curves.c_str(), heat.c_str());
}
