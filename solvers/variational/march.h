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

#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "solvers/variational/march_types.h"
#include "solvers/variational/solve_ivp.h"

namespace vivp {

namespace detail {

// Solves windows of one length. The operators, the reduced system with its
// scratch space, and the Jacobian factorization are built once and reused:
// the Lagrangian does not depend on t, so every window of the same length has
// the same discrete equations up to the initial data. A linear problem is
// thus factored once and each window costs back-substitutions and residuals
// (the chord steps of solvers::Newton with a FactorCache); a nonlinear one
// starts each window from the previous window's factorization and refactors
// only when the chord steps stop contracting.
template <class P>
class WindowEngine {
 public:
  static constexpr int d = P::kDim;
  using State = std::array<double, d>;

  // A window of `points` nodes of the global grid, solved on a grid refined
  // `refine` times (refine − 1 extra nodes per global step).
  WindowEngine(const P& problem, const Grid& global, long long points,
               int order, int refine)
      : problem_(problem),
        grid_(WindowGrid(global, points, refine)),
        dbar_(
            sbp::MakeOperator<double>(grid_.op, grid_.points, 0.0, grid_.t_end),
            grid_.sigma0),
        system_(problem, dbar_, State{}, State{}, order),
        y_(system_.size(), 0.0) {}

  const sbp::Operator<double>& D() const { return dbar_.base(); }
  int order() const { return system_.order(); }
  // The last solved window: position and velocity D x of DOF c at node i.
  double x(int i, int c) const { return xc_[c][i]; }
  double v(int i, int c) const { return v_[c][i]; }
  double end_velocity(int c) const { return end_v_[c]; }

  struct Outcome {
    solvers::NewtonReport report;
    CorrectedEnd<double> end;
    std::string failure;      // empty on success
    bool split_helps = true;  // false: a shorter window has the same Δt
  };

  // Solves the window that starts at `initial`. On success the nodes are in
  // x(i, c), the velocities D x in v(i, c) if `velocities` is set.
  Outcome Solve(const InitialData& initial,
                const solvers::NewtonOptions& newton, bool velocities) {
    Outcome o;
    State x0{}, v0{};
    for (int c = 0; c < d; ++c) {
      x0[c] = initial.x[c];
      v0[c] = initial.v.empty() ? 0.0 : initial.v[c];
    }
    system_.SetInitial(x0, v0);
    // Guess: a Taylor polynomial with the previous window's mean second
    // derivative (order 2) or slope (order 1); the multipliers stay at the
    // previous window's values, which change slowly from window to window.
    const auto& D = dbar_.base();
    const int n = D.points();
    for (int i = 0; i < n; ++i) {
      const double tau = D.t(i);
      for (int c = 0; c < d; ++c)
        y_[system_.X(i, c)] =
            order() == 2 ? x0[c] + tau * (v0[c] + 0.5 * tau * trend_[c])
                         : x0[c] + tau * trend_[c];
    }
    o.report = solvers::Newton<double>(system_, y_, newton, {}, &cache_);
    if (!o.report.converged) {
      cache_.valid = false;
      o.failure = o.report.reason;
      return o;
    }
    for (int c = 0; c < d; ++c) {
      xc_[c].resize(n);
      for (int i = 0; i < n; ++i) xc_[c][i] = y_[system_.X(i, c)];
    }
    double xe[2][d], ve[2][d];
    for (int k = 0; k < 2; ++k) {
      const int i = k == 0 ? 0 : n - 1;
      for (int c = 0; c < d; ++c) {
        xe[k][c] = xc_[c][i];
        ve[k][c] = D.ApplyRow(i, xc_[c].data());
      }
    }
    double omega_end = 0.0;
    if (order() == 2) {
      // ω at the window's start: when the window starts from this engine's
      // last hand-off, it is the last window's ω at its end (the same time,
      // and the same state up to the multiplier correction, which is the
      // size of the error estimate). Only the first window, and a window
      // after a fallback, evaluates it: one pointwise Hessian per window
      // instead of two.
      const bool continues =
          omega_end_ >= 0.0 && x0 == handed_x_ && v0 == handed_v_;
      const double omega_start =
          continues ? omega_end_ : FastestFrequency(problem_, xe[0], ve[0]);
      omega_end = FastestFrequency(problem_, xe[1], ve[1]);
      std::string why = UnderResolution(grid_, omega_start, omega_end);
      if (!why.empty()) {
        omega_end_ = -1.0;
        o.failure = std::move(why);
        o.split_helps = false;
        return o;
      }
    }
    for (int c = 0; c < d; ++c) end_v_[c] = ve[1][c];
    double l3[d], l4[d];
    for (int c = 0; c < d; ++c) {
      l3[c] = y_[system_.Lambda3(c)];
      l4[c] = order() == 2 ? y_[system_.Lambda4(c)] : 0.0;
    }
    o.end = CorrectEnd<double>(problem_, order(), xe[1], ve[1], l3,
                               order() == 2 ? l4 : nullptr);
    omega_end_ = omega_end;
    for (int c = 0; c < d; ++c) {
      handed_x_[c] = o.end.position[c];
      handed_v_[c] = order() == 2 ? o.end.velocity[c] : 0.0;
    }
    const double length = grid_.t_end;
    for (int c = 0; c < d; ++c)
      trend_[c] = order() == 2 ? (o.end.velocity[c] - v0[c]) / length
                               : (o.end.position[c] - x0[c]) / length;
    if (velocities) {
      for (int c = 0; c < d; ++c) {
        v_[c].resize(n);
        D.Apply(std::span<const double>(xc_[c]), std::span<double>(v_[c]));
      }
    }
    return o;
  }

