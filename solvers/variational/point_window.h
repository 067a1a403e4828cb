// The window of a point-mechanics march (march.h) as the generic window
// solver sees it (window_solve.h: the predictor, the window's solve, what
// the checks and the step control ask): reduced Newton on a kept engine per
// window length (window_engine.h), or a solve of its own by full Newton or
// Ceres Levenberg–Marquardt (a window is small enough for LM's normal
// equations, docs/method.md §8). The field counterpart is
// solvers/spacetime/field_window.h.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "solvers/variational/ceres_lm.h"
#include "solvers/variational/march_types.h"
#include "solvers/variational/predictor.h"
#include "solvers/variational/window_checks.h"
#include "solvers/variational/window_engine.h"

namespace vivp::variational::detail {

template <class P>
class PointWindow {
 public:
  static constexpr int d = P::kDim;
  using State = std::array<double, d>;

  PointWindow(const P& problem, const std::string& op, double sigma0,
              const MarchOptions& options, int order)
      : problem_(problem),
        op_(op),
        sigma0_(sigma0),
        options_(options),
        order_(order),
        // The shortcut of a constant mass only where the window engine
        // solves, whose assembly checks the declaration (options_ is set).
        predictor_(problem, order, EngineApplies()) {}

  int dim() const { return d; }
  int order() const { return order_; }
  const std::string& op() const { return op_; }
  // At the state the last window handed off, the ω its engine took there
  // (one pointwise Hessian and eigenproblem per window instead of two).
  double FastestFrequency(const double* x, const double* v) const {
    if (last_engine_)
      if (const double omega = last_engine_->HandedFrequency(x, v);
          omega >= 0.0)
        return omega;
    return variational::FastestFrequency(problem_, x, v);
  }

  // The Lagrangian does not depend on t: the window's start time t0 does
  // not matter.
  PredictorReport Predict(double /*t0*/, const double* x0, const double* v0,
                          const double* tau, int points, double tol_abs,
                          double tol_rel, double* px, double* pv) {
    return predictor_.Run(x0, v0, tau, points, tol_abs, tol_rel, px, pv);
  }
  // The factor on the predictor's tolerance a uniform march carries from
  // window to window (window_solve.h).
  double predictor_factor() const { return predictor_factor_; }
  void set_predictor_factor(double f) { predictor_factor_ = f; }

  // Solves the window of a.points nodes spaced a.dt from `initial`, Newton
  // started at the predictor's path px (node-major); false (with `a`
  // failed) if it did not converge. The window's start time does not
  // matter: the Lagrangian does not depend on t.
  bool Solve(WindowAttempt& a, double /*t0*/, const InitialData& initial,
             const std::vector<double>& px, const std::vector<double>& pv,
             bool fresh, bool nodes) {
    last_engine_ = nullptr;
    State x0{}, v0{};
    for (int c = 0; c < d; ++c) {
      x0[c] = initial.x[c];
      v0[c] = order_ == 2 ? initial.v[c] : 0.0;
    }
    if (EngineApplies())
      return SolveWithEngine(a, x0, v0, px, pv, fresh, nodes);
    return SolveOwn(a, initial, px, pv, nodes);
  }

  // A window that was solved but failed a check: the residual of the
  // solution it rejected, where the engine kept it.
  void RecordResidual(WindowAttempt& a) const {
    if (last_engine_) a.residual = last_engine_->LastResidual();
  }

  // Whether a window starts from an earlier window's factorization (the
  // reduced Newton engine), so that solving it again afresh can help.
  bool ReusesFactorizations() const { return EngineApplies(); }

  // Windows of one length solved in alternation at two steps (a spectral
  // element and its halves, element_halves.h) each keep an engine, and so
  // their operators and factorization: slot 0 or 1.
  void set_engine_slot(int slot) { slot_ = slot; }

  long long factorizations() const {
    long long n = 0;
    for (const auto& e : engines_) n += e->factorizations();
    return n;
  }

 private:
  // Jacobian factorizations a window's Newton may take under error control.
  static constexpr int kControlledIterations = 8;

  bool EngineApplies() const {
    return options_.solve.path == Path::kReducedNewton &&
           !options_.solve.extended_residual;
  }

  static void Failed(WindowAttempt& a, WindowFailure f, std::string why) {
    a.failure = f;
    a.why = std::move(why);
  }

