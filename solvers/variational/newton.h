// Newton's method on F(y) = 0 with the exact Jacobian (or an approximation
// of it), iterative refinement, and stopping on step size with a stagnation
// guard: the one Newton of point mechanics and of fields.
//
// A System provides
//   int size() const;
//   void Residual(const Real* y, Real* f) const;      // matrix-free
// and whatever its linear solver asks of it (the Jacobian). The linear
// solver is the part that varies (a LinearSolver below): a banded LU for the
// time nodes of point mechanics (BandedSolver, the default), a sparse LU or
// a space-diagonalized solve for the space-time window of a field
// (solvers/spacetime/window_solver.h).
//
// Each iteration assembles and factors the Jacobian once, then takes the
// Newton step followed by up to `refinement_steps` further corrections with
// the same factorization and a freshly evaluated matrix-free residual: for a
// linear system this is iterative refinement, which removes the round-off the
// Nt³ conditioning puts into a single solve (docs/method.md §6); for a
// nonlinear one it is a cheap simplified-Newton step.
//
// A factorization that is not the Jacobian at y — one carried over from an
// earlier solve, or one the solver only approximates (LinearSolver::exact()
// false: a preconditioner) — takes chord (simplified Newton) steps, up to
// eight per factorization, as long as each contracts.
//
// Stopping (docs/method.md §6: never on an absolute residual):
//   converged   the last correction is at round-off, |δ|∞ <= tol·max(1, |y|∞)
//               with tol = step_tolerance (default 32 eps); or two
//               successive corrections on one factorization (a fresh exact
//               one's Newton step and the next; on a stale one, from its
//               third) contract with ratio θ < ½ and θ/(1−θ)|δ|, the
//               estimated remaining error, is below that bound; or the
//               corrections stopped shrinking (stagnation) while already below
//               sqrt(eps) after a fresh factorization that had contracted;
//   failed      non-finite residual, singular Jacobian, stagnation above
//               sqrt(eps), or the iteration limit.
#pragma once

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "solvers/variational/banded_solver.h"
#include "solvers/variational/summary.h"

namespace vivp::variational {

struct NewtonOptions {
  int max_iterations = 50;
  int refinement_steps = 2;
  double step_tolerance = 0;  // 0: 32 eps of the scalar type
  // Time residual, assembly, factorization and solve separately. Off in
  // time-slab marching: a window of 32 points is solved in a few
  // microseconds, and the clock reads would cost 7 % of that.
  bool phase_timings = true;
  // Evaluate F once more after the converging correction, for
  // NewtonReport::residual_norm (NaN when off). Marching turns it off: the
  // window's last residual is a third of its cost and nobody reads it.
  bool final_residual = true;
};

struct Timings {
  double residual = 0;  // seconds in matrix-free residual evaluations
  double assembly = 0;  // Jacobian assembly
  double factorization = 0;
  double solve = 0;  // triangular solves
  double total = 0;
};

// The Summary of one Newton solve (iterations: Jacobian factorizations;
// last_residual: |F(y)|∞ at the returned y), and its steps and phases.
struct NewtonReport : Summary {
  int corrections = 0;   // Newton + refinement steps taken
  double last_step = 0;  // |δ|∞ of the last correction
  Timings phases;        // residual, assembly, factorization, solve, total
};

namespace detail {
template <class Real>
Real MaxAbs(const std::vector<Real>& v) {
  Real m(0);
  for (const Real& x : v) m = std::max(m, std::abs(x));
  return m;
}
template <class Real>
bool AllFinite(const std::vector<Real>& v) {
  for (const Real& x : v)
    if (!std::isfinite(x)) return false;
  return true;
}
// A System spread over processes (solvers/distributed/window.h) holds part
// of y and F: it provides ReduceMax(std::span<double>), the largest of each
// value over all of them, so that every process takes the same decision.
// Any other System: the values are its own.
template <class System>
void GlobalMax(const System& system, std::span<double> v) {
  if constexpr (requires { system.ReduceMax(v); }) system.ReduceMax(v);
}
inline double Since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
      .count();
}
}  // namespace detail

