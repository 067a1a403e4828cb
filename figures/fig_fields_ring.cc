// The sine-Gordon ring soliton of Christiansen & Lomdahl ("Numerical study
// of 2+1 dimensional sine-Gordon solitons", Physica D 2 (1981) 482):
// φ(0) = 4 atan(exp(R0 − r)), R0 = 6, φ_t(0) = 0, SBP42 in space on both
// axes with natural faces and SBP42 in time in windows of 16 points, to
// t = 16 (the grid of scenes/field2d_ring_soliton.toml). Four runs: the
// scene's 97² points on [−14, 14]² at Δt = 1/30, the same at Δt = 1/60,
// 193² points at Δt = 1/30, and 145² points on [−21, 21]² (the same Δx in
// a larger box) at Δt = 1/30.
//
// Measured in every slice: the radius R of the ring, where |φ| crosses π
// going outwards from the centre, along the x axis and along the diagonal
// (linear interpolation between grid points, which is accurate to O(Δx³)
// where the profile, like the kink 4 atan eˣ, has no curvature at φ = π); the
// collapse time, where φ(0, 0, t) crosses π (there R = 0 by the same
// definition), from the cubic Hermite interpolant of φ and φ_t between
// slices; the deepest φ(0, 0, t); the energy of each slice against that of
// the discrete initial data.
//
// The law it is compared with is the collective-coordinate equation of a
// thin ring far from the centre, R R'' = −(1 − R'²): the ring's energy
// 8·2πR/√(1 − R'²) (a kink of energy 8 per unit length, Lorentz
// contracted) is conserved, so from rest R² + R0²R'² = R0², R = R0 cos(t/R0)
// and the ring reaches R = 0 at t = πR0/2 (9.42 for R0 = 6). It neglects
// the ring's width against its radius and the radiation, so it holds while
// R ≫ 1. After R = 0 its time-reversed branch, R0|cos(t/R0)|, is drawn: the
// bounce of a ring that radiates nothing.
//
// - fig_fields_ring: R(t) along x and along the diagonal (193²), along x
//   (97²) and the law; after the deepest φ(0, 0, t), where |φ| is largest
//   along x (the outgoing pulse).
// - fig_fields_ring_center: φ(0, 0, t) of the four runs.
//
// What it shows: the collapse at t = 8.535 ± 0.005 on every grid, Δt and
// box, 9.4 % before the law's 9.42; the law within 2.4 % while R ≥ 3, the
// ring running ahead of it once R is comparable with its width; no elastic
// bounce, but a focus φ(0, 0, t) ≈ −13.8 and a radiating pulse
// (docs/fields_nd.md §4).
//
// Usage: fig_fields_ring [OUTPUT_DIR]                       (about 2 minutes)
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

using Density = fields::SineGordonIn<2>;
using Grid = sbp::SpaceGrid<double>;

constexpr double kR0 = 6.0, kEnd = 16.0, kPi = std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The curves and the table are sampled every kStep (the coarser Δt).
constexpr double kStep = 1.0 / 30;

// n² points on [−half, half]², nt time points on [0, kEnd].
struct RingRun {
  int n;
  double half;
  long long nt;
  std::string Key() const {
    char key[96];
    std::snprintf(key, sizeof key, "%d² on [−%g, %g]², Δt = 1/%g", n, half,
                  half, std::round((nt - 1) / kEnd));
    return key;
  }
};

struct Measured {
  std::vector<double> rx, rd, center;  // at t = 0, kStep, 2kStep, …
  // After the deepest φ(0, 0, t): where |φ| is largest along x, and that
  // largest |φ| (the outgoing pulse); NaN before.
  std::vector<double> peak_r, peak;
  double collapse = kNaN;               // φ(0, 0, t) = π
  double half_x = kNaN, half_d = kNaN;  // R = R0/2 along x, along the diagonal
  double deepest = 0, deepest_t = 0;    // the least φ(0, 0, t) and when
  double e0 = 0, drift = 0, drift_end = 0;  // max |E − E0|: before T, at T
  double seconds = 0;
};

