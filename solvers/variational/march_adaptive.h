// Marching under error control (march.h, MarchOptions::tolerance): every
// window has W points and a Δt chosen by a step-size controller
// (step_control.h) from the window's embedded error estimates; a window
// whose estimates exceed the tolerance, or that fails, is rejected and solved
// again with a smaller Δt. SBP21, whose position estimate is unreliable,
// estimates by step doubling (the window again at Δt/2; the finer one is
// kept); a spectral element by its own end-node estimates as a
// finite-difference window or by its two halves (element_halves.h), which
// are kept (ElementEstimate: by default the first down to a tolerance of
// 10⁻⁸, the halves below). See docs/error_control.md.
#pragma once

#include <algorithm>
#include <optional>
#include <utility>

#include "core/sbp/builder.h"
#include "solvers/variational/element_halves.h"
#include "solvers/variational/march_core.h"

namespace vivp::variational::detail {

template <class WindowT>
class AdaptiveMarch : public MarchCore<WindowT> {
 public:
  using Core = MarchCore<WindowT>;
  using Core::Core;
  using typename Core::Attempt;

  // Error control: Δt per window from the embedded estimates.
  bool Run(InitialData& state) {
    const sbp::Coefficients& table = sbp::Table(grid_.op);
    const bool element = table.max_points > 0;
    const Tolerance& tol = options_.tolerance;
    const ElementEstimate estimate = options_.element_estimate;
    if (element && (estimate == ElementEstimate::kHalves ||
                    (estimate == ElementEstimate::kAuto &&
                     std::max(tol.absolute, tol.relative) < kEmbeddedFrom)))
      halves_.emplace(window_, grid_.op, options_.hand_off);
    const bool doubling = !element && !table.measured.position_estimate;
    // An element under its own estimates with the predictive term
    // (step_control.h): near pericentre of Kepler e = 0.9 its error rose
    // 12–18-fold element by element, and every other one was rejected.
    const bool predictive = element && !halves_;
    // Such an element, and a second-order finite-difference window of
    // boundary order 3 or more, is fitted to its far end's frequency (Cap;
    // not the halves, judged at the step asked for, nor step doubling).
    // SBP42's estimate grows the slowest with ω, and the far end's ω (70 ns
    // a window) cost its cheap windows 1–7 % more time for the same nodes.
    const bool fit = order_ == 2 && !halves_ && !doubling &&
                     (element || table.boundary_order >= 3);
    StepController control(EstimateOrder(grid_.op), predictive);
    double t = grid_.t_start;
    double dt = InitialStep(state);
    int rejected_in_row = 0;
    const double span = grid_.t_end - grid_.t_start;
    while (t < grid_.t_end) {
      // The fastest frequency at the start (the engine keeps the one at its
      // last hand-off), for the window's stability limit and its fit.
      const double omega =
          order_ == 2 ? window_.FastestFrequency(state.x.data(), state.v.data())
                      : 0.0;
      const Window w = NextWindow(t, dt, omega);
      if (!CanContinue(t, w, rejected_in_row)) return false;
      Attempt* a = SolveWindow(state, t, w, fit ? Cap(w.dt, omega) : 0.0, omega,
                               doubling);
      const double err = a->ok() ? ErrorNorm(state, *a) : NAN;
      // The step solved: a fitted window's own (a last one shortened so is
      // the last no longer); else w.dt, the halves' pair judged by a half.
      const double solved = fit ? a->dt : w.dt;
      if (!a->ok() || !(err <= 1)) {
        ++out_.rejected;
        ++rejected_in_row;
        if (!Rejected(state, *a, err, t, solved, control, dt)) return false;
        continue;
      }
      rejected_in_row = 0;
      truncation_rejected_at_ = 0;
      tried_between_ = false;
      const bool last = w.last && solved == w.dt;
      if (fit) omega_last_ = std::max({a->omega, omega, 1.0 / span});
      const double t1 = last ? grid_.t_end : t + solved * double(w.points - 1);
      if (halves_) {
        const double middle = t + 0.5 * w.dt * double(w.points - 1);
        AcceptWindow(halves_->half(0), state, t, middle, false, err);
        AcceptWindow(halves_->half(1), state, middle, t1, last, err);
      } else {
        AcceptWindow(*a, state, t, t1, last, err);
      }
      t = t1;
      dt = control.Accept(solved, err, predictive && AtRoundOff(state, *a));
    }
    return true;
  }

