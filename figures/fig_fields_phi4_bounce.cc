// φ⁴ kink–antikink collisions: bounce, capture and escape (Campbell,
// Schonfeld & Wingate, "Resonance structure in kink-antikink interactions
// in φ⁴ theory", Physica D 9, 1983: capture below v_c ≈ 0.2598 except in
// two-bounce windows, the first and widest near 0.19–0.20).
//
// Normalization. Phi4 with λ = 1, v = 1: V = ¼(φ² − 1)², the field equation
// φ_tt − φ_xx − φ + φ³ = 0, the kink tanh(x/√2) (width √2), the meson mass
// √2, the kink's shape mode √(3/2). This is the normalization in which
// v_c ≈ 0.2598 is commonly quoted (e.g. Goodman & Haberman, "Kink-antikink
// collisions in the φ⁴ equation: the n-bounce resonance and the separatrix
// map", 2005); Campbell et al.'s own text was not at hand to check it. The
// velocities do not depend on it: φ = vψ, (t, x) = (t′, x′)/(v√λ) turn
// V = ¼λ(φ² − v²)² into ¼(ψ² − 1)² with the speed of light still 1, so every
// λ, v has the same critical velocity and windows; only lengths and times
// scale, by 1/(v√λ).
//
// Initial data: a kink at −x₀ moving right and an antikink at +x₀ moving
// left, φ = φ_K(x + x₀, v) − φ_K(x − x₀, −v) − 1 (vacuum −1 outside, +1
// between), x₀ = 12 (17 kink widths apart; the tails overlap by 1e-7), on
// a periodic domain (the same vacuum at both ends), [−80, 80): the fastest
// radiation of the first bounce, at speed 1, wraps round and comes back to
// the outgoing pair after t = 160 (the table says when).
//
// Grid: order-8 differences at Δx = 0.1, SBP42 at Δt = 0.04 in windows of
// 8 (29 s a run against 92 s with windows of 16). ω_max² = ρ(D_x)² + max V″
// with ρ = 17.3 and V″ = 3φ² − 1 (2 at the vacua, the meson mass squared)
// gives Δt·ω_max ≈ 0.70, under the SBP42 limit 1 that SolveField checks.
//
// A bounce is a downward zero crossing of φ(t, 0): the pair meets and the
// field between them swings to the other vacuum. After the last bounce the
// pair has escaped if φ(t, 0) stays positive and the antikink's zero (the
// outermost sign change at x > 0) moves outward; its speed, fitted over the
// last 30 time units, is the outgoing velocity. A pair that separates too
// slowly to tell by t_end (near a window's edge or v_c) is "undecided".
//
// Measured with --scan (velocities where v_out → 0, extrapolated in v_out²):
// the first two-bounce window is 0.1925 < v < 0.2034 at Δx = 0.2, Δt = 0.08,
// at Δx = 0.1, Δt = 0.04 and at Δx = 0.05, Δt = 0.02 alike (v_out at its
// edges agrees to 1e-3 between the last two grids); one bounce and escape
// above v_c ≈ 0.2600 (Δx = 0.2 and 0.1, run to t = 300 on [−128, 128)).
//
// Usage: fig_fields_phi4_bounce [OUTPUT_DIR]                (about 100 s)
//        fig_fields_phi4_bounce OUTPUT_DIR --scan V0 V1 DV [DX DT [W [T L]]]
// (the scan: velocities V0, V0 + DV, … V1 on the grid Δx = DX, Δt = DT,
// windows of W, to t = T on [−L, L); defaults 0.1, 0.04, 8, 160, 80; about
// 32 s a velocity at the defaults)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "core/action/field_charges.h"
#include "problems/fields/densities.h"
#include "problems/fields/exact.h"
#include "report/field_plots.h"
#include "report/plot.h"
#include "solvers/spacetime/solve.h"

using namespace vivp;

