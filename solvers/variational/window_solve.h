// One window of a time-slab march (march.h), solved and checked: the
// predictor's path is the start of the window's solver (reduced Newton on a
// kept engine, full Newton, or Ceres LM: a window is small enough for LM's
// normal equations, docs/method.md §8), and the converged window is accepted
// only if an independent integration agrees with it.
//
// The checks are those of window_checks.h.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "core/sbp/builder.h"
#include "solvers/variational/ceres_lm.h"
#include "solvers/variational/march_types.h"
#include "solvers/variational/predictor.h"
#include "solvers/variational/window_checks.h"
#include "solvers/variational/window_engine.h"

namespace vivp::variational::detail {

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
      if (pr.error_x <= options_.max_relative_deviation * scale) break;
      predictor_tol.absolute *= 1e-2;
      predictor_tol.relative *= 1e-2;
    }
    if (!pr.ok) return Failed(a, WindowFailure::kPredictor, pr.failure);
    const double* pend_x = &px_[(points - 1) * d];
    const double* pend_v = &pv_[(points - 1) * d];
    if (!SolveNewton(a, initial, x0, v0, fresh, nodes)) return a;
    std::string why = CheckFinite(a, order_);
    WindowFailure failure = WindowFailure::kNewton;
    if (why.empty()) {
      why = CheckConsistent(a, pr, pend_x, pend_v, order_,
                            sbp::Table(op_).measured.position_estimate);
      failure = WindowFailure::kCheck;
    }
    if (why.empty() && uniform) {
      why = CheckResolved(a, pr, pend_x, px_, options_.max_relative_deviation);
      failure = WindowFailure::kCoarse;
    }
    if (why.empty()) return a;
    if (last_engine_) a.residual = last_engine_->LastResidual();
    return Failed(a, failure, why);
  }

  // Whether a window starts from an earlier window's factorization (the
  // reduced Newton engine), so that solving it again afresh can help.
  bool ReusesFactorizations() const { return EngineApplies(); }

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

  // The window from the predictor's path, by the path of options.solve;
  // false (with `a` failed) if it did not converge.
  bool SolveNewton(Attempt& a, const InitialData& initial, const State& x0,
                   const State& v0, bool fresh, bool nodes) {
    last_engine_ = nullptr;
    if (EngineApplies()) return SolveWithEngine(a, x0, v0, fresh, nodes);
    return SolveOwn(a, initial, nodes);
  }

  // Reduced Newton on the engine of this window length (window_engine.h).
  bool SolveWithEngine(Attempt& a, const State& x0, const State& v0, bool fresh,
                       bool nodes) {
    const int n = a.points;
    WindowEngine<P>& e = Engine(n, a.dt);
    last_engine_ = &e;
    variational::NewtonOptions newton = options_.solve.newton;
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

  // Full Newton, Ceres LM, or the reduced Newton with an extended-precision
  // residual: a solve of its own from the same start. Ceres LM also starts
  // λ3 at the predictor's −p, as the engine does; full Newton starts the
  // multipliers at 0.
  bool SolveOwn(Attempt& a, const InitialData& initial, bool nodes) {
    const int n = a.points;
    SolveOptions so = options_.solve;
    so.guess = px_;
    const Grid g{.op = op_,
                 .points = n,
                 .t_start = 0.0,
                 .t_end = a.dt * double(n - 1),
                 .sigma0 = sigma0_};
    IvpSolution<double> s;
    if (so.path == Path::kCeresLm) {
      CeresOptions lm;
      const State lambda3 = Lambda3Start(n);
      lm.lambda3.assign(lambda3.begin(), lambda3.end());
      // The predictor's start is within Newton's quadratic convergence, so
      // LM starts undamped (Ceres' largest trust region; a failed step still
      // shrinks it) and stops on a step of 4 ε relative, Newton's stop in a
      // march (above). With the global solve's settings (region 1e4, stop
      // at 1e-16) it spent 34 iterations per window tripling the region
      // until the stiff directions moved, against 8 (anharmonic to T = 10,
      // SBP42, 4097 points, W = 48; docs/method.md §8).
      lm.initial_radius = 1e16;
      lm.parameter_tolerance = 4 * std::numeric_limits<double>::epsilon();
      s = SolveIvpCeres(problem_, initial, g, so, lm);
    } else {
      s = SolveIvp(problem_, initial, g, so);
    }
    a.residual = s.residual_norm;
    a.iterations = s.iterations;
    a.corrections = s.iterations;
    if (!s.status.converged) {
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

}  // namespace vivp::variational::detail
