#include "scene/field_run.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/action/field_charges.h"
#include "core/action/field_constraints.h"
#include "core/sbp/builder.h"
#include "scene/charged_scene.h"
#include "solvers/distributed/composed.h"
#include "solvers/spacetime/composed.h"

namespace vivp::scene {

namespace {

// max over the grid and components of |φ − φ_exact| at time t; slice: value
// j·m + a.
double SliceError(const FieldScene& s, const sbp::SpaceGrid<double>& grid,
                  double t, const double* slice) {
  const int m = s.components;
  double phi[4], phi_t[4], x[3], worst = 0;
  for (int j = 0; j < grid.points(); ++j) {
    for (int a = 0; a < grid.dim(); ++a) x[a] = grid.x(j, a);
    s.exact(t, x, phi, phi_t);
    for (int a = 0; a < m; ++a) {
      const double e = std::abs(slice[j * m + a] - phi[a]);
      if (std::isnan(e)) return e;  // no exact value: no error, not 0
      worst = std::max(worst, e);
    }
  }
  return worst;
}

// The larger of two residuals, NaN if either is (a non-finite slice stays
// visible in the summary).
double MaxOrNan(double a, double b) {
  return std::isnan(a) || std::isnan(b) ? NAN : std::max(a, b);
}

// The diagnostics' columns: the scene's names, with "momentum" one column
// per axis on a grid (momentum_x, momentum_y, …).
std::vector<std::string> Columns(const FieldScene& s) {
  std::vector<std::string> c;
  for (const auto& name : s.output.diagnostics) {
    if (name != "momentum" || s.Dim() == 1) {
      c.push_back(name);
      continue;
    }
    for (int a = 0; a < s.Dim(); ++a)
      c.push_back(std::string("momentum_") + "xyz"[a]);
  }
  return c;
}

double Column(const std::string& name, const action::FieldCharges& q) {
  if (name == "energy") return q.energy;
  if (name == "momentum" || name == "momentum_x") return q.momenta[0];
  if (name == "momentum_y") return q.momenta[1];
  if (name == "momentum_z") return q.momenta[2];
  return q.charge;
}

// A gauge field's error: max over the grid and axes of |E − E_exact|, E_b =
// −D_bA₀ − ∂_tA_b of the slice and of the exact potentials (the potentials
// themselves depend on the gauge; E does not).
template <int d>
double GaugeSliceError(const FieldScene& s, const sbp::SpaceGrid<double>& grid,
                       double t, std::span<const double> phi,
                       std::span<const double> phi_t) {
  constexpr int m = d + 1;
  const std::size_t n = grid.points();
  std::vector<double> exact(n * m), exact_t(n * m), gx(n * d * m),
      ex(n * d * m);
  double x[3];
  for (std::size_t j = 0; j < n; ++j) {
    for (int a = 0; a < d; ++a) x[a] = grid.x(int(j), a);
    s.exact(t, x, &exact[j * m], &exact_t[j * m]);
  }
  sbp::SpaceGrid<double>::GradientWork<double> w;
  grid.Gradient<double>(m, phi, gx, w);
  grid.Gradient<double>(m, exact, ex, w);
  double worst = 0;
  for (std::size_t j = 0; j < n; ++j)
    for (int b = 0; b < d; ++b) {
      const double e = -gx[(j * d + b) * m] - phi_t[j * m + 1 + b];
      const double e0 = -ex[(j * d + b) * m] - exact_t[j * m + 1 + b];
      if (std::isnan(e - e0)) return NAN;
      worst = std::max(worst, std::abs(e - e0));
    }
  return worst;
}

template <int d, class Density>
FieldRun Run(const Density& density, const FieldScene& s,
             const std::function<void(int, int, double)>& on_window,
             const FieldRunHooks& hooks) {
  constexpr int M = Density::kDim;
  constexpr bool gauge = action::ConstraintMaskOf<Density>() != 0u;
  const auto grid = s.Grid();
  FieldRun run;
  if (d == 1)
    for (int j = 0; j < grid.points(); ++j) run.x.push_back(grid.x(j, 0));
  spacetime::FieldSolveOptions options;
  options.on_window = on_window;
  options.on_checkpoint = hooks.on_checkpoint;
  options.resume = hooks.resume;
  options.boundary = s.Boundary();
  options.tolerance = s.method.tolerance;
  options.max_points = kMaxFieldValues / (grid.points() * M);
  options.linear = spacetime::WindowLinearSolverNamed(s.method.linear_solver);
  const spacetime::FieldGrid time{.op = s.method.op,
                                  .points = s.time_points,
                                  .t_end = s.t_end,
                                  .window_points = s.method.window_points};
  // One axis: the solver compiled for the derivative (composed.h).
  if constexpr (d == 1) {
    if (hooks.comm && hooks.comm->size() > 1)
      throw std::invalid_argument(
          "a field on one axis runs on one process: run it without mpirun");
    run.solution = spacetime::SolveField(density, s.Space(), time, s.phi0,
                                         s.phi_t0, options);
  } else if constexpr (gauge) {
    if (hooks.comm && hooks.comm->size() > 1)
      throw std::invalid_argument(
          "a gauge field is not built across ranks: run it on one process, "
          "without mpirun");
    run.solution =
        spacetime::SolveField(density, grid, time, s.phi0, s.phi_t0, options);
  } else if (hooks.comm) {
    run.solution = distributed::SolveField(*hooks.comm, density, grid, time,
                                           s.phi0, s.phi_t0, options);
  } else {
    run.solution =
        spacetime::SolveField(density, grid, time, s.phi0, s.phi_t0, options);
  }
  const auto& sol = run.solution;
  if (hooks.resume) run.first_node = hooks.resume->node;
  run.end_state_error = std::numeric_limits<double>::quiet_NaN();
  if (!sol.status.converged) return run;
  run.closure.assign(sol.t.size(), 0);
  if (!sol.window_ends.empty()) run.closure.at(sol.window_ends.back()) = 1;
  run.columns = Columns(s);
  run.values.assign(run.columns.size(), {});
  const std::size_t n = std::size_t(grid.points()) * M;
  const bool charges =
      s.Wants("energy") || s.Wants("momentum") || s.Wants("charge");
  if (gauge) run.gauss_residual = run.gauss_textbook = 0;
  for (std::size_t k = 0; k < sol.t.size(); ++k) {
    const std::span<const double> phi(sol.phi.data() + k * n, n);
    const std::span<const double> phi_t(sol.phi_t.data() + k * n, n);
    action::FieldCharges q;
    if (charges) q = action::ChargesOfSlice(density, grid, phi, phi_t);
    double gauss = NAN, textbook = NAN;
    if constexpr (gauge) {
      gauss = action::ConstraintsOfSlice(density, grid, phi, phi_t).relative();
      textbook = action::TextbookConstraintsOfSlice(density, grid, phi, phi_t)
                     .relative();
      run.gauss_residual = MaxOrNan(run.gauss_residual, gauss);
      run.gauss_textbook = MaxOrNan(run.gauss_textbook, textbook);
    }
    for (std::size_t c = 0; c < run.columns.size(); ++c) {
      const std::string& name = run.columns[c];
      double v = Column(name, q);
      if (name == "gauss") v = gauss;
      if (name == "gauss_textbook") v = textbook;
      if (name == "error")
        v = gauge ? GaugeSliceError<d>(s, grid, sol.t[k], phi, phi_t)
                  : SliceError(s, grid, sol.t[k], phi.data());
      run.values[c].push_back(v);
    }
  }
  if (s.exact)
    run.end_state_error =
        gauge ? GaugeSliceError<d>(s, grid, s.t_end, sol.end.phi, sol.end.phi_t)
              : SliceError(s, grid, s.t_end, sol.end.phi.data());
  return run;
}

template <int M, int d>
FieldRun Run(const FieldScene& s,
             const std::function<void(int, int, double)>& on_window,
             const FieldRunHooks& hooks) {
  return Run<d>(s.Density<M, d>(), s, on_window, hooks);
}

}  // namespace

FieldRun RunFieldScene(const FieldScene& s,
                       const std::function<void(int, int, double)>& on_window,
                       const FieldRunHooks& hooks) {
  if (s.Charged()) {
    if (hooks.comm && hooks.comm->size() > 1)
      throw std::invalid_argument(
          "a charged field is not built across ranks: run it on one process, "
          "without mpirun");
    return RunChargedScene(s, on_window);
  }
  if (s.Gauge())
    return s.Dim() == 3 ? Run<3>(fields::MaxwellIn<3>{}, s, on_window, hooks)
                        : Run<2>(fields::MaxwellIn<2>{}, s, on_window, hooks);
  const bool two = s.components == 2;
  switch (s.Dim()) {
    case 2:
      return two ? Run<2, 2>(s, on_window, hooks)
                 : Run<1, 2>(s, on_window, hooks);
    case 3:
      return two ? Run<2, 3>(s, on_window, hooks)
                 : Run<1, 3>(s, on_window, hooks);
    default:
      return two ? Run<2, 1>(s, on_window, hooks)
                 : Run<1, 1>(s, on_window, hooks);
  }
}

}  // namespace vivp::scene
