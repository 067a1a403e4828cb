// What the one-process field window (field_window.h) and one rank's window
// of a distributed march (solvers/distributed/window.h) do alike: keep the
// window's time operator, account for its Newton solve, and check the
// resolution limit at the window's ends.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/sbp/builder.h"
#include "core/sbp/regularized.h"
#include "solvers/spacetime/resolution.h"
#include "solvers/spacetime/window_data.h"
#include "solvers/variational/ivp_types.h"
#include "solvers/variational/newton.h"
#include "solvers/variational/resolution.h"
#include "solvers/variational/window_checks.h"

namespace vivp::spacetime::detail {

// The time operator of a window of `points` nodes spaced dt, kept while
// they stay (a step within 64 ε of the last is the same step: the windows
// of a uniform march differ in the last bits).
struct WindowOperator {
  std::unique_ptr<sbp::RegularizedOperator<double>> dbar;
  double dt = 0;
  double row_sum = 0;  // Σ|row N of D|, for the round-off of (Dφ)_N
  // True if it was rebuilt.
  bool Set(const std::string& op, int points, double step) {
    if (dbar && dbar->points() == points &&
        std::abs(step - dt) <= 64 * std::numeric_limits<double>::epsilon() * dt)
      return false;
    dt = step;
    dbar = std::make_unique<sbp::RegularizedOperator<double>>(
        sbp::MakeOperator<double>(op, points, 0.0, step * double(points - 1)));
    row_sum = 0;
    for (double w : dbar->base().row(points - 1).coeffs) row_sum += std::abs(w);
    return true;
  }
};

// The Newton start of a window that no independent integration predicts:
// the Taylor path φ₀ + τφ_t0 + ½τ²φ̈₀, φ_t0 + τφ̈₀ with `acc` the
// semi-discrete acceleration φ̈₀ at the start (method_of_lines.h), or the
// straight path φ₀ + τφ_t0 when there is none (acc null). The second-order
// term takes about one Newton iteration off a window of sine-Gordon at 0.6
// of the resolution limit (docs/distributed.md §5).
inline void TaylorStart(const double* x0, const double* v0, const double* acc,
                        const double* tau, int points, int n, double* px,
                        double* pv) {
  for (int i = 0; i < points; ++i) {
    double* x = px + std::size_t(i) * n;
    double* v = pv + std::size_t(i) * n;
    const double t = tau[i];
    if (acc)
      for (int k = 0; k < n; ++k) {
        x[k] = x0[k] + t * (v0[k] + 0.5 * t * acc[k]);
        v[k] = v0[k] + t * acc[k];
      }
    else
      for (int k = 0; k < n; ++k) {
        x[k] = x0[k] + t * v0[k];
        v[k] = v0[k];
      }
  }
}

// The Newton solve's counts and phases into the attempt and the timings;
// false (the attempt failed with Newton's reason) unless it converged.
inline bool AccountNewton(const variational::NewtonReport& r,
                          variational::detail::WindowAttempt& a,
                          FieldTimings& timings, double& worst_residual) {
  a.iterations = r.iterations;
  a.corrections = r.corrections;
  timings.residual += r.phases.residual;
  timings.assembly += r.phases.assembly;
  timings.factorization += r.phases.factorization;
  timings.solve += r.phases.solve;
  worst_residual = std::max(worst_residual, r.last_residual);
  if (r.converged) return true;
  a.residual = r.last_residual;
  a.failure = variational::detail::WindowFailure::kNewton;
  a.why = r.reason;
  return false;
}

// Δt·ω_max at both ends of each window against the time operator's limit
// (the rule of SolveField's check before the march, resolution.h). ω at a
// window's start is the last window's at its end when it continues from
// that window's hand-off (the same state up to the correction).
class WindowResolution {
 public:
  // fastest(x, v): ω_max of a state. False (the attempt failed as
  // under-resolved) if either end is beyond the limit; its time is added to
  // `seconds`.
  template <class Fastest>
  bool Check(Fastest&& fastest, variational::detail::WindowAttempt& a,
             double t0, const variational::InitialData& initial,
             const std::string& op, double t_end, double& seconds) {
    const auto start = std::chrono::steady_clock::now();
    const bool ok = Check(fastest, a, t0, initial, op, t_end);
    seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
            .count();
    return ok;
  }
  // The state an accepted window hands on.
  void Handed(const std::vector<double>& x, const std::vector<double>& v) {
    handed_x_ = x;
    handed_v_ = v;
  }
  double omega_dt() const { return omega_dt_; }

 private:
  template <class Fastest>
  bool Check(Fastest&& fastest, variational::detail::WindowAttempt& a,
             double t0, const variational::InitialData& initial,
             const std::string& op, double t_end) {
    const bool continues =
        omega_end_ >= 0 && initial.x == handed_x_ && initial.v == handed_v_;
    const double omega_start =
        continues ? omega_end_ : fastest(initial.x.data(), initial.v.data());
    omega_end_ = fastest(a.x_end.data(), a.v_end.data());
    omega_dt_ = std::max(omega_dt_, a.dt * std::max(omega_start, omega_end_));
    const double limit = variational::StabilityLimit(op);
    std::string why = UnderResolved(op, limit, a.dt, omega_start, t0, t_end);
    if (why.empty())
      why = UnderResolved(op, limit, a.dt, omega_end_,
                          t0 + a.dt * double(a.points - 1), t_end);
    if (why.empty()) return true;
    omega_end_ = -1;
    a.failure = variational::detail::WindowFailure::kUnderResolved;
    a.why = std::move(why);
    return false;
  }

  std::vector<double> handed_x_, handed_v_;
  double omega_end_ = -1, omega_dt_ = 0;
};

}  // namespace vivp::spacetime::detail
