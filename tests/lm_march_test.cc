// Ceres Levenberg–Marquardt per window of a march, and the one place that
// parses solver names and refuses impossible combinations
// (solvers/variational/solve.h, solver_choice.h; docs/method.md §8).
#define BOOST_TEST_MODULE lm_march
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <stdexcept>
#include <string>

#include "scene/run.h"
#include "scene/scene.h"
#include "solvers/variational/solver_choice.h"
#include "studies/registry.h"

using namespace vivp;
using namespace vivp::variational;

namespace {

MarchResult AnharmonicMarch(Path path, long long window) {
  // Δt = 10/1024; the solver templates are compiled in the registry.
  const Grid g{.op = "sbp42", .points = 1025, .t_end = 10.0};
  MarchOptions o;
  o.window_points = window;
  o.solve.path = path;
  o.keep_trajectory = false;
  return vivp::studies::FindProblem("anharmonic").march(g, o, {});
}

class NullSink : public scene::RunSink {
 public:
  void Begin(const scene::RunLayout&) override {}
  void Node(double, const double*, const double*, const double*) override {
    ++nodes;
  }
  long long nodes = 0;
};

// A spring scene with the given [method] lines.
std::string SpringScene(const std::string& method, const std::string& time) {
  return "[system]\ndof = 1\n[[effect]]\ntype = \"kinetic\"\n"
         "[[effect]]\ntype = \"spring\"\nk = 4.0\n"
         "[initial]\nx = [1.0]\nv = [0.0]\n[time]\nend = 10.0\n" +
         time + "\n[method]\n" + method + "\n";
}

std::string SceneError(const std::string& text) {
  try {
    scene::ParseScene(text, "lm.toml");
  } catch (const scene::SceneError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

BOOST_AUTO_TEST_CASE(AnharmonicToT10_LmMarchAgreesWithNewtonMarch) {
  // Proves: Ceres LM per window, started from the predictor as Newton is,
  // reaches the same discrete solution over 2.4 periods of x'' = −20x³ in
  // LM's default SBP42 window.
  const long long w = DefaultWindowPoints(Path::kCeresLm, "sbp42");
  const MarchResult lm = AnharmonicMarch(Path::kCeresLm, w);
  const MarchResult newton = AnharmonicMarch(Path::kReducedNewton, w);
  BOOST_TEST_REQUIRE(lm.status.converged, lm.status.reason);
  BOOST_TEST_REQUIRE(newton.status.converged, newton.status.reason);
  BOOST_TEST(lm.window_count == newton.window_count);
  BOOST_TEST(std::abs(lm.end_position[0] - newton.end_position[0]) <= 1e-9);
  BOOST_TEST(std::abs(lm.end_velocity[0] - newton.end_velocity[0]) <= 1e-9);
}

BOOST_AUTO_TEST_CASE(SolverNames_ParseBothWays) {
  for (Path p : {Path::kReducedNewton, Path::kFullNewton, Path::kCeresLm})
    BOOST_TEST(int(ParseSolver(PathName(p))) == int(p));
  BOOST_TEST(SolverNameList() == "newton, full-newton, ceres-lm");
  try {
    ParseSolver("lm");
    BOOST_FAIL("no throw");
  } catch (const std::invalid_argument& e) {
    BOOST_TEST(std::string(e.what()) ==
               "'lm' is not a solver; valid: newton, full-newton, ceres-lm");
  }
}

BOOST_AUTO_TEST_CASE(Windows_LmMarchesByDefaultNewtonSolvesGlobally) {
  BOOST_TEST(WindowPoints({.path = Path::kReducedNewton}) == 0);
  // Newton under error control: windows of 24 (solver_choice.h).
  BOOST_TEST(WindowPoints({.path = Path::kReducedNewton, .tolerance = true}) ==
             24);
  BOOST_TEST(WindowPoints({.path = Path::kCeresLm, .op = "sbp42"}) ==
             DefaultWindowPoints(Path::kCeresLm, "sbp42"));
  BOOST_TEST(WindowPoints({.path = Path::kCeresLm, .window_points = 0}) == 0);
  BOOST_TEST(WindowPoints({.path = Path::kCeresLm, .window_points = 32}) == 32);
}

BOOST_AUTO_TEST_CASE(ImpossibleCombinations_RefusedAsDataInTheApiWords) {
  // The solver layer says which setting is wrong, its value, the valid
  // windows and the alternative, in the library's names; the command line's
  // words are checked in failure_cli_test, the scene's below.
  using R = Refusal::Reason;
  auto api = [](SolveRequest r) {
    return Describe(CheckSolveRequest(r)).Sentence();
  };
  BOOST_TEST(
      CheckSolveRequest({.path = Path::kCeresLm, .window_points = 48}).ok());
  const Refusal below = CheckSolveRequest({.window_points = 4});
  BOOST_TEST((below.reason == R::kWindowBelowMinimum));
  BOOST_TEST((below.setting == Setting::kWindowPoints));
  BOOST_TEST(below.value == "4");
  BOOST_TEST(below.op == "sbp42");
  BOOST_TEST(below.minimum == 8);
  BOOST_TEST(api({.window_points = 4}) ==
             "window_points 4 is below the minimum of sbp42 (8); expected "
             "window_points >= 8, or 0 for one global solve");
  const Refusal global =
      CheckSolveRequest({.window_points = 0, .tolerance = true});
  BOOST_TEST((global.reason == R::kToleranceWithoutWindows));
  BOOST_TEST((global.setting == Setting::kWindowPoints));
  BOOST_TEST(global.value == "0");
  BOOST_TEST(global.fallback == 24);
  BOOST_TEST(api({.window_points = 0, .tolerance = true}) ==
             "tolerance marches in windows, but window_points 0 asks for "
             "one global solve; expected window_points >= 8 or no "
             "window_points (24)");
  const Refusal residual =
      CheckSolveRequest({.path = Path::kCeresLm, .extended_residual = true});
  BOOST_TEST((residual.reason == R::kResidualUnused));
  BOOST_TEST((residual.setting == Setting::kExtendedResidual));
  BOOST_TEST(residual.solver == "ceres-lm");
  BOOST_TEST(residual.instead == "newton");
  BOOST_TEST(api({.path = Path::kCeresLm, .extended_residual = true}) ==
             "extended_residual evaluates reduced Newton's residual in long "
             "double, which solver ceres-lm does not use; expected solver "
             "newton, or no extended_residual");
  const Refusal none =
      CheckSolveRequest({.path = Path::kCeresLm, .op = "sbp84"});
  BOOST_TEST((none.reason == R::kNoDefaultWindow));
  BOOST_TEST((none.setting == Setting::kSolver));
  BOOST_TEST(none.value == "ceres-lm");
  BOOST_TEST(none.fallback == 0);
  BOOST_TEST(none.instead == "newton");
  BOOST_TEST(api({.path = Path::kCeresLm, .op = "sbp84"})
                 .find("solver ceres-lm has no default window for "
                       "operator sbp84") == 0u);
  // An explicit window is the user's choice.
  BOOST_TEST(CheckSolveRequest(
                 {.path = Path::kCeresLm, .op = "sbp84", .window_points = 32})
                 .ok());
  // An operator without a table is an error, not a default.
  BOOST_CHECK_THROW(CheckSolveRequest({.op = "sbp105"}), std::invalid_argument);
  BOOST_CHECK_THROW(DefaultWindowPoints(Path::kCeresLm, "sbp105"),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(Scene_SameSentenceAtItsPosition) {
  BOOST_TEST(SceneError(SpringScene("slab_points = 0\ntolerance = 1e-6", "")) ==
             "lm.toml:15:15: a tolerance marches in windows, but slab_points = "
             "0 asks for one global solve; expected slab_points >= 8 or no "
             "slab_points (24)");
  BOOST_TEST(SceneError(SpringScene("operator = \"sbp84\"\nsolver = "
                                    "\"ceres-lm\"",
                                    "points = 1001"))
                 .find("lm.toml:16:10: solver = \"ceres-lm\" has no default "
                       "window for operator = \"sbp84\"") == 0u);
}

BOOST_AUTO_TEST_CASE(Scene_CeresLmMarches) {
  // With slab_points, with its default window, and under error control.
  for (const std::string& method :
       {std::string("solver = \"ceres-lm\"\nslab_points = 32"),
        std::string("solver = \"ceres-lm\"")}) {
    const scene::Scene s =
        scene::ParseScene(SpringScene(method, "points = 1001"), "lm.toml");
    BOOST_TEST(s.method.slab_points > 0);
    NullSink sink;
    const scene::RunOutcome r = scene::RunScene(s, sink);
    BOOST_TEST(r.converged, r.status);
    BOOST_TEST(sink.nodes == 1001);
    // x = cos 2t
    BOOST_TEST(std::abs(r.end_x[0] - std::cos(20.0)) <= 1e-5);
  }
  const scene::Scene e = scene::ParseScene(
      SpringScene("solver = \"ceres-lm\"\ntolerance = 1e-6", ""), "lm.toml");
  BOOST_TEST(e.method.slab_points ==
             DefaultWindowPoints(Path::kCeresLm, "sbp42"));
  NullSink sink;
  const scene::RunOutcome r = scene::RunScene(e, sink);
  BOOST_TEST(r.converged, r.status);
  BOOST_TEST(std::abs(r.end_x[0] - std::cos(20.0)) <= 1e-4);
}