namespace {

const fields::Phi4 kPhi4{.lambda = 1.0, .v = 1.0};
constexpr double kX0 = 12;

struct Grid {
  double half_length = 80, dx = 0.1, dt = 0.04, t_end = 160;
  int window = 8;  // cheaper than 16 here: 29 s against 92 s a run
};

// The kink at −x₀ (velocity +v) and the antikink at +x₀ (velocity −v).
struct Pair {
  fields::Phi4Kink left, right;
  template <class T>
  T operator()(const T& t, const T& x) const {
    return left(t, x) - right(t, x) - T(kPhi4.v);
  }
};

struct Outcome {
  double v = 0;
  int bounces = 0;
  // 1 escaped; 0 captured (φ(t, 0) negative in the last quarter); −1
  // undecided: φ(t, 0) positive but the pair not clearly apart by t_end.
  int fate = 0;
  double v_out = 0, seconds = 0, drift = 0;
  double first_bounce = 0, front = 0;  // the time of the first; X(T)
  double omega_dt = 0;                 // Δt·ω_max, the worst window's
  std::vector<double> t, center;       // φ(t, 0)
  report::FieldSeries field;
};

// The outermost sign change of φ at x > 0, by linear interpolation; 0 if
// none.
double Front(const std::vector<double>& x, const double* phi, int nx) {
  for (int j = nx - 1; j > 0; --j)
    if (x[j - 1] > 0 && (phi[j - 1] > 0) != (phi[j] > 0))
      return x[j - 1] + (x[j] - x[j - 1]) * phi[j - 1] / (phi[j - 1] - phi[j]);
  return 0;
}

// Escape: φ(t, 0) positive over the last quarter and the front (the
// antikink's zero) receding; the outgoing velocity is the least-squares
// slope of the front over the last 30 time units.
void Classify(Outcome& o, const std::vector<double>& front, double t_end) {
  const std::size_t n = o.t.size(), quarter = n - n / 4;
  bool positive = true;
  for (std::size_t k = quarter; k < n; ++k) positive &= o.center[k] > 0;
  double st = 0, sx = 0, stt = 0, stx = 0, m = 0;
  for (std::size_t k = 0; k < n; ++k)
    if (o.t[k] >= t_end - 30) {
      st += o.t[k];
      sx += front[k];
      stt += o.t[k] * o.t[k];
      stx += o.t[k] * front[k];
      ++m;
    }
  o.v_out = (m * stx - st * sx) / (m * stt - st * st);
  o.front = front.back();
  if (positive)
    o.fate = o.v_out > 0.01 && o.front > 4 * std::sqrt(2.0) ? 1 : -1;
  else
    o.v_out = 0;  // a bion has no outgoing velocity
}

Outcome Collide(double v, const Grid& g) {
  const int nx = int(std::lround(2 * g.half_length / g.dx));
  const auto dx = sbp::SpaceDerivative<double>::Periodic(8, nx, -g.half_length,
                                                         2 * g.half_length);
  const Pair pair{{kPhi4, v, -kX0}, {kPhi4, -v, kX0}};
  const auto [phi0, pi0] = fields::InitialData(pair, dx);
  const long long nt = std::llround(g.t_end / g.dt) + 1;
  const auto s = spacetime::SolveField(
      kPhi4, dx, {"sbp42", nt, g.t_end, g.window}, phi0, pi0);
  if (!s.status.converged) throw std::runtime_error(s.status.reason);
  Outcome o;
  o.v = v;
  o.seconds = s.seconds_total;
  o.omega_dt = s.omega_dt;
  std::vector<double> x(nx), front;
  for (int j = 0; j < nx; ++j) x[j] = dx.x(j);
  const int mid = nx / 2;  // x = 0
  const double e0 = action::ChargesOfSlice(kPhi4, dx, phi0, pi0).energy;
  for (std::size_t k = 0; k < s.t.size(); ++k) {
    const double* p = s.phi.data() + k * nx;
    o.t.push_back(s.t[k]);
    o.center.push_back(p[mid]);
    if (k > 0 && o.center[k - 1] > 0 && p[mid] <= 0 && !o.bounces++)
      o.first_bounce = s.t[k];
    front.push_back(Front(x, p, nx));
    // Interior slices only: a window's last one has the closure row's φ_t.
    if (k % (g.window - 1) && k + 1 < s.t.size()) {
      const std::span<const double> q(s.phi_t.data() + k * nx, nx);
      const double e =
          action::ChargesOfSlice(kPhi4, dx, std::span<const double>(p, nx), q)
              .energy;
      o.drift = std::max(o.drift, std::abs(e - e0) / e0);
    }
  }
  Classify(o, front, g.t_end);
  o.field.x = x;
  o.field.t = s.t;
  o.field.phi = s.phi;
  return o;
}

std::string Short(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

std::string Describe(const Outcome& o) {
  char b[160];
  if (o.fate == 1)
    std::snprintf(b, sizeof b, "v = %.4g: %d bounce%s, escape at %.3f", o.v,
                  o.bounces, o.bounces == 1 ? "" : "s", o.v_out);
  else if (o.fate == 0)
    std::snprintf(b, sizeof b,
                  "v = %.4g: captured (bion), %d bounces by t = %g", o.v,
                  o.bounces, o.t.back());
  else
    std::snprintf(b, sizeof b,
                  "v = %.4g: %d bounce%s, apart by %.1f at t = %g, receding at "
                  "%.3f: undecided",
                  o.v, o.bounces, o.bounces == 1 ? "" : "s", 2 * o.front,
                  o.t.back(), o.v_out);
  return b;
}

// The scanned velocities where the pair escaped, as runs of neighbours:
// "0.1925–0.2025 (2)" with the bounce counts in brackets.
std::vector<std::string> EscapeWindows(
    const std::vector<std::vector<double>>& rows) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < rows.size();) {
    if (rows[i][2] != 1) {
      ++i;
      continue;
    }
    std::size_t j = i;
    int lo = int(rows[i][1]), hi = lo;
    while (j + 1 < rows.size() && rows[j + 1][2] == 1) {
      ++j;
      lo = std::min(lo, int(rows[j][1]));
      hi = std::max(hi, int(rows[j][1]));
    }
    std::string w = Short(rows[i][0]);
    if (j > i) w += "–" + Short(rows[j][0]);
    w += " (" + std::to_string(lo) + (hi > lo ? "–" + std::to_string(hi) : "") +
         ")";
    out.push_back(w);
    i = j + 1;
  }
  return out;
}

