// Error control for time-slab marching (march.h): the tolerance, the error
// norm of a window's embedded estimates, and the step-size controller.
//
// Every window of the variational method carries its own error estimates at
// no cost, as the two members of a Runge–Kutta pair do: x_N is the order-p end
// value and x_N + M⁻¹λ4 the one of higher order, so |M⁻¹λ4| estimates the
// error of x_N; likewise |(Dx)_N − M⁻¹(−λ3)| estimates that of the end
// velocity (Dx)_N. These two are the largest local errors of the values a
// window returns (the nodes near its end, where the SBP closure is least
// accurate); the state handed to the next window is the corrected one, which
// is one or more orders better. Controlling both keeps every returned node
// within the tolerance of the local flow; measured ratios of estimate to true
// error: docs/error_control.md.
#pragma once

#include <algorithm>
#include <cmath>
#include <string_view>

#include "core/sbp/builder.h"

namespace vivp::variational {

// Like an ODE solver's atol/rtol: a value y is accurate enough when its error
// is below absolute + relative·|y|. At least one must be positive.
struct Tolerance {
  double absolute = 0;
  double relative = 0;
  bool enabled() const { return absolute > 0 || relative > 0; }
  // The allowance for a value of size |y|.
  double Allowance(double y) const { return absolute + relative * std::abs(y); }
};

// The order in Δt of the dominant estimate at a fixed number of points per
// window, measured per operator (core/sbp, Measured::estimate_order: the
// lower end of the measured slope, since a controller that assumes too high
// an order overshoots and is rejected). An unknown operator is
// std::invalid_argument naming the valid ones.
inline double EstimateOrder(std::string_view op) {
  return sbp::Table(op).measured.estimate_order;
}

// The standard step-size rule with a proportional-integral term
// (Gustafsson 1991; Hairer & Wanner, Solving ODEs II, §IV.2):
//   Δt_new = Δt · clamp(safety · ε_n^(−0.7/q) · ε_(n−1)^(0.4/q), 0.2, 2)
// after an accepted window with error norm ε_n ≤ 1 (ε_(n−1) at least ½,
// kPreviousFloor below), and
//   Δt_new = Δt · clamp(safety · ε_n^(−1/q), 0.1, 0.8)
// after a rejected one (no growth right after a rejection). q is the order
// of the estimate (EstimateOrder).
//
// Predictive (asked for by the march of a spectral element under its own
// estimates): after an accepted window the factor is at most
//   safety · (Δt_n/Δt_m) · (ε_m/ε_n)^(1/q) · ε_n^(−1/q),
// m the previously accepted window (Gustafsson 1994; Hairer & Wanner,
// Solving ODEs II, §IV.8, as Radau5 does): a step that had to shrink and
// an error that rises carry on. On Kepler e = 0.9 over three orbits, lgl8
// and lgl12 at 10⁻⁶ … 10⁻⁸, the rejections fell from 19–36 to 2–6 and the
// time at 10⁻⁶ by 22–27 %; on the anharmonic oscillator it moved by
// −2 … +8 % (docs/performance.md §9). Not measured for the
// finite-difference windows, which keep the rule above.
class StepController {
 public:
  explicit StepController(double order, bool predictive = false)
      : q_(order), predictive_(predictive) {}

  // `roundoff`: the error is at the estimate's round-off level, which grows
  // as the step shrinks; the predictive term then sits out (it would follow
  // that rise down to ever smaller steps).
  double Accept(double dt, double err, bool roundoff = false) {
    const double e = std::max(err, 1e-10);
    double factor =
        kSafety * std::pow(e, -0.7 / q_) * std::pow(previous_, 0.4 / q_);
    if (predictive_ && last_dt_ > 0 && !roundoff)
      factor = std::min(factor, kSafety * (dt / last_dt_) *
                                    std::pow(last_err_ / e, 1.0 / q_) *
                                    std::pow(e, -1.0 / q_));
    last_dt_ = dt;
    last_err_ = e;
    factor = std::clamp(factor, 0.2, just_rejected_ ? 1.0 : 2.0);
    previous_ = std::max(e, kPreviousFloor);
    just_rejected_ = false;
    // Keep the step when the rule asks for a change between −15 % and
    // +20 %: the window's operators and factorization then serve the next
    // window (Radau5 keeps its LU for step ratios in [1, 1.2]). Skipping the
    // small decreases too, which the safety factor asks for at every
    // ε_n near 1, cut the time of the 24 marches of bench/march_phases_bench
    // (Kepler e = 0.9 and the anharmonic oscillator, SBP42/63/84,
    // 10⁻⁵ … 10⁻⁸) by 18 % in geometric mean, with 5 % fewer nodes; the
    // bounds 0.8 … 0.9 measured within 4 % of each other.
    if (factor >= kKeepFrom && factor < kKeepBelow) factor = 1.0;
    return dt * factor;
  }

  double Reject(double dt, double err) {
    just_rejected_ = true;
    const double e = std::isfinite(err) ? err : 1e10;
    return dt * std::clamp(kSafety * std::pow(e, -1.0 / q_), 0.1, 0.8);
  }

 private:
  static constexpr double kSafety = 0.8;
  // The integral term's ε_(n−1) counts at least this much. The term holds
  // the step back when the error rises; with the error far below the
  // tolerance in window after window, ε_(n−1) = ε_n = ε gives the step only
  // 0.8·ε^(−0.3/q) per window (×1.2 at ε = 0.003), and a march that leaves
  // a fast stretch lags behind it: on Kepler e = 0.9 (SBP84, 10⁻⁵, windows
  // of 48) half the accepted windows had ε below 0.003, steps a quarter of
  // what the tolerance allows. From ½ the growth is that of the
  // proportional term, at most ×2: 3432 nodes instead of 4231, 35.8 M
  // instructions instead of 34.4 M at that tolerance with an end error of
  // 4.0e-9 instead of 3.9e-8 (callgrind; docs/error_control.md, "The integral
  // term's floor").
  static constexpr double kPreviousFloor = 0.5;
  static constexpr double kKeepFrom = 0.85, kKeepBelow = 1.2;
  double q_;
  bool predictive_;
  double last_dt_ = 0, last_err_ = 1;
  double previous_ = 1.0;
  bool just_rejected_ = false;
};

}  // namespace vivp::variational