  long long factorizations() const { return cache_.factorizations; }

 private:
  static Grid WindowGrid(const Grid& global, long long points, int refine) {
    Grid g = global;
    const double dt =
        (global.t_end - global.t_start) / double(global.points - 1);
    g.t_start = 0.0;
    g.t_end = dt * double(points - 1);
    g.points = (points - 1) * refine + 1;
    return g;
  }

  const P& problem_;
  Grid grid_;
  sbp::RegularizedOperator<double> dbar_;
  action::ReducedSystem<P, double> system_;
  std::vector<double> y_;
  solvers::FactorCache<double> cache_;
  State trend_{};
  // The last window's corrected end state (the next window's initial data
  // unless a fallback intervened) and ω there; ω < 0: none yet.
  State handed_x_{}, handed_v_{};
  double omega_end_ = -1.0;
  std::vector<double> xc_[d], v_[d];
  double end_v_[d] = {};
};

template <class P>
struct Marcher {
  static constexpr int d = P::kDim;
  const P& problem;
  const MarchOptions& options;
  const Grid& global;
  const NodeObserver& observer;
  MarchResult& out;
  int min_points;
  int order;
  long long emitted = 0;  // global index of the next node to emit
  std::vector<double> xs, vs;
  int refine = 1;  // solve grid = global grid refined this many times
  std::map<std::pair<long long, int>, std::unique_ptr<WindowEngine<P>>> engines;

  bool EngineApplies() const {
    return options.solve.path == Path::kReducedNewton &&
           !options.solve.extended_residual;
  }

  WindowEngine<P>& Engine(long long points) {
    auto& e = engines[{points, refine}];
    if (!e)
      e = std::make_unique<WindowEngine<P>>(problem, global, points, order,
                                            refine);
    return *e;
  }

  // Δt·ω of the global grid at a state, against the operator's limit.
  double StepRatio(const InitialData& state) const {
    if (order != 2) return 0.0;
    const double dt =
        (global.t_end - global.t_start) / double(global.points - 1);
    return dt * FastestFrequency(problem, state.x.data(), state.v.data()) /
           StabilityLimit(global.op);
  }