// The items joined by ", ", with a line break (gnuplot's \n) every `per`.
std::string Join(const std::vector<std::string>& items, std::size_t per) {
  std::string s;
  for (std::size_t k = 0; k < items.size(); ++k)
    s += (k == 0 ? "" : k % per ? ", " : ",\\n") + items[k];
  return s;
}

// The outgoing velocity against the incoming one, as in Campbell et al.'s
// figures, with the escape windows in the title.
void ScanFigure(const std::filesystem::path& dir, const Grid& g,
                const std::vector<std::vector<double>>& rows) {
  char stem[160];
  std::snprintf(stem, sizeof stem,
                "fig_fields_phi4_bounce_scan_v%g-%g_dx%g_dt%g_T%g",
                rows.front()[0], rows.back()[0], g.dx, g.dt, g.t_end);
  report::Figure fig(dir, stem, 1000, 700);
  const auto d = fig.Data(
      "table", rows, "v bounces fate(1_escaped_0_captured_-1_undecided) v_out");
  const auto windows = EscapeWindows(rows);
  std::printf("escapes (bounces): %s\n", Join(windows, 1000).c_str());
  fig.script() << "set title \"φ⁴ kink–antikink, V = ¼(φ² − 1)²: outgoing "
                  "against incoming velocity\\nperiodic [−"
               << g.half_length << ", " << g.half_length << "), Δx = " << g.dx
               << ", Δt = " << g.dt << " (SBP42, windows of " << g.window
               << "), run to t = " << g.t_end
               << "\\nescapes, bounces in brackets: " << Join(windows, 6)
               << "\\nCampbell, Schonfeld and Wingate (1983): v_c ≈ 0.2598\"\n"
               << "set xlabel 'incoming velocity v'\n"
               << "set ylabel 'outgoing velocity (0: captured by t = "
               << g.t_end << ")'\nset key top left\nset grid\n"
               << "set xrange [" << rows.front()[0] - 0.002 << ":"
               << rows.back()[0] + 0.002 << "]\nset yrange [-0.02:*]\n"
               << "plot '" << d
               << "' using 1:($3 > 0 && $2 == 1 ? $4 : 1/0) with points pt 7 "
                  "title 'one bounce', '' using 1:($3 > 0 && $2 == 2 ? $4 : "
                  "1/0) with points pt 5 title 'two bounces', '' using 1:($3 "
                  "> 0 && $2 > 2 ? $4 : 1/0) with points pt 9 title 'three or "
                  "more', '' using 1:($3 == 0 ? 0 : 1/0) with points pt 6 "
                  "title 'captured', '' using 1:($3 < 0 ? $4 : 1/0) with "
                  "points pt 4 title 'undecided by t_{end}'\n";
  std::printf("%s\n", fig.Render().c_str());
}

