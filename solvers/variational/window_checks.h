// The a-posteriori checks of a converged window (window_solve.h), and what a
// solved window carries until it is accepted (march_core.h).
//
// The checks, in order (each failure names itself in `failure`):
//  1. finite: no NaN or infinity leaves a window, in any node or in the
//     hand-off state;
//  2. consistency: the hand-off state H = (x_N + M⁻¹λ4, M⁻¹(−λ3)) and the
//     predictor's end state P, both estimates of the exact local flow, must
//     agree within what their error estimates allow,
//        |H_x − P_x| ≤ κ(e_x + ε_x) + s,   |H_v − P_v| ≤ κ(e_v + ε_v) + s,
//     with e the window's embedded estimates of the *lower*-order values x_N,
//     (Dx)_N (H is more accurate than they are), ε the predictor's error
//     bound, κ = 2 and s a round-off allowance. Measured on resolved windows
//     (SBP42–84, four problems, Δt over a factor 32): |H_x − exact| ≤ 0.53 e_x
//     and |H_v − exact| ≤ 0.26 e_v. A window on another branch of the
//     discrete equations is off by the size of the solution.
//     SBP21's position estimate is not one (ratio to the true error of x_N
//     0.02–19, and the corrected x_N is not more accurate than x_N), so an
//     operator without one (core/sbp, Measured::position_estimate) bounds
//     the position by the velocity estimate, e_x = L·e_v over the window's
//     length L (the velocity estimate is reliable: ratio 0.9–1.1);
//  3. resolution (uniform grids only, where no tolerance bounds the
//     estimates): the window's nodes and hand-off may deviate from the
//     predictor by at most 1 % of the solution's size (a measurement, not an
//     estimate, so valid for SBP21 too: the predictor tightens its tolerance
//     until its own error bound is within that). Kepler e = 0.9 on a
//     uniform grid of 4001 points for 10 orbits passes 1 and 2 at pericentre
//     (its estimates are honest) with local errors of 4–23 % — an answer
//     with error 5.7.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "solvers/variational/ivp_types.h"
#include "solvers/variational/march_types.h"
#include "solvers/variational/predictor.h"

namespace vivp::variational::detail {

// kUnderResolved: Δt·ω above the stability limit (a finer grid helps);
// kCoarse: check 3 (a uniform grid that does not resolve the solution).
enum class WindowFailure {
  kNone,
  kNewton,
  kUnderResolved,
  kCheck,
  kPredictor,
  kCoarse
};

// A solved window before it is accepted: nodes on its solve grid, the
// hand-off state, the estimates and the outcome of the checks, for a system
// of n components (a point-mechanics problem's d coordinates, or a field's
// Nx·m values of a time slice).
struct WindowAttempt {
  using State = std::vector<double>;
  explicit WindowAttempt(int components = 0)
      : n(components),
        x_end(components),
        v_end(components),
        est_x(components),
        est_v(components),
        roundoff_v(components) {}
  int n;
  WindowFailure failure = WindowFailure::kNone;
  std::string why;  // empty on success
  double residual = std::numeric_limits<double>::quiet_NaN();
  int points = 0;
  double dt = 0;
  // The larger fastest frequency of the window's ends, when it was fitted
  // to one (window_solve.h, theta_cap); 0 otherwise.
  double omega = 0;
  int iterations = 0, corrections = 0;
  State x_end, v_end;        // x_N, (Dx)_N
  State est_x, est_v;        // embedded estimates of their errors
  State roundoff_v;          // the round-off level of (Dx)_N (window_engine.h)
  CorrectedEnd<double> end;  // hand-off
  std::vector<double> x, v;  // nodes (node-major, points·n), if kept
  // Components that are data, not unknowns (a field's Dirichlet points):
  // checks 2 and 3 skip them. Empty: none.
  std::vector<char> data;
  bool IsData(int c) const { return !data.empty() && data[c]; }
  double distance = 0;   // worst |H − P| / allowed of check 2
  double deviation = 0;  // max over nodes of |x_i − P(t_i)|
  long predictor_steps = 0;
  MarchPhases phases;  // this attempt's (MarchOptions::phase_timings)
  bool ok() const { return failure == WindowFailure::kNone; }
  bool split_helps() const {
    return failure == WindowFailure::kNewton ||
           failure == WindowFailure::kCheck ||
           failure == WindowFailure::kPredictor;
  }
  double X(int i, int c) const { return x[std::size_t(i) * n + c]; }
  double V(int i, int c) const { return v[std::size_t(i) * n + c]; }