 private:
  using Core::d_;
  using Core::grid_;
  using Core::min_points_;
  using Core::options_;
  using Core::order_;
  using Core::out_;
  using Core::Text;
  using Core::window_;

  // Accepts a window from t0 to t1 (its last node at t1 exactly): all its
  // nodes if it is the last, else all but the end node, which is the next
  // window's first. A spectral element's nodes at their Gauss–Lobatto times.
  void AcceptWindow(const Attempt& a, InitialData& state, double t0, double t1,
                    bool last, double err) {
    const sbp::Coefficients& table = sbp::Table(grid_.op);
    this->Accept(a, state, t0, 1, last ? a.points : a.points - 1, 0, err,
                 [&](long long i) {
                   return i == a.points - 1
                              ? t1
                              : t0 + a.dt * table.Offset<double>(int(i));
                 });
  }

  // The next window from t: W points at the step dt, which is first kept at
  // half the stability limit of Δt·ω (resolution.h); the last windows are
  // fitted to end at T exactly (two equal ones when less than two remain).
  struct Window {
    int points;
    double dt;
    bool last;
  };
  // `omega`: the fastest frequency at t (second order; 0 otherwise).
  Window NextWindow(double t, double& dt, double omega) const {
    if (omega > 0) dt = std::min(dt, 0.5 * StabilityLimit(grid_.op) / omega);
    const int w = int(options_.window_points);
    const double remaining = grid_.t_end - t;
    if (remaining <= double(w - 1) * dt * (1 + 1e-12)) {
      const int n =
          std::clamp(int(std::ceil(remaining / dt - 1e-9)) + 1, min_points_, w);
      return {n, remaining / double(n - 1), true};
    }
    if (remaining < 2.0 * double(w - 1) * dt)
      return {w, remaining / (2.0 * double(w - 1)), false};
    return {w, dt, false};
  }

  // The window w from t, solved with its fine half-step twin (step
  // doubling) or its halves; the attempt to judge.
  Attempt* SolveWindow(const InitialData& state, double t, const Window& w,
                       double cap, double omega, bool doubling) {
    // A whole element factors its own Jacobian: the last one is a pair
    // back, a whole element's length away and at another step, and chord
    // steps on it failed or crawled (Kepler e = 0.9 over three orbits,
    // lgl8 at 10⁻⁹ … 10⁻¹²: 2 fallbacks and 1 check failure to none, time
    // −5 … −30 %).
    const double solving = out_.phases.Solving();
    Attempt* a =
        &this->Solve(attempt_, state, t, w.points, w.dt, bool(halves_),
                     PredictorTolerance(), false, bool(halves_), cap, omega);
    if (halves_) out_.phases.whole_elements += out_.phases.Solving() - solving;
    if (a->ok() && doubling) {
      Doubled(state, t, *a, fine_);
      std::swap(attempt_, fine_);  // a (attempt_) is now the fine window
    } else if (a->ok() && halves_) {
      halves_->Solve(*a, state, t, this->WantNodes());
      for (int k = 0; k < 2; ++k) out_.phases += halves_->half(k).phases;
      a = &halves_->judged();
    }
    return a;
  }

  // False, with the status set, when the march cannot go on: the step fell
  // to the round-off of the time span, too many windows in a row were
  // rejected, or the nodes would exceed max_points.
  bool CanContinue(double t, const Window& w, int rejected_in_row) {
    const double span = grid_.t_end - grid_.t_start;
    const bool underflow = !(w.dt > 1e-13 * std::max(std::abs(t), span));
    if (underflow || rejected_in_row > 40) {
      Unreachable(t, (underflow ? "the step fell to " + Text(w.dt) +
                                      ", below the round-off limit 1e-13 of "
                                      "the time span"
                                : std::to_string(rejected_in_row) +
                                      " windows in a row rejected (step " +
                                      Text(w.dt) + ")") +
                         (last_why_.empty() ? "" : "; last: " + last_why_));
      return false;
    }
    if (out_.points + w.points > options_.max_points) {
      Unreachable(t, "it needs more than max_points = " +
                         std::to_string(options_.max_points) + " nodes (step " +
                         Text(w.dt) + ")");
      return false;
    }
    return true;
  }

