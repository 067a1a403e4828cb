// Convergence studies of the variational solver: errors at t_end against an
// exact solution for a list of grid sizes, and fitted orders.
//
// Orders are fitted twice: against Δt = 1/Nt (the convention of Rothkopf &
// Nordström 2023, which reproduces their numbers) and against the true grid
// spacing (t_end − t_start)/(Nt − 1) (docs/method.md §10).
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/linalg/fit.h"
#include "solvers/variational/ivp_types.h"

namespace vivp::studies {

struct ConvergenceRow {
  long long points = 0;
  double dt = 0;       // (t_end − t_start)/Nt, the paper's convention
  double dt_true = 0;  // (t_end − t_start)/(Nt − 1)
  double err_x = 0;    // |x_N − x(T)|∞
  double err_v = 0;  // |(Dx)_N − ẋ(T)|∞ (first order: |(Dx)_N − ẋ(T)| too)
  double err_x_corrected = 0;  // |x_N + M⁻¹λ4 − x(T)|∞
  double err_p_corrected = 0;  // |p_N − p(T)|∞, p_N = −λ3 moved to the
                               // corrected position (docs/method.md §7;
                               // NaN for first order;
                               // marching: error of the handed-off velocity)
  double error_estimate = 0;   // |M⁻¹λ4|∞, the built-in estimate of err_x
  int iterations = 0;
  int fallbacks = 0;  // marching: windows solved again (split, refactored)
  // Error control (RunToleranceStudy): the tolerance (absolute = relative),
  // the largest position error over every returned node, the windows and
  // how many were rejected. NaN / 0 otherwise.
  double tolerance = std::numeric_limits<double>::quiet_NaN();
  double max_error = std::numeric_limits<double>::quiet_NaN();
  double max_error_v = std::numeric_limits<double>::quiet_NaN();  // velocity
  long long windows = 0;
  int rejected = 0;
  double seconds = 0;
  bool converged = false;
  std::string reason;
};

struct ConvergenceOrders {
  double x = 0, v = 0, x_corrected = 0, p_corrected = 0;
};

// How the achieved error of a tolerance study follows the tolerance: the
// fitted slope of log(error) against log(tolerance) (1: proportional) and
// the range of error / tolerance, over the converged rows.
struct ToleranceTracking {
  double slope = std::numeric_limits<double>::quiet_NaN();
  double min_ratio = std::numeric_limits<double>::quiet_NaN();
  double max_ratio = std::numeric_limits<double>::quiet_NaN();
};

struct ConvergenceStudy {
  std::vector<ConvergenceRow> rows;
  ConvergenceOrders orders;          // against 1/Nt
  ConvergenceOrders orders_true_dt;  // against 1/(Nt − 1)
  ToleranceTracking tracking;        // RunToleranceStudy: end error
  ToleranceTracking tracking_max;    // RunToleranceStudy: max node error
  ToleranceTracking tracking_max_v;  // … of the node velocities
};

// Fits the orders of the converged rows (a solve that did not converge has
// no discretization error to speak of); errors at or below `floor` are
// round-off and left out of the fit. Fewer than two usable rows give NaN.
inline void FitOrders(ConvergenceStudy& study, double floor) {
  std::vector<double> h, ht, ex, ev, exc, epc;
  for (const auto& r : study.rows) {
    if (!r.converged) continue;
    h.push_back(r.dt);
    ht.push_back(r.dt_true);
    ex.push_back(r.err_x);
    ev.push_back(r.err_v);
    exc.push_back(r.err_x_corrected);
    epc.push_back(r.err_p_corrected);
  }
  auto fit = [&](const std::vector<double>& step, ConvergenceOrders& o) {
    o.x = linalg::FitPowerLaw(step, ex, floor).order;
    o.v = linalg::FitPowerLaw(step, ev, floor).order;
    o.x_corrected = linalg::FitPowerLaw(step, exc, floor).order;
    o.p_corrected = linalg::FitPowerLaw(step, epc, floor).order;
  };
  fit(h, study.orders);
  fit(ht, study.orders_true_dt);
}

// The tracking of a tolerance study (rows with a tolerance), over the
// converged rows; errors at or below `floor` are round-off and left out.
inline void FitTracking(ConvergenceStudy& study, double floor) {
  auto track = [&](auto error_of) {
    ToleranceTracking t;
    std::vector<double> tol, err;
    for (const auto& r : study.rows) {
      const double e = error_of(r);
      if (!r.converged || !(e > floor)) continue;
      tol.push_back(r.tolerance);
      err.push_back(e);
      const double ratio = e / r.tolerance;
      t.min_ratio =
          std::isnan(t.min_ratio) ? ratio : std::min(t.min_ratio, ratio);
      t.max_ratio =
          std::isnan(t.max_ratio) ? ratio : std::max(t.max_ratio, ratio);
    }
    t.slope = linalg::FitPowerLaw(tol, err, floor).order;
    return t;
  };
  study.tracking =
      track([](const ConvergenceRow& r) { return r.err_x_corrected; });
  study.tracking_max =
      track([](const ConvergenceRow& r) { return r.max_error; });
  study.tracking_max_v =
      track([](const ConvergenceRow& r) { return r.max_error_v; });
}

}  // namespace vivp::studies