  // Reduced Newton on the engine of this window length (window_engine.h).
  bool SolveWithEngine(WindowAttempt& a, const State& x0, const State& v0,
                       const std::vector<double>& px,
                       const std::vector<double>& pv, bool fresh, bool nodes) {
    const int n = a.points;
    const PhaseClock clock{options_.phase_timings};
    const auto setting = clock.Now();
    WindowEngine<P>& e = Engine(n, a.dt);
    a.phases.setup += clock.Since(setting);
    last_engine_ = &e;
    variational::NewtonOptions newton = options_.solve.newton;
    newton.phase_timings = options_.phase_timings;
    newton.final_residual = false;
    // Under error control a window that does not converge is solved again
    // at a smaller step, where the predictor's start lies within Newton's
    // basin: no use iterating long. Kepler e = 0.9, lgl8, lgl12 and lgl16 at
    // 10⁻⁴ … 10⁻¹²: of 1405 whole elements that converged from the predictor
    // 1387 took one to three factorizations and 17 four to seven; one took 28
    // (its halves failed). 82 took all 50 without converging (an element too
    // long for the pericentre: first correction as large as the solution,
    // then wandering), each at the price of some 50 element solves. Capped
    // at 8, the same marches (same nodes and end errors) took 14–51 % fewer
    // instructions for lgl8 at 10⁻⁶ … 10⁻⁹ (none from 10⁻¹⁰ on), 27–58 % for
    // lgl12 and lgl16 (docs/error_control.md).
    if (options_.tolerance.enabled())
      newton.max_iterations =
          std::min(newton.max_iterations, kControlledIterations);
    // A march hands each window's round-off to the next, and an
    // oscillation amplifies it: with the global solve's stop at 32 ε an
    // SBP84 march of the anharmonic oscillator (4096 steps to t = 10) ended
    // 1.3e-11 off in the velocity, at 4 ε 1.7e-13, for 10 % more
    // corrections. Round-off that stops the corrections short of 4 ε is
    // recognised as stagnation (newton.h). So under error control too: a
    // stop at a hundredth of the tolerance, as implicit Runge–Kutta codes
    // take, saved up to a third of the corrections and 2–8 % of the
    // instructions (lgl8) and left the end error 2.6–60 times larger
    // (docs/error_control.md, "Newton's stop").
    if (newton.step_tolerance == 0)
      newton.step_tolerance = 4 * std::numeric_limits<double>::epsilon();
    const State lambda3 = Lambda3Start(n, px, pv);
    const auto& o = e.Solve(outcome_, x0, v0, px.data(), lambda3.data(), newton,
                            fresh, nodes);
    a.iterations = o.report.iterations;
    a.corrections = o.report.corrections;
    a.phases.residual += o.report.phases.residual;
    a.phases.assembly += o.report.phases.assembly;
    a.phases.factorization += o.report.phases.factorization;
    a.phases.solve += o.report.phases.solve;
    a.phases.end += o.seconds_end;
    if (!o.failure.empty()) {
      a.residual = o.report.last_residual;
      Failed(a,
             o.split_helps ? WindowFailure::kNewton
                           : WindowFailure::kUnderResolved,
             o.failure);
      return false;
    }
    a.end = o.end;
    for (int c = 0; c < d; ++c) {
      a.x_end[c] = o.x_end[c];
      a.v_end[c] = o.v_end[c];
      a.est_x[c] = o.est_x[c];
      a.est_v[c] = o.est_v[c];
      a.roundoff_v[c] = o.roundoff_v[c];
    }
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < d; ++c)
        a.deviation =
            std::max(a.deviation, std::abs(e.x(i, c) - px[i * d + c]));
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
  bool SolveOwn(WindowAttempt& a, const InitialData& initial,
                const std::vector<double>& px, const std::vector<double>& pv,
                bool nodes) {
    const int n = a.points;
    SolveOptions so = options_.solve;
    so.guess = px;
    const Grid g{.op = op_,
                 .points = n,
                 .t_start = 0.0,
                 .t_end = a.dt * double(n - 1),
                 .sigma0 = sigma0_};
    IvpSolution<double> s;
    if (so.path == Path::kCeresLm) {
      CeresOptions lm;
      const State lambda3 = Lambda3Start(n, px, pv);
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
            std::max(a.deviation, std::abs(s.x1(i, c) - px[i * d + c]));
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

  State Lambda3Start(int n, const std::vector<double>& px,
                     const std::vector<double>& pv) const {
    State l{};
    if (order_ != 2) return l;
    const auto p = predictor_.Momentum(&px[(n - 1) * d], &pv[(n - 1) * d]);
    for (int c = 0; c < d; ++c) l[c] = -p[c];
    return l;
  }

  WindowEngine<P>& Engine(int points, double dt) {
    for (std::size_t k = 0; k < engines_.size(); ++k)
      if (engines_[k]->points() == points && slots_[k] == slot_) {
        engines_[k]->SetStep(dt);
        return *engines_[k];
      }
    engines_.push_back(std::make_unique<WindowEngine<P>>(problem_, op_, sigma0_,
                                                         points, dt, order_));
    slots_.push_back(slot_);
    return *engines_.back();
  }

  const P& problem_;
  std::string op_;
  double sigma0_;
  const MarchOptions& options_;
  int order_;
  Predictor<P> predictor_;
  double predictor_factor_ = 1.0;
  std::vector<std::unique_ptr<WindowEngine<P>>> engines_;
  std::vector<int> slots_;  // the slot each engine serves (set_engine_slot)
  int slot_ = 0;
  const WindowEngine<P>* last_engine_ = nullptr;  // of the last solve
  // Every window's engine outcome, its arrays' storage kept.
  typename WindowEngine<P>::Outcome outcome_;
};

}  // namespace vivp::variational::detail