// The radius where |φ| last falls through π along the ray from the centre
// c (index of both axes) in steps of (sx, sy) grid points, each dr long;
// NaN where |φ| < π on the whole ray (the ring has collapsed).
double RayRadius(std::span<const double> phi, int n, int c, int sx, int sy,
                 double dr) {
  const int steps = c;  // the ray ends on a face
  for (int k = steps - 1; k >= 0; --k) {
    const double a = std::abs(phi[(c + k * sy) * n + c + k * sx]);
    if (a < kPi) continue;
    const double b = std::abs(phi[(c + (k + 1) * sy) * n + c + (k + 1) * sx]);
    return dr * (k + (a - kPi) / (a - b));
  }
  return kNaN;
}

// Where |φ| is largest along x from the centre c (a parabola through the
// largest sample and its neighbours), and that largest |φ|, in *value.
double PeakRadius(std::span<const double> phi, int n, int c, double dr,
                  double* value) {
  int best = 0;
  for (int k = 1; k < c; ++k)
    if (std::abs(phi[c * n + c + k]) > std::abs(phi[c * n + c + best]))
      best = k;
  *value = std::abs(phi[c * n + c + best]);
  if (best == 0) return 0;
  const double a = std::abs(phi[c * n + c + best - 1]), b = *value,
               d = std::abs(phi[c * n + c + best + 1]);
  return dr * (best + 0.5 * (a - d) / (a - 2 * b + d));
}

