// Solve a field's initial value problem from its action: one global
// space-time solve, or time-slab marching with the multiplier hand-off per
// spatial point (docs/fields.md).
//
//   vivp::fields::SineGordon density;
//   auto dx = vivp::sbp::SpaceDerivative<double>::Periodic(8, 200, -20, 40);
//   vivp::fields::FieldGrid grid{.op = "sbp42", .points = 201, .t_end = 2};
//   auto s = vivp::fields::SolveField(density, dx, grid, phi0, pi0);
//   // s.phi: every kept slice, value (slice·Nx + j)·m + a
//
// On an interval the ends may carry data (core/action/field_boundary.h):
//
//   vivp::fields::FieldSolveOptions o;
//   o.boundary.left = {vivp::action::BoundaryKind::kDirichlet,
//                      [](double t, int) { return std::sin(t); }};
//
// Windows of W time points cover W − 1 intervals; the last one takes the
// remainder (at least the operator's minimum). Each window is an IVP of its
// own whose initial data are the previous window's corrected end state
// (end_state.h). The Jacobian's pattern and ordering are shared by all
// windows of one size, and the factorization too: Newton starts each window
// with chord steps on the previous window's factors (for a linear field the
// same matrix, so one factorization serves the whole march) and refactors
// only when they stop contracting.
//
// Before solving, the grid is checked against the resolution limit
// (resolution.h) at the initial state; a march checks every window's
// initial state. An under-resolved run is reported as not converged with
// the number of time points it needs, never returned as a solution.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/action/field_system.h"
#include "core/sbp/builder.h"
#include "core/sbp/regularized.h"
#include "solvers/fields/end_state.h"
#include "solvers/fields/input.h"
#include "solvers/fields/resolution.h"
#include "solvers/fields/window_solver.h"
#include "solvers/variational/newton.h"
#include "solvers/variational/resolution.h"

