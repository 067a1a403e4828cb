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
//       exceeds the stability limit is solved on a refined grid;
//   error control (tolerance enabled): every window has W points and a Δt
//       chosen by a step-size controller (step_control.h) from the window's
//       embedded error estimates; a window whose estimates exceed the
//       tolerance, or that fails, is rejected and solved again with a
//       smaller Δt. SBP21, whose position estimate is unreliable, estimates
//       by step doubling (the window again at Δt/2; the finer one is kept).
// Every fallback, rejection and check failure is counted and reported.
//
// Output: an observer sees every node once, in order, with its time, so
// memory stays O(window) when the caller streams; the stitched trajectory is
// kept only if asked for.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "solvers/variational/march_types.h"
#include "solvers/variational/solve_ivp.h"
#include "solvers/variational/window_solve.h"

namespace vivp {

namespace detail {

template <class P>
class Marcher {
 public:
  static constexpr int d = P::kDim;
  using Attempt = WindowAttempt<d>;

  Marcher(const P& problem, const Grid& grid, const MarchOptions& options,
          const NodeObserver& observer, MarchResult& out, int order,
          int min_points)
      : problem_(problem),
        grid_(grid),
        options_(options),
        observer_(observer),
        out_(out),
        order_(order),
        min_points_(min_points),
        solver_(problem, grid.op, grid.sigma0, options, order) {}

  // The uniform grid of grid.points nodes.
  bool Uniform(InitialData& state) {
    Refine(state, false);  // planned from the initial state, not a fallback
    const long long intervals = grid_.points - 1;
    const long long per_window = options_.window_points - 1;
    long long done = 0;
    while (done < intervals) {
      long long take = std::min(per_window, intervals - done);
      // Never leave a remainder shorter than the operator allows: absorb it.
      if (intervals - done - take > 0 &&
          intervals - done - take < min_points_ - 1)
        take = intervals - done;
      if (!Window(state, done, take + 1, 0, done + take == intervals))
        return false;
      done += take;
    }
    return true;
  }

  // Error control: Δt per window from the embedded estimates.
  bool Adaptive(InitialData& state) {
    const double span = grid_.t_end - grid_.t_start;
    const int w = int(options_.window_points);
    const bool doubling = grid_.op == "sbp21";
    StepController control(EstimateOrder(grid_.op));
    double t = grid_.t_start;
    double dt = InitialStep(state);
    int rejected_in_row = 0;
    // Since the last accepted window: the largest step rejected on
    // truncation, and whether a step below it was tried after round-off.
    double truncation_rejected_at = 0;
    bool tried_between = false;
    while (t < grid_.t_end) {
      if (order_ == 2) {
        // Keep Δt·ω at half the stability limit (resolution.h) at the
        // window's start.
        const double omega =
            FastestFrequency(problem_, state.x.data(), state.v.data());
        if (omega > 0)
          dt = std::min(dt, 0.5 * StabilityLimit(grid_.op) / omega);
      }
      const double remaining = grid_.t_end - t;
      int n = w;
      double dtw = dt;
      bool last = false;
      if (remaining <= double(w - 1) * dt * (1 + 1e-12)) {
        n = int(std::ceil(remaining / dt - 1e-9)) + 1;
        n = std::clamp(n, min_points_, w);
        dtw = remaining / double(n - 1);
        last = true;
      } else if (remaining < 2.0 * double(w - 1) * dt) {
        dtw = remaining / (2.0 * double(w - 1));  // two equal windows left
      }
      const bool underflow = !(dtw > 1e-13 * std::max(std::abs(t), span));
      if (underflow || rejected_in_row > 40) {
        Unreachable(t, (underflow ? "the step fell to " + Text(dtw) +
                                        ", below the round-off limit 1e-13 of "
                                        "the time span"
                                  : std::to_string(rejected_in_row) +
                                        " windows in a row rejected (step " +
                                        Text(dtw) + ")") +
                           (last_why_.empty() ? "" : "; last: " + last_why_));
        return false;
      }
      if (out_.points + n > options_.max_points) {
        Unreachable(t, "it needs more than max_points = " +
                           std::to_string(options_.max_points) +
                           " nodes (step " + Text(dtw) + ")");
        return false;
      }
      Attempt a = Solve(state, n, dtw, false);
      if (a.ok() && doubling) a = Doubled(state, a);
      const double err = a.ok() ? ErrorNorm(state, a) : NAN;
      if (!a.ok() || !(err <= 1)) {
        ++out_.rejected;
        ++rejected_in_row;
        last_why_ = a.ok()
                        ? "error estimate " + Text(err) + " times the tolerance"
                        : a.why;
        last_residual_ = a.residual;
        // Truncation errors fall with the step; the round-off of (Dx)_N
        // grows like ε|x|/Δt. A window rejected on a velocity estimate at
        // its round-off level needs a larger step, not a smaller one. When a
        // larger step was rejected on truncation since the last accepted
        // window, one step between the two is tried; if that fails too, no
        // step meets the tolerance in double precision here (measured:
        // SBP84 on Kepler e = 0.9 below 1e-9).
        const std::string roundoff = a.ok() ? RoundOffBound(state, a) : "";
        if (!roundoff.empty()) {
          if (truncation_rejected_at > dtw && tried_between) {
            Unreachable(t, roundoff);
            return false;
          }
          tried_between = truncation_rejected_at > dtw;
          dt =
              tried_between ? std::sqrt(dtw * truncation_rejected_at) : 4 * dtw;
          continue;
        }
        if (a.ok())
          truncation_rejected_at = std::max(truncation_rejected_at, dtw);
        dt = a.ok() ? control.Reject(dtw, err) : 0.25 * dtw;
        continue;
      }
      rejected_in_row = 0;
      truncation_rejected_at = 0;
      tried_between = false;
      Accept(a, state, -1, t, last ? a.points : a.points - 1, 0, err);
      t = last ? grid_.t_end : t + a.dt * double(a.points - 1);
      dt = control.Accept(dtw, err);
    }
    return true;
  }

