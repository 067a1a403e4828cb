// Running a charged field's scene (charged_scene.h): the model of its terms,
// the march, and at every node the gauge-invariant values and diagnostics
// that apps/ writes.
#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/action/vortex_tracks.h"
#include "core/sbp/builder.h"
#include "scene/charged_scene.h"
#include "scene/field_profile.h"
#include "solvers/spacetime/charged_march_2d.h"
#include "solvers/spacetime/resolution.h"

namespace vivp::scene {

fields::ScalarQed ChargedModel(const FieldScene& s) {
  const detail::TermSet terms{s};
  fields::ScalarQed model;
  const double m = terms.Value("scalar_qed", "mass", 0);
  const double v = terms.Value("abelian_higgs", "v", 0);
  model.mass2 = m * m;
  model.lambda = terms.Value("abelian_higgs", "lambda", 0);
  model.v2 = v * v;
  const double e = terms.Value("scalar_qed", "charge", 1),
               a = terms.Value("scalar_qed", "modulation", 0),
               w = terms.Value("scalar_qed", "frequency", 0);
  model.coupling = [e, a, w](double t) {
    return e * (1 + a * std::sin(w * t));
  };
  return model;
}

std::vector<std::string> ChargedValueNames(int d) {
  std::vector<std::string> n = {"abs_phi"};
  for (int b = 0; b < d; ++b) n.push_back(std::string("E_") + "xyz"[b]);
  n.push_back("rho");
  return n;
}

std::vector<std::string> ChargedValueLabels(int d) {
  std::vector<std::string> n = {"|φ|"};
  for (int b = 0; b < d; ++b)
    n.push_back(d == 1 ? std::string("E") : std::string("E_") + "xyz"[b]);
  n.push_back("ρ");
  return n;
}

double ChargedOmegaMax(const FieldScene& s) {
  const auto model = ChargedModel(s);
  const detail::TermSet terms{s};
  double links = 0, s_max = 0;
  for (int b = 0; b < s.Dim(); ++b) {
    const double h = s.Axis(b).Space().dx();
    links += 4 / (h * h);
  }
  const int m = 2 + s.Dim();
  for (std::size_t j = 0; j < s.phi0.size(); j += std::size_t(m))
    s_max =
        std::max(s_max, s.phi0[j] * s.phi0[j] + s.phi0[j + 1] * s.phi0[j + 1]);
  // e(t) = e(1 + a sin ωt) is at most e(1 + |a|).
  const double e_max =
      terms.Value("scalar_qed", "charge", 1) *
      (1 + std::abs(terms.Value("scalar_qed", "modulation", 0)));
  // The radial curvature of V at |φ|² = s: V'(s) + 2sV''(s), at 0 and s_max.
  const double curvature =
      std::max({0.0, model.PotentialSlope(0),
                model.PotentialSlope(s_max) + 2 * s_max * model.lambda});
  return std::sqrt(links + curvature + 2 * e_max * e_max * s_max);
}

namespace {

// s.phi0 and s.phi_t0 in charged_field.h's layout: χ = 0 after A.
template <int d>
void SystemData(const FieldScene& s, std::vector<double>& phi,
                std::vector<double>& pi) {
  constexpr int m = 3 + d, given = 2 + d;
  const std::size_t n = s.phi0.size() / given;
  phi.assign(n * m, 0.0);
  pi.assign(n * m, 0.0);
  for (std::size_t j = 0; j < n; ++j)
    for (int a = 0; a < given; ++a) {
      phi[j * m + a] = s.phi0[j * given + a];
      pi[j * m + a] = s.phi_t0[j * given + a];
    }
}

// One slice's diagnostics from the nodes of a window, node i.
double Column(const std::string& name, const action::ChargedNodes& nodes,
              const sbp::SpaceGrid<double>& grid, int i) {
  const std::size_t n0 = std::size_t(i) * grid.points();
  double sum = 0, worst = 0;
  for (int j = 0; j < grid.points(); ++j) {
    const std::size_t k = n0 + j;
    if (name == "energy") sum += grid.NormWeight(j) * nodes.energy_density[k];
    if (name == "charge") sum += grid.NormWeight(j) * nodes.charge_action[k];
    if (name == "gauss") worst = std::max(worst, nodes.gauss_action[k]);
    if (name == "gauss_textbook")
      worst = std::max(worst, nodes.gauss_textbook[k]);
  }
  return name == "gauss" || name == "gauss_textbook" ? worst : sum;
}

// The corrected end state a window hands on (charged_march.h) as the
// values of its last slice: |φ|, E_b = ∂_tA_b in the gauge A₀ = 0 there,
// ρ = 2 Im(φ̄ D_0φ); and its energy and charge for the diagnostics (the
// node's own values use D_t's closure row, an order less accurate).
template <int d>
void AppendHanded(const spacetime::ChargedSliceState& handed,
                  const sbp::SpaceGrid<double>& grid, std::vector<double>& out,
                  double& charge) {
  using L = action::ChargedLayout<d>;
  charge = 0;
  for (int j = 0; j < grid.points(); ++j) {
    const double* x = &handed.x[std::size_t(j) * L::m];
    const double* v = &handed.v[std::size_t(j) * L::m];
    const action::Complex phi(x[L::kRe], x[L::kIm]), dphi(v[L::kRe], v[L::kIm]);
    out.push_back(std::abs(phi));
    for (int b = 0; b < d; ++b) out.push_back(v[L::A(b)]);
    const double rho = action::ChargeDensity(phi, dphi);
    out.push_back(rho);
    charge += grid.NormWeight(j) * rho;
  }
}

// The vortices of node i of a window (its own slice of y), or of the
// handed state at the window's end.
template <class System>
void Track(const System& sys, const std::vector<double>& y, int i,
           const spacetime::ChargedSliceState* handed, double t,
           FieldRun& run) {
  const auto found =
      handed ? action::FindVortices(sys.space_grid(), handed->x.data())
             : action::FindVorticesAtNode(sys, y.data(), i);
  for (const auto& v : found) run.vortices.push_back({t, v.x, v.y, v.winding});
}

template <int d>
FieldRun Run(const FieldScene& s,
             const std::function<void(int, int, double)>& on_window) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const auto model = ChargedModel(s);
  const auto grid = s.Grid();
  FieldRun run;
  auto& sol = run.solution;
  const int w = int(s.method.window_points);
  spacetime::ChargedMarchOptions o;
  o.time_operator = s.method.op;
  o.window = w;
  o.windows = int((s.time_points - 1) / (w - 1));
  o.dt = s.t_end / double(s.time_points - 1);
  sol.dt = o.dt;
  sol.linear_solver = s.method.linear_solver;
  sol.limit = variational::StabilityLimit(s.method.op);
  sol.omega_dt = o.dt * ChargedOmegaMax(s);
  sol.status.reason = spacetime::UnderResolved(
      s.method.op, sol.limit, o.dt, sol.omega_dt / o.dt, 0.0, s.t_end);
  if (!sol.status.reason.empty()) return run;
  if (d == 1)
    for (int j = 0; j < grid.points(); ++j) run.x.push_back(grid.x(j, 0));
  run.columns = s.output.diagnostics;
  run.values.assign(run.columns.size(), {});
  run.gauss_residual = run.gauss_textbook = 0;
  std::vector<double> phi, pi;
  SystemData<d>(s, phi, pi);
  const int nx = grid.points();
  int done = 0;
  auto observe = [&](const auto& sys, const std::vector<double>& y,
                     const action::ChargedNodes& nodes,
                     const spacetime::ChargedSliceState& handed) {
    const auto& D = sys.time_operator().base();
    // The junction is the previous window's end state.
    for (int i = done == 0 ? 0 : 1; i < w; ++i) {
      sol.t.push_back(D.t(i));
      double charge = 0;
      if constexpr (d == 2)
        Track(sys, y, i, i == w - 1 ? &handed : nullptr, D.t(i), run);
      if (i == w - 1) {
        AppendHanded<d>(handed, grid, sol.phi, charge);
      } else {
        for (int j = 0; j < nx; ++j) {
          const std::size_t k = std::size_t(i) * nx + j;
          sol.phi.push_back(nodes.modulus[k]);
          for (int b = 0; b < d; ++b)
            sol.phi.push_back(nodes.electric[k * d + b]);
          sol.phi.push_back(nodes.charge_action[k]);
        }
      }
      for (std::size_t c = 0; c < run.columns.size(); ++c) {
        double v = Column(run.columns[c], nodes, grid, i);
        if (i == w - 1 && run.columns[c] == "energy")
          v = spacetime::SliceEnergy<d>(model, grid, D.t(i), handed);
        if (i == w - 1 && run.columns[c] == "charge") v = charge;
        run.values[c].push_back(v);
      }
      run.gauss_residual =
          std::max(run.gauss_residual, Column("gauss", nodes, grid, i));
      run.gauss_textbook = std::max(run.gauss_textbook,
                                    Column("gauss_textbook", nodes, grid, i));
    }
    sol.window_ends.push_back(sol.t.size() - 1);
    ++done;
    if (on_window) on_window(done, o.windows, D.t(w - 1));
  };
  // The Higgs vacuum's charge density 2v²·√2ev is the scale of the Gauss
  // law of data with E = 0 and ρ = 0 (static vortices).
  o.gauss_scale_floor =
      2 * std::sqrt(2.0) * model.coupling(0) * std::pow(model.v2, 1.5);
  spacetime::ChargedMarch march;
  if constexpr (d == 2)
    march = spacetime::MarchChargedSupernodal(model, grid, phi, pi, o, observe);
  else
    march = spacetime::MarchCharged<fields::ScalarQed, d>(model, grid, phi, pi,
                                                          o, observe);
  sol.windows = int(march.windows.size());
  for (const auto& r : march.windows) {
    sol.factorizations += r.iterations;
    sol.march_fallbacks += r.retries;
    sol.residual_norm = std::max(sol.residual_norm, r.residual);
  }
  sol.corrections = int(sol.factorizations);
  sol.points = (long long)sol.t.size();
  sol.nx = nx;
  sol.components = s.components;
  sol.status.converged = march.ok;
  sol.status.reason = march.ok ? "marched " + std::to_string(sol.windows) +
                                     " windows, the action's Gauss law "
                                     "checked at every node"
                               : march.reason;
  sol.status.iterations = sol.factorizations;
  sol.unchecked =
      "each window is checked by the action's Gauss law at every node, not "
      "against an independent integration";
  // Every window's last slice is its corrected end state, not a closure
  // row's (AppendHanded).
  run.closure.assign(sol.t.size(), 0);
  run.end_state_error = NAN;
  sol.seconds_total = sol.status.seconds =
      std::chrono::duration<double>(Clock::now() - start).count();
  return run;
}

}  // namespace

void ChargedSystemData(const FieldScene& s, std::vector<double>& phi,
                       std::vector<double>& pi) {
  if (s.Dim() == 2)
    SystemData<2>(s, phi, pi);
  else
    SystemData<1>(s, phi, pi);
}

FieldRun RunChargedScene(
    const FieldScene& s,
    const std::function<void(int, int, double)>& on_window) {
  if (s.Dim() == 1) return Run<1>(s, on_window);
  if (!s.phi0.empty()) return Run<2>(s, on_window);
  FieldScene ready = s;
  const double residual = PrepareVortexStart(ready);
  FieldRun run = Run<2>(ready, on_window);
  run.relaxation_residual = residual;
  return run;
}

}  // namespace vivp::scene