// A clock for optional phase timings (NewtonOptions::phase_timings,
// MarchOptions::phase_timings): when off, it reads nothing and every
// duration is 0.
struct PhaseClock {
  using Clock = std::chrono::steady_clock;
  bool on;
  Clock::time_point Now() const {
    return on ? Clock::now() : Clock::time_point{};
  }
  double Since(Clock::time_point t0) const {
    return on ? detail::Since(t0) : 0.0;
  }
};

// The linear solver of Newton's method, a concept:
//
//   bool valid;                   holds a factorization to start from
//   void Invalidate();            valid = false
//   void Prepare(const System&, const Real* y);  before each solve: sizes
//   void Assemble(const System&, const Real* y); the Jacobian at y (timed as
//                                 assembly)
//   void AssembleWithResidual(const System&, const Real* y, Real* f);
//                                 optional: the Jacobian and F(y) into f
//                                 in one pass, for a solve that factors at
//                                 its start
//   bool Factorize();             false if singular (why in message())
//   void Solve(Real* b);          b ← J⁻¹ b with the last factorization
//   bool exact() const;           the last factorization is J at the point
//                                 it was assembled at (false: an
//                                 approximation, whose steps are chord steps)
//   std::string message() const;
//
// A solver outlives one solve: time-slab marching solves one window after
// another with the same operator, and for a linear problem the Jacobian is
// the same matrix every time, for a nonlinear one the previous window's is a
// good approximation. Newton then starts with chord (simplified Newton)
// steps on the carried-over factorization and refactors only when they stop
// contracting — "factor once, back-substitute per window".

