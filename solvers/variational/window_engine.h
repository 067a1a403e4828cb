// One time-slab window (march.h) solved by Newton on the reduced system, with
// its operators, scratch space and Jacobian factorization kept from window to
// window.
//
// The Lagrangian does not depend on t, so every window of the same length has
// the same discrete equations up to the initial data. A linear problem is
// thus factored once and each window costs back-substitutions and residuals
// (the chord steps of variational::Newton on a kept factorization); a
// nonlinear one starts each window from the previous window's factorization
// and refactors only when the chord steps stop contracting. Under error
// control the step changes from window to window (SetStep): the operators are
// rebuilt, and the last factorization, with the step's scaling undone
// (step_scaled_lu.h), is still the chord start.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "solvers/variational/solve_ivp.h"
#include "solvers/variational/step_scaled_lu.h"

namespace vivp::variational::detail {

template <class P>
class WindowEngine {
 public:
  static constexpr int d = P::kDim;
  using State = std::array<double, d>;

  // A window of `points` nodes spaced `dt`: the grid [0, (points − 1)·dt].
  WindowEngine(const P& problem, const std::string& op, double sigma0,
               int points, double dt, int order)
      : problem_(problem),
        op_(op),
        sigma0_(sigma0),
        requested_dt_(dt),
        dbar_(MakeDbar(op, points, dt, sigma0)),
        system_(problem, dbar_, State{}, State{}, order),
        y_(system_.size(), 0.0),
        lu_(d, system_.Lambda3(0), order == 2) {
    lu_.SetStep(this->dt());
  }

  const sbp::Operator<double>& D() const { return dbar_.base(); }
  int points() const { return dbar_.points(); }
  double dt() const { return dbar_.base().dt(); }
  int order() const { return system_.order(); }

  // The same number of points at another spacing (error control). The
  // Jacobian's blocks scale like Δt and 1/Δt: used as it stands, the
  // factorization of one step is a chord start only within a few per cent
  // of it (a first-order window: 5 %), and from a very different step its
  // chord steps are so short that the stopping rule (a correction at
  // round-off) fires before they converge (measured, unscaled: Kepler
  // e = 0.9 with the factorization of a pericentre window, Δt = 6e-5, reused
  // at apocentre, Δt = 1.2e-2: "converged" with the Newton start's error).
  // A second-order window undoes the scaling (step_scaled_lu.h) and keeps
  // it within a factor kScaledReuse of its step.
  // A step within 64 ε of the last one asked for is the same step: a
  // uniform march computes each window's Δt from its end times, which differ
  // from window to window in the last bits, and its windows keep one
  // operator and one factorization (rebuilding the operators of every
  // window cost 8 % of a linear march, perf). A new step moves the operator
  // to it (Operator::Retime) instead of building it from its table again,
  // which was 4 % of a march under error control (Kepler e = 0.9, SBP84,
  // callgrind).
  void SetStep(double dt) {
    if (std::abs(dt - requested_dt_) <=
        64 * std::numeric_limits<double>::epsilon() * requested_dt_)
      return;
    const double ratio = dt * lu_.Ratio() / this->dt();
    if (order() == 2 ? std::max(ratio, 1.0 / ratio) > kScaledReuse
                     : std::abs(dt / this->dt() - 1.0) > 0.05)
      lu_.valid = false;
    requested_dt_ = dt;
    dbar_.Retime(0.0, dt * double(points() - 1));
    lu_.SetStep(this->dt());
    omega_end_ = -1.0;
  }

  // The last solved window: position and velocity D x of DOF c at node i.
  double x(int i, int c) const { return xc_[c][i]; }
  double v(int i, int c) const { return v_[c][i]; }

