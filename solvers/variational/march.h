// Time-slab marching: [t_start, t_end] solved window by window (Rothkopf &
// Nordström 2023 solve one global system; windows keep the cost per node
// constant and the memory O(window)). The method is causal, so each window is
// an IVP of its own whose initial data are handed over from the previous one:
//
//   HandOff::kCorrected (default)  (x_N + M⁻¹λ4, M⁻¹(−λ3)) — the
//       multiplier-corrected end state; marching then keeps the global order
//       for every window size (first-order systems: x_N + C⁻¹λ3);
//   HandOff::kNaive  (x_N, (Dx)_N) — kept to show why it is not the default:
//       the one-window map grows by ≈1.5 % per window at Δt = 0.1 and the
//       march does not converge.
//
// Every window starts Newton from an independent order-5 integration of the
// Euler–Lagrange equations (predictor.h) and is accepted only after the
// a-posteriori checks of window_solve.h: the right branch of the discrete
// equations, or a reported failure, never a wrong answer marked converged.
//
// Two ways to choose the windows:
//   uniform grid (MarchOptions::tolerance disabled): grid.points nodes; a
//       window of W points covers W − 1 intervals, the last one takes the
//       remainder (at least the operator's minimum). A window that fails is
//       solved again with a fresh Jacobian, then split in halves (down to
//       the operator's minimum); with `stabilize`, a window whose Δt·ω
//       exceeds the stability limit is solved on a refined grid. Or given
//       windows (MarchOptions::given_windows), each its end and points,
//       the same way;
//   error control (tolerance enabled): every window has W points and a Δt
//       chosen by a step-size controller (step_control.h) from the window's
//       embedded error estimates; a window whose estimates exceed the
//       tolerance, or that fails, is rejected and solved again with a
//       smaller Δt. SBP21, whose position estimate is unreliable, estimates
//       by step doubling (the window again at Δt/2; the finer one is kept);
//       a spectral element's window is the element, solved whole and as
//       two halves, which are kept (element_halves.h).
// Every fallback, rejection and check failure is counted and reported.
//
// Output: an observer sees every node once, in order, with its time, so
// memory stays O(window) when the caller streams; the stitched trajectory is
// kept only if asked for.
#pragma once

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "solvers/variational/march_adaptive.h"
#include "solvers/variational/march_types.h"
#include "solvers/variational/march_uniform.h"
#include "solvers/variational/point_window.h"
#include "solvers/variational/solve_ivp.h"
#include "solvers/variational/solver_choice.h"