  long long factorizations() const { return solver_.factorizations(); }

 private:
  bool WantNodes() const { return bool(observer_) || options_.keep_trajectory; }

  // The predictor's tolerance: a hundredth of the march's, so that its error
  // is small against the window's (the consistency check compares them);
  // on a uniform grid 1e-4, enough to tell a branch of the discrete
  // equations from another (they differ by the size of the solution), to
  // check a window's resolution to 1 %, and to start Newton within a few
  // chord steps of its solution. (Measured, SBP42, 2^18 points: at 1e-6 the
  // predictor took 3.2 steps per window of the damped oscillator and cost
  // 6 % of the throughput; the anharmonic marches did not change.)
  Tolerance PredictorTolerance() const {
    const Tolerance& t = options_.tolerance;
    if (!t.enabled()) return {1e-4, 1e-4};
    return {t.absolute > 0 ? std::max(0.01 * t.absolute, 1e-15) : 0.0,
            t.relative > 0 ? std::max(0.01 * t.relative, 1e-14) : 0.0};
  }

  Attempt Solve(const InitialData& state, int points, double dt, bool fresh) {
    Attempt a = solver_.Solve(state, points, dt, fresh, WantNodes(),
                              PredictorTolerance(), !AdaptiveMode());
    out_.predictor_steps += a.predictor_steps;
    if (a.failure == WindowFailure::kCheck) ++out_.check_failures;
    if (!fresh && a.failure == WindowFailure::kNewton) {
      // Chord steps on an earlier window's factorization did not converge:
      // once more with a Jacobian of this window's own.
      ++out_.fallbacks;
      return Solve(state, points, dt, true);
    }
    return a;
  }

  bool AdaptiveMode() const { return options_.tolerance.enabled(); }

  // SBP21: the window again at Δt/2; the difference of the two end states
  // estimates the error of the coarse one, and the fine one is kept.
  Attempt Doubled(const InitialData& state, const Attempt& coarse) {
    Attempt fine = Solve(state, 2 * coarse.points - 1, 0.5 * coarse.dt, false);
    if (!fine.ok()) return fine;
    for (int c = 0; c < d; ++c) {
      fine.est_x[c] = std::abs(coarse.x_end[c] - fine.x_end[c]);
      fine.est_v[c] = std::abs(coarse.v_end[c] - fine.v_end[c]);
    }
    return fine;
  }