  struct Outcome {
    variational::NewtonReport report;
    CorrectedEnd<double> end;  // the hand-off state
    State x_end{}, v_end{};    // x_N and (Dx)_N
    // Per component: |M⁻¹λ4| and |(Dx)_N − M⁻¹(−λ3)|, the embedded error
    // estimates of x_N and (Dx)_N (first order: |C⁻¹λ3| and 0).
    State est_x{}, est_v{};
    // The round-off level of (Dx)_N, ε·Σ_j|D_{N,j}|·max_i|x_i| per
    // component: below it est_v is noise (measured: at steps where
    // round-off dominates, est_v stayed below 0.5 of it, SBP42–84, Kepler
    // e = 0.9 and the anharmonic oscillator).
    State roundoff_v{};
    double seconds_end = 0;   // after Newton (newton.phase_timings)
    std::string failure;      // empty on success
    bool split_helps = true;  // false: a shorter window has the same Δt
  };

  // Solves the window from (x0, v0), Newton started at `guess` (positions,
  // node-major, points·d values) with λ3 = lambda3 and λ4 = 0. `fresh`
  // refactors at the start instead of taking chord steps on the previous
  // window's factorization. On success the nodes are in x(i, c), and the
  // velocities D x in v(i, c) if `velocities` is set.
  // The result goes into `o` (its arrays' storage kept), which is returned.
  Outcome& Solve(Outcome& o, const State& x0, const State& v0,
                 const double* guess, const double* lambda3,
                 const variational::NewtonOptions& newton, bool fresh,
                 bool velocities) {
    o.report = {};
    o.failure.clear();
    o.split_helps = true;
    o.seconds_end = 0;
    system_.SetInitial(x0, v0);
    const auto& D = dbar_.base();
    const int n = D.points();
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < d; ++c) y_[system_.X(i, c)] = guess[i * d + c];
    for (int c = 0; c < d; ++c) {
      y_[system_.Lambda3(c)] = lambda3[c];
      if (order() == 2) y_[system_.Lambda4(c)] = 0.0;
    }
    // Whether this window starts on the last window's factorization (chord
    // steps) or with one of its own. A stale start is wasted when the
    // factorization is one window old (made in the window before) and its
    // chord steps either failed (Newton refactored) or converged more slowly
    // than a fresh start would have: more than kSlowChords corrections. The
    // factorization made in its place will be as old in the next window, so
    // the next one starts with its own. When the first stale start after
    // such fresh windows is wasted again, the next fresh_run_ windows start
    // with their own, the run doubling each time (4, 8, 16 …, at most 64)
    // until a stale start pays. A factorization older than one window is
    // renewed only by Newton itself, when its chord steps stop contracting:
    // marches that reuse one over many windows (Kepler e = 0.9 on a uniform
    // grid: 3 factorizations in 349 windows) lost up to 2 % when any
    // failure triggered fresh windows (callgrind, 28 November), and renewing
    // one whose chord steps merely took more than kSlowChords corrections
    // gained 2.5 % in geometric mean on the anharmonic oscillator's lgl8
    // halves, nothing on Kepler's, and cost up to 8 % on SBP windows
    // (docs/performance.md §9).
    // Measured in time (docs/performance.md §2): on the anharmonic
    // oscillator a window's Jacobian moves so far that chord steps on the
    // last one took 6.6 corrections where a fresh start takes 2.
    if (refactor_next_) {
      lu_.valid = false;
    } else if (fresh_windows_ > 0) {
      --fresh_windows_;
      lu_.valid = false;
    }
    if (fresh) lu_.valid = false;
    const bool stale_start = lu_.valid;
    o.report = variational::Newton<double>(system_, y_, newton, lu_);
    const bool refactored = o.report.iterations > 0;
    refactor_next_ = false;
    if (stale_start) {
      const bool wasted = factorization_age_ <= 1 &&
                          (refactored || o.report.corrections > kSlowChords);
      if (wasted) {
        if (last_stale_wasted_) {
          fresh_windows_ = fresh_run_;
          fresh_run_ = std::min(2 * fresh_run_, kMaxFreshWindows);
        }
        last_stale_wasted_ = true;
        refactor_next_ = true;
      } else if (!refactored) {
        last_stale_wasted_ = false;
        fresh_run_ = kFreshWindows;
      }
    }
    factorization_age_ = refactored ? 1 : factorization_age_ + 1;
    if (!o.report.converged) {
      lu_.valid = false;
      o.failure = o.report.reason;
      return o;
    }
    const PhaseClock clock{newton.phase_timings};
    const auto ending = clock.Now();
    const auto timed = [&] { o.seconds_end = clock.Since(ending); };
    for (int c = 0; c < d; ++c) {
      xc_[c].resize(n);
      for (int i = 0; i < n; ++i) xc_[c][i] = y_[system_.X(i, c)];
    }
    double xe[2][d], ve[2][d];
    for (int k = 0; k < 2; ++k) {
      const int i = k == 0 ? 0 : n - 1;
      for (int c = 0; c < d; ++c) {
        xe[k][c] = xc_[c][i];
        ve[k][c] = D.ApplyRow(i, xc_[c].data());
      }
    }
    double omega_end = 0.0;
    // L's Hessian at the end node: ω there and the mass of the multiplier
    // correction below, one pointwise evaluation for both (it was two, 1.5 %
    // of an lgl8 march on Kepler e = 0.9).
    Eigen::Matrix<double, 2 * d, 2 * d> end_hessian;
    if (order() == 2) {
      end_hessian = action::LagrangianHessian(problem_, xe[1], ve[1]);
      // ω at the window's start: when the window starts from this engine's
      // last hand-off, it is the last window's ω at its end (the same time,
      // and the same state up to the multiplier correction, which is the
      // size of the error estimate). Only the first window, and a window
      // after a fallback, evaluates it: one pointwise Hessian per window
      // instead of two.
      const double handed = HandedFrequency(x0.data(), v0.data());
      const double omega_start =
          handed >= 0.0 ? handed : FastestFrequency(problem_, xe[0], ve[0]);
      omega_end = FastestFrequencyOf(end_hessian);
      const Grid grid{.op = op_, .points = n, .t_end = D.t_end()};
      std::string why = UnderResolution(grid, omega_start, omega_end);
      if (!why.empty()) {
        omega_end_ = -1.0;
        o.failure = std::move(why);
        o.split_helps = false;
        timed();
        return o;
      }
    }
    double l3[d], l4[d];
    for (int c = 0; c < d; ++c) {
      l3[c] = y_[system_.Lambda3(c)];
      l4[c] = order() == 2 ? y_[system_.Lambda4(c)] : 0.0;
    }
    CorrectEndInto<double>(problem_, order(), xe[1], ve[1], l3,
                           order() == 2 ? l4 : nullptr, o.end,
                           order() == 2 ? &end_hessian : nullptr);
    for (int c = 0; c < d; ++c) {
      o.x_end[c] = xe[1][c];
      o.v_end[c] = ve[1][c];
      o.est_x[c] = std::abs(o.end.position[c] - xe[1][c]);
      o.est_v[c] = order() == 2 ? std::abs(ve[1][c] - o.end.velocity[c]) : 0;
    }
    double row_sum = 0;
    for (double w : D.row(n - 1).coeffs) row_sum += std::abs(w);
    for (int c = 0; c < d; ++c) {
      double xmax = 0;
      for (double v : xc_[c]) xmax = std::max(xmax, std::abs(v));
      o.roundoff_v[c] =
          std::numeric_limits<double>::epsilon() * row_sum * D.inv_dt() * xmax;
    }
    omega_end_ = omega_end;
    for (int c = 0; c < d; ++c) {
      handed_x_[c] = o.end.position[c];
      handed_v_[c] = order() == 2 ? o.end.velocity[c] : 0.0;
    }
    if (velocities) {
      for (int c = 0; c < d; ++c) {
        v_[c].resize(n);
        D.Apply(std::span<const double>(xc_[c]), std::span<double>(v_[c]));
      }
    }
    timed();
    return o;
  }

