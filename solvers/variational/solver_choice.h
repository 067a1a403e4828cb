// Which solver a user asks for, by name, and which combinations of solver,
// windows and error control can run: the one place that parses a solver
// name and the one place that refuses a combination, for the command line
// (`vivp converge`) and for scenes (`vivp run`) alike, before any work.
//
// A refusal is one sentence with the settings spelled as the front end
// spells them (`--slab-points 0` on the command line, `slab_points = 0` in a
// scene): "what is wrong; expected what".
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

// The window a march takes when none is given. Newton: 48 points, the
// throughput optimum measured by bench/march_bench (MarchOptions). Ceres LM
// marches by default, in the largest window in which it keeps the Newton
// march's accuracy and iteration count, measured by bench/lm_window_bench
// (docs/method.md §8): its normal equations square a condition number that
// grows with the window. 0: no window keeps them (SBP84, whose condition
// number is ~1e9 in every window).
inline long long DefaultWindowPoints(Path path, const std::string& op) {
  if (path != Path::kCeresLm) return 48;
  if (op == "sbp21") return 192;
  if (op == "sbp42") return 128;
  if (op == "sbp63") return 16;
  return 0;
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
  if (r.tolerance || r.path == Path::kCeresLm)
    return DefaultWindowPoints(r.path, r.op);
  return 0;
}

enum class Spelling { kCommandLine, kScene };

// Why a request cannot run: `what` is wrong; `expected` starts "expected".
struct Refusal {
  std::string what, expected;
  bool ok() const { return what.empty(); }
  std::string Sentence() const { return what + "; " + expected; }
};

// The refusal of an impossible combination, or an empty one.
inline Refusal CheckSolveRequest(const SolveRequest& r,
                                 Spelling spelling = Spelling::kCommandLine) {
  const bool cli = spelling == Spelling::kCommandLine;
  // A setting as the front end writes it: `--slab-points 0`, `slab_points =
  // 0`, `solver = "ceres-lm"`.
  auto setting = [&](const char* flag, const char* key,
                     const std::string& value, bool text = false) {
    if (cli) return std::string(flag) + " " + value;
    return std::string(key) + " = " + (text ? "\"" + value + "\"" : value);
  };
  const std::string slab = cli ? "--slab-points" : "slab_points";
  const std::string solver =
      setting("--solver", "solver", PathName(r.path), true);
  const long long minimum = sbp::Table(r.op).min_points;
  const std::string at_least = slab + " >= " + std::to_string(minimum);
  if (r.window_points > 0 && r.window_points < minimum)
    return {setting("--slab-points", "slab_points",
                    std::to_string(r.window_points)) +
                " is below the minimum of " + r.op + " (" +
                std::to_string(minimum) + ")",
            "expected " + at_least + ", or 0 for one global solve"};
  const long long fallback = DefaultWindowPoints(r.path, r.op);
  if (r.window_points < 0 && fallback == 0 &&
      (r.tolerance || r.path == Path::kCeresLm))
    return {solver + " has no default window for " +
                setting("--operator", "operator", r.op, true) +
                ": Levenberg-Marquardt loses Newton's accuracy in every "
                "window measured (its normal equations square a condition "
                "number near 1e9)",
            "expected " + slab + " to march anyway (0: one global solve), " +
                "or " + setting("--solver", "solver", "newton", true)};
  if (r.tolerance && r.window_points == 0)
    return {std::string(cli ? "--tolerance" : "a tolerance") +
                " marches in windows, but " +
                setting("--slab-points", "slab_points", "0") +
                " asks for one global solve",
            "expected " + at_least +
                (fallback > 0
                     ? " or no " + slab + " (" + std::to_string(fallback) + ")"
                     : std::string())};
  if (r.extended_residual && r.path != Path::kReducedNewton)
    return {
        "--extended-residual evaluates reduced Newton's residual in long "
        "double, which " +
            solver + " does not use",
        "expected --solver newton, or no --extended-residual"};
  return {};
}

}  // namespace vivp::variational