// `residual_override`, when given, replaces system.Residual for every
// residual evaluation (e.g. the same residual evaluated in long double: mixed
// precision iterative refinement). `solver` supplies a factorization to start
// from and keeps the last one for the next call.
template <class Real, class System, class LinearSolver>
NewtonReport Newton(
    const System& system, std::vector<Real>& y, const NewtonOptions& options,
    LinearSolver& solver,
    const std::function<void(const Real*, Real*)>& residual_override = {}) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const PhaseClock clock{options.phase_timings};
  NewtonReport report;
  const int n = system.size();
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real tol = options.step_tolerance > 0 ? Real(options.step_tolerance)
                                              : Real(32) * eps;
  const Real stagnation_floor = std::sqrt(eps);

  if (static_cast<int>(y.size()) != n) y.assign(n, Real(0));
  solver.Prepare(system, y.data());
  std::vector<Real> f(n);

  auto residual = [&] {
    const auto t0 = clock.Now();
    if (residual_override)
      residual_override(y.data(), f.data());
    else
      system.Residual(y.data(), f.data());
    report.phases.residual += clock.Since(t0);
    double finite[1] = {detail::AllFinite(f) ? 0.0 : 1.0};
    detail::GlobalMax(system, finite);
    return finite[0] == 0.0;
  };
  auto finish = [&](bool ok, std::string why) {
    report.converged = ok;
    report.reason = std::move(why);
    double last[2] = {detail::AllFinite(f) ? 0.0 : 1.0,
                      detail::AllFinite(f) ? double(detail::MaxAbs(f)) : 0.0};
    detail::GlobalMax(system, last);
    report.last_residual =
        last[0] == 0.0 ? last[1] : std::numeric_limits<double>::quiet_NaN();
    report.phases.total = detail::Since(start);
    report.seconds = report.phases.total;
    return report;
  };

  // A solve that factors at its start (no factorization to start from) and
  // whose solver and system evaluate the residual with the Jacobian: both
  // from one pass over the nodes, the path and the pointwise derivatives
  // once rather than twice. (With the test below that skips F after the
  // converging correction: a uniform SBP84 march of the anharmonic
  // oscillator, 1152 steps, 0.252 → 0.241 ms; Kepler e = 0.9, 8192 steps,
  // 2.55 → 2.41 ms; the same counts and end errors; bench/small_solve_bench,
  // least of three interleaved medians.)
  bool assembled = false;
  if constexpr (requires {
                  solver.AssembleWithResidual(system, y.data(), f.data());
                }) {
    if (!solver.valid && !residual_override) {
      const auto t0 = clock.Now();
      solver.AssembleWithResidual(system, y.data(), f.data());
      report.phases.assembly += clock.Since(t0);
      double finite[1] = {detail::AllFinite(f) ? 0.0 : 1.0};
      detail::GlobalMax(system, finite);
      if (finite[0] != 0.0)
        return finish(false, "non-finite residual at the initial guess");
      assembled = true;
    }
  }
  if (!assembled && !residual())
    return finish(false, "non-finite residual at the initial guess");
  Real previous_step = std::numeric_limits<Real>::infinity();
  // A factorization carried over from an earlier solve is stale: it may take
  // more (chord) corrections, as long as each contracts. So is one that only
  // approximates the Jacobian.
  bool stale = solver.valid;
  // Whether the chord steps of an approximate factorization made in this
  // solve contracted (θ ≤ ¼) before they stopped shrinking.
  bool contracted = false;
  constexpr int kChordSteps = 8;
  while (report.iterations < options.max_iterations) {
    if (!solver.valid) {
      auto t0 = clock.Now();
      if (!assembled) solver.Assemble(system, y.data());
      assembled = false;
      report.phases.assembly += clock.Since(t0);
      t0 = clock.Now();
      const bool ok = solver.Factorize();
      report.phases.factorization += clock.Since(t0);
      ++report.iterations;
      if (!ok) {
        const std::string why = solver.message();
        return finish(false, "singular Jacobian at iteration " +
                                 std::to_string(report.iterations) +
                                 (why.empty() ? "" : ": " + why));
      }
      solver.valid = true;
      stale = !solver.exact();
      contracted = false;
    }
    const bool fresh_approximation = stale && !solver.exact();
    const int inner = stale ? kChordSteps : options.refinement_steps;
    for (int r = 0; r <= inner; ++r) {
      std::vector<Real>& delta = f;  // solve in place: δ = −J⁻¹F
      auto t0 = clock.Now();
      solver.Solve(delta.data());
      report.phases.solve += clock.Since(t0);
      Real step(0), ymax(1);
      for (int i = 0; i < n; ++i) {
        step = std::max(step, std::abs(delta[i]));
        y[i] -= delta[i];
        ymax = std::max(ymax, std::abs(y[i]));
      }
      if constexpr (std::is_same_v<Real, double>) {
        double global[2] = {step, ymax};
        detail::GlobalMax(system, global);
        step = global[0];
        ymax = global[1];
      }
      ++report.corrections;
      report.last_step = double(step);
      const Real scale = ymax;
      if (!options.final_residual && std::isfinite(step) &&
          std::isfinite(scale) && step <= tol * scale) {
        // Converged; F at the returned y is not evaluated (f holds δ).
        std::fill(f.begin(), f.end(), std::numeric_limits<Real>::quiet_NaN());
        return finish(true, "correction at round-off");
      }
      // The contraction test below needs only the corrections: when nobody
      // reads F at the returned y, it is taken before F is evaluated: one
      // residual fewer per window of a march.
      const Real theta = step / previous_step;
      const bool contracted_to_roundoff =
          r >= (stale ? 2 : 1) && theta < Real(0.5) &&
          theta / (Real(1) - theta) * step <= tol * scale;
      // The estimate in three digits by std::to_chars: std::to_string's
      // "%f" printed it as 0.000000, through vsnprintf, at 1 % of a march.
      auto finish_contracted = [&] {
        char digits[32];
        const auto end = std::to_chars(digits, digits + sizeof digits,
                                       double(theta / (1 - theta) * step),
                                       std::chars_format::scientific, 2)
                             .ptr;
        std::string why = "refinement converged (estimated remaining error ";
        why.append(digits, end).push_back(')');
        return finish(true, std::move(why));
      };
      if (!options.final_residual && contracted_to_roundoff) {
        std::fill(f.begin(), f.end(), std::numeric_limits<Real>::quiet_NaN());
        return finish_contracted();
      }
      if (!residual())
        return finish(false, "non-finite residual after correction " +
                                 std::to_string(report.corrections));
      if (step <= tol * scale) return finish(true, "correction at round-off");
      // Two refinement steps in a row give the contraction θ of the
      // simplified iteration; the error left is about θ/(1−θ)·step. On a
      // fresh exact factorization the Newton step and the one correction
      // after it already do: Newton contracts at least as fast from there
      // on (its rate falls with the error), so θ/(1−θ)·step bounds what is
      // left. Marched windows converge so, 3e-6 → 5e-12 (θ ≈ 2e-6), and
      // used to take a third correction at round-off to confirm it
      // (callgrind, twelve uniform marches: 195.9 → 194.8 M instructions,
      // none more; anharmonic SBP84 at 1024 steps −2.8 %, Kepler e = 0.9 at
      // 8192 −1.3 %; the same end errors to four digits).
      if (contracted_to_roundoff) return finish_contracted();
      if (fresh_approximation && r >= 1 && theta <= Real(0.25))
        contracted = true;
      previous_step = step;
      if (theta >= Real(0.5)) {
        // Corrections stopped shrinking: round-off if already tiny, after a
        // fresh factorization. Chord steps on a stale one that stop shrinking
        // contract slowly, with an error of about step/(1 − θ) left: they
        // are no evidence of round-off (with an accurate start, chord steps
        // at θ ≈ 0.5 reach √ε with 1e-8 left; measured SBP84 marches on the
        // anharmonic oscillator stopped there), so re-linearise instead.
        if (!stale && step <= stagnation_floor * scale)
          return finish(true, "corrections stagnated at round-off level");
        // An approximate factorization of this solve whose steps contracted
        // and then stopped at a tiny size has met the round-off of the
        // system: as for a fresh exact one (the space-time window of SBP84,
        // condition ≈ 4e9, stalls near 1e-11 relative; docs/fields.md §3).
        if (fresh_approximation && contracted && r >= 2 &&
            step <= stagnation_floor * scale)
          return finish(true, "corrections stagnated at round-off level");
        // Stale chord steps that stall within 64 ε of the solution's size
        // are at its round-off: the error left, about step/(1 − θ), is too
        // (a fresh factorization would only confirm it; measured, marching
        // with a 4 ε stop refactored for this in 26 of 175 windows).
        if (stale && step <= Real(64) * eps * scale)
          return finish(true, "chord corrections stagnated at round-off level");
        // The first two chord steps on a stale factorization do not measure
        // its contraction: from a start whose error is mostly in the path,
        // the first correction is the path's and the second λ3's (measured,
        // marching from the predictor: 2.5e-7 at a node, then 1.4e-7 at λ3,
        // then 5e-9, 7e-11); judged there, 22 of 175 windows refactored
        // without need.
        if ((stale && r >= 2) || (!stale && r > 0)) break;
      }
    }
    // Re-linearise at the current point: after a fresh factorization's
    // refinement budget, or when the (stale or fresh) corrections stall.
    solver.Invalidate();
  }
  return finish(false, "no convergence in " +
                           std::to_string(options.max_iterations) +
                           " iterations (last correction " +
                           std::to_string(report.last_step) + ")");
}

// Newton with a banded solver of its own (`cache`, when given, is kept for
// the next call).
template <class Real, class System>
NewtonReport Newton(
    const System& system, std::vector<Real>& y,
    const NewtonOptions& options = {},
    const std::function<void(const Real*, Real*)>& residual_override = {},
    BandedSolver<Real>* cache = nullptr) {
  BandedSolver<Real> local;
  return Newton<Real>(system, y, options, cache ? *cache : local,
                      residual_override);
}

}  // namespace vivp::variational