  long long factorizations() const { return lu_.factorizations; }

  // ω at (x, v) when that is this engine's last hand-off state: the one it
  // evaluated at the window's end (the same time; the state differs by the
  // multiplier correction, the size of the error estimate); −1 otherwise.
  double HandedFrequency(const double* x, const double* v) const {
    if (omega_end_ < 0.0) return -1.0;
    for (int c = 0; c < d; ++c)
      if (x[c] != handed_x_[c] || (order() == 2 && v[c] != handed_v_[c]))
        return -1.0;
    return omega_end_;
  }

  // ‖F‖∞ of the window's equations at the last solve's result: the residual
  // a rejected window reports (marching does not evaluate it otherwise).
  double LastResidual() const {
    std::vector<double> f(system_.size());
    system_.Residual(y_.data(), f.data());
    double m = 0;
    for (double v : f) m = std::isfinite(v) ? std::max(m, std::abs(v)) : NAN;
    return m;
  }

 private:
  // A second-order window's factorization stays its chord start (scaled,
  // step_scaled_lu.h) for steps within this factor of the step it was made
  // at. Measured over the 24 marches of bench/march_phases_bench
  // (geometric-mean time; factorizations and corrections per window):
  //   unscaled, within 5 %   6.59 ms   0.36   2.70
  //   scaled, factor 1.25    6.53 ms   0.28   2.85
  //   scaled, factor 1.5     6.09 ms   0.16   3.09
  //   scaled, factor 2       5.73 ms   0.08   3.28
  //   scaled, factor 4       5.56 ms   0.03   3.50
  //   scaled, any step       5.69 ms   0.01   3.83
  // Under error control Δt follows the solution's time scale, so Δt²·V''
  // — all the scaled equations still depend on — changes little from window
  // to window (Kepler e = 0.9: one factorization serves pericentre and
  // apocentre), and a chord step (residual and substitution, 2.9 µs for an
  // SBP84 window of 48 points) costs a seventh of a fresh Jacobian
  // (assembly and factorization, 21 µs; bench/window_algebra_bench).
  static constexpr double kScaledReuse = 4.0;

