// One window of a time-slab march (march.h), solved and checked: the
// predictor's path is the start of the window's solve, and the converged
// window is accepted only if an independent integration agrees with it.
// The same for every system a march solves: what varies is the Window,
// which integrates the predictor and solves the window's equations —
// point_window.h (reduced Newton with a banded LU, full Newton, Ceres LM)
// or solvers/spacetime/field_window.h (a field's space-time window). A Window
// provides
//
//   int dim() const;  int order() const;  const std::string& op() const;
//   double FastestFrequency(const double* x, const double* v) const;
//   PredictorReport Predict(t0, x0, v0, tau, points, tol_abs, tol_rel, px,
//                           pv);
//   bool Solve(WindowAttempt&, double t0, const InitialData&, px, pv,
//              bool fresh, bool nodes);
//   void RecordResidual(WindowAttempt&) const;
//   bool ReusesFactorizations() const;  long long factorizations() const;
//   double predictor_factor() const;  void set_predictor_factor(double);
//       (on a uniform grid, the factor on the predictor's tolerance the
//       last window settled on: part of what a checkpoint carries)
//
// The checks are those of window_checks.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/sbp/builder.h"
#include "solvers/variational/march_types.h"
#include "solvers/variational/predictor.h"
#include "solvers/variational/window_checks.h"

namespace vivp::variational::detail {

template <class WindowT>
class WindowSolver {
 public:
  using Attempt = WindowAttempt;

  WindowSolver(WindowT& window, const MarchOptions& options)
      : window_(window), options_(options) {}

  WindowT& window() { return window_; }
  const WindowT& window() const { return window_; }

  // Solves `points` nodes spaced `dt` from `initial` at time t0. `fresh`: no
  // chord steps on an earlier factorization; `nodes`: keep positions and
  // velocities. `predictor_tol` (absolute, relative) sets the predictor's
  // accuracy; `uniform` adds check 3.
  // The result goes into `a` (reset first), which is returned.
  //
  // `theta_cap` > 0 (error control of a second-order system,
  // march_adaptive.h): the window is first shortened until Δt times the
  // larger fastest frequency of its two ends, the far one at the
  // predictor's end state, is within theta_cap; a.dt and a.omega say what
  // was solved. `omega_start`, when not negative, is the start's (the
  // march has it already).
  Attempt& Solve(Attempt& a, const InitialData& initial, double t0, int points,
                 double dt, bool fresh, bool nodes, Tolerance predictor_tol,
                 bool uniform, double theta_cap = 0, double omega_start = -1) {
    const int d = window_.dim(), order = window_.order();
    a.Reset(d);
    a.points = points;
    a.dt = dt;
    x0_.assign(d, 0.0);
    v0_.assign(d, 0.0);
    for (int c = 0; c < d; ++c) {
      x0_[c] = initial.x[c];
      v0_[c] = order == 2 ? initial.v[c] : 0.0;
    }
    // The nodes' times from the window's start: uniform, or a spectral
    // element's Gauss–Lobatto nodes (lobatto.h).
    const sbp::Coefficients& table = sbp::Table(window_.op());
    tau_.resize(points);
    const auto times = [&] {
      for (int i = 0; i < points; ++i) tau_[i] = dt * table.Offset<double>(i);
    };
    times();
    px_.resize(std::size_t(points) * d);
    pv_.resize(std::size_t(points) * d);
    // On a uniform grid check 3 compares with the predictor to 1 % of the
    // solution: its own error bound must be within that, which a window
    // of many periods (a stiff spring refined for stability: 11 periods in
    // one window) needs a tighter tolerance for than the default.
    if (uniform) {
      // Absolute accuracy relative to the state's size: a decaying
      // solution (the damped oscillator after 10^4 periods, amplitude
      // 1e-4 and below) would otherwise fail the error bound below and
      // retry at ever tighter tolerances (measured: 3.8 predictor steps per
      // window at 2^22 points against 1.6 at 2^18).
      double size = 0;
      for (int c = 0; c < d; ++c)
        size = std::max({size, std::abs(x0_[c]),
                         std::abs(v0_[c]) * dt * double(points - 1)});
      predictor_tol.absolute = std::max(predictor_tol.absolute * size, 1e-300);
    }
    PredictorReport pr;
    const PhaseClock clock{options_.phase_timings};
    const auto predicting = clock.Now();
    // This try's factor on the default tolerance. The windows of a uniform
    // march are alike: the first try is at the factor the last one settled
    // on rather than failing at the default.
    double factor = uniform ? window_.predictor_factor() : 1.0;
    for (int tries = 0;; ++tries) {
      pr = window_.Predict(t0, x0_.data(), v0_.data(), tau_.data(), points,
                           factor * predictor_tol.absolute,
                           factor * predictor_tol.relative, px_.data(),
                           pv_.data());
      a.predictor_steps += pr.steps;
      // An unbounded start (no independent integration) cannot be tightened.
      if (!pr.ok || !uniform || tries == 3 || std::isinf(pr.error_x)) break;
      double scale = 0;
      for (double v : px_) scale = std::max(scale, std::abs(v));
      const double ratio =
          pr.error_x / (options_.max_relative_deviation * scale + 1e-300);
      // The tolerance factor that puts the bound at kAim of the allowance:
      // the bound is 10·k·tol over k ∝ tol^(−1/5) steps, so ∝ tol^(4/5).
      // (A bound that is not a number tightens a hundredfold, as before.)
      const double f =
          ratio >= 0 ? std::pow(kAim / std::max(ratio, 1e-300), 1.25) : 1e-2;
      window_.set_predictor_factor(std::clamp(factor * f, kTightest, 1.0));
      if (ratio <= 1.0) break;
      const double next =
          std::max(factor * std::clamp(f, 1e-4, 0.5), kTightest);
      if (next >= factor) break;  // as tight as the predictor goes
      factor = next;
    }
    if (theta_cap > 0 && order == 2 && pr.ok)
      pr = FitToFrequency(a, t0, dt, theta_cap, omega_start, predictor_tol,
                          times, pr);
    a.phases.predictor += clock.Since(predicting);
    if (!pr.ok) return Failed(a, WindowFailure::kPredictor, pr.failure);
    const double* pend_x = &px_[std::size_t(points - 1) * d];
    const double* pend_v = &pv_[std::size_t(points - 1) * d];
    if (!window_.Solve(a, t0, initial, px_, pv_, fresh, nodes)) return a;
    const auto checking = clock.Now();
    std::string why = CheckFinite(a, order);
    WindowFailure failure = WindowFailure::kNewton;
    if (why.empty()) {
      why =
          CheckConsistent(a, pr, pend_x, pend_v, order,
                          sbp::Table(window_.op()).measured.position_estimate);
      failure = WindowFailure::kCheck;
    }
    if (why.empty() && uniform) {
      why = CheckResolved(a, pr, pend_x, px_, options_.max_relative_deviation);
      failure = WindowFailure::kCoarse;
    }
    a.phases.checks += clock.Since(checking);
    if (why.empty()) return a;
    window_.RecordResidual(a);
    return Failed(a, failure, why);
  }

