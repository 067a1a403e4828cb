// A φ⁴ oscillon in 2 + 1 dimensions: the collapsing bubble of Copeland,
// Gleiser & Müller ("Oscillons: resonant configurations during bubble
// collapse", Phys. Rev. D 52, 1995), here on a plane. L = ½φ_t² − ½|∇φ|² −
// ¼λ(φ² − v²)² with λ = ½, v = 1, so the mass of the vacuum is
// m = √(2λ) v = 1 and times and lengths are in units of 1/m; in 2-D the
// energy scales as v² at fixed m·x, so E is given in units of v². (With
// λ = v = 1, m = √2: divide R and t by √2, ω/m is unchanged.)
//
// φ(0) = v − 2v exp(−r²/R²), R = 3, φ_t(0) = 0, centred in a periodic
// square [−24, 24)², order-8 differences on both axes, SBP42 in time in
// windows of 16. Four runs: Δx = 1/2 at Δt = 0.1 and 0.05, Δx = 1/3 at
// Δt = 0.1, and Δx = 1/3 with the bubble's amplitude multiplied by
// 1 + 10⁻³ cos 4θ (the shape the square grid can imprint). Each run's
// window boundaries give φ and φ_t everywhere; from them:
//
// - φ(0, t) at the centre, and the frequency from its upward crossings of
//   φ = v/2 (cubic Hermite interpolation between boundaries, which have
//   φ_t), averaged over t ∈ [50, 125] and per period;
// - the energy in the disk r < 3R, E(r < 3R, t), with the order-8 gradient
//   and the trapezoidal weights (the total is ChargesOfSlice's);
// - where the first stage ends: the first t > 50 at which that energy falls
//   below 0.9 of its mean over [50, 125].
//
// The references are the ones a reader can check without the papers'
// figures: the frequency of a localized lump lies below the mass gap m; the
// exact energy of the initial bubble, E(0) = 2πv² + πλv⁴R²/3 (the gradient
// gives 2πv² at every R); and the small-amplitude limit of the 2-D
// oscillon. Near the vacuum, u = φ/v − 1 obeys ü + u + (3/2)u² + ½u³ = ∇²u
// (m = 1); its oscillation frequency at first-harmonic amplitude a is
// 1 − κa², κ = 3b/8 − 5a₂²/12 = 3/4 (Landau & Lifshitz, "Mechanics", §28,
// with a₂ = 3/2, b = ½), so a slowly varying envelope obeys the 2-D cubic
// Schrödinger equation, whose stationary lumps (the Townes profile of
// Chiao, Garmire & Townes, "Self-trapping of optical beams", Phys. Rev.
// Lett. 13, 1964) all have the same norm N_T. The oscillon's energy then
// tends to N_T v²/(4κ) = N_T v²/3 as ω → m, whatever λ; N_T is computed
// below by shooting. The 2-D studies of Hindmarsh & Salmi ("Numerical
// investigations of oscillons in 2 dimensions", 2006) and Salmi & Hindmarsh
// ("Radiation and relaxation of oscillons", 2012) give their frequencies
// and energies in figures not checked here; the lifetimes in their
// abstracts (at least 10⁷ oscillations; no decay within 10⁸ time units)
// are far beyond t = 300.
//
// What it shows: the bubble settles within t ≈ 30 into a lump oscillating
// at ω = 0.780 m, below the gap, with 9.89 v² in r < 3R; both agree to
// 0.1 % between the grids and time steps. That first stage then ends at a
// time that is not converged: 162 on Δx = 1/2 (either Δt), 290 on
// Δx = 1/3, and 153 once the bubble carries the 10⁻³ cos 4θ perturbation.
//
// - fig_fields_oscillon: φ(0, t); the frequency per period; E(r < 3R, t).
//
// Usage: fig_fields_oscillon [OUTPUT_DIR]                   (about 5 minutes)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/action/field_charges.h"
#include "figures/field_figures.h"
#include "problems/fields/densities.h"
#include "report/field_plots.h"
#include "solvers/spacetime/solve.h"

using namespace vivp;