  // With options.stabilize: refines the solve grid so that Δt·ω/refine is
  // half the stability limit at `state` (measured, stiff spring Δt·ω = 10,
  // SBP42, 159 periods: at 0.9 of the limit the marched path still grew to
  // max|x| = 1.42, at 0.5 it stays at 1.03), and at least doubles it when
  // `at_least_double` (a window came out under-resolved somewhere inside).
  // False when refinement is off or would exceed options.max_refinement.
  bool Refine(const InitialData& state, bool at_least_double) {
    if (!options.stabilize) return false;
    int needed = static_cast<int>(std::ceil(StepRatio(state) / 0.5));
    if (at_least_double) needed = std::max(needed, 2 * refine);
    if (needed <= refine || needed > options.max_refinement) return false;
    refine = needed;
    out.refinement = std::max(out.refinement, refine);
    return true;
  }

  // Solves one window from `initial`, falling back to a fresh solve and then
  // to halving on failure. Emits its nodes except the last (the next window
  // starts there) and updates `initial` to the hand-off state.
  bool Window(InitialData& initial, double t0, double t1, long long points,
              int depth, bool last_of_march) {
    const bool want_nodes = bool(observer) || options.keep_trajectory;
    if (depth == 0 && EngineApplies()) {
      WindowEngine<P>& e = Engine(points);
      solvers::NewtonOptions newton = options.solve.newton;
      newton.phase_timings = false;
      newton.final_residual = false;
      auto o = e.Solve(initial, newton, want_nodes);
      if (o.failure.empty()) {
        Record(t0, t1, points, o.report, depth, o.end);
        const int r = refine;
        EmitNodes(
            last_of_march ? int(points) : int(points) - 1,
            [&](int i, int c) { return e.x(i * r, c); },
            [&](int i, int c) { return e.v(i * r, c); });
        HandOff(initial, o.end, &e, nullptr);
        return true;
      }
      if (!o.split_helps) {
        // Under-resolved: a shorter window has the same Δt, a finer grid
        // does not. Refine (counted as a fallback) or report.
        if (Refine(initial, true)) {
          ++out.fallbacks;
          return Window(initial, t0, t1, points, depth, last_of_march);
        }
        Fail(t0, t1, o.failure, o.report.residual_norm);
        return false;
      }
      ++out.fallbacks;  // retried below from the default guess, then halved
    }
    Grid g = global;
    g.t_start = t0;
    g.t_end = t1;
    g.points = (points - 1) * refine + 1;
    const IvpSolution<double> s = SolveIvp(problem, initial, g, options.solve);
    if (!s.status.converged) {
      const long long half = (points + 1) / 2;
      if (depth >= options.max_split_depth || half < min_points) {
        Fail(t0, t1, s.status.reason, s.residual_norm);
        return false;
      }
      ++out.fallbacks;
      const double tm = t0 + (t1 - t0) * double(half - 1) / double(points - 1);
      return Window(initial, t0, tm, half, depth + 1, false) &&
             Window(initial, tm, t1, points - half + 1, depth + 1,
                    last_of_march);
    }
    solvers::NewtonReport report;
    report.iterations = s.iterations;
    Record(t0, t1, points, report, depth, s.corrected);
    const int r = refine;
    EmitNodes(
        last_of_march ? int(points) : int(points) - 1,
        [&](int i, int c) { return s.x1(i * r, c); },
        [&](int i, int c) { return s.velocity(i * r, c); });
    HandOff(initial, s.corrected, nullptr, &s);
    return true;
  }

  // A failed window: the march reports where, why, and the residual left.
  void Fail(double t0, double t1, const std::string& why, double residual) {
    out.last_residual = residual;
    std::ostringstream s;
    s << "window [" << t0 << ", " << t1 << "] did not converge: " << why
      << "; last residual ‖F‖∞ = " << residual;
    out.status = {false, s.str()};
  }