namespace vivp::fields {

struct FieldGrid {
  std::string op = "sbp42";  // the time operator: sbp21, sbp42, sbp63, sbp84
  long long points = 65;     // time points on [0, t_end]
  double t_end = 1.0;
  // Time points per window; 0 (or ≥ points) solves globally.
  long long window_points = 0;
};

// One end of an interval: the natural condition ∂L/∂φ_x = 0 of the discrete
// action, or Dirichlet / Neumann data imposed by multipliers
// (core/action/field_boundary.h); value(t, a) is g or h of component a
// (empty: 0).
struct FieldBoundarySide {
  action::BoundaryKind kind = action::BoundaryKind::kNatural;
  std::function<double(double t, int a)> value;
};
struct FieldBoundary {
  FieldBoundarySide left, right;
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
  // Called after each accepted window with the windows done, their number
  // and the time reached (a progress line; it runs on the solving thread).
  std::function<void(int done, int total, double t)> on_window;
};

struct FieldSolution {
  bool converged = false;
  std::string message;
  int nx = 0, components = 0;
  std::vector<double> t;                   // the kept slices' times
  std::vector<double> phi, phi_t;          // kept slices, (s·Nx + j)·m + a
  FieldEnd end;                            // corrected state at t_end
  std::vector<double> end_phi_node;        // φ at the last node, uncorrected
  double dt = 0, omega_dt = 0, limit = 0;  // Δt·ω_max at the worst window
  int windows = 0, corrections = 0;
  long long factorizations = 0;  // Newton iterations: one each
  std::string linear_solver;     // "modes" or "sparse-lu"
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
  // solves; around it, each window's operators, system and data (setup:
  // the allocations), the resolution check, the corrected end state and the
  // kept slices (hand-off), and the rest of the total.
  double seconds_assembly = 0, seconds_factor = 0, seconds_solve = 0,
         seconds_residual = 0, seconds_setup = 0, seconds_check = 0,
         seconds_handoff = 0, seconds_total = 0;
};

namespace detail {

// The window lengths (points) of a march of `points` over W-point windows.
inline std::vector<long long> WindowSizes(long long points, long long w,
                                          long long min_points) {
  std::vector<long long> sizes;
  if (w <= 0 || w >= points) return {points};
  long long left = points - 1;  // intervals
  while (left > 0) {
    long long take = std::min(left, w - 1);
    // A short remainder is merged into the last window.
    if (left - take > 0 && left - take < min_points - 1) take = left;
    sizes.push_back(take + 1);
    left -= take;
  }
  return sizes;
}

// The window's boundary data at its nodes t0 + iΔt.
template <class System>
void SetBoundaryData(System& sys, const FieldBoundary& b, double t0,
                     double dt) {
  constexpr int m = System::m;
  const FieldBoundarySide* sides[2] = {&b.left, &b.right};
  for (int side = 0; side < 2; ++side) {
    if (sides[side]->kind == action::BoundaryKind::kNatural) continue;
    std::vector<double> values(std::size_t(sys.time_points()) * m, 0.0);
    if (sides[side]->value)
      for (int i = 0; i < sys.time_points(); ++i)
        for (int a = 0; a < m; ++a) {
          const double t = t0 + dt * i;
          values[i * m + a] = sides[side]->value(t, a);
          if (!std::isfinite(values[i * m + a]))
            throw std::invalid_argument(
                std::string(side == 0 ? "left" : "right") + " " +
                action::BoundaryName(sides[side]->kind) +
                " data: non-finite value at t = " + std::to_string(t));
        }
    sys.SetBoundary(side, sides[side]->kind, std::move(values));
  }
}

}  // namespace detail

template <class Density>
FieldSolution SolveField(const Density& density,
                         const sbp::SpaceDerivative<double>& dx,
                         const FieldGrid& grid, std::vector<double> phi0,
                         std::vector<double> pi0,
                         const FieldSolveOptions& options = {}) {
  constexpr int m = Density::kComponents;
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  FieldSolution s;
  s.nx = dx.points();
  s.components = m;
  const auto& table = sbp::Table(grid.op);
  if (grid.points < table.min_points)
    throw std::invalid_argument(
        grid.op + " needs at least " + std::to_string(table.min_points) +
        " time points, got " + std::to_string(grid.points));
  CheckFieldInput(grid.t_end, dx, m, phi0, pi0);
  const std::size_t n = static_cast<std::size_t>(s.nx) * m;
  s.dt = grid.t_end / double(grid.points - 1);
  s.limit = variational::StabilityLimit(grid.op);
  const auto sizes =
      detail::WindowSizes(grid.points, grid.window_points, table.min_points);

  s.linear_solver = std::string(WindowLinearSolverName(options.linear));
  ModesSolver<Density> modes(density, options.sparse);
  SparseLuSolver sparse(options.sparse);
  long long cached_size = -1, lu_retired = 0;
  double t0 = 0;
  std::vector<double> phi = std::move(phi0), pi = std::move(pi0);
  auto finish = [&](bool ok, std::string message) {
    s.converged = ok;
    s.message = std::move(message);
    s.mode_factorizations = modes.mode_factorizations();
    s.factor_bytes = modes.factor_bytes();
    s.fallbacks = int(modes.fallbacks);
    s.lu_factorizations =
        lu_retired + sparse.factorizations + modes.lu_factorizations();
    s.jacobian_nonzeros = sparse.nonzeros();
    s.seconds_total =
        std::chrono::duration<double>(Clock::now() - start).count();
    return s;
  };
  const double rho = SpectralRadius(dx);
  action::FieldValues<double> v;  // the accepted window's fields
  auto keep = [&](const action::FieldSystem<Density>& sys, int first,
                  double t_start) {
    if (!options.keep_field) return;
    for (int i = first; i < sys.time_points(); ++i) {
      s.t.push_back(t_start + s.dt * i);
      const auto b = v.phi.begin() + sys.At(i, 0, 0);
      s.phi.insert(s.phi.end(), b, b + n);
      const auto c = v.phi_t.begin() + sys.At(i, 0, 0);
      s.phi_t.insert(s.phi_t.end(), c, c + n);
    }
  };
  auto since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  for (std::size_t w = 0; w < sizes.size(); ++w) {
    const long long pts = sizes[w];
    const double t1 = t0 + s.dt * double(pts - 1);
    auto lap = Clock::now();
    // The system first: its boundary data are checked before anything else.
    sbp::RegularizedOperator<double> dt(
        sbp::MakeOperator<double>(grid.op, pts, t0, t1));
    action::FieldSystem<Density> sys(density, dt, dx, phi, pi);
    detail::SetBoundaryData(sys, options.boundary, t0, s.dt);
    s.seconds_setup += since(lap);
    lap = Clock::now();
    if (options.check_resolution) {
      const double od = s.dt * FastestFieldFrequency(density, dx, rho, phi, pi);
      s.omega_dt = std::max(s.omega_dt, od);
      if (od > s.limit) {
        const long long need = static_cast<long long>(std::ceil(
                                   grid.t_end * (od / s.dt) / s.limit)) +
                               1;
        std::ostringstream msg;
        msg << "under-resolved: Δt·ω_max = " << od << " at t = " << t0
            << " exceeds the " << grid.op << " limit " << s.limit
            << " (ω_max = " << od / s.dt << " from the spatial grid and the "
            << "potential); use at least " << need << " time points";
        return finish(false, msg.str());
      }
    }
    s.seconds_check += since(lap);
    lap = Clock::now();
    if (pts != cached_size) {
      // The sparse LU's pattern is that of one window length (the modes
      // solver rebuilds its own per length).
      lu_retired += sparse.factorizations;
      sparse = SparseLuSolver(options.sparse);
      cached_size = pts;
    }
    // Start from φ₀ + (t − t0)·π₀.
    std::vector<double> y(sys.size(), 0.0);
    for (int j = 0; j < s.nx; ++j)
      for (int i = 0; i < pts; ++i)
        for (int a = 0; a < m; ++a)
          y[sys.Phi(i, j, a)] = phi[j * m + a] + s.dt * i * pi[j * m + a];
    s.seconds_setup += since(lap);
    const auto r =
        options.linear == WindowLinearSolver::kModes
            ? variational::Newton<double>(sys, y, options.newton, modes)
            : variational::Newton<double>(sys, y, options.newton, sparse);
    ++s.windows;
    s.factorizations += r.iterations;
    s.corrections += r.corrections;
    s.residual_norm = std::max(s.residual_norm, r.residual_norm);
    s.seconds_assembly += r.seconds.assembly;
    s.seconds_factor += r.seconds.factorization;
    s.seconds_solve += r.seconds.solve;
    s.seconds_residual += r.seconds.residual;
    if (!r.converged) {
      std::ostringstream msg;
      msg << "Newton did not converge in the window [" << t0 << ", " << t1
          << "]: " << r.reason;
      return finish(false, msg.str());
    }
    lap = Clock::now();
    sys.Fields(y.data(), v);
    keep(sys, w == 0 ? 0 : 1, t0);
    s.end = CorrectFieldEnd(sys, y.data(), v);
    if (w + 1 == sizes.size()) {
      const auto b = v.phi.begin() + sys.At(int(pts) - 1, 0, 0);
      s.end_phi_node.assign(b, b + n);
    }
    phi = s.end.phi;
    pi = s.end.phi_t;
    s.seconds_handoff += since(lap);
    t0 = t1;
    if (options.on_window) options.on_window(int(w) + 1, int(sizes.size()), t1);
  }
  return finish(true, "converged");
}

}  // namespace vivp::fields
