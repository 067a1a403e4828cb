// Solve a field's initial value problem from its action: one global
// space-time solve, or time-slab marching with the multiplier hand-off per
// spatial point (docs/fields.md).
//
//   vivp::fields::SineGordon density;
//   auto dx = vivp::sbp::SpaceDerivative<double>::Periodic(8, 200, -20, 40);
//   vivp::spacetime::FieldGrid grid{.op = "sbp42", .points = 201, .t_end = 2};
//   auto s = vivp::spacetime::SolveField(density, dx, grid, phi0, pi0);
//   // s.phi: every kept slice, value (slice·Nx + j)·m + a
//
// In d = 2 or 3 spatial dimensions the density declares kSpaceDim and the
// space is a grid of one derivative per axis (core/sbp/space_grid.h):
//
//   vivp::fields::SineGordonIn<2> density;
//   vivp::sbp::SpaceGrid<double> space({
//       vivp::sbp::SpaceDerivative<double>::Periodic(8, 64, -16, 16),
//       vivp::sbp::SpaceDerivative<double>::Periodic(8, 64, -16, 16)});
//   auto s = vivp::spacetime::SolveField(density, space, grid, phi0, pi0);
//   // s.phi: value (slice·N + j)·m + a, j the grid's flat index
//
// On an interval the ends may carry data (core/action/field_boundary.h):
//
//   vivp::spacetime::FieldSolveOptions o;
//   o.boundary.left = {vivp::action::BoundaryKind::kDirichlet,
//                      [](double t, int) { return std::sin(t); }};
//
// The march is that of point mechanics (solvers/variational/march.h): a
// field is a Lagrangian density with components, and what differs is the
// window (field_window.h) and its linear solver (window_solver.h). So each
// window is an IVP of its own whose initial data are the previous window's
// corrected end state, Newton starts from an independent integration of the
// semi-discrete equations (predictor.h) and the converged window is checked
// against it (solvers/variational/window_checks.h), a failing window is
// solved again afresh and then split, and with a tolerance the march
// chooses each window's Δt from the windows' embedded estimates (error
// control, docs/error_control.md). On a uniform grid, windows of W time
// points cover W − 1 intervals; the last one takes the remainder (at least
// the operator's minimum).
//
// Before solving, the grid is checked against the resolution limit
// (resolution.h) at the initial state, and every window again at its ends.
// An under-resolved run is reported as not converged with the number of
// time points it needs, never returned as a solution.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "core/sbp/builder.h"
#include "solvers/spacetime/checkpoint.h"
#include "solvers/spacetime/end_state.h"
#include "solvers/spacetime/field_window.h"
#include "solvers/spacetime/input.h"
#include "solvers/spacetime/resolution.h"
#include "solvers/variational/march_adaptive.h"
#include "solvers/variational/march_uniform.h"
#include "solvers/variational/resolution.h"
#include "solvers/variational/step_control.h"
#include "solvers/variational/summary.h"