int Scan(const std::filesystem::path& dir, int argc, char** argv) {
  if (argc < 6) {
    std::fprintf(stderr, "usage: %s DIR --scan V0 V1 DV [DX DT [W [T L]]]\n",
                 argv[0]);
    return 2;
  }
  const double v0 = std::atof(argv[3]), v1 = std::atof(argv[4]),
               dv = std::atof(argv[5]);
  Grid g;
  if (argc > 7) {
    g.dx = std::atof(argv[6]);
    g.dt = std::atof(argv[7]);
  }
  if (argc > 8) g.window = std::atoi(argv[8]);
  if (argc > 10) {
    g.t_end = std::atof(argv[9]);
    g.half_length = std::atof(argv[10]);
  }
  std::vector<std::vector<double>> rows;
  for (int i = 0; v0 + i * dv <= v1 + 1e-12; ++i) {
    const Outcome o = Collide(v0 + i * dv, g);
    std::printf("%s (energy drift %.1e, %.0f s)\n", Describe(o).c_str(),
                o.drift, o.seconds);
    std::fflush(stdout);
    rows.push_back({o.v, double(o.bounces), double(o.fate), o.v_out});
  }
  ScanFigure(dir, g, rows);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  if (argc > 2 && std::strcmp(argv[2], "--scan") == 0)
    return Scan(dir, argc, argv);
  const Grid g;
  const std::vector<double> velocities = {0.18, 0.198, 0.30};
  std::vector<Outcome> runs;
  std::vector<report::FieldSeries> maps;
  std::vector<report::HeatMapStyle> styles;
  std::vector<std::pair<std::string, std::vector<double>>> centers;
  std::vector<std::vector<double>> table;
  for (double v : velocities) {
    runs.push_back(Collide(v, g));
    const Outcome& o = runs.back();
    // The fastest radiation of the first bounce wraps round the periodic
    // domain and re-enters |x| ≤ X(T), the outgoing pair's span, at
    // t_b + 2L − X(T).
    const double back = o.first_bounce + 2 * g.half_length - o.front;
    std::printf(
        "%s; first bounce t = %.1f, radiation back at t = %.0f; "
        "energy drift %.1e; Δt·ω_max %.2f; %.0f s\n",
        Describe(o).c_str(), o.first_bounce, back, o.drift, o.omega_dt,
        o.seconds);
    maps.push_back(report::Crop(o.field, -25, 25, 0, g.t_end));
    styles.push_back(
        {.title = Describe(o), .max_slices = 240, .max_points = 200});
    centers.push_back({Describe(o), o.center});
    table.push_back({v, double(o.bounces), double(o.fate), o.v_out,
                     o.first_bounce, back, o.drift, o.omega_dt});
  }
  report::Figure data(dir, "fig_fields_phi4_bounce");
  data.Data(
      "table", table,
      "v bounces fate(1_escaped_0_captured_-1_undecided) v_out first_bounce_t "
      "radiation_back_t "
      "energy_drift omega_dt");
  char grid[160];
  std::snprintf(grid, sizeof grid,
                "periodic [−%g, %g), Δx = %g (order 8), Δt = %g (SBP42, "
                "windows of %d)",
                g.half_length, g.half_length, g.dx, g.dt, g.window);
  const auto heat = report::HeatMaps(
      dir, "fig_fields_phi4_bounce", maps, styles,
      "φ⁴ kink–antikink from x = ∓12: V = ¼(φ² − 1)² (λ = 1, v = 1, kink "
      "tanh(x/√2)); " +
          std::string(grid) +
          "; |x| ≤ 25 shown\nCampbell, Schonfeld and Wingate (1983): "
          "capture below v_c ≈ 0.2598 except in two-bounce windows, "
          "the first near 0.19–0.20",
      1350, 600);
  const auto center = report::Curves(
      dir, "fig_fields_phi4_bounce_center", runs.front().t, centers,
      {.title = "φ⁴ kink–antikink: φ(t, 0), a bounce is a downward zero "
                "crossing\n" +
                std::string(grid),
       .ylabel = "φ(t, 0)",
       .key = "below"});
  std::printf("%s\n%s\n", heat.c_str(), center.c_str());
}