  // max over components of estimate / (absolute + relative·|value|), the
  // value being the larger of the window's start and end.
  double ErrorNorm(const InitialData& state, const Attempt& a) const {
    const Tolerance& tol = options_.tolerance;
    double err = 0;
    for (int c = 0; c < d; ++c) {
      err = std::max(err, a.est_x[c] / tol.Allowance(std::max(
                                           std::abs(state.x[c]),
                                           std::abs(a.end.position[c]))));
      if (order_ == 2)
        err = std::max(err, a.est_v[c] / tol.Allowance(std::max(
                                             std::abs(state.v[c]),
                                             std::abs(a.end.velocity[c]))));
    }
    return err;
  }

  // Why a rejected window's error is round-off: its largest term is a
  // velocity estimate within twice the round-off level of (Dx)_N; "" if not.
  std::string RoundOffBound(const InitialData& state, const Attempt& a) const {
    if (order_ != 2) return "";
    const Tolerance& tol = options_.tolerance;
    double worst = 0, est = 0, level = 0, allowance = 0;
    bool velocity = false;
    for (int c = 0; c < d; ++c) {
      const double ax = tol.Allowance(
          std::max(std::abs(state.x[c]), std::abs(a.end.position[c])));
      const double av = tol.Allowance(
          std::max(std::abs(state.v[c]), std::abs(a.end.velocity[c])));
      if (a.est_x[c] / ax > worst) {
        worst = a.est_x[c] / ax;
        velocity = false;
      }
      if (a.est_v[c] / av > worst) {
        worst = a.est_v[c] / av;
        velocity = true;
        est = a.est_v[c];
        level = a.roundoff_v[c];
        allowance = av;
      }
    }
    if (!velocity || !(est <= 2 * level)) return "";
    return "it is below the round-off of the window's velocity estimate (at "
           "step " +
           Text(a.dt) + " the estimate " + Text(est) +
           " is within twice the round-off level eps*sum|D_N|*max|x| = " +
           Text(level) + " of (Dx)_N; the allowance is " + Text(allowance) +
           "); use a larger tolerance";
  }

  double InitialStep(const InitialData& state) const {
    const double span = grid_.t_end - grid_.t_start;
    const double longest = span / double(options_.window_points - 1);
    if (options_.initial_step > 0)
      return std::min(options_.initial_step, longest);
    if (order_ != 2) return longest / 8;
    const double omega =
        FastestFrequency(problem_, state.x.data(), state.v.data());
    if (!(omega > 0)) return longest / 8;
    // The estimates scale like (Δt·ω)^q: start near where they meet the
    // tolerance; the controller corrects the rest.
    const Tolerance& t = options_.tolerance;
    const double level = std::max(t.relative, 1e-14);
    return std::min(longest,
                    std::pow(level, 1.0 / EstimateOrder(grid_.op)) / omega);
  }

  // Uniform grid: Δt·ω of the requested grid at a state, against the limit.
  double StepRatio(const InitialData& state) const {
    if (order_ != 2) return 0.0;
    const double dt = (grid_.t_end - grid_.t_start) / double(grid_.points - 1);
    return dt * FastestFrequency(problem_, state.x.data(), state.v.data()) /
           StabilityLimit(grid_.op);
  }

  // With options.stabilize: refines the solve grid so that Δt·ω/refine is
  // half the stability limit at `state` (measured, stiff spring Δt·ω = 10,
  // SBP42, 159 periods: at 0.9 of the limit the marched path still grew to
  // max|x| = 1.42, at 0.5 it stays at 1.03), and at least doubles it when
  // `at_least_double` (a window came out under-resolved somewhere inside).
  // False when refinement is off or would exceed options.max_refinement.
  bool Refine(const InitialData& state, bool at_least_double) {
    if (!options_.stabilize) return false;
    int needed = static_cast<int>(std::ceil(StepRatio(state) / 0.5));
    if (at_least_double)
      needed = std::max(needed, std::min(2 * refine_, options_.max_refinement));
    if (needed <= refine_ || needed > options_.max_refinement) return false;
    refine_ = needed;
    out_.refinement = std::max(out_.refinement, refine_);
    return true;
  }