namespace {

using Density = fields::Phi4In<2>;
using Grid = sbp::SpaceGrid<double>;

constexpr double kLambda = 0.5, kV = 1.0, kRadius = 3.0, kHalf = 24.0;
constexpr double kDisk = 3 * kRadius, kLevel = 0.5 * kV;
constexpr double kFrom = 50, kTo = 125, kEnd = 300;  // the first stage
constexpr double kPi = std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// n² points on [−kHalf, kHalf)², nt time points on [0, t_end], and the
// amplitude of the cos 4θ perturbation of the bubble.
struct Run {
  int n;
  long long nt;
  double t_end, seed;
  std::string Key() const {
    char key[96];
    std::snprintf(key, sizeof key, "Δx = %.3g, Δt = %g%s", 2 * kHalf / n,
                  t_end / double(nt - 1), seed ? ", 10⁻³ cos 4θ" : "");
    return key;
  }
};

// At every window boundary.
struct Series {
  std::vector<double> t, center, center_t, disk, total;
  double seconds = 0;
};

Grid MakeGrid(int n) {
  const auto axis =
      sbp::SpaceDerivative<double>::Periodic(8, n, -kHalf, 2 * kHalf);
  return Grid({axis, axis});
}

// The energy density ½φ_t² + ½|∇φ|² + ¼λ(φ² − v²)² summed with the grid's
// weights over r < kDisk (returned) and over the box (total).
double DiskEnergy(const Grid& g, std::span<const double> phi,
                  std::span<const double> phi_t, double& total) {
  std::vector<double> phi_x(phi.size() * 2);
  Grid::GradientWork<double> work;
  g.Gradient<double>(1, phi, phi_x, work);
  double disk = 0;
  total = 0;
  for (int j = 0; j < g.points(); ++j) {
    const double w = phi[j] * phi[j] - kV * kV;
    const double e = 0.5 * phi_t[j] * phi_t[j] +
                     0.5 * (phi_x[2 * j] * phi_x[2 * j] +
                            phi_x[2 * j + 1] * phi_x[2 * j + 1]) +
                     0.25 * kLambda * w * w;
    total += g.NormWeight(j) * e;
    if (std::hypot(g.x(j, 0), g.x(j, 1)) < kDisk) disk += g.NormWeight(j) * e;
  }
  return disk;
}

Series Solve(const Run& run) {
  const Density density{kLambda, kV};
  const Grid g = MakeGrid(run.n);
  std::vector<double> phi0(g.points()), pi0(g.points(), 0.0);
  for (int j = 0; j < g.points(); ++j) {
    const double x = g.x(j, 0), y = g.x(j, 1);
    const double bump = std::exp(-(x * x + y * y) / (kRadius * kRadius));
    phi0[j] =
        kV - 2 * kV * bump * (1 + run.seed * std::cos(4 * std::atan2(y, x)));
  }
  const int centre = run.n / 2 * (run.n + 1);  // x = y = 0
  Series s;
  auto record = [&](double t, std::span<const double> p,
                    std::span<const double> q) {
    double total = 0;
    s.disk.push_back(DiskEnergy(g, p, q, total));
    s.total.push_back(total);
    s.t.push_back(t);
    s.center.push_back(p[centre]);
    s.center_t.push_back(q[centre]);
  };
  record(0, phi0, pi0);
  spacetime::FieldSolveOptions o;
  o.keep_field = false;  // 144² points × 3000 slices would not fit
  o.on_checkpoint = [&](const spacetime::FieldCheckpoint& c) {
    if (c.t > s.t.back()) record(c.t, c.phi, c.phi_t);
  };
  const spacetime::FieldGrid fg{
      .op = "sbp42", .points = run.nt, .t_end = run.t_end, .window_points = 16};
  const auto r = spacetime::SolveField(density, g, fg, phi0, pi0, o);
  if (!r.status.converged) throw std::runtime_error(r.status.reason);
  record(run.t_end, r.end.phi, r.end.phi_t);
  // The total must be the Noether energy of the library.
  const double e0 = action::ChargesOfSlice(density, g, phi0, pi0).energy;
  if (std::abs(e0 - s.total[0]) > 1e-9 * e0)
    throw std::logic_error("the energy density disagrees with ChargesOfSlice");
  s.seconds = r.seconds_total;
  return s;
}

// φ(0, t) between boundaries k and k + 1 at fraction u: the cubic Hermite
// interpolant of φ and φ_t.
double Hermite(const Series& s, std::size_t k, double u) {
  const double h = s.t[k + 1] - s.t[k], u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * s.center[k] +
         (u3 - 2 * u2 + u) * h * s.center_t[k] +
         (3 * u2 - 2 * u3) * s.center[k + 1] +
         (u3 - u2) * h * s.center_t[k + 1];
}

// The times at which φ(0, t) rises through kLevel (bisection on the
// interpolant between boundaries that bracket it).
std::vector<double> UpCrossings(const Series& s) {
  std::vector<double> up;
  for (std::size_t k = 0; k + 1 < s.t.size(); ++k) {
    if (!(s.center[k] < kLevel && s.center[k + 1] >= kLevel)) continue;
    double a = 0, b = 1;
    for (int i = 0; i < 60; ++i)
      ((Hermite(s, k, 0.5 * (a + b)) < kLevel) ? a : b) = 0.5 * (a + b);
    up.push_back(s.t[k] + 0.5 * (a + b) * (s.t[k + 1] - s.t[k]));
  }
  return up;
}

struct Stage {
  double omega = 0;  // 2π · periods / their span, in [kFrom, kTo]
  int periods = 0;
  double e_mean = 0, e_lo = 1e300, e_hi = 0;  // E(r < 3R) in [kFrom, kTo]
  double phi_lo = 1e300, phi_hi = -1e300;     // φ(0, t) in [kFrom, kTo]
  double end = kNaN;                          // E(r < 3R) < 0.9 e_mean
  double drift = 0;                           // max |E(t) − E(0)|
};

Stage Measure(const Series& s) {
  Stage m;
  int n = 0;
  for (std::size_t k = 0; k < s.t.size(); ++k) {
    m.drift = std::max(m.drift, std::abs(s.total[k] - s.total[0]));
    if (s.t[k] < kFrom || s.t[k] > kTo) continue;
    m.e_mean += s.disk[k];
    m.e_lo = std::min(m.e_lo, s.disk[k]);
    m.e_hi = std::max(m.e_hi, s.disk[k]);
    m.phi_lo = std::min(m.phi_lo, s.center[k]);
    m.phi_hi = std::max(m.phi_hi, s.center[k]);
    ++n;
  }
  m.e_mean /= n;
  for (std::size_t k = 0; k < s.t.size(); ++k)
    if (s.t[k] > kFrom && s.disk[k] < 0.9 * m.e_mean) {
      m.end = s.t[k];
      break;
    }
  std::vector<double> up;
  for (double c : UpCrossings(s))
    if (c >= kFrom && c <= kTo) up.push_back(c);
  m.periods = int(up.size()) - 1;
  if (m.periods < 1) throw std::runtime_error("no period in [50, 125]");
  m.omega = 2 * kPi * m.periods / (up.back() - up.front());
  return m;
}

// N_T = ∫ Q² d²y of the Townes profile, Q'' + Q'/r − Q + Q³ = 0, Q'(0) = 0,
// Q → 0: Q(0) by bisection (too large: Q crosses zero; too small: Q turns
// back up), the norm by the trapezoidal rule up to where the shot leaves
// the profile (RK4, h = 10⁻³).
double TownesNorm() {
  auto shoot = [](double q0, double& norm) {
    constexpr double h = 1e-3;
    double r = 1e-8, q = q0, p = 0;
    norm = 0;
    auto f = [](double r, double q, double p, double& dq, double& dp) {
      dq = p;
      dp = -p / r + q - q * q * q;
    };
    while (r < 12) {
      double k[4][2];
      f(r, q, p, k[0][0], k[0][1]);
      f(r + h / 2, q + h / 2 * k[0][0], p + h / 2 * k[0][1], k[1][0], k[1][1]);
      f(r + h / 2, q + h / 2 * k[1][0], p + h / 2 * k[1][1], k[2][0], k[2][1]);
      f(r + h, q + h * k[2][0], p + h * k[2][1], k[3][0], k[3][1]);
      const double qn =
          q + h / 6 * (k[0][0] + 2 * k[1][0] + 2 * k[2][0] + k[3][0]);
      p += h / 6 * (k[0][1] + 2 * k[1][1] + 2 * k[2][1] + k[3][1]);
      norm += kPi * h * (r * q * q + (r + h) * qn * qn);
      q = qn;
      r += h;
      if (q < 0) return -1;
      if (p > 0) return 1;
    }
    return 0;
  };
  double lo = 2.0, hi = 2.4, norm = 0;
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (shoot(mid, norm) < 0 ? hi : lo) = mid;
  }
  shoot(lo, norm);
  return norm;
}