// The first s in [0, 1] where the cubic Hermite interpolant of (p0, d0) at
// t0 and (p1, d1) at t0 + h equals π (p0 ≥ π > p1), by bisection.
double HermiteCrossing(double p0, double d0, double p1, double d1, double h) {
  auto p = [&](double s) {
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * h * d0 +
           (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * h * d1 - kPi;
  };
  double a = 0, b = 1;
  for (int i = 0; i < 60; ++i) {
    const double m = 0.5 * (a + b);
    (p(m) >= 0 ? a : b) = m;
  }
  return 0.5 * (a + b);
}

// The time where the samples r (every kStep) first fall through the level.
double FirstBelow(const std::vector<double>& r, double level) {
  for (std::size_t k = 0; k + 1 < r.size(); ++k)
    if (r[k] >= level && r[k + 1] < level)
      return kStep * (k + (r[k] - level) / (r[k] - r[k + 1]));
  return kNaN;
}

Measured Solve(const RingRun& run) {
  const Density density;
  const auto axis = sbp::SpaceDerivative<double>::Bounded("sbp42", run.n,
                                                          -run.half, run.half);
  const Grid g({axis, axis});
  std::vector<double> phi0(g.points()), pi0(g.points(), 0.0);
  for (int j = 0; j < g.points(); ++j)
    phi0[j] = 4 * std::atan(std::exp(kR0 - std::hypot(g.x(j, 0), g.x(j, 1))));
  const spacetime::FieldGrid fg{
      .op = "sbp42", .points = run.nt, .t_end = kEnd, .window_points = 16};
  const auto s = spacetime::SolveField(density, g, fg, phi0, pi0);
  if (!s.status.converged) throw std::runtime_error(s.status.reason);
  Measured m;
  m.seconds = s.seconds_total;
  m.e0 = action::ChargesOfSlice(density, g, phi0, pi0).energy;
  const int n = run.n, c = (n - 1) / 2, pts = g.points();
  const double dx = axis.dx();
  const auto stride = std::size_t(std::lround(kStep / s.dt));
  for (std::size_t k = 0; k < s.t.size(); ++k) {
    const std::span<const double> p(s.phi.data() + k * pts, pts);
    const std::span<const double> q(s.phi_t.data() + k * pts, pts);
    const double de =
        std::abs(action::ChargesOfSlice(density, g, p, q).energy - m.e0);
    // The last slice has the closure row's φ_t, an order less accurate
    // (docs/fields.md §6): its energy is reported apart.
    double& worst = k + 1 == s.t.size() ? m.drift_end : m.drift;
    worst = std::max(worst, de);
    const double centre = p[c * n + c];
    if (centre < m.deepest) m.deepest = centre, m.deepest_t = s.t[k];
    if (std::isnan(m.collapse) && k + 1 < s.t.size()) {
      const double next = s.phi[(k + 1) * pts + c * n + c];
      if (centre >= kPi && next < kPi)
        m.collapse =
            s.t[k] + s.dt * HermiteCrossing(centre, q[c * n + c], next,
                                            s.phi_t[(k + 1) * pts + c * n + c],
                                            s.dt);
    }
    if (k % stride) continue;
    m.rx.push_back(RayRadius(p, n, c, 1, 0, dx));
    double value = 0;
    m.peak_r.push_back(PeakRadius(p, n, c, dx, &value));
    m.peak.push_back(value);
    m.rd.push_back(RayRadius(p, n, c, 1, 1, std::sqrt(2.0) * dx));
    m.center.push_back(centre);
  }
  m.half_x = FirstBelow(m.rx, kR0 / 2);
  m.half_d = FirstBelow(m.rd, kR0 / 2);
  for (std::size_t k = 0; k * kStep <= m.deepest_t + 1e-9; ++k)
    m.peak_r[k] = m.peak[k] = kNaN;
  return m;
}

// The law R R'' = −(1 − R'²) from rest at R0, by RK4 in steps of kStep/20,
// up to R = 0 (where it is singular); the time-reversed branch after it.
// Returns R at t = 0, kStep, … up to kEnd, and the time of R = 0 in *zero.
std::vector<double> LawRadius(std::size_t samples, double* zero) {
  const double h = kStep / 20;
  auto f = [](double r, double v) { return -(1 - v * v) / r; };
  std::vector<double> out{kR0};
  double r = kR0, v = 0, t = 0;
  *zero = kNaN;
  while (out.size() < samples && std::isnan(*zero)) {
    for (int i = 0; i < 20; ++i) {
      const double k1r = v, k1v = f(r, v);
      const double k2r = v + h / 2 * k1v, k2v = f(r + h / 2 * k1r, k2r);
      const double k3r = v + h / 2 * k2v, k3v = f(r + h / 2 * k2r, k3r);
      const double k4r = v + h * k3v, k4v = f(r + h * k3r, k4r);
      const double rn = r + h / 6 * (k1r + 2 * k2r + 2 * k3r + k4r);
      // Near R = 0, R' → −1: the last stretch is straight.
      if (rn < 1e-3 * kR0) {
        *zero = t + r / -v;
        break;
      }
      v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
      r = rn;
      t += h;
    }
    if (std::isnan(*zero)) out.push_back(r);
  }
  // Time reversal about R = 0: R(t0 + τ) = R(t0 − τ), linear between the
  // samples and from the last sample to R = 0 at t0.
  const std::vector<double> before = out;
  const double last = kStep * double(before.size() - 1);
  while (out.size() < samples) {
    const double back = 2 * *zero - kStep * double(out.size());
    if (back < 0) break;  // past the first return to R0
    const std::size_t i = std::size_t(back / kStep);
    const double w = back / kStep - double(i);
    out.push_back(i + 1 < before.size()
                      ? (1 - w) * before[i] + w * before[i + 1]
                      : before.back() * (*zero - back) / (*zero - last));
  }
  out.resize(samples, kNaN);
  return out;
}

void PrintTable(const std::vector<double>& t, const Measured& fine,
                const Measured& coarse, const std::vector<double>& law) {
  std::printf(
      "\nR(t): where |φ| crosses π (193² along x and the diagonal, 97² along "
      "x); the law, integrated and in closed form R0|cos(t/R0)|; after the "
      "deepest φ(0, 0, t), the largest |φ| along x and where it is (193²)\n\n"
      "| t | R_x 193² | R_diag 193² | R_x 97² | R_law | closed form | "
      "largest |φ| | at r |\n|---|---|---|---|---|---|---|---|\n");
  const auto every = std::size_t(std::lround(1.0 / kStep));
  for (std::size_t k = 0; k < t.size(); k += every)
    std::printf("| %.0f | %.3f | %.3f | %.3f | %.3f | %.3f | %.2f | %.2f |\n",
                t[k], fine.rx[k], fine.rd[k], coarse.rx[k], law[k],
                kR0 * std::abs(std::cos(t[k] / kR0)), fine.peak[k],
                fine.peak_r[k]);
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  const std::vector<RingRun> runs = {
      {97, 14, 481}, {97, 14, 961}, {193, 14, 481}, {145, 21, 481}};
  std::vector<double> t;
  for (int i = 0; i * kStep <= kEnd + 1e-9; ++i) t.push_back(i * kStep);
  double law_zero = 0;
  const auto law = LawRadius(t.size(), &law_zero);
  std::vector<Measured> m;
  std::printf(
      "| run | collapse: φ(0,0,t) = π | R = 3 along x | along diagonal | "
      "least φ(0,0,t) at t | E(0) | max |E − E0| before T | at T | seconds "
      "|\n|---|---|---|---|---|---|---|---|---|\n");
  for (const RingRun& run : runs) {
    m.push_back(Solve(run));
    const Measured& r = m.back();
    std::printf(
        "| %s | %.4f | %.4f | %.4f | %.2f at %.3f | %.4f | %.1e | %.1e | "
        "%.1f |\n",
        run.Key().c_str(), r.collapse, r.half_x, r.half_d, r.deepest,
        r.deepest_t, r.e0, r.drift, r.drift_end, r.seconds);
    std::fflush(stdout);
  }
  std::printf(
      "| law R R'' = −(1 − R'²), R0 = 6 | %.4f (πR0/2 = %.4f) | %.4f "
      "(2π) | | | 16πR0 = %.4f | | | |\n",
      law_zero, kPi / 2 * kR0, FirstBelow(law, kR0 / 2), 16 * kPi * kR0);
  PrintTable(t, m[2], m[0], law);
  // The re-expansion: the largest R_x after the collapse and when.
  for (std::size_t k : {std::size_t(2), std::size_t(0)}) {
    std::size_t top = 0;
    for (std::size_t i = 0; i < t.size(); ++i)
      if (t[i] > m[k].collapse && !std::isnan(m[k].rx[i]) &&
          (top == 0 || m[k].rx[i] > m[k].rx[top]))
        top = i;
    std::printf(
        "\n%s: after the collapse, |φ| = π out to R_x = %.3f at t = "
        "%.3f at most",
        runs[k].Key().c_str(), m[k].rx[top], t[top]);
  }
  std::printf("\n");
  char title[256];
  std::snprintf(title, sizeof title,
                "sine-Gordon ring, R0 = 6: |φ| = π at R(t); R = 0 at "
                "t = %.2f (193²), %.2f (97²); law πR0/2 = %.2f",
                m[2].collapse, m[0].collapse, law_zero);
  // The pulse is drawn where it has left the centre.
  std::vector<double> pulse = m[2].peak_r;
  for (double& r : pulse)
    if (r == 0) r = kNaN;
  const auto radius = report::Curves(
      dir, "fig_fields_ring", t,
      {{"193², along x", m[2].rx},
       {"193², along the diagonal", m[2].rd},
       {"97², along x", m[0].rx},
       {"law R R'' = −(1 − R'^2) (reversed after R = 0)", law},
       {"193², where |φ| is largest along x, after the focus", pulse}},
      {.title = title,
       .ylabel = "R",
       .key = "top right",
       .with = {"lines lw 6 lc '#fdae61'", "lines lw 2.5 lc '#1a9641'",
                "lines lw 1.5 lc '#2c7bb6'", "lines lw 2 dt 2 lc 'black'",
                "points pt 7 ps 0.4 lc '#d7191c'"}});
  std::vector<std::pair<std::string, std::vector<double>>> centre;
  for (std::size_t k = 0; k < runs.size(); ++k)
    centre.push_back({runs[k].Key(), m[k].center});
  const auto centre_png =
      report::Curves(dir, "fig_fields_ring_center", t, centre,
                     {.title = "sine-Gordon ring, R0 = 6: φ at the centre",
                      .ylabel = "φ(0, 0, t)",
                      .key = "bottom left",
                      .with = figures::ThickUnderThin()});
  std::printf("\n%s\n%s\n", radius.c_str(), centre_png.c_str());
}