namespace vivp::variational {

namespace detail {

// A spectral element (lobatto.h) marches in windows of its own size n; on a
// uniform grid the steps are a multiple of n − 1. Otherwise
// std::invalid_argument naming the fix.
inline void CheckElementMarch(const Grid& grid, int n, bool adaptive,
                              long long window_points, bool given_windows) {
  const std::string what =
      grid.op + " is a spectral element of " + std::to_string(n) + " points";
  if (window_points != n)
    throw std::invalid_argument(what + ": it marches in windows of " +
                                std::to_string(n) + " points, got " +
                                std::to_string(window_points) +
                                "; leave the window at its default");
  if (adaptive || given_windows) return;
  const long long steps = grid.points - 1, per = n - 1;
  const long long below = steps / per * per, above = below + per;
  if (steps < per || steps % per != 0)
    throw std::invalid_argument(
        what + ": the steps must be a multiple of " + std::to_string(per) +
        ", got " + std::to_string(steps) + "; use " +
        (below > 0 ? std::to_string(below) + " or " : std::string()) +
        std::to_string(above));
}

// MarchOptions::given_windows: none under error control (it chooses its
// own windows); each of at least the operator's minimum of points (an
// element: its own), ending after the one before, finite, the last at
// t_end; start_node at a window's first node. Otherwise
// std::invalid_argument naming the fix.
inline void CheckGivenWindows(const Grid& grid, const MarchOptions& options,
                              int min_points, int element_points) {
  const std::vector<GivenWindow>& w = options.given_windows;
  if (w.empty()) return;
  if (options.tolerance.enabled())
    throw std::invalid_argument(
        "given_windows are the windows of a march without error control; "
        "under a tolerance the march chooses its own: clear one of them");
  const long long need = element_points > 0 ? element_points : min_points;
  double last = grid.t_start;
  long long first = 0;
  bool start_found = options.start_node == 0;
  for (std::size_t k = 0; k < w.size(); ++k) {
    const std::string at = "given_windows[" + std::to_string(k) + "]";
    const std::string end =
        at + " ends at " + std::to_string(w[k].t_end) + ", which";
    const bool is_last = k + 1 == w.size();
    if (!std::isfinite(w[k].t_end))
      throw std::invalid_argument(end + " is not finite; give finite times");
    if (!(w[k].t_end > last))
      throw std::invalid_argument(
          end + " is not after " +
          (k == 0 ? "t_start = " : "the window before's end, ") +
          std::to_string(last) + "; give strictly increasing ends");
    if (is_last ? w[k].t_end != grid.t_end : !(w[k].t_end < grid.t_end))
      throw std::invalid_argument(
          end + (is_last ? " is not t_end = " : " is not before t_end = ") +
          std::to_string(grid.t_end) +
          (is_last ? "; the last window ends at t_end"
                   : "; only the last window ends "
                     "at t_end"));
    if (element_points > 0 ? w[k].points != need : w[k].points < need)
      throw std::invalid_argument(
          at + " has " + std::to_string(w[k].points) + " points, " +
          (element_points > 0 ? "not " : "below ") + std::to_string(need) +
          (element_points > 0 ? ", the element's size"
                              : ", the minimum of " + grid.op) +
          "; give windows of " + (element_points > 0 ? "" : "at least ") +
          std::to_string(need) + " points");
    last = w[k].t_end;
    first += w[k].points - 1;
    start_found = start_found || (!is_last && first == options.start_node);
  }
  if (!start_found)
    throw std::invalid_argument(
        "start_node " + std::to_string(options.start_node) +
        " is not the first node of a given window; resume at a window's "
        "first node");
}

}  // namespace detail

template <action::LagrangianProblem P>
MarchResult MarchIvp(const P& problem, const InitialData& initial,
                     const Grid& grid, const MarchOptions& given = {},
                     const NodeObserver& observer = {}) {
  constexpr int d = P::kDim;
  const auto start = std::chrono::steady_clock::now();
  const bool adaptive = given.tolerance.enabled();
  // window_points = 0: the solver's default for a uniform grid or error
  // control (solver_choice.h).
  MarchOptions options = given;
  if (options.window_points == 0)
    options.window_points =
        DefaultWindowPoints(options.solve.path, grid.op, adaptive);
  const Tolerance& tol = options.tolerance;
  if (adaptive &&
      !(std::isfinite(tol.absolute) && std::isfinite(tol.relative) &&
        tol.absolute >= 0 && tol.relative >= 0))
    throw std::invalid_argument(
        "tolerance must be finite and non-negative (absolute, relative), got "
        "(" +
        std::to_string(tol.absolute) + ", " + std::to_string(tol.relative) +
        ")");
  // Validates the grid (operator, points, interval) once; under error
  // control or on given windows the operator's minimum stands in for the
  // points.
  const sbp::Coefficients& table = sbp::Table(grid.op);
  const int min_points = table.min_points;
  const bool given_windows = !options.given_windows.empty();
  if (table.max_points > 0)
    detail::CheckElementMarch(grid, table.max_points, adaptive,
                              options.window_points, given_windows);
  sbp::CheckOperatorArguments<double>(
      grid.op,
      adaptive || given_windows || table.max_points > 0 ? min_points
                                                        : grid.points,
      grid.t_start, grid.t_end);
  detail::CheckGivenWindows(grid, options, min_points, table.max_points);
  if (options.window_points < min_points)
    throw std::invalid_argument(
        "window of " + std::to_string(options.window_points) +
        " points is below the minimum of " + grid.op + " (" +
        std::to_string(min_points) + "); use window_points >= " +
        std::to_string(min_points) + ", or one global solve");
  MarchResult out;
  InitialData state = initial;
  const int order = detail::CheckInitialData(problem, state);
  if (order == 1) state.v.clear();
  detail::PointWindow<P> window(problem, grid.op, grid.sigma0, options, order);
  detail::UniformMarch<detail::PointWindow<P>> uniform(
      window, grid, options, observer, out, min_points);
  detail::AdaptiveMarch<detail::PointWindow<P>> controlled(
      window, grid, options, observer, out, min_points);
  const bool ok = adaptive ? controlled.Run(state) : uniform.Run(state);
  const std::vector<double>& xs = adaptive ? controlled.xs_ : uniform.xs_;
  const std::vector<double>& vs = adaptive ? controlled.vs_ : uniform.vs_;
  if (ok) {
    std::string how;
    if (adaptive) how = " under error control";
    if (out.refinement > 1)
      how = " on a grid refined x" + std::to_string(out.refinement) +
            " (the requested step exceeds the stability limit of " + grid.op +
            ")";
    out.status = {true, "all windows converged" + how};
  }
  out.end_position = state.x;
  out.end_velocity = state.v;
  if (options.keep_trajectory) {
    const Eigen::Index n = static_cast<Eigen::Index>(out.t.size());
    out.x.resize(n, d);
    out.v.resize(n, d);
    for (Eigen::Index i = 0; i < n; ++i)
      for (int c = 0; c < d; ++c) {
        out.x(i, c) = xs[i * d + c];
        out.v(i, c) = vs[i * d + c];
      }
  }
  out.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  if (options.phase_timings) out.phases.total = out.seconds;
  out.status.iterations = out.iterations;
  out.status.seconds = out.seconds;
  if (out.status.converged)
    out.status.last_residual = NAN;  // not evaluated
  else
    out.status.last_residual = out.last_residual;
  return out;
}

}  // namespace vivp::variational