// The curves on the common times t: φ(0, t) (Hermite), the frequency of the
// period each t lies in (NaN outside crossings), E(r < 3R) (linear).
void Resample(const Series& s, const std::vector<double>& t,
              std::vector<double>& phi, std::vector<double>& omega,
              std::vector<double>& disk) {
  const std::vector<double> up = UpCrossings(s);
  std::size_t k = 0, c = 0;
  for (double ti : t) {
    while (k + 2 < s.t.size() && s.t[k + 1] < ti) ++k;
    while (c + 1 < up.size() && up[c + 1] < ti) ++c;
    const bool in = ti <= s.t.back() + 1e-9;
    const double u = std::clamp((ti - s.t[k]) / (s.t[k + 1] - s.t[k]), 0., 1.);
    phi.push_back(in ? Hermite(s, k, u) : kNaN);
    disk.push_back(in ? (1 - u) * s.disk[k] + u * s.disk[k + 1] : kNaN);
    const bool period = c + 1 < up.size() && up[c] <= ti && ti <= up[c + 1];
    omega.push_back(period ? 2 * kPi / (up[c + 1] - up[c]) : kNaN);
  }
}

// The three panels, the reference lines and the titles with the numbers.
std::filesystem::path Draw(const std::filesystem::path& dir,
                           const std::vector<double>& t,
                           std::vector<report::CurvePanel> panels,
                           const std::vector<Stage>& st, double exact0,
                           double limit) {
  const std::string dashed = "lines lw 1.5 dt 2 lc 'black'";
  panels[1].curves.push_back({"mass gap m", std::vector<double>(t.size(), 1)});
  panels[2].curves.push_back(
      {"E(0) = 2πv² + πλv⁴R²/3", std::vector<double>(t.size(), exact0)});
  panels[2].curves.push_back(
      {"small-amplitude limit N_T v²/3", std::vector<double>(t.size(), limit)});
  char title[3][200];
  std::snprintf(title[0], sizeof title[0],
                "φ(0, 0, t)/v: the core swings between %.2f and %.2f in "
                "t ∈ [50, 125] (Δx = 1/3)",
                st[0].phi_lo, st[0].phi_hi);
  std::snprintf(title[1], sizeof title[1],
                "ω/m per period (upward crossings of φ = v/2): %.4f on "
                "[50, 125] (Δx = 1/3), %.4f (Δx = 1/2)",
                st[0].omega, st[1].omega);
  std::snprintf(title[2], sizeof title[2],
                "energy in r < 3R (units v²): %.3f on [50, 125] (Δx = 1/3); "
                "the first stage ends at t = %.0f (Δx = 1/3), %.0f (1/2), "
                "%.0f (seeded)",
                st[0].e_mean, st[0].end, st[1].end, st[3].end);
  auto with = figures::ThickUnderThin();
  panels[0].style = {.title = title[0],
                     .xlabel = "",
                     .ylabel = "φ(0, t)/v",
                     .key = "below",
                     .with = with};
  with.push_back(dashed);
  panels[1].style = {.title = title[1],
                     .xlabel = "",
                     .ylabel = "ω/m",
                     .key = "off",
                     .with = with};
  with.push_back("lines lw 1.5 dt 3 lc 'red'");
  panels[2].style = {.title = title[2],
                     .ylabel = "E(r < 3R)/v²",
                     .key = "below",
                     .with = with};
  return report::CurvePanels(
      dir, "fig_fields_oscillon", t, panels,
      "φ⁴ oscillon in 2 + 1 D: bubble R = 3/m, λ = ½, v = 1, periodic "
      "[−24, 24)², order-8 differences, SBP42 in time",
      1000, 1250);
}
}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  const double townes = TownesNorm(), limit = townes * kV * kV / 3;
  const double exact0 = 2 * kPi * kV * kV +
                        kPi * kLambda * std::pow(kV, 4) * kRadius * kRadius / 3;
  const std::vector<Run> runs = {{144, 3001, kEnd, 0},
                                 {96, 3001, kEnd, 0},
                                 {96, 4001, 200, 0},
                                 {144, 2001, 200, 1e-3}};
  std::vector<double> t;
  for (int i = 0; i * 0.25 <= kEnd + 1e-9; ++i) t.push_back(i * 0.25);
  std::vector<report::CurvePanel> panels(3);
  std::printf(
      "φ⁴ oscillon, λ = ½, v = 1 (m = 1), R = 3, periodic [−24, 24)², "
      "order-8 differences, SBP42 (windows of 16); first stage t ∈ [50, 125]"
      "\nE(0) exact 2πv² + πλv⁴R²/3 = %.6f; small-amplitude limit "
      "N_T v²/3 = %.4f (N_T = %.4f)\n\n"
      "| run | E(0) | ω/m | periods | φ(0)/v range | E(r < 3R) mean "
      "[min, max] | stage ends | max |E − E(0)| | seconds |\n"
      "|---|---|---|---|---|---|---|---|---|\n",
      exact0, limit, townes);
  std::vector<Stage> st;
  for (const Run& run : runs) {
    const Series s = Solve(run);
    st.push_back(Measure(s));
    const Stage& m = st.back();
    std::printf(
        "| %s | %.6f | %.4f | %d | [%.3f, %.3f] | %.3f [%.3f, %.3f] | %.1f | "
        "%.1e | %.0f |\n",
        run.Key().c_str(), s.total[0], m.omega, m.periods, m.phi_lo, m.phi_hi,
        m.e_mean, m.e_lo, m.e_hi, m.end, m.drift, s.seconds);
    std::fflush(stdout);
    std::vector<double> phi, omega, disk;
    Resample(s, t, phi, omega, disk);
    panels[0].curves.push_back({run.Key(), phi});
    panels[1].curves.push_back({run.Key(), omega});
    panels[2].curves.push_back({run.Key(), disk});
  }
  std::printf("\n%s\n", Draw(dir, t, panels, st, exact0, limit).c_str());
}
