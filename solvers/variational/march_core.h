// What both ways of marching share (march.h): solving and checking a window
// (window_solve.h), accepting it — its report, its nodes to the observer and
// the trajectory, the hand-off — and reporting a failure with its window,
// reason and residual. The same for a point-mechanics problem and a field:
// the Window (point_window.h, solvers/spacetime/field_window.h) is what varies.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "core/sbp/builder.h"
#include "solvers/variational/march_types.h"
#include "solvers/variational/resolution.h"
#include "solvers/variational/step_control.h"
#include "solvers/variational/window_solve.h"

namespace vivp::variational::detail {

template <class WindowT>
class MarchCore {
 public:
  using Attempt = WindowAttempt;

  MarchCore(WindowT& window, const Grid& grid, const MarchOptions& options,
            const NodeObserver& observer, MarchResult& out, int min_points)
      : window_(window),
        grid_(grid),
        options_(options),
        observer_(observer),
        out_(out),
        d_(window.dim()),
        order_(window.order()),
        min_points_(min_points),
        element_(sbp::IsElement(grid.op)),
        solver_(window, options) {}

  std::vector<double> xs_, vs_;  // kept nodes, node-major

 protected:
  bool WantNodes() const { return bool(observer_) || options_.keep_trajectory; }

  // The window from `state` at time t0, into `a` (returned); `uniform` adds
  // the resolution check of window_solve.h; `nodes` keeps the nodes even
  // when nothing asks for them.
  Attempt& Solve(Attempt& a, const InitialData& state, double t0, int points,
                 double dt, bool fresh, Tolerance predictor, bool uniform,
                 bool nodes = false, double theta_cap = 0,
                 double omega_start = -1) {
    solver_.Solve(a, state, t0, points, dt, fresh, nodes || WantNodes(),
                  predictor, uniform, theta_cap, omega_start);
    out_.predictor_steps += a.predictor_steps;
    out_.phases += a.phases;
    if (a.failure == WindowFailure::kCheck) ++out_.check_failures;
    if (!fresh && a.failure == WindowFailure::kNewton &&
        solver_.ReusesFactorizations()) {
      // Chord steps on an earlier window's factorization did not converge:
      // once more with a Jacobian of this window's own. (A solver that
      // starts each window afresh would only repeat itself.)
      ++out_.fallbacks;
      return Solve(a, state, t0, points, dt, true, predictor, uniform, nodes,
                   theta_cap, omega_start);
    }
    return a;
  }

  // Records an accepted window, emits the nodes i·stride of its solve grid
  // for i < count, at the times time_of(i), and hands off to `state`.
  template <class TimeOf>
  void Accept(const Attempt& a, InitialData& state, double t_start, int stride,
              long long count, int depth, double err, const TimeOf& time_of) {
    WindowReport w;
    w.t_start = t_start;
    w.t_end = t_start + a.dt * double(a.points - 1);
    w.points = a.points;
    w.iterations = a.iterations;
    w.corrections = a.corrections;
    w.converged = true;
    w.fallbacks = depth;
    w.dt = a.dt;
    w.error_norm = err;
    const int d = d_;
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
      node_x_.resize(d);
      node_v_.resize(d);
      const bool corrected = options_.hand_off == HandOff::kCorrected;
      for (long long i = 0; i < count; ++i) {
        // A spectral element's first node is the state handed to it, and
        // its last (the march's end) the state it hands on: its (Dx)_0 and
        // (Dx)_N are derivatives of the element's polynomial, of order about
        // n, the hand-off of order 2n − 2 (docs/method.md §13).
        const bool first = element_ && i == 0;
        const bool last = element_ && corrected && i * stride == a.points - 1;
        for (int c = 0; c < d; ++c) {
          node_x_[c] = first  ? state.x[c]
                       : last ? a.end.position[c]
                              : a.X(int(i * stride), c);
          node_v_[c] = order_ != 2 ? a.V(int(i * stride), c)
                       : first     ? state.v[c]
                       : last      ? a.end.velocity[c]
                                   : a.V(int(i * stride), c);
        }
        Emit(time_of(i), node_x_.data(), node_v_.data());
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

  // A failed window: the march reports where, why, and the residual left
  // (for a window that was solved but rejected by a check, the residual of
  // the solution it rejected).
  void FailAt(double t0, double t1, const Attempt& a) {
    out_.last_residual = a.residual;
    out_.failed_at = t0;
    const bool solved = a.failure == WindowFailure::kCheck ||
                        a.failure == WindowFailure::kCoarse;
    std::ostringstream s;
    s << "window [" << t0 << ", " << t1 << "] "
      << (solved ? "was solved but rejected: " : "did not converge: ") << a.why
      << "; last residual ‖F‖∞ = " << a.residual;
    out_.status = {false, s.str()};
  }

  static std::string Text(double v) {
    std::ostringstream s;
    s.precision(3);
    s << v;
    return s.str();
  }

  WindowT& window_;
  const Grid& grid_;
  const MarchOptions& options_;
  const NodeObserver& observer_;
  MarchResult& out_;
  int d_;  // components of the state
  int order_;
  int min_points_;
  bool element_;  // a spectral element's windows (lobatto.h)

 private:
  void Emit(double t, const double* x, const double* v) {
    if (observer_) observer_(t, x, v);
    if (options_.keep_trajectory) {
      out_.t.push_back(t);
      xs_.insert(xs_.end(), x, x + d_);
      vs_.insert(vs_.end(), v, v + d_);
    }
  }

  WindowSolver<WindowT> solver_;
  std::vector<double> node_x_, node_v_;
};

}  // namespace vivp::variational::detail