  // A rejected window at step dtw: sets the next step dt, or the status and
  // false when no step meets the tolerance in double precision. Truncation
  // errors fall with the step, the round-off of (Dx)_N grows like ε|x|/Δt:
  // a window rejected on a velocity estimate at its round-off level needs
  // a larger step. When a larger step was rejected on truncation since the
  // last accepted window, one step between the two is tried; if that fails
  // too, no step meets the tolerance (SBP84, Kepler e = 0.9, below 1e-9).
  bool Rejected(const InitialData& state, const Attempt& a, double err,
                double t, double dtw, StepController& control, double& dt) {
    last_why_ =
        a.ok() ? "error estimate " + Text(err) + " times the tolerance" : a.why;
    last_residual_ = a.residual;
    const std::string roundoff = a.ok() ? RoundOffBound(state, a) : "";
    if (!roundoff.empty()) {
      if (truncation_rejected_at_ > dtw && tried_between_) {
        Unreachable(t, roundoff);
        return false;
      }
      tried_between_ = truncation_rejected_at_ > dtw;
      dt = tried_between_ ? std::sqrt(dtw * truncation_rejected_at_) : 4 * dtw;
      return true;
    }
    if (a.ok())
      truncation_rejected_at_ = std::max(truncation_rejected_at_, dtw);
    dt = a.ok() ? control.Reject(dtw, err) : 0.25 * dtw;
    return true;
  }

  // The predictor's tolerance: a hundredth of the march's, so that its error
  // is small against the window's (the consistency check compares them).
  Tolerance PredictorTolerance() const {
    const Tolerance& t = options_.tolerance;
    // A spectral element's predictor is its Newton start and the reference
    // of check 2 only (the halves estimate its error): at 10⁻⁶ it is small
    // against the solution, which another branch differs by, and against
    // the check's allowance (the end node's error, of order about n).
    // Kepler e = 0.9, lgl8 at 10⁻⁹ … 10⁻¹³: 5–18 times fewer predictor
    // steps than at a hundredth, the same corrections, nodes within 1 %.
    if (halves_)
      return {std::max(t.absolute, kElementPredictor),
              std::max(t.relative, kElementPredictor)};
    // An element under its embedded estimates: at the tolerance, 2–22 %
    // less time per node than at a hundredth (docs/performance.md §9).
    // Check 2 allows for the predictor's error, and a branch off by the
    // solution's size is still far outside it.
    const double f = sbp::IsElement(grid_.op) ? 1.0 : 0.01;
    return {t.absolute > 0 ? std::max(f * t.absolute, 1e-15) : 0.0,
            t.relative > 0 ? std::max(f * t.relative, 1e-14) : 0.0};
  }

  // SBP21: the window again at Δt/2, into `fine`; the difference of the two
  // end states estimates the error of the coarse one, and the fine one is
  // kept.
  void Doubled(const InitialData& state, double t0, const Attempt& coarse,
               Attempt& fine) {
    this->Solve(fine, state, t0, 2 * coarse.points - 1, 0.5 * coarse.dt, false,
                PredictorTolerance(), false);
    if (!fine.ok()) return;
    const int d = d_;
    for (int c = 0; c < d; ++c) {
      fine.est_x[c] = std::abs(coarse.x_end[c] - fine.x_end[c]);
      fine.est_v[c] = std::abs(coarse.v_end[c] - fine.v_end[c]);
    }
  }