  // Uniform grid: the window of `points` nodes from global node `first`.
  // Emits its nodes except the last (the next window starts there) and
  // updates `state` to the hand-off state.
  bool Window(InitialData& state, long long first, long long points, int depth,
              bool last_of_march) {
    const double t0 = T(first), t1 = T(first + points - 1);
    const double dt = (t1 - t0) / double((points - 1) * refine_);
    const Attempt a = Solve(state, int((points - 1) * refine_ + 1), dt, false);
    if (a.ok()) {
      Accept(a, state, first, 0.0, last_of_march ? points : points - 1, depth,
             0.0);
      return true;
    }
    // Δt·ω above the limit: a shorter window has the same Δt, a finer grid
    // does not. Refine (counted as a fallback) or report. Once the requested
    // grid is known to be beyond the stability limit, the march chooses the
    // solve grid, and then one that passes the a-posteriori checks too; a
    // grid within the limit that fails them is the user's, reported.
    const bool refinable =
        a.failure == WindowFailure::kUnderResolved ||
        (refine_ > 1 && (a.failure == WindowFailure::kCoarse ||
                         a.failure == WindowFailure::kCheck));
    if (refinable && Refine(state, true)) {
      ++out_.fallbacks;
      return Window(state, first, points, depth, last_of_march);
    }
    if (!a.split_helps()) {
      FailAt(t0, t1, a.why, a.residual, Solved(a));
      return false;
    }
    const long long half = (points + 1) / 2;
    if (depth >= options_.max_split_depth || half < min_points_) {
      FailAt(t0, t1, a.why, a.residual, Solved(a));
      return false;
    }
    ++out_.fallbacks;
    return Window(state, first, half, depth + 1, false) &&
           Window(state, first + half - 1, points - half + 1, depth + 1,
                  last_of_march);
  }

  double T(long long index) const {
    const double dt = (grid_.t_end - grid_.t_start) / double(grid_.points - 1);
    return index == grid_.points - 1 ? grid_.t_end
                                     : grid_.t_start + dt * double(index);
  }

  // Records an accepted window, emits its first `count` nodes (every
  // refine_-th of the solve grid on a refined uniform grid) and hands off.
  // The window starts at global node `first` of the uniform grid, or at time
  // `t_first` under error control (first < 0).
  void Accept(const Attempt& a, InitialData& state, long long first,
              double t_first, long long count, int depth, double err) {
    WindowReport w;
    const bool adaptive = first < 0;
    const int stride = adaptive ? 1 : refine_;
    w.t_start = adaptive ? t_first : T(first);
    w.t_end = w.t_start + a.dt * double(a.points - 1);
    w.points = a.points;
    w.iterations = a.iterations;
    w.corrections = a.corrections;
    w.converged = true;
    w.fallbacks = depth;
    w.dt = a.dt;
    w.error_norm = err;
    for (int c = 0; c < d; ++c) {
      w.position_error_estimate =
          std::max(w.position_error_estimate, a.est_x[c]);
      w.velocity_error_estimate =
          std::max(w.velocity_error_estimate, a.est_v[c]);
    }
    // Per-window reports grow with the number of windows: kept with the
    // trajectory only, so a streamed march stays O(window) in memory.
    if (options_.keep_trajectory) out_.windows.push_back(w);
    ++out_.window_count;
    out_.iterations += a.iterations;
    out_.corrections += a.corrections;
    out_.error_estimate += w.position_error_estimate;
    out_.min_step = out_.min_step == 0 ? a.dt : std::min(out_.min_step, a.dt);
    out_.max_step = std::max(out_.max_step, a.dt);
    if (WantNodes()) {
      double x[d], v[d];
      for (long long i = 0; i < count; ++i) {
        for (int c = 0; c < d; ++c) {
          x[c] = a.X(int(i * stride), c);
          v[c] = a.V(int(i * stride), c);
        }
        const double t =
            adaptive
                ? (i == a.points - 1 ? w.t_end : w.t_start + a.dt * double(i))
                : T(first + i);
        Emit(t, x, v);
      }
    }
    out_.points += count;
    InitialData start;
    if (options_.window_observer) start = state;
    for (int c = 0; c < d; ++c) {
      const bool corrected = options_.hand_off == HandOff::kCorrected;
      state.x[c] = corrected ? a.end.position[c] : a.x_end[c];
      if (order_ == 2) state.v[c] = corrected ? a.end.velocity[c] : a.v_end[c];
    }
    if (options_.window_observer)
      options_.window_observer({w.t_start, w.t_end, a.dt, a.points,
                                start.x.data(), start.v.data(), a.x_end.data(),
                                a.v_end.data(), state.x.data(), state.v.data(),
                                a.est_x.data(), a.est_v.data()});
  }

