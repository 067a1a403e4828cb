// One window of a time-slab march (march.h), solved and checked: the
// predictor's path is the Newton start, and the converged window is accepted
// only if an independent integration agrees with it.
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
//     0.02–19, and the corrected x_N is not more accurate than x_N), so SBP21
//     bounds the position by the velocity estimate, e_x = L·e_v over the
//     window's length L (the velocity estimate is reliable: ratio 0.9–1.1);
//  3. resolution (uniform grids only, where no tolerance bounds the
//     estimates): the window's nodes and hand-off may deviate from the
//     predictor by at most 1 % of the solution's size (a measurement, not an
//     estimate: the predictor is accurate to 1e-6 there, which also makes it
//     valid for SBP21). Kepler e = 0.9 on a uniform grid of 4001 points for
//     10 orbits passes 1 and 2 at pericentre (its estimates are honest) with
//     local errors of 4–23 % — an answer with error 5.7.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "solvers/variational/march_types.h"
#include "solvers/variational/predictor.h"
#include "solvers/variational/window_engine.h"

namespace vivp::detail {

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
// hand-off state, the estimates and the outcome of the checks.
template <int d>
struct WindowAttempt {
  using State = std::array<double, d>;
  WindowFailure failure = WindowFailure::kNone;
  std::string why;  // empty on success
  double residual = std::numeric_limits<double>::quiet_NaN();
  int points = 0;
  double dt = 0;
  int iterations = 0, corrections = 0;
  State x_end{}, v_end{};    // x_N, (Dx)_N
  State est_x{}, est_v{};    // embedded estimates of their errors
  State roundoff_v{};        // the round-off level of (Dx)_N (window_engine.h)
  CorrectedEnd<double> end;  // hand-off
  std::vector<double> x, v;  // nodes (node-major, points·d), if kept
  double distance = 0;       // worst |H − P| / allowed of check 2
  double deviation = 0;      // max over nodes of |x_i − P(t_i)|
  long predictor_steps = 0;
  bool ok() const { return failure == WindowFailure::kNone; }
  bool split_helps() const {
    return failure == WindowFailure::kNewton ||
           failure == WindowFailure::kCheck ||
           failure == WindowFailure::kPredictor;
  }
  double X(int i, int c) const { return x[i * d + c]; }
  double V(int i, int c) const { return v[i * d + c]; }
};

template <class P>
class WindowSolver {
 public:
  static constexpr int d = P::kDim;
  using State = std::array<double, d>;
  using Attempt = WindowAttempt<d>;

  WindowSolver(const P& problem, const std::string& op, double sigma0,
               const MarchOptions& options, int order)
      : problem_(problem),
        op_(op),
        sigma0_(sigma0),
        options_(options),
        order_(order),
        predictor_(problem, order) {}

  // Solves `points` nodes spaced `dt` from `initial`. `fresh`: no chord steps
  // on an earlier factorization; `nodes`: keep positions and velocities.
  // `predictor_tol` (absolute, relative) sets the predictor's accuracy;
  // `uniform` adds check 3.
  Attempt Solve(const InitialData& initial, int points, double dt, bool fresh,
                bool nodes, Tolerance predictor_tol, bool uniform) {
    Attempt a;
    a.points = points;
    a.dt = dt;
    State x0{}, v0{};
    for (int c = 0; c < d; ++c) {
      x0[c] = initial.x[c];
      v0[c] = order_ == 2 ? initial.v[c] : 0.0;
    }
    tau_.resize(points);
    for (int i = 0; i < points; ++i) tau_[i] = dt * double(i);
    px_.resize(std::size_t(points) * d);
    pv_.resize(std::size_t(points) * d);
    // On a uniform grid check 3 compares with the predictor to 1 % of the
    // solution: its own error bound must be half of that, which a window
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
        size = std::max(
            {size, std::abs(x0[c]), std::abs(v0[c]) * dt * double(points - 1)});
      predictor_tol.absolute = std::max(predictor_tol.absolute * size, 1e-300);
    }
    PredictorReport pr;
    for (int tries = 0;; ++tries) {
      pr = predictor_.Run(x0.data(), v0.data(), tau_.data(), points,
                          predictor_tol.absolute, predictor_tol.relative,
                          px_.data(), pv_.data());
      a.predictor_steps += pr.steps;
      if (!pr.ok || !uniform || tries == 3) break;
      double scale = 0;
      for (double v : px_) scale = std::max(scale, std::abs(v));
      if (pr.error_x <= 0.5 * options_.max_relative_deviation * scale) break;
      predictor_tol.absolute *= 1e-2;
      predictor_tol.relative *= 1e-2;
    }
    if (!pr.ok) return Failed(a, WindowFailure::kPredictor, pr.failure);
    const double* pend_x = &px_[(points - 1) * d];
    const double* pend_v = &pv_[(points - 1) * d];
    if (!SolveNewton(a, initial, x0, v0, fresh, nodes)) return a;
    std::string why = Finite(a);
    WindowFailure failure = WindowFailure::kNewton;
    if (why.empty()) {
      why = Consistent(a, pr, pend_x, pend_v);
      failure = WindowFailure::kCheck;
    }
    if (why.empty() && uniform) {
      why = Resolved(a, pr, pend_x);
      failure = WindowFailure::kCoarse;
    }
    if (why.empty()) return a;
    if (last_engine_) a.residual = last_engine_->LastResidual();
    return Failed(a, failure, why);
  }