  void Record(double t0, double t1, long long points,
              const solvers::NewtonReport& r, int depth,
              const CorrectedEnd<double>& end) {
    WindowReport w;
    w.t_start = t0;
    w.t_end = t1;
    w.points = points;
    w.iterations = r.iterations;
    w.corrections = r.corrections;
    w.converged = true;
    w.fallbacks = depth;
    w.position_error_estimate = end.position_error_estimate;
    w.velocity_error_estimate = end.velocity_error_estimate;
    // Per-window reports grow with Nt/W: kept with the trajectory only, so a
    // streamed march stays O(window) in memory.
    if (options.keep_trajectory) out.windows.push_back(w);
    ++out.window_count;
    out.iterations += r.iterations;
    out.corrections += r.corrections;
    out.error_estimate += w.position_error_estimate;
  }

  // The next window's initial data: the corrected end state (default) or the
  // naive (x_N, (Dx)_N) from the engine or the fresh solve.
  void HandOff(InitialData& initial, const CorrectedEnd<double>& end,
               const WindowEngine<P>* e, const IvpSolution<double>* s) const {
    for (int c = 0; c < d; ++c) {
      if (options.hand_off == HandOff::kCorrected) {
        initial.x[c] = end.position[c];
        if (order == 2) initial.v[c] = end.velocity[c];
      } else if (e) {
        const int n = e->D().points() - 1;
        initial.x[c] = e->x(n, c);
        if (order == 2) initial.v[c] = e->end_velocity(c);
      } else {
        const int n = s->points() - 1;
        initial.x[c] = s->x1(n, c);
        if (order == 2) initial.v[c] = s->velocity(n, c);
      }
    }
  }

  // Emits the first `count` nodes of a solved window (position and velocity
  // of DOF c at node i through the accessors), unless nobody wants them.
  template <class X, class V>
  void EmitNodes(int count, const X& x_of, const V& v_of) {
    if (!observer && !options.keep_trajectory) return;
    double x[d], v[d];
    for (int i = 0; i < count; ++i) {
      for (int c = 0; c < d; ++c) {
        x[c] = x_of(i, c);
        v[c] = v_of(i, c);
      }
      Emit(x, v);
    }
  }

  void Emit(const double* x, const double* v) {
    const double dt =
        (global.t_end - global.t_start) / double(global.points - 1);
    const double t = global.t_start + dt * double(emitted++);
    if (observer) observer(t, x, v);
    if (options.keep_trajectory) {
      out.t.push_back(t);
      for (int c = 0; c < d; ++c) {
        xs.push_back(x[c]);
        vs.push_back(v[c]);
      }
    }
  }
};

}  // namespace detail

template <action::LagrangianProblem P>
MarchResult MarchIvp(const P& problem, const InitialData& initial,
                     const Grid& grid, const MarchOptions& options = {},
                     const NodeObserver& observer = {}) {
  constexpr int d = P::kDim;
  const auto start = std::chrono::steady_clock::now();
  // Validates the global grid (operator, points, interval) once.
  const auto global =
      sbp::MakeOperator<double>(grid.op, grid.points, grid.t_start, grid.t_end);
  const int min_points = global.min_points();
  if (options.window_points < min_points)
    throw std::invalid_argument(
        "window of " + std::to_string(options.window_points) +
        " points is "
        "below the minimum of " +
        grid.op + " (" + std::to_string(min_points) +
        "); use --slab-points >= " + std::to_string(min_points) +
        " or 0 for one global solve");
  MarchResult out;
  InitialData state = initial;
  const int order = detail::CheckInitialData(problem, state);
  detail::Marcher<P> m{problem, options, grid, observer, out, min_points,
                       order,   0,       {},   {},       1,   {}};
  m.Refine(state, false);  // planned from the initial state, not a fallback
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
  if (ok)
    out.status = {true, out.refinement == 1
                            ? "all windows converged"
                            : "all windows converged on a grid refined x" +
                                  std::to_string(out.refinement) +
                                  " (the requested step exceeds the stability "
                                  "limit of " +
                                  grid.op + ")"};
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