  // max over components of estimate / (absolute + relative·|value|), the
  // value being the larger of the window's start and end.
  double ErrorNorm(const InitialData& state, const Attempt& a) const {
    const Tolerance& tol = options_.tolerance;
    const int d = d_;
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

  // The term of a window's error norm that is largest against its
  // allowance: its estimate, that estimate's round-off level (the
  // velocity's of (Dx)_N, an element's difference of halves; 0 for a
  // finite-difference window's position) and the allowance.
  struct Term {
    bool velocity = false;
    double est = 0, level = 0, allowance = 0;
  };
  Term LargestTerm(const InitialData& state, const Attempt& a) const {
    const Tolerance& tol = options_.tolerance;
    Term t;
    double worst = 0;
    const int d = d_;
    for (int c = 0; c < d; ++c) {
      const double ax = tol.Allowance(
          std::max(std::abs(state.x[c]), std::abs(a.end.position[c])));
      const double av = tol.Allowance(
          std::max(std::abs(state.v[c]), std::abs(a.end.velocity[c])));
      if (a.est_x[c] / ax > worst) {
        worst = a.est_x[c] / ax;
        t = {false, a.est_x[c], halves_ ? halves_->PositionRoundOff(c) : 0.0,
             ax};
      }
      if (a.est_v[c] / av > worst) {
        worst = a.est_v[c] / av;
        t = {true, a.est_v[c], a.roundoff_v[c], av};
      }
    }
    return t;
  }

  // Whether a window's largest term is within 8 times its round-off level
  // (the step controller's predictive term then sits out).
  bool AtRoundOff(const InitialData& state, const Attempt& a) const {
    if (order_ != 2) return false;
    const Term t = LargestTerm(state, a);
    return t.est <= 8 * t.level;
  }

  // Why a rejected window's error is round-off: its largest term is a
  // velocity estimate within twice the round-off level of (Dx)_N (an
  // element's: the difference of its halves within twice theirs, position
  // or velocity); "" if not.
  std::string RoundOffBound(const InitialData& state, const Attempt& a) const {
    if (order_ != 2) return "";
    const Term t = LargestTerm(state, a);
    if (!(t.velocity || halves_) || !(t.est <= 2 * t.level)) return "";
    const std::string of =
        halves_ ? "64*n*eps*|" + std::string(t.velocity ? "v" : "x") + "|/" +
                      Text(ElementHalves<WindowT>::kDivisor) + ", " +
                      Text(t.level) +
                      ", of the difference of an element and its halves"
                : "eps*sum|D_N|*max|x| = " + Text(t.level) + " of (Dx)_N";
    return "it is below the round-off of the window's " +
           std::string(t.velocity ? "velocity" : "position") +
           " estimate (at step " + Text(a.dt) + " the estimate " + Text(t.est) +
           " is within twice the round-off level " + of +
           "; the allowance is " + Text(t.allowance) +
           "); use a larger tolerance";
  }

  // The cap on Δt·ω̂ of a window at the step dt asked for, ω the fastest
  // frequency at its start (window_solve.h fits the window to it): its far
  // end's, at the predictor's end state, may rise kFrequencyRise-fold over
  // the start's and the last window's (an element's kElementFrequencyRise),
  // and Δt·ω̂ stays within half the stability limit. Kepler e = 0.9 at
  // 1e-7: lgl16 rejected 16 of 57 elements unfitted, 4 of 47 fitted; SBP84
  // at 1e-5 30 windows, fitted 9, and 3–7 instead of 20–24 on the
  // anharmonic oscillator (docs/performance.md §9, docs/error_control.md).
  double Cap(double dt, double omega) const {
    const double rise =
        sbp::IsElement(grid_.op) ? kElementFrequencyRise : kFrequencyRise;
    const double span = grid_.t_end - grid_.t_start;
    return std::min(rise * dt * std::max({omega, 1.0 / span, omega_last_}),
                    0.5 * StabilityLimit(grid_.op));
  }

  double InitialStep(const InitialData& state) const {
    const double span = grid_.t_end - grid_.t_start;
    const double longest = span / double(options_.window_points - 1);
    if (options_.initial_step > 0)
      return std::min(options_.initial_step, longest);
    if (order_ != 2) return longest / 8;
    const double omega =
        window_.FastestFrequency(state.x.data(), state.v.data());
    if (!(omega > 0)) return longest / 8;
    // The estimates scale like (Δt·ω)^q: start near where they meet the
    // tolerance; the controller corrects the rest.
    const Tolerance& t = options_.tolerance;
    const double level = std::max(t.relative, 1e-14);
    return std::min(longest,
                    std::pow(level, 1.0 / EstimateOrder(grid_.op)) / omega);
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

  static constexpr double kElementPredictor = 1e-6;
  // How far a fitted window's far-end frequency may rise (Cap), an
  // element's, and ω̂ of the last accepted window.
  static constexpr double kFrequencyRise = 1.25, kElementFrequencyRise = 2.0;
  double omega_last_ = 0;
  std::string last_why_;
  double last_residual_ = NAN;
  // Every window's attempt and, with step doubling, its half-step
  // solution's: their storage kept from window to window.
  Attempt attempt_, fine_;
  // A spectral element's halves (element_halves.h).
  std::optional<ElementHalves<WindowT>> halves_;
  // Since the last accepted window: the largest step rejected on
  // truncation, and whether a step below it was tried after round-off.
  double truncation_rejected_at_ = 0;
  bool tried_between_ = false;
};

}  // namespace vivp::variational::detail
