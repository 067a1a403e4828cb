// Time-slab marching: [t_start, t_end] solved window by window (formulation
// §1.8). The method is causal, so each window is an IVP of its own whose
// initial data are handed over from the previous one:
//
//   HandOff::kCorrected (default)  (x_N + M⁻¹λ4, M⁻¹(−λ3)) — the
//       multiplier-corrected end state; marching then keeps the global order
//       for every window size (first-order systems: x_N + C⁻¹λ3);
//   HandOff::kNaive  (x_N, (Dx)_N) — kept to show why it is not the default:
//       the one-window map grows by ≈1.5 % per window at Δt = 0.1 and the
//       march does not converge.
//
// Windows share their end points: a global grid of Nt points with windows of W
// points has (Nt − 1)/(W − 1) windows (the last one takes the remainder, at
// least the operator's minimum). A window whose Newton solve fails is split in
// two halves (recursively, down to the operator's minimum), and every such
// fallback is counted.
//
// Output: an observer sees every node once, in order, so memory stays
// O(window) when the caller streams; the stitched trajectory is kept only if
// asked for.
#pragma once

#include <functional>
#include <vector>

#include "solvers/variational/march_types.h"
#include "solvers/variational/solve_ivp.h"

namespace vivp {


namespace detail {

template <class P>
struct Marcher {
  static constexpr int d = P::kDim;
  const P& problem;
  const MarchOptions& options;
  const Grid& global;
  const NodeObserver& observer;
  MarchResult& out;
  int min_points;

  // Solves one window from `initial`, splitting on failure. Emits its nodes
  // except the last (the next window starts there) and returns the hand-off.
  bool Window(InitialData& initial, double t0, double t1, long long points,
              int depth, bool last_of_march) {
    Grid g = global;
    g.t_start = t0;
    g.t_end = t1;
    g.points = points;
    const IvpSolution<double> s = SolveIvp(problem, initial, g, options.solve);
    if (!s.status.converged) {
      const long long half = (points + 1) / 2;
      if (depth >= options.max_split_depth || half < min_points) {
        out.status = {false, "window [" + std::to_string(t0) + ", " +
                                 std::to_string(t1) + "] did not converge: " +
                                 s.status.reason};
        return false;
      }
      ++out.fallbacks;
      const double tm = t0 + (t1 - t0) * double(half - 1) / double(points - 1);
      return Window(initial, t0, tm, half, depth + 1, false) &&
             Window(initial, tm, t1, points - half + 1, depth + 1,
                    last_of_march);
    }
    WindowReport w;
    w.t_start = t0;
    w.t_end = t1;
    w.points = points;
    w.iterations = s.iterations;
    w.converged = true;
    w.fallbacks = depth;
    w.position_error_estimate = s.corrected.position_error_estimate;
    w.velocity_error_estimate = s.corrected.velocity_error_estimate;
    out.windows.push_back(w);
    out.iterations += s.iterations;
    out.error_estimate += w.position_error_estimate;
    const int emit = last_of_march ? s.points() : s.points() - 1;
    for (int i = 0; i < emit; ++i) Emit(s, i);
    // Hand-off.
    const int n = s.points() - 1;
    for (int c = 0; c < d; ++c) {
      if (options.hand_off == HandOff::kCorrected) {
        initial.x[c] = s.corrected.position[c];
        if (s.order == 2) initial.v[c] = s.corrected.velocity[c];
      } else {
        initial.x[c] = s.x1(n, c);
        if (s.order == 2) initial.v[c] = s.velocity(n, c);
      }
    }
    return true;
  }

  void Emit(const IvpSolution<double>& s, int i) {
    double x[d], v[d];
    for (int c = 0; c < d; ++c) {
      x[c] = s.x1(i, c);
      v[c] = s.velocity(i, c);
    }
    if (observer) observer(s.t[i], x, v);
    if (options.keep_trajectory) {
      out.t.push_back(s.t[i]);
      for (int c = 0; c < d; ++c) {
        xs.push_back(x[c]);
        vs.push_back(v[c]);
      }
    }
  }

  std::vector<double> xs, vs;
};

}  // namespace detail

template <action::LagrangianProblem P>
MarchResult MarchIvp(const P& problem, const InitialData& initial,
                     const Grid& grid, const MarchOptions& options = {},
                     const NodeObserver& observer = {}) {
  constexpr int d = P::kDim;
  const auto start = std::chrono::steady_clock::now();
  // Validates the global grid (operator, points, interval) once.
  const auto global = sbp::MakeOperator<double>(grid.op, grid.points,
                                                grid.t_start, grid.t_end);
  const int min_points = global.min_points();
  if (options.window_points < min_points)
    throw std::invalid_argument(
        "window of " + std::to_string(options.window_points) + " points is "
        "below the minimum of " + grid.op + " (" + std::to_string(min_points) +
        "); use --slab-points >= " + std::to_string(min_points) +
        " or 0 for one global solve");
  MarchResult out;
  detail::Marcher<P> m{problem, options, grid, observer, out, min_points, {}, {}};
  InitialData state = initial;
  const long long intervals = grid.points - 1;
  const long long per_window = options.window_points - 1;
  long long done = 0;
  bool ok = true;
  while (ok && done < intervals) {
    long long take = std::min(per_window, intervals - done);
    // Never leave a remainder shorter than the operator allows: absorb it.
    if (intervals - done - take > 0 && intervals - done - take < min_points - 1)
      take = intervals - done;
    const double t0 = global.t(int(done)), t1 = global.t(int(done + take));
    ok = m.Window(state, t0, t1, take + 1, 0, done + take == intervals);
    done += take;
  }
  if (ok) out.status = {true, "all windows converged"};
  out.end_position = state.x;
  out.end_velocity = state.v;
  if (options.keep_trajectory) {
    const Eigen::Index n = static_cast<Eigen::Index>(out.t.size());
    out.x.resize(n, d);
    out.v.resize(n, d);
    for (Eigen::Index i = 0; i < n; ++i)
      for (int c = 0; c < d; ++c) {
        out.x(i, c) = m.xs[i * d + c];
        out.v(i, c) = m.vs[i * d + c];
      }
  }
  out.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  return out;
}

}  // namespace vivp
