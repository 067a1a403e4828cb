// Which solver a user asks for, by name, and which combinations of solver,
// windows and error control can run: the one place that parses a solver
// name and the one place that refuses a combination, for every front end
// (the command line's `vivp converge`, scenes' `vivp run`, a library
// caller of Solve) alike, before any work.
//
// A refusal is data (Refusal: the setting that is wrong, its value, the
// valid windows and the alternative), with the settings named as this
// library's API names them (SolveRequest: solver, operator, window_points,
// ...). A front end turns it into one sentence, "what is wrong; expected
// what", with Describe and its own spelling of the settings
// (SettingSpelling).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "core/sbp/builder.h"
#include "solvers/variational/ivp_types.h"

namespace vivp::variational {

// The solver names, in the order of Path (PathName is the other direction).
inline const std::vector<std::string>& SolverNames() {
  static const std::vector<std::string> names = {PathName(Path::kReducedNewton),
                                                 PathName(Path::kFullNewton),
                                                 PathName(Path::kCeresLm)};
  return names;
}

// "newton, full-newton, ceres-lm".
inline std::string SolverNameList() {
  std::string out;
  for (const auto& n : SolverNames()) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// The path of a solver name; std::invalid_argument names the valid ones.
inline Path ParseSolver(const std::string& name) {
  for (Path p : {Path::kReducedNewton, Path::kFullNewton, Path::kCeresLm})
    if (name == PathName(p)) return p;
  throw std::invalid_argument("'" + name +
                              "' is not a solver; valid: " + SolverNameList());
}

// The window a march takes when none is given. Newton on a uniform grid:
// 48 points, the throughput optimum measured by bench/march_bench. Newton
// under error control (`tolerance`): 24 points. A window's step is one for
// all its nodes, so a window adapts its step once per W − 1 nodes, and its
// error estimates grow with its length; on an eccentric orbit, whose time
// scale changes by a factor of about 80 within a period, shorter windows follow
// it with fewer nodes (Kepler e = 0.9, SBP84, 10⁻⁵: 2415 nodes in windows
// of 24 against 3432 in windows of 48). Fitted to end errors of 10⁻⁸ over
// tolerances 3·10⁻⁵ … 3·10⁻⁷, that march takes 27.5 M instructions in
// windows of 24, 29.6 M in windows of 32 and 37.0 M in windows of 48
// (callgrind; docs/error_control.md, docs/performance.md §3). Ceres LM marches
// by default, in the largest window in which it keeps the Newton march's
// accuracy and iteration count, measured per operator (core/sbp,
// Measured::lm_window_points); 0: no window keeps them. An unknown operator
// is std::invalid_argument naming the valid ones.
inline long long DefaultWindowPoints(Path path, const std::string& op,
                                     bool tolerance = false) {
  // A spectral element's window is the element (lobatto.h).
  if (const sbp::Coefficients& t = sbp::Table(op); t.max_points > 0)
    return t.max_points;
  if (path != Path::kCeresLm) return tolerance ? 24 : 48;
  return sbp::Table(op).measured.lm_window_points;
}

// What a front end asks of the solver.
struct SolveRequest {
  Path path = Path::kReducedNewton;
  std::string op = "sbp42";
  // -1: not given (the default of the path: Newton solves globally unless a
  // tolerance asks for windows, Ceres LM marches); 0: one global solve;
  // otherwise windows of this many points.
  long long window_points = -1;
  bool tolerance = false;          // error control, which marches
  bool extended_residual = false;  // reduced Newton's long-double residual
};

// The window of a march the request asks for, or 0 for one global solve
// (for a request CheckSolveRequest accepts).
inline long long WindowPoints(const SolveRequest& r) {
  if (r.window_points >= 0) return r.window_points;
  if (r.tolerance || r.path == Path::kCeresLm || sbp::IsElement(r.op))
    return DefaultWindowPoints(r.path, r.op, r.tolerance);
  return 0;
}

// The settings of a SolveRequest, named as this library's API names them
// (SettingName); a front end spells them as its own options.
enum class Setting {
  kSolver,
  kOperator,
  kWindowPoints,
  kTolerance,
  kExtendedResidual
};

// "solver", "operator", "window_points", "tolerance", "extended_residual".
inline std::string SettingName(Setting s) {
  switch (s) {
    case Setting::kSolver:
      return "solver";
    case Setting::kOperator:
      return "operator";
    case Setting::kWindowPoints:
      return "window_points";
    case Setting::kTolerance:
      return "tolerance";
    case Setting::kExtendedResidual:
      return "extended_residual";
  }
  return "?";
}

// Why a request cannot run, as data for a front end to word.
struct Refusal {
  enum class Reason {
    kNone,
    // window_points is between 0 and the operator's minimum.
    kWindowBelowMinimum,
    // No window is given, and the solver, which marches (Ceres LM, or any
    // solver under a tolerance), has none measured for the operator.
    kNoDefaultWindow,
    // A tolerance, which marches in windows, with window_points = 0.
    kToleranceWithoutWindows,
    // extended_residual with a solver that does not use it.
    kResidualUnused,
  };
  Reason reason = Reason::kNone;
  Setting setting = Setting::kWindowPoints;  // the setting that is wrong
  std::string value;                         // and its value as given
  std::string solver;                        // the solver asked for
  std::string op;                            // the operator asked for
  // The valid windows: 0 (one global solve) or at least `minimum` points;
  // none given is the solver's default, `fallback` points (0: none).
  long long minimum = 0;
  long long fallback = 0;
  // The solver that would run instead ("": none suggested).
  std::string instead;

  bool ok() const { return reason == Reason::kNone; }
};

// How a front end writes a setting: its name alone (the library's
// "window_points"), with a value ("window_points 0"), and as the subject
// of a sentence when it is given.
class SettingSpelling {
 public:
  virtual ~SettingSpelling() = default;
  virtual std::string Name(Setting s) const { return SettingName(s); }
  virtual std::string With(Setting s, const std::string& value) const {
    return Name(s) + " " + value;
  }
  virtual std::string Given(Setting s) const { return Name(s); }
};

// A refusal in words: `what` is wrong; `expected` starts "expected".
struct RefusalText {
  std::string what, expected;
  std::string Sentence() const { return what + "; " + expected; }
};

// The refusal in one sentence, its settings spelled by `spelling` (by
// default as the library's API names them).
inline RefusalText Describe(const Refusal& r,
                            const SettingSpelling& spelling = {}) {
  using R = Refusal::Reason;
  const std::string window = spelling.Name(Setting::kWindowPoints);
  const std::string at_least = window + " >= " + std::to_string(r.minimum);
  switch (r.reason) {
    case R::kNone:
      return {};
    case R::kWindowBelowMinimum:
      return {spelling.With(Setting::kWindowPoints, r.value) +
                  " is below the minimum of " + r.op + " (" +
                  std::to_string(r.minimum) + ")",
              "expected " + at_least + ", or 0 for one global solve"};
    case R::kNoDefaultWindow:
      return {spelling.With(Setting::kSolver, r.solver) +
                  " has no default window for " +
                  spelling.With(Setting::kOperator, r.op) +
                  ": Levenberg-Marquardt loses Newton's accuracy in every "
                  "window measured (its normal equations square a condition "
                  "number near 1e9)",
              "expected " + window + " to march anyway (0: one global " +
                  "solve), or " + spelling.With(Setting::kSolver, r.instead)};
    case R::kToleranceWithoutWindows:
      return {spelling.Given(Setting::kTolerance) +
                  " marches in windows, but " +
                  spelling.With(Setting::kWindowPoints, r.value) +
                  " asks for one global solve",
              "expected " + at_least +
                  (r.fallback > 0 ? " or no " + window + " (" +
                                        std::to_string(r.fallback) + ")"
                                  : std::string())};
    case R::kResidualUnused: {
      const std::string residual = spelling.Name(Setting::kExtendedResidual);
      return {residual +
                  " evaluates reduced Newton's residual in long double, "
                  "which " +
                  spelling.With(Setting::kSolver, r.solver) + " does not use",
              "expected " + spelling.With(Setting::kSolver, r.instead) +
                  ", or no " + residual};
    }
  }
  return {};
}

// The refusal of an impossible combination, or an empty one (ok()).
inline Refusal CheckSolveRequest(const SolveRequest& r) {
  using R = Refusal::Reason;
  Refusal out{.solver = PathName(r.path),
              .op = r.op,
              .minimum = sbp::Table(r.op).min_points,
              .fallback = DefaultWindowPoints(r.path, r.op, r.tolerance)};
  if (r.window_points > 0 && r.window_points < out.minimum) {
    out.reason = R::kWindowBelowMinimum;
    out.setting = Setting::kWindowPoints;
    out.value = std::to_string(r.window_points);
  } else if (r.window_points < 0 && out.fallback == 0 &&
             (r.tolerance || r.path == Path::kCeresLm)) {
    out.reason = R::kNoDefaultWindow;
    out.setting = Setting::kSolver;
    out.value = out.solver;
    out.instead = PathName(Path::kReducedNewton);
  } else if (r.tolerance && r.window_points == 0) {
    out.reason = R::kToleranceWithoutWindows;
    out.setting = Setting::kWindowPoints;
    out.value = "0";
  } else if (r.extended_residual && r.path != Path::kReducedNewton) {
    out.reason = R::kResidualUnused;
    out.setting = Setting::kExtendedResidual;
    out.value = "true";
    out.instead = PathName(Path::kReducedNewton);
  }
  return out;
}

}  // namespace vivp::variational