  bool ReusesFactorizations() const { return window_.ReusesFactorizations(); }
  long long factorizations() const { return window_.factorizations(); }

 private:
  // The window shortened, and predicted again, until dt·ω̂ ≤ theta_cap, ω̂
  // the larger fastest frequency of its start and its predicted end (into
  // a.omega; a.dt the step): a step set for the start's frequency meets
  // a rising one at its far end (an lgl16 element approaching pericentre
  // of Kepler e = 0.9: 10² … 10⁶ times the tolerance). The new end is
  // where τ·ω(τ)/(the end's offset) meets theta_cap along the predicted
  // path, between its nodes log-linearly: shortening by the far end's ω
  // alone overshot up to fourfold, the frequency rising across the window,
  // and a model with ln ω linear between the two ends took more nodes and
  // time (lgl16 at 10⁻⁷: 736 nodes against 706, 0.81 against 0.76 µs per
  // node).
  template <class Times>
  PredictorReport FitToFrequency(Attempt& a, double t0, double& dt,
                                 double theta_cap, double start, Tolerance tol,
                                 const Times& times, PredictorReport pr) {
    const int d = window_.dim(), points = a.points;
    const double offset =
        sbp::Table(window_.op()).template Offset<double>(points - 1);
    if (start < 0) start = window_.FastestFrequency(x0_.data(), v0_.data());
    const auto omega = [&](int i) {
      const std::size_t at = std::size_t(i) * d;
      return std::max(start, window_.FastestFrequency(&px_[at], &pv_[at]));
    };
    // An element is sampled inside, not only at its far end: one that jumps
    // a pericentre has low frequencies at both ends (lgl16 at 10⁻⁵ on
    // Kepler e = 0.9: two of four rejections, an estimate 10⁵ times the
    // tolerance, and a Newton failure). Every kStride-th node and the far
    // end are sampled, and only past a sample over the cap the nodes
    // between it and the last sample under it. A frequency costs about 1100
    // instructions. Against the far end alone (callgrind, one march each of
    // Kepler e = 0.9 and the anharmonic oscillator, lgl8/12/16, 10⁻⁵ …
    // 10⁻⁸): taken at every node +4.4 … +15 % in the 23 marches that jump no
    // pericentre, every fourth −0.7 … +2.7 %; lgl16 at 10⁻⁵ −27 and −32 %.
    // Sampled at the middle node only, that march still jumped (556 nodes
    // and 10.2 M instructions against 541 and 7.3 M). A finite-difference
    // window is short and rises monotonically across it: its far end says
    // enough.
    const bool scan = sbp::IsElement(window_.op());
    const double cap = theta_cap * (1 + 1e-9);
    // g(τ) = τ·ω(τ)/offset at node i (the largest ω into a.omega).
    const auto g_at = [&](int i) {
      const double w = omega(i);
      a.omega = std::max(a.omega, w);
      return tau_[i] * w / offset;
    };
    // Where g meets theta_cap between node lo (g_lo ≤ cap) and node hi
    // (g_hi past it), log-linearly; from (0, 0) where g_lo is 0 (the start:
    // ω constant).
    const auto crossing = [&](int lo, double g_lo, int hi, double g_hi) {
      return g_lo > 0 ? tau_[lo] * std::exp(std::log(theta_cap / g_lo) *
                                            std::log(tau_[hi] / tau_[lo]) /
                                            std::log(g_hi / g_lo))
                      : tau_[hi] * theta_cap / g_hi;
    };
    for (int tries = 0;; ++tries) {
      a.omega = start;
      // The first node past the cap (hi) and the one before it (lo).
      int lo = 0, hi = 0;
      double g_lo = 0, g_hi = 0;
      if (scan) {
        // The samples, then the nodes between the first past the cap and
        // the last under it.
        for (int i = std::min(kStride, points - 1); !hi;
             i = std::min(i + kStride, points - 1)) {
          const double g = g_at(i);
          if (g > cap)
            hi = i, g_hi = g;
          else if (i == points - 1)
            break;
          else
            lo = i, g_lo = g;
        }
        if (!hi || tries == 3) return pr;
        for (int i = lo + 1; i < hi; ++i) {
          const double g = g_at(i);
          if (g > cap) {
            hi = i, g_hi = g;
            break;
          }
          lo = i, g_lo = g;
        }
      } else {
        // The far end, then back from it to the last node under the cap
        // (none: from (0, 0) to the far end). Only the far end's ω is the
        // window's (a.omega).
        hi = points - 1;
        a.omega = omega(hi);
        g_hi = dt * a.omega;
        if (!(g_hi > cap) || tries == 3) return pr;
        double g_next = g_hi;
        for (int i = points - 2; i > 0; --i) {
          const double g = tau_[i] * omega(i) / offset;
          if (g <= theta_cap) {
            lo = i, g_lo = g, hi = i + 1, g_hi = g_next;
            break;
          }
          g_next = g;
        }
      }
      const double tau = crossing(lo, g_lo, hi, g_hi);
      dt = tau / offset;
      a.dt = dt;
      times();
      pr = window_.Predict(t0, x0_.data(), v0_.data(), tau_.data(), points,
                           tol.absolute, tol.relative, px_.data(), pv_.data());
      a.predictor_steps += pr.steps;
      if (!pr.ok) return pr;
    }
  }

  static Attempt& Failed(Attempt& a, WindowFailure f, std::string why) {
    a.failure = f;
    a.why = std::move(why);
    return a;
  }

  WindowT& window_;
  const MarchOptions& options_;
  std::vector<double> x0_, v0_, tau_, px_, pv_;
  // On a uniform grid the window keeps a factor (≤ 1) on the predictor's
  // default tolerance that puts a window's error bound at kAim of check 3's
  // allowance, as the last window measured it. A tenth: a start that close
  // saves chord steps and factorizations (callgrind, ten uniform marches of
  // three problems: 6 % fewer instructions than the default with hundredfold
  // retries, 3–5 % at 0.4, 0.2 and 0.05, 2 % at 0.01; docs/performance.md
  // §2). Never below kTightest, where three hundredfold retries ended.
  static constexpr double kAim = 0.1;
  static constexpr double kTightest = 1e-6;
  // The spacing, in nodes, of an element's frequency samples (FitToFrequency).
  static constexpr int kStride = 4;
};

}  // namespace vivp::variational::detail
