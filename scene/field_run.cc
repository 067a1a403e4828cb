#include "scene/field_run.h"

#include <cmath>
#include <limits>

#include "core/action/field_charges.h"
#include "core/sbp/builder.h"
#include "solvers/spacetime/composed.h"

namespace vivp::scene {

namespace {

// max over x and components of |φ − φ_exact| at time t; slice: value
// j·m + a.
double SliceError(const FieldScene& s, const std::vector<double>& x, double t,
                  const double* slice) {
  const int m = s.components;
  double phi[2], phi_t[2], worst = 0;
  for (std::size_t j = 0; j < x.size(); ++j) {
    s.exact(t, x[j], phi, phi_t);
    for (int a = 0; a < m; ++a) {
      const double e = std::abs(slice[j * m + a] - phi[a]);
      if (std::isnan(e)) return e;  // no exact value: no error, not 0
      worst = std::max(worst, e);
    }
  }
  return worst;
}

template <int M>
FieldRun Run(const FieldScene& s,
             const std::function<void(int, int, double)>& on_window) {
  const auto density = s.Density<M>();
  const auto dx = s.Space();
  FieldRun run;
  for (int j = 0; j < dx.points(); ++j) run.x.push_back(dx.x(j));
  spacetime::FieldSolveOptions options;
  options.on_window = on_window;
  options.boundary = s.Boundary();
  options.tolerance = s.method.tolerance;
  options.max_points = kMaxFieldValues / (dx.points() * M);
  options.linear = s.method.linear_solver == "sparse-lu"
                       ? spacetime::WindowLinearSolver::kSparseLu
                       : spacetime::WindowLinearSolver::kModes;
  const spacetime::FieldGrid grid{.op = s.method.op,
                                  .points = s.time_points,
                                  .t_end = s.t_end,
                                  .window_points = s.method.window_points};
  run.solution =
      spacetime::SolveField(density, dx, grid, s.phi0, s.phi_t0, options);
  const auto& sol = run.solution;
  run.end_state_error = std::numeric_limits<double>::quiet_NaN();
  if (!sol.status.converged) return run;
  run.closure.assign(sol.t.size(), 0);
  if (!sol.window_ends.empty()) run.closure.at(sol.window_ends.back()) = 1;
  run.columns = s.output.diagnostics;
  run.values.assign(run.columns.size(), {});
  const std::size_t n = std::size_t(dx.points()) * M;
  for (std::size_t k = 0; k < sol.t.size(); ++k) {
    const std::span<const double> phi(sol.phi.data() + k * n, n);
    const std::span<const double> phi_t(sol.phi_t.data() + k * n, n);
    action::FieldCharges q;
    if (s.Wants("energy") || s.Wants("momentum") || s.Wants("charge"))
      q = action::ChargesOfSlice(density, dx, phi, phi_t);
    for (std::size_t c = 0; c < run.columns.size(); ++c) {
      const std::string& name = run.columns[c];
      run.values[c].push_back(name == "energy"     ? q.energy
                              : name == "momentum" ? q.momentum
                              : name == "charge"
                                  ? q.charge
                                  : SliceError(s, run.x, sol.t[k], phi.data()));
    }
  }
  if (s.exact)
    run.end_state_error = SliceError(s, run.x, s.t_end, sol.end.phi.data());
  return run;
}

}  // namespace

FieldRun RunFieldScene(const FieldScene& s,
                       const std::function<void(int, int, double)>& on_window) {
  return s.components == 2 ? Run<2>(s, on_window) : Run<1>(s, on_window);
}

}  // namespace vivp::scene