  void Emit(double t, const double* x, const double* v) {
    if (observer_) observer_(t, x, v);
    if (options_.keep_trajectory) {
      out_.t.push_back(t);
      for (int c = 0; c < d; ++c) {
        xs_.push_back(x[c]);
        vs_.push_back(v[c]);
      }
    }
  }

  // A failed window: the march reports where, why, and the residual left
  // (for a window that was solved but rejected by a check, the residual of
  // the solution it rejected).
  void FailAt(double t0, double t1, const std::string& why, double residual,
              bool solved = false) {
    out_.last_residual = residual;
    out_.failed_at = t0;
    std::ostringstream s;
    s << "window [" << t0 << ", " << t1 << "] "
      << (solved ? "was solved but rejected: " : "did not converge: ") << why
      << "; last residual ‖F‖∞ = " << residual;
    out_.status = {false, s.str()};
  }

  // Error control that cannot go on at time t.
  void Unreachable(double t, const std::string& why) {
    out_.last_residual = last_residual_;
    out_.failed_at = t;
    std::ostringstream s;
    s << "the tolerance cannot be met at t = " << t << ": " << why;
    // Windows rejected for their error were solved: no residual to report.
    if (!std::isnan(last_residual_))
      s << "; last residual ‖F‖∞ = " << last_residual_;
    out_.status = {false, s.str()};
  }

  static bool Solved(const Attempt& a) {
    return a.failure == WindowFailure::kCheck ||
           a.failure == WindowFailure::kCoarse;
  }

  static std::string Text(double v) {
    std::ostringstream s;
    s.precision(3);
    s << v;
    return s.str();
  }

 public:
  std::vector<double> xs_, vs_;  // kept nodes, node-major

 private:
  const P& problem_;
  const Grid& grid_;
  const MarchOptions& options_;
  const NodeObserver& observer_;
  MarchResult& out_;
  int order_;
  int min_points_;
  WindowSolver<P> solver_;
  int refine_ = 1;  // uniform grid: solve grid = requested grid refined
  std::string last_why_;
  double last_residual_ = NAN;
};

}  // namespace detail

template <action::LagrangianProblem P>
MarchResult MarchIvp(const P& problem, const InitialData& initial,
                     const Grid& grid, const MarchOptions& options = {},
                     const NodeObserver& observer = {}) {
  constexpr int d = P::kDim;
  const auto start = std::chrono::steady_clock::now();
  const bool adaptive = options.tolerance.enabled();
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
  // control the operator's minimum stands in for the points.
  const int min_points = sbp::Table(grid.op).min_points;
  const auto global = sbp::MakeOperator<double>(
      grid.op, adaptive ? min_points : grid.points, grid.t_start, grid.t_end);
  if (options.window_points < min_points)
    throw std::invalid_argument(
        "window of " + std::to_string(options.window_points) +
        " points is below the minimum of " + grid.op + " (" +
        std::to_string(min_points) + "); use --slab-points >= " +
        std::to_string(min_points) + " or 0 for one global solve");
  MarchResult out;
  InitialData state = initial;
  const int order = detail::CheckInitialData(problem, state);
  if (order == 1) state.v.clear();
  detail::Marcher<P> m(problem, grid, options, observer, out, order,
                       min_points);
  const bool ok = adaptive ? m.Adaptive(state) : m.Uniform(state);
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
        out.x(i, c) = m.xs_[i * d + c];
        out.v(i, c) = m.vs_[i * d + c];
      }
  }
  out.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  return out;
}

}  // namespace vivp