  // As WindowAttempt(components), keeping the arrays' storage: a march
  // solves every window into the same attempt (a fresh one allocated a
  // dozen arrays per window).
  void Reset(int components) {
    n = components;
    failure = WindowFailure::kNone;
    why.clear();
    residual = std::numeric_limits<double>::quiet_NaN();
    points = 0;
    dt = omega = 0;
    iterations = corrections = 0;
    for (State* s : {&x_end, &v_end, &est_x, &est_v, &roundoff_v})
      s->assign(std::size_t(components), 0.0);
    end.Clear();
    x.clear();
    v.clear();
    data.clear();
    distance = deviation = 0;
    predictor_steps = 0;
    phases = MarchPhases{};
  }
};

// Three significant digits, for messages.
inline std::string ShortNumber(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

inline std::string CheckFinite(const WindowAttempt& a, int order) {
  const int d = a.n;
  bool ok = true;
  for (double v : a.x) ok = ok && std::isfinite(v);
  for (double v : a.v) ok = ok && std::isfinite(v);
  for (int c = 0; c < d; ++c) {
    ok = ok && std::isfinite(a.end.position[c]) && std::isfinite(a.x_end[c]);
    if (order == 2)
      ok = ok && std::isfinite(a.end.velocity[c]) && std::isfinite(a.v_end[c]);
  }
  return ok ? "" : "the converged window holds non-finite values";
}

// Check 2: the hand-off against the predictor's end state; records the worst
// ratio of distance to allowance in a.distance.
inline std::string CheckConsistent(WindowAttempt& a, const PredictorReport& pr,
                                   const double* pend_x, const double* pend_v,
                                   int order, bool position_estimate) {
  constexpr double kKappa = 2.0;
  const int d = a.n;
  const double length = a.dt * double(a.points - 1);
  double sx = 0, sv = 0;
  for (int c = 0; c < d; ++c) {
    sx = std::max({sx, std::abs(pend_x[c]), std::abs(a.end.position[c])});
    if (order == 2)
      sv = std::max({sv, std::abs(pend_v[c]), std::abs(a.end.velocity[c])});
  }
  // Round-off of a window's solution grows with its points (the reduced
  // system's condition number grows like N³; refinement keeps it near
  // N·eps, measured with SBP84 at Δt = 0.001 on Kepler e = 0.9).
  const double roundoff =
      64.0 * a.points * std::numeric_limits<double>::epsilon();
  double worst = 0;
  // The first component out of bounds, which the message names; written
  // only then (a stream per window was 1.3 % of an lgl8 march).
  std::string why;
  const auto note = [&why](const char* what, int c, double by) {
    if (!why.empty()) return;
    std::ostringstream s;
    s << what << ' ' << c << " differs by " << by;
    why = s.str();
  };
  for (int c = 0; c < d; ++c) {
    if (a.IsData(c)) continue;
    const double est = !position_estimate && order == 2
                           ? std::max(a.est_x[c], length * a.est_v[c])
                           : a.est_x[c];
    const double dx = std::abs(a.end.position[c] - pend_x[c]);
    const double bx = kKappa * (est + pr.error_x) + roundoff * (sx + 1e-300);
    worst = std::max(worst, dx / bx);
    if (!(dx <= bx)) note("position", c, dx);
    if (order == 2) {
      const double dv = std::abs(a.end.velocity[c] - pend_v[c]);
      const double bv =
          kKappa * (a.est_v[c] + pr.error_v) + roundoff * (sv + 1e-300);
      worst = std::max(worst, dv / bv);
      if (!(dv <= bv)) note("velocity", c, dv);
    }
  }
  a.distance = worst;
  if (why.empty()) return "";
  std::ostringstream s;
  s << "a-posteriori check failed: the window's end state and an "
       "independent integration of the Euler-Lagrange equations disagree ("
    << why << ", " << ShortNumber(worst)
    << " times what their error estimates allow): another branch of the "
       "discrete equations, or a grid too coarse for its error estimate";
  return s.str();
}

// Check 3: the window's measured local error against the solution's size
// (px: the predictor's positions at the nodes).
inline std::string CheckResolved(const WindowAttempt& a,
                                 const PredictorReport& pr,
                                 const double* pend_x,
                                 const std::vector<double>& px, double rho) {
  const int d = a.n;
  double scale = 0, dev = a.deviation;
  for (double v : px) scale = std::max(scale, std::abs(v));
  for (int c = 0; c < d; ++c)
    if (!a.IsData(c))
      dev = std::max(dev, std::abs(a.end.position[c] - pend_x[c]));
  if (dev <= rho * scale + pr.error_x) return "";
  std::ostringstream s;
  s << "under-resolved: the window's nodes deviate from an independent "
       "integration of the Euler-Lagrange equations by "
    << ShortNumber(dev) << ", " << ShortNumber(100 * dev / scale)
    << " % of the solution's size (at most " << ShortNumber(100 * rho)
    << " %); the uniform grid is too coarse here: use more points, or a "
       "tolerance so that the grid adapts";
  return s.str();
}

}  // namespace vivp::variational::detail