namespace vivp::spacetime {

struct FieldGrid {
  std::string op = "sbp42";  // the time operator: sbp21, sbp42, sbp63, sbp84
  long long points = 65;     // time points on [0, t_end] (uniform grid)
  double t_end = 1.0;
  // Time points per window; 0 (or ≥ points) solves globally. Under error
  // control every window has this many points (0: 16).
  long long window_points = 0;
};

struct FieldSolveOptions {
  variational::NewtonOptions newton;
  // The window's linear solver (window_solver.h): the space-diagonalized
  // solve, or the sparse LU of the whole window (the reference), and which
  // sparse LU (also the fallback of the former).
  WindowLinearSolver linear = WindowLinearSolver::kModes;
  SparseSolver sparse = SparseSolver::kUmfpack;
  FieldBoundary boundary;  // natural unless set; an interval only
  bool keep_field = true;  // every slice of φ and φ_t in FieldSolution
  bool check_resolution = true;
  // Error control (docs/error_control.md): each window's Δt chosen so that
  // the local error of every node stays below absolute + relative·|value|,
  // φ and φ_t at every spatial point; FieldGrid::points is then unused and
  // the slices are not uniform in time. Disabled: the uniform grid.
  variational::Tolerance tolerance;
  double initial_step = 0;  // error control: the first Δt (0: from ω_max)
  long long max_points = 100'000'000;  // error control: time nodes at most
  // Called after each accepted window with the windows done, their number
  // (0 under error control, where it is not known) and the time reached (a
  // progress line; it runs on the solving thread).
  std::function<void(int done, int total, double t)> on_window;
  // A uniform march: called at every window boundary with the checkpoint
  // there (checkpoint.h), and a checkpoint to resume from — the fields are
  // then those of the uninterrupted march, bit for bit, from its node on
  // (φ0 and π0 are not used; the kept slices start at the checkpoint).
  std::function<void(const FieldCheckpoint&)> on_checkpoint;
  const FieldCheckpoint* resume = nullptr;
};

struct FieldSolution {
  // converged, reason, Newton iterations (Jacobian factorizations over all
  // windows), the worst window's last residual, the wall time.
  variational::Summary status;
  int nx = 0, components = 0;
  std::vector<double> t;                   // the kept slices' times
  std::vector<std::size_t> window_ends;    // kept slices that end a window
  std::vector<double> phi, phi_t;          // kept slices, (s·Nx + j)·m + a
  FieldEnd end;                            // corrected state at t_end
  std::vector<double> end_phi_node;        // φ at the last node, uncorrected
  double dt = 0, omega_dt = 0, limit = 0;  // Δt·ω_max at the worst window
  int windows = 0, corrections = 0;
  long long factorizations = 0;  // Newton iterations: one each
  long long points = 0;          // time nodes returned
  // The march's fallbacks (windows solved again afresh or split), windows
  // rejected by error control, and windows that failed an a-posteriori
  // check; the smallest and largest Δt (they differ under error control).
  int march_fallbacks = 0, rejected = 0, check_failures = 0;
  double min_step = 0, max_step = 0;
  long predictor_steps = 0;
  // Why the windows were not checked against an independent integration
  // (empty: every window was).
  std::string unchecked;
  std::string linear_solver;  // "modes" or "sparse-lu"
  int ranks = 0;  // the processes space was spread over; 0: not distributed
  // The space-diagonalized solve: time systems factored (one per distinct
  // spatial mode and factorization), the bytes its factors hold, and the
  // windows that fell back to the sparse LU.
  long long mode_factorizations = 0;
  std::size_t factor_bytes = 0;
  int fallbacks = 0;
  long long lu_factorizations = 0;
  long long jacobian_nonzeros = 0;  // the sparse LU's, when it ran
  double residual_norm = 0;         // worst window's |F|∞
  // Where the time goes: in Newton, the residuals, the Jacobian's assembly
  // (the sparse LU's) or the Hessian blocks (the modes'), factorizations and
  // solves; around it, each window's system and data (setup), the
  // resolution check, the corrected end state and kept slices (hand-off),
  // the predictor, and the rest of the total (the march's own work).
  double seconds_assembly = 0, seconds_factor = 0, seconds_solve = 0,
         seconds_residual = 0, seconds_setup = 0, seconds_check = 0,
         seconds_handoff = 0, seconds_predictor = 0, seconds_total = 0;
};

// The march with the window `make(options, φ0, π0)` returns (a
// std::unique_ptr): FieldWindow on one process, or the slab of one rank of
// a distributed march (solvers/distributed/solve.h).
template <class Density, class MakeWindow>
FieldSolution SolveFieldWith(const Density& density,
                             const sbp::SpaceGrid<double>& space,
                             const FieldGrid& grid, std::vector<double> phi0,
                             std::vector<double> pi0,
                             const FieldSolveOptions& options,
                             MakeWindow&& make) {
  constexpr int m = Density::kDim;
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  FieldSolution s;
  s.nx = space.points();
  s.components = m;
  const bool adaptive = options.tolerance.enabled();
  if (adaptive && (options.on_checkpoint || options.resume))
    throw std::invalid_argument(
        "checkpoints are taken of uniform marches; an error-controlled march "
        "(a tolerance) has a step controller whose history they do not keep");
  if (options.resume) {
    phi0 = options.resume->phi;
    pi0 = options.resume->phi_t;
  }
  const auto& table = sbp::Table(grid.op);
  if (!adaptive && grid.points < table.min_points)
    throw std::invalid_argument(
        grid.op + " needs at least " + std::to_string(table.min_points) +
        " time points, got " + std::to_string(grid.points));
  CheckFieldInput(grid.t_end, space, m, phi0, pi0);
  if (space.dim() != action::SpaceDimOf<Density>())
    throw std::invalid_argument("the density has " +
                                std::to_string(action::SpaceDimOf<Density>()) +
                                " spatial dimensions, the grid " +
                                std::to_string(space.dim()) + " axes");
  if (space.dim() > 1 &&
      (options.boundary.left.kind != action::BoundaryKind::kNatural ||
       options.boundary.right.kind != action::BoundaryKind::kNatural))
    throw std::invalid_argument(
        "boundary data at the ends (left, right) are for one spatial "
        "dimension; in " +
        std::to_string(space.dim()) + " give Neumann data per face (faces)");
  CheckFaces(space, options.boundary.faces);
  CheckLinearSolver<Density>(space, options.linear, options.boundary);
  const variational::Tolerance& tol = options.tolerance;
  if (adaptive &&
      !(std::isfinite(tol.absolute) && std::isfinite(tol.relative) &&
        tol.absolute >= 0 && tol.relative >= 0))
    throw std::invalid_argument(
        "tolerance must be finite and non-negative (absolute, relative)");
  const std::size_t n = static_cast<std::size_t>(s.nx) * m;
  s.dt = adaptive ? 0 : grid.t_end / double(grid.points - 1);
  s.limit = variational::StabilityLimit(grid.op);
  s.linear_solver = std::string(WindowLinearSolverName(options.linear));

  // The boundary data first, on the first window's nodes (what they are
  // checked against is the system's: field_boundary.h).
  if (!adaptive) {
    const long long w =
        grid.window_points > 0 && grid.window_points < grid.points
            ? grid.window_points
            : grid.points;
    const sbp::RegularizedOperator<double> first(
        sbp::MakeOperator<double>(grid.op, w, 0.0, s.dt * double(w - 1)));
    action::FieldSystem<Density> sys(density, first, space, phi0, pi0);
    detail::SetBoundaryData(sys, options.boundary, 0.0, s.dt);
  }
  // Then the initial state: a grid too coarse for it is refused with the
  // number of points it needs, before any work.
  if (options.check_resolution && !adaptive) {
    const double omega =
        FastestFieldFrequency(density, space, SpectralRadius(space), phi0, pi0);
    s.omega_dt = s.dt * omega;
    s.status.reason =
        UnderResolved(grid.op, s.limit, s.dt, omega, 0.0, grid.t_end);
    if (!s.status.reason.empty()) {
      s.seconds_total =
          std::chrono::duration<double>(Clock::now() - start).count();
      s.status.seconds = s.seconds_total;
      return s;
    }
  }

  const FieldWindowOptions wo{options.newton,           options.linear,
                              options.sparse,           options.boundary,
                              options.check_resolution, grid.t_end};
  const auto window_owner = make(wo, phi0, pi0);
  auto& window = *window_owner;
  using Window = std::remove_reference_t<decltype(window)>;
  s.unchecked = window.unchecked();
  variational::MarchOptions mo;
  const long long all = adaptive ? 0 : grid.points;
  mo.window_points =
      grid.window_points > 0 && (adaptive || grid.window_points < all)
          ? grid.window_points
      : adaptive ? 16
                 : all;
  if (mo.window_points < table.min_points)
    throw std::invalid_argument("a window of " +
                                std::to_string(mo.window_points) +
                                " points is below the minimum of " + grid.op +
                                " (" + std::to_string(table.min_points) + ")");
  mo.keep_trajectory = false;
  // A field refuses an under-resolved grid (above) rather than refining it.
  mo.stabilize = false;
  mo.tolerance = options.tolerance;
  mo.initial_step = options.initial_step;
  mo.max_points = options.max_points;
  mo.solve.newton = options.newton;
  const int total = adaptive
                        ? 0
                        : int((grid.points - 1 + mo.window_points - 2) /
                              std::max<long long>(mo.window_points - 1, 1));
  int done = 0;
  if (options.resume) {
    const std::string why = CannotResume(*options.resume, grid.op, grid.points,
                                         mo.window_points, grid.t_end, s.nx, m);
    if (!why.empty()) throw std::invalid_argument(why);
    window.Restore(options.resume->carry);
    mo.start_node = options.resume->node;
    done = options.resume->windows;
  }
  if (options.on_checkpoint)
    mo.at_boundary = [&](long long node, const variational::InitialData& x) {
      FieldCheckpoint c{
          grid.op, grid.points,  mo.window_points,    grid.t_end, s.nx,
          m,       node,         s.dt * double(node), x.x,        x.v,
          done,    window.Save()};
      options.on_checkpoint(c);
    };
  mo.window_observer = [&](const variational::WindowSample& w) {
    ++done;
    // The window's nodes but its last are kept; its last is the next one
    // to come (or, for the march's last window, the last kept).
    if (options.keep_field) s.window_ends.push_back(s.t.size());
    if (options.on_window)
      options.on_window(done, std::max(total, done), w.t_end);
  };
  const variational::NodeObserver keep = [&](double t, const double* x,
                                             const double* v) {
    if (!options.keep_field) return;
    s.t.push_back(t);
    s.phi.insert(s.phi.end(), x, x + n);
    s.phi_t.insert(s.phi_t.end(), v, v + n);
  };
  const variational::Grid g{.op = grid.op,
                            .points = adaptive ? table.min_points : grid.points,
                            .t_start = 0.0,
                            .t_end = grid.t_end};
  variational::MarchResult out;
  variational::InitialData state{std::move(phi0), std::move(pi0)};
  bool ok;
  if (adaptive) {
    variational::detail::AdaptiveMarch<Window> march(window, g, mo, keep, out,
                                                     table.min_points);
    ok = march.Run(state);
  } else {
    variational::detail::UniformMarch<Window> march(window, g, mo, keep, out,
                                                    table.min_points);
    ok = march.Run(state);
  }
  for (auto& e : s.window_ends) e = std::min(e, s.t.size() - 1);
  s.status.converged = ok;
  s.status.reason =
      ok ? std::string(adaptive ? "converged under error control" : "converged")
         : out.status.reason;
  s.status.iterations = out.iterations;
  s.windows = int(out.window_count);
  s.factorizations = out.iterations;
  s.corrections = out.corrections;
  s.points = out.points;
  s.march_fallbacks = out.fallbacks;
  s.rejected = out.rejected;
  s.check_failures = out.check_failures;
  s.min_step = out.min_step;
  s.max_step = out.max_step;
  s.predictor_steps = out.predictor_steps;
  s.omega_dt = std::max(s.omega_dt, window.omega_dt());
  s.mode_factorizations = window.mode_factorizations();
  s.lu_factorizations = window.lu_factorizations();
  s.fallbacks = window.fallbacks();
  s.factor_bytes = window.factor_bytes();
  s.jacobian_nonzeros = window.jacobian_nonzeros();
  s.residual_norm = window.residual_norm();
  if (ok) {
    s.end.phi = state.x;
    s.end.phi_t = state.v;
    s.end_phi_node = window.last_node();
    s.end.phi_estimate = window.last_estimates().first;
    s.end.phi_t_estimate = window.last_estimates().second;
  }
  const FieldTimings& ft = window.timings();
  s.seconds_residual = ft.residual;
  s.seconds_assembly = ft.assembly;
  s.seconds_factor = ft.factorization;
  s.seconds_solve = ft.solve;
  s.seconds_setup = ft.setup;
  s.seconds_check = ft.check;
  s.seconds_handoff = ft.handoff;
  s.seconds_predictor = ft.predictor;
  s.seconds_total = std::chrono::duration<double>(Clock::now() - start).count();
  s.status.seconds = s.seconds_total;
  s.status.last_residual = ok ? s.residual_norm : out.last_residual;
  return s;
}

template <class Density>
FieldSolution SolveField(const Density& density,
                         const sbp::SpaceGrid<double>& space,
                         const FieldGrid& grid, std::vector<double> phi0,
                         std::vector<double> pi0,
                         const FieldSolveOptions& options = {}) {
  return SolveFieldWith(
      density, space, grid, std::move(phi0), std::move(pi0), options,
      [&](const FieldWindowOptions& wo, const std::vector<double>& x0,
          const std::vector<double>& v0) {
        return std::make_unique<FieldWindow<Density>>(density, space, grid.op,
                                                      wo, x0, v0);
      });
}

// A field of one spatial axis.
template <class Density>
FieldSolution SolveField(const Density& density,
                         const sbp::SpaceDerivative<double>& dx,
                         const FieldGrid& grid, std::vector<double> phi0,
                         std::vector<double> pi0,
                         const FieldSolveOptions& options = {}) {
  return SolveField(density, sbp::SpaceGrid<double>(dx), grid, std::move(phi0),
                    std::move(pi0), options);
}

}  // namespace vivp::spacetime