  long long factorizations() const {
    long long n = 0;
    for (const auto& e : engines_) n += e->factorizations();
    return n;
  }

 private:
  bool EngineApplies() const {
    return options_.solve.path == Path::kReducedNewton &&
           !options_.solve.extended_residual;
  }

  // Newton from the predictor's path; false (with `a` failed) if it did not
  // converge.
  bool SolveNewton(Attempt& a, const InitialData& initial, const State& x0,
                   const State& v0, bool fresh, bool nodes) {
    const int n = a.points;
    last_engine_ = nullptr;
    if (EngineApplies()) {
      WindowEngine<P>& e = Engine(n, a.dt);
      last_engine_ = &e;
      solvers::NewtonOptions newton = options_.solve.newton;
      newton.phase_timings = false;
      newton.final_residual = false;
      // A march hands each window's round-off to the next, and an
      // oscillation amplifies it: with the global solve's stop at 32 ε an
      // SBP84 march of the anharmonic oscillator (4096 steps to t = 10) ended
      // 1.3e-11 off in the velocity, at 4 ε 1.7e-13, for 10 % more
      // corrections. Round-off that stops the corrections short of 4 ε is
      // recognised as stagnation (newton.h).
      if (newton.step_tolerance == 0)
        newton.step_tolerance = 4 * std::numeric_limits<double>::epsilon();
      const State lambda3 = Lambda3Start(n);
      const auto o =
          e.Solve(x0, v0, px_.data(), lambda3.data(), newton, fresh, nodes);
      a.iterations = o.report.iterations;
      a.corrections = o.report.corrections;
      if (!o.failure.empty()) {
        a.residual = o.report.residual_norm;
        Failed(a,
               o.split_helps ? WindowFailure::kNewton
                             : WindowFailure::kUnderResolved,
               o.failure);
        return false;
      }
      a.end = o.end;
      a.x_end = o.x_end;
      a.v_end = o.v_end;
      a.est_x = o.est_x;
      a.est_v = o.est_v;
      a.roundoff_v = o.roundoff_v;
      for (int i = 0; i < n; ++i)
        for (int c = 0; c < d; ++c)
          a.deviation =
              std::max(a.deviation, std::abs(e.x(i, c) - px_[i * d + c]));
      if (nodes) {
        a.x.resize(std::size_t(n) * d);
        a.v.resize(std::size_t(n) * d);
        for (int i = 0; i < n; ++i)
          for (int c = 0; c < d; ++c) {
            a.x[i * d + c] = e.x(i, c);
            a.v[i * d + c] = e.v(i, c);
          }
      }
      return true;
    }
    // Full Newton, or the reduced one with an extended-precision residual:
    // a solve of its own from the same start.
    SolveOptions so = options_.solve;
    so.guess = px_;
    const Grid g{.op = op_,
                 .points = n,
                 .t_start = 0.0,
                 .t_end = a.dt * double(n - 1),
                 .sigma0 = sigma0_};
    const IvpSolution<double> s = SolveIvp(problem_, initial, g, so);
    a.residual = s.residual_norm;
    a.iterations = s.iterations;
    a.corrections = s.iterations;
    if (!s.status.converged) {
      a.residual = s.residual_norm;
      Failed(a,
             s.status.reason.rfind("under-resolved", 0) == 0
                 ? WindowFailure::kUnderResolved
                 : WindowFailure::kNewton,
             s.status.reason);
      return false;
    }
    a.end = s.corrected;
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < d; ++c)
        a.deviation =
            std::max(a.deviation, std::abs(s.x1(i, c) - px_[i * d + c]));
    for (int c = 0; c < d; ++c) {
      a.x_end[c] = s.x1(n - 1, c);
      a.v_end[c] = s.velocity(n - 1, c);
      a.est_x[c] = std::abs(a.end.position[c] - a.x_end[c]);
      a.est_v[c] = order_ == 2 ? std::abs(a.v_end[c] - a.end.velocity[c]) : 0.0;
    }
    if (nodes) {
      a.x.resize(std::size_t(n) * d);
      a.v.resize(std::size_t(n) * d);
      for (int i = 0; i < n; ++i)
        for (int c = 0; c < d; ++c) {
          a.x[i * d + c] = s.x1(i, c);
          a.v[i * d + c] = s.velocity(i, c);
        }
    }
    return true;
  }

  State Lambda3Start(int n) const {
    State l{};
    if (order_ != 2) return l;
    const auto p = predictor_.Momentum(&px_[(n - 1) * d], &pv_[(n - 1) * d]);
    for (int c = 0; c < d; ++c) l[c] = -p[c];
    return l;
  }

  WindowEngine<P>& Engine(int points, double dt) {
    for (auto& e : engines_)
      if (e->points() == points) {
        e->SetStep(dt);
        return *e;
      }
    engines_.push_back(std::make_unique<WindowEngine<P>>(problem_, op_, sigma0_,
                                                         points, dt, order_));
    return *engines_.back();
  }

  static Attempt& Failed(Attempt& a, WindowFailure f, std::string why) {
    a.failure = f;
    a.why = std::move(why);
    return a;
  }

  std::string Finite(const Attempt& a) const {
    bool ok = true;
    for (double v : a.x) ok = ok && std::isfinite(v);
    for (double v : a.v) ok = ok && std::isfinite(v);
    for (int c = 0; c < d; ++c) {
      ok = ok && std::isfinite(a.end.position[c]) && std::isfinite(a.x_end[c]);
      if (order_ == 2)
        ok =
            ok && std::isfinite(a.end.velocity[c]) && std::isfinite(a.v_end[c]);
    }
    return ok ? "" : "the converged window holds non-finite values";
  }

  // Check 2 (see the top of this file).
  std::string Consistent(Attempt& a, const PredictorReport& pr,
                         const double* pend_x, const double* pend_v) const {
    constexpr double kKappa = 2.0;
    const double length = a.dt * double(a.points - 1);
    double sx = 0, sv = 0;
    for (int c = 0; c < d; ++c) {
      sx = std::max({sx, std::abs(pend_x[c]), std::abs(a.end.position[c])});
      if (order_ == 2)
        sv = std::max({sv, std::abs(pend_v[c]), std::abs(a.end.velocity[c])});
    }
    // Round-off of a window's solution grows with its points (the reduced
    // system's condition number grows like N³; refinement keeps it near
    // N·eps, measured with SBP84 at Δt = 0.001 on Kepler e = 0.9).
    const double roundoff = 64.0 * a.points * kEps;
    double worst = 0;
    std::ostringstream why;
    for (int c = 0; c < d; ++c) {
      const double est = op_ == "sbp21" && order_ == 2
                             ? std::max(a.est_x[c], length * a.est_v[c])
                             : a.est_x[c];
      const double dx = std::abs(a.end.position[c] - pend_x[c]);
      const double bx = kKappa * (est + pr.error_x) + roundoff * (sx + 1e-300);
      worst = std::max(worst, dx / bx);
      if (!(dx <= bx) && why.str().empty())
        why << "position " << c << " differs by " << dx;
      if (order_ == 2) {
        const double dv = std::abs(a.end.velocity[c] - pend_v[c]);
        const double bv =
            kKappa * (a.est_v[c] + pr.error_v) + roundoff * (sv + 1e-300);
        worst = std::max(worst, dv / bv);
        if (!(dv <= bv) && why.str().empty())
          why << "velocity " << c << " differs by " << dv;
      }
    }
    a.distance = worst;
    if (why.str().empty()) return "";
    std::ostringstream s;
    s << "a-posteriori check failed: the window's end state and an "
         "independent integration of the Euler-Lagrange equations disagree ("
      << why.str() << ", " << Short(worst)
      << " times what their error estimates allow): another branch of the "
         "discrete equations, or a grid too coarse for its error estimate";
    return s.str();
  }

  // Check 3: the window's measured local error against the solution's size.
  std::string Resolved(const Attempt& a, const PredictorReport& pr,
                       const double* pend_x) const {
    const double rho = options_.max_relative_deviation;
    double scale = 0, dev = a.deviation;
    for (double v : px_) scale = std::max(scale, std::abs(v));
    for (int c = 0; c < d; ++c)
      dev = std::max(dev, std::abs(a.end.position[c] - pend_x[c]));
    if (dev <= rho * scale + pr.error_x) return "";
    std::ostringstream s;
    s << "under-resolved: the window's nodes deviate from an independent "
         "integration of the Euler-Lagrange equations by "
      << Short(dev) << ", " << Short(100 * dev / scale)
      << " % of the solution's size (at most " << Short(100 * rho)
      << " %); the uniform grid is too coarse here: use more points, or a "
         "tolerance so that the grid adapts";
    return s.str();
  }

  static std::string Short(double v) {
    std::ostringstream s;
    s.precision(3);
    s << v;
    return s.str();
  }

  static constexpr double kEps = std::numeric_limits<double>::epsilon();

  const P& problem_;
  std::string op_;
  double sigma0_;
  const MarchOptions& options_;
  int order_;
  Predictor<P> predictor_;
  std::vector<std::unique_ptr<WindowEngine<P>>> engines_;
  const WindowEngine<P>* last_engine_ = nullptr;  // of the last solve
  std::vector<double> tau_, px_, pv_;
};

}  // namespace vivp::detail
