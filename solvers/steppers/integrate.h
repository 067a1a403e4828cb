// Running a stepper over n steps of size h, with an observer for output, and
// the run's report: status, steps done, iterations (total and per step),
// function evaluations. Bad arguments throw std::invalid_argument naming the
// argument; a blow-up is a status (kUnstable), never an exception or NaN.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "solvers/steppers/step_result.h"

namespace vivp::steppers {

struct RunReport {
  StepOutcome status = StepOutcome::kOk;
  long steps = 0;          // steps completed
  long iterations = 0;     // implicit iterations, summed over steps
  int max_iterations = 0;  // most iterations in one step
  long evaluations = 0;    // ∇H (or ∇Ĥ) evaluations
  double failed_at = NAN;  // time of the failed step, if any
  double iterations_per_step() const {
    return steps ? static_cast<double>(iterations) / steps : 0.0;
  }
};

// A state grows beyond this multiple of its initial size (plus one) only
// when the method has gone unstable; energy-bounded problems stay O(1).
inline constexpr double kBlowUpFactor = 1e8;

inline void CheckRunArguments(double h, long steps) {
  if (!std::isfinite(h) || !(h > 0))
    throw std::invalid_argument("step size must be finite and positive, got " +
                                std::to_string(h));
  if (steps < 0)
    throw std::invalid_argument("step count must be non-negative, got " +
                                std::to_string(steps));
}

// observer(t, y) is called at t = 0 and after every step.
template <class Stepper, class Vector, class Observer>
RunReport Integrate(Stepper& stepper, Vector& y, double h, long steps,
                    Observer&& observer) {
  CheckRunArguments(h, steps);
  RunReport report;
  const long evaluations0 = stepper.evaluations();
  const double bound =
      kBlowUpFactor * (y.template lpNorm<Eigen::Infinity>() + 1);
  observer(0.0, static_cast<const Vector&>(y));
  for (long n = 0; n < steps; ++n) {
    const StepReport r = stepper.Step(y, h);
    report.iterations += r.iterations;
    report.max_iterations = std::max(report.max_iterations, r.iterations);
    StepOutcome status = r.status;
    if (status == StepOutcome::kOk &&
        !(y.allFinite() && y.template lpNorm<Eigen::Infinity>() <= bound))
      status = StepOutcome::kUnstable;
    if (status != StepOutcome::kOk) {
      report.status = status;
      report.failed_at = (n + 1) * h;
      break;
    }
    report.steps = n + 1;
    observer((n + 1) * h, static_cast<const Vector&>(y));
  }
  report.evaluations = stepper.evaluations() - evaluations0;
  return report;
}

template <class Stepper, class Vector>
RunReport Integrate(Stepper& stepper, Vector& y, double h, long steps) {
  return Integrate(stepper, y, h, steps, [](double, const Vector&) {});
}

}  // namespace vivp::steppers