  static sbp::RegularizedOperator<double> MakeDbar(const std::string& op,
                                                   int points, double dt,
                                                   double sigma0) {
    return sbp::RegularizedOperator<double>(
        sbp::MakeOperator<double>(op, points, 0.0, dt * double(points - 1)),
        sigma0);
  }

  const P& problem_;
  std::string op_;
  double sigma0_;
  double requested_dt_;
  sbp::RegularizedOperator<double> dbar_;
  action::ReducedSystem<P, double> system_;  // refers to dbar_
  std::vector<double> y_;
  StepScaledLu lu_;
  // Windows solved since lu_ was factored (1: in the last one), and whether
  // the next window refactors at its start (Solve).
  int factorization_age_ = 0;
  bool refactor_next_ = false;
  // The fresh starts left, the length of the next run of them, and whether
  // the last stale start was wasted (Solve).
  static constexpr int kFreshWindows = 4, kMaxFreshWindows = 64;
  int fresh_windows_ = 0;
  int fresh_run_ = kFreshWindows;
  bool last_stale_wasted_ = false;
  // A fresh start costs a factorization and 2 corrections; a factorization
  // (assembly and LU) about 3d corrections (residual and substitution) in
  // time, SBP84 in windows of 48: 3–4 for one coordinate (the pendulum's
  // 5.5 chord corrections per window and fresh starts took the same time),
  // 7 for two (Kepler e = 0.9, bench/window_algebra_bench: 14.5 µs against
  // 2.0 µs).
  static constexpr int kSlowChords = 2 + 3 * d;
  // The last window's corrected end state (the next window's initial data
  // unless a fallback intervened) and ω there; ω < 0: none yet.
  State handed_x_{}, handed_v_{};
  double omega_end_ = -1.0;
  std::vector<double> xc_[d], v_[d];
};

}  // namespace vivp::variational::detail
