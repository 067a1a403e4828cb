// The scene reader: what a scene means once read, and every kind of bad
// input rejected with one message FILE:LINE:COL: what; expected.
#define BOOST_TEST_MODULE scene_reader
#include <boost/test/unit_test.hpp>
#include <regex>
#include <string>

#include "scene/run.h"
#include "scene/scene.h"

using namespace vivp::scene;

namespace {

// A valid scene; the cases below replace one of its lines.
const std::vector<std::string> kBase = {
    "[system]",            // 1
    "dof = 1",             // 2
    "",                    // 3
    "[[effect]]",          // 4
    "type = \"kinetic\"",  // 5
    "mass = 0.5",          // 6
    "",                    // 7
    "[[effect]]",          // 8
    "type = \"spring\"",   // 9
    "k = 1.0",             // 10
    "",                    // 11
    "[initial]",           // 12
    "x = [1.0]",           // 13
    "v = [0.0]",           // 14
    "",                    // 15
    "[time]",              // 16
    "end = 10.0",          // 17
    "points = 101",        // 18
};

// kBase with line `line` (1-based) replaced, and more lines appended.
std::string With(int line, const std::string& text,
                 const std::vector<std::string>& more = {}) {
  std::string out;
  for (std::size_t i = 0; i < kBase.size(); ++i)
    out += (int(i) + 1 == line ? text : kBase[i]) + "\n";
  for (const auto& m : more) out += m + "\n";
  return out;
}

std::string ErrorOf(const std::string& text) {
  try {
    ParseScene(text, "bad.toml");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "no error";
}

const std::string kEffects =
    "kinetic, gravity, spring, quartic, pendulum, central, gaussian_well, "
    "chain, damping, growth, cyclotron";

}  // namespace

BOOST_AUTO_TEST_CASE(BaseScene_ReadsWithItsDefaults) {
  const Scene s = ParseScene(With(0, ""), "good.toml");
  BOOST_TEST(s.dof == 1);
  BOOST_TEST(s.order == 2);
  BOOST_TEST(s.effects.size() == 2u);
  BOOST_TEST(s.effects[1].values.at("centre") == std::vector<double>{0.0});
  BOOST_TEST(s.t_start == 0.0);
  BOOST_TEST(s.points == 101);
  BOOST_TEST(s.method.kind == "variational");
  BOOST_TEST(s.method.op == "sbp42");
  BOOST_TEST(s.method.solver == "newton");
  BOOST_TEST(s.output.reference == "none");
  BOOST_TEST(s.output.diagnostics.empty());
}

BOOST_AUTO_TEST_CASE(DiagnosticsAndReference_AreComputedOnlyWhenAsked) {
  struct Counting : RunSink {
    void Begin(const RunLayout& l) override { layout = l; }
    void Node(double, const double*, const double*, const double*) override {
      ++nodes;
    }
    RunLayout layout;
    int nodes = 0;
  };
  Counting bare;
  RunScene(ParseScene(With(0, ""), "a.toml"), bare);
  BOOST_TEST(bare.layout.columns.empty());
  BOOST_TEST(bare.layout.reference_x == -1);
  BOOST_TEST(bare.nodes == 101);

  Counting energy;
  RunScene(ParseScene(
               With(0, "",
                    {"[output]", "diagnostics = [\"energy\"]", "stride = 10"}),
               "b.toml"),
           energy);
  BOOST_TEST(energy.layout.columns == std::vector<std::string>{"energy"});
  BOOST_TEST(energy.nodes == 11);  // nodes 0, 10, …, 100
}

BOOST_AUTO_TEST_CASE(BadInput_UnknownEffectTypeNamesTheValidOnesAndTheNearest) {
  BOOST_TEST(ErrorOf(With(9, "type = \"sprng\"")) ==
             "bad.toml:9:8: unknown effect type 'sprng' (did you mean "
             "'spring'?); expected one of " +
                 kEffects);
}

BOOST_AUTO_TEST_CASE(BadInput_MistypedParameter) {
  BOOST_TEST(ErrorOf(With(10, "k = \"stiff\"")) ==
             "bad.toml:10:5: 'k' of effect 'spring' must be a number, got a "
             "string; expected a finite number >= 0 (stiffness k)");
}

BOOST_AUTO_TEST_CASE(BadInput_UnknownParameter) {
  BOOST_TEST(ErrorOf(With(10, "stiffness = 1.0")) ==
             "bad.toml:10:1: unknown key 'stiffness' in effect 'spring'; "
             "expected one of type, k, centre");
}

BOOST_AUTO_TEST_CASE(BadInput_UnknownKeyWithSuggestion) {
  BOOST_TEST(ErrorOf(With(18, "pionts = 101")) ==
             "bad.toml:18:1: unknown key 'pionts' in [time] (did you mean "
             "'points'?); expected one of start, end, points");
}

BOOST_AUTO_TEST_CASE(BadInput_UnknownTable) {
  BOOST_TEST(ErrorOf(With(0, "", {"[methods]", "kind = \"rk4\""})) ==
             "bad.toml:19:2: unknown key 'methods' in the top level (did you "
             "mean 'method'?); expected one of title, system, effect, "
             "initial, time, method, output");
}

BOOST_AUTO_TEST_CASE(BadInput_NonFiniteNumber) {
  BOOST_TEST(ErrorOf(With(17, "end = inf")) ==
             "bad.toml:17:7: 'end' must be finite, got inf; expected a finite "
             "end time after start");
  BOOST_TEST(ErrorOf(With(10, "k = nan")) ==
             "bad.toml:10:5: 'k' of effect 'spring' must be finite, got nan; "
             "expected a finite number >= 0 (stiffness k)");
}

BOOST_AUTO_TEST_CASE(BadInput_NonPositiveMass) {
  BOOST_TEST(ErrorOf(With(6, "mass = -0.5")) ==
             "bad.toml:6:8: 'mass' of effect 'kinetic' must be positive, got "
             "-0.5; expected a finite number > 0 (scalar mass m)");
  BOOST_TEST(ErrorOf(With(6, "mass = 0")) ==
             "bad.toml:6:8: 'mass' of effect 'kinetic' must be positive, got "
             "0; expected a finite number > 0 (scalar mass m)");
}

BOOST_AUTO_TEST_CASE(BadInput_MassMatrixNotPositiveDefinite) {
  const std::string text = With(2, "dof = 2", {});
  std::string scene = text;
  scene.replace(scene.find("mass = 0.5"), 10,
                "matrix = [[1.0, 2.0], [2.0, 1.0]]");
  scene.replace(scene.find("x = [1.0]"), 9, "x = [1.0, 0.0]");
  scene.replace(scene.find("v = [0.0]"), 9, "v = [0.0, 0.0]");
  BOOST_TEST(ErrorOf(scene) ==
             "bad.toml:6:10: 'matrix' of effect 'kinetic' is not symmetric "
             "positive definite; expected a symmetric positive definite 2x2 "
             "array of arrays (symmetric positive definite M, dof rows "
             "(instead of mass))");
}

BOOST_AUTO_TEST_CASE(BadInput_PointsBelowTheOperatorMinimum) {
  BOOST_TEST(ErrorOf(With(18, "points = 5")) ==
             "bad.toml:18:10: points = 5 is below the minimum; expected at "
             "least 8 for sbp42");
  BOOST_TEST(
      ErrorOf(With(18, "points = 12", {"[method]", "operator = \"sbp84\""})) ==
      "bad.toml:18:10: points = 12 is below the minimum; expected at "
      "least 16 for sbp84");
}

BOOST_AUTO_TEST_CASE(BadInput_EndNotAfterStart) {
  BOOST_TEST(ErrorOf(With(17, "end = -1.0")) ==
             "bad.toml:17:7: end = -1 is not after start = 0; expected end > "
             "start");
}

BOOST_AUTO_TEST_CASE(BadInput_InitialDataOfTheWrongLength) {
  BOOST_TEST(ErrorOf(With(13, "x = [1.0, 2.0]")) ==
             "bad.toml:13:5: 'x' has 2 entries; expected an array of 1 finite "
             "number (dof = 1)");
}

BOOST_AUTO_TEST_CASE(BadInput_VelocityForAFirstOrderSystem) {
  std::string scene = With(5, "type = \"growth\"");
  scene.replace(scene.find("mass = 0.5"), 10, "kappa = 0.5");
  scene.replace(scene.find("type = \"spring\""), 15, "type = \"quartic\"");
  scene.replace(scene.find("k = 1.0"), 7, "kappa = 1.0");
  BOOST_TEST(ErrorOf(scene) ==
             "bad.toml:14:5: [initial] gives a velocity but the system is "
             "first order (no kinetic energy: the initial position fixes the "
             "solution); expected no 'v' in [initial]");
}

BOOST_AUTO_TEST_CASE(BadInput_NoVelocityForASecondOrderSystem) {
  BOOST_TEST(ErrorOf(With(14, "")) ==
             "bad.toml:12:1: [initial] has no velocity 'v' but the system is "
             "second order (it has kinetic energy); expected v = [...] with 1 "
             "finite number");
}

BOOST_AUTO_TEST_CASE(BadInput_UnreadableFile) {
  try {
    ReadScene("/nonexistent/scene.toml");
    BOOST_FAIL("no error");
  } catch (const SceneError& e) {
    BOOST_TEST(std::string(e.what()) ==
               "/nonexistent/scene.toml:1:1: cannot read the scene file (no "
               "such file); expected the path of a TOML scene file");
  }
}

BOOST_AUTO_TEST_CASE(BadInput_TomlSyntax) {
  BOOST_TEST(ErrorOf(With(17, "end = ")) ==
             "bad.toml:17:7: Error while parsing key-value pair: expected "
             "value, saw '\\n'; expected a TOML scene (see 'vivp run --help')");
}

BOOST_AUTO_TEST_CASE(BadInput_UnknownOperatorSuggestsTheNearest) {
  BOOST_TEST(ErrorOf(With(0, "", {"[method]", "operator = \"sbp44\""})) ==
             "bad.toml:20:12: 'sbp44' is not a valid operator (did you mean "
             "'sbp42'?); expected one of sbp21, sbp42, sbp63, sbp84");
}

BOOST_AUTO_TEST_CASE(BadInput_StepperOnADissipativeSystem) {
  BOOST_TEST(ErrorOf(With(0, "",
                          {"[[effect]]", "type = \"damping\"", "[method]",
                           "kind = \"gauss2\""})) ==
             "bad.toml:22:8: kind = \"gauss2\" needs a Hamiltonian system, "
             "but effect 'damping' is dissipative (a Λ term); expected kind = "
             "\"variational\"");
}

BOOST_AUTO_TEST_CASE(BadInput_VariationalKeyForAStepper) {
  BOOST_TEST(
      ErrorOf(With(0, "",
                   {"[method]", "kind = \"rk4\"", "operator = \"sbp42\""})) ==
      "bad.toml:21:12: 'operator' applies to kind = \"variational\" "
      "only; expected no 'operator' for the stepper 'rk4'");
}

BOOST_AUTO_TEST_CASE(BadInput_DofNotCompiled) {
  // The list is the build's VIVP_DIMS (default 1, 2, 3, 8; the
  // sanitizer build of .ci/run compiles 1 and 2 only).
  std::string sizes;
  for (const int d : SupportedDofs())
    sizes += (sizes.empty() ? "" : ", ") + std::to_string(d);
  BOOST_TEST(ErrorOf(With(2, "dof = 5")) ==
             "bad.toml:2:7: dof = 5 is not among the compiled sizes; expected "
             "one of " +
                 sizes +
                 " (configure with the size added to VIVP_DIMS, e.g. cmake "
                 "-DVIVP_DIMS=\"1;2;3;8;4\")");
}

BOOST_AUTO_TEST_CASE(BadInput_NoEquationOfMotion) {
  std::string scene = With(5, "type = \"gravity\"");
  scene.replace(scene.find("mass = 0.5"), 10, "g = 9.81");
  BOOST_TEST(ErrorOf(scene) ==
             "bad.toml:4:1: the effects give no equation of motion (no "
             "kinetic energy and no first-order term); expected a 'kinetic' "
             "effect (second order) or 'growth' (first order)");
}

BOOST_AUTO_TEST_CASE(BadInput_ExactReferenceWithoutAClosedForm) {
  BOOST_TEST(ErrorOf(With(0, "",
                          {"[[effect]]", "type = \"gaussian_well\"", "[output]",
                           "reference = \"exact\""})) ==
             "bad.toml:22:13: reference = \"exact\": no closed form for "
             "gaussian_well + kinetic + spring; closed forms exist for linear "
             "systems (kinetic, spring, gravity, damping, growth, chain with "
             "beta = 0), kinetic + quartic (dof 1), kinetic + pendulum (dof "
             "1, librating) and kinetic + central (dof 2, bound orbit); "
             "expected reference = \"ode\" (the Euler–Lagrange equations by "
             "automatic differentiation, integrated to 1e-13) or \"none\"");
}

BOOST_AUTO_TEST_CASE(BadInput_ErrorDiagnosticWithoutReference) {
  BOOST_TEST(ErrorOf(With(0, "", {"[output]", "diagnostics = [\"error\"]"})) ==
             "bad.toml:20:16: diagnostic 'error' needs a reference solution; "
             "expected reference = \"exact\" or \"ode\" in [output]");
}

BOOST_AUTO_TEST_CASE(BadInput_RegisteredLagrangianWithTheWrongDof) {
  BOOST_TEST(ErrorOf(With(5, "type = \"cyclotron\"")) ==
             "bad.toml:6:1: unknown key 'mass' in effect 'cyclotron'; "
             "expected one of type, B");
  std::string scene = With(5, "type = \"cyclotron\"");
  scene.replace(scene.find("mass = 0.5"), 10, "B = 1.0");
  BOOST_TEST(ErrorOf(scene) ==
             "bad.toml:2:7: dof = 1 but the registered Lagrangian 'cyclotron' "
             "has 2 degrees of freedom; expected dof = 2");
}

BOOST_AUTO_TEST_CASE(CeresLm_MarchesInItsWindowUnlessSlabPointsSays) {
  const Scene given = ParseScene(
      With(0, "", {"[method]", "solver = \"ceres-lm\"", "slab_points = 32"}),
      "a.toml");
  BOOST_TEST(given.method.slab_points == 32);
  const Scene global = ParseScene(
      With(0, "", {"[method]", "solver = \"ceres-lm\"", "slab_points = 0"}),
      "b.toml");
  BOOST_TEST(global.method.slab_points == 0);
  // The default window (sbp42: 128) is longer than the 101 points: one.
  const Scene fallback =
      ParseScene(With(0, "", {"[method]", "solver = \"ceres-lm\""}), "c.toml");
  BOOST_TEST(fallback.method.slab_points == 101);
  // SBP84 has none (tests/lm_march_test.cc).
}

BOOST_AUTO_TEST_CASE(BadInput_TooManyPointsForAGlobalSolve) {
  BOOST_TEST(ErrorOf(With(18, "points = 1000000000")) ==
             "bad.toml:18:10: points = 1000000000 is too many for one global "
             "solve; expected at most 4194304 (or march: [method] slab_points "
             "= 48)");
}

BOOST_AUTO_TEST_CASE(Tolerance_MarchesUnderErrorControl) {
  // A number sets both parts; a table each; the march then chooses the
  // nodes ([time] has no points) in windows of 48 unless slab_points says.
  const Scene a =
      ParseScene(With(18, "", {"[method]", "tolerance = 1e-6"}), "a.toml");
  BOOST_TEST(a.method.tolerance.absolute == 1e-6);
  BOOST_TEST(a.method.tolerance.relative == 1e-6);
  BOOST_TEST(a.method.slab_points == 24);
  BOOST_TEST(a.points == 0);
  const Scene b =
      ParseScene(With(18, "",
                      {"[method]", "slab_points = 32",
                       "tolerance = {absolute = 1e-9, relative = 1e-7}"}),
                 "b.toml");
  BOOST_TEST(b.method.tolerance.absolute == 1e-9);
  BOOST_TEST(b.method.tolerance.relative == 1e-7);
  BOOST_TEST(b.method.slab_points == 32);
  BOOST_TEST(SceneJson(b)["method"]["tolerance"]["relative"] == 1e-7);
  BOOST_TEST(SceneJson(b)["time"]["points"].is_null());
}

BOOST_AUTO_TEST_CASE(BadInput_Tolerance) {
  BOOST_TEST(ErrorOf(With(0, "", {"[method]", "tolerance = 1e-6"})) ==
             "bad.toml:18:10: points and [method] tolerance exclude each "
             "other: the tolerance chooses the grid; expected no points "
             "(error control), or no tolerance (a uniform grid of that many "
             "points)");
  BOOST_TEST(ErrorOf(With(18, "", {"[method]", "tolerance = 0"})) ==
             "bad.toml:20:13: a tolerance of zero cannot be met; expected "
             "tolerance = 1e-6 (absolute and relative) or tolerance = "
             "{absolute = 1e-8, relative = 1e-6}, numbers in [0, 1) with at "
             "least one positive");
  BOOST_TEST(ErrorOf(With(18, "", {"[method]", "tolerance = 1.5"}))
                 .find("bad.toml:20:13: 'tolerance' = 1.5 is outside [0, 1)") ==
             0u);
  BOOST_TEST(ErrorOf(With(18, "", {"[method]", "tolerance = -1e-6"}))
                 .find("is outside [0, 1)") != std::string::npos);
  BOOST_TEST(ErrorOf(With(18, "", {"[method]", "tolerance = 1e-16"})) ==
             "bad.toml:20:13: a relative tolerance of 1e-16 is beyond double "
             "precision; expected a relative tolerance of at least 1e-14 (or "
             "0 with an absolute one)");
  BOOST_TEST(ErrorOf(With(18, "",
                          {"[method]",
                           "tolerance = {relative = 1e-6, "
                           "absolut = 1e-8}"}))
                 .find("unknown key 'absolut' in tolerance (did you mean "
                       "'absolute'?)") != std::string::npos);
  BOOST_TEST(
      ErrorOf(
          With(18, "", {"[method]", "slab_points = 0", "tolerance = 1e-6"})) ==
      "bad.toml:20:15: a tolerance marches in windows, but slab_points = 0 "
      "asks for one global solve; expected slab_points >= 8 or no "
      "slab_points (24)");
  BOOST_TEST(ErrorOf(With(
                 18, "", {"[method]", "kind = \"rk4\"", "tolerance = 1e-6"})) ==
             "bad.toml:21:13: 'tolerance' applies to kind = \"variational\" "
             "only; expected no 'tolerance' for the stepper 'rk4'");
  BOOST_TEST(ParseScene(With(18, "",
                             {"[method]", "solver = \"ceres-lm\"",
                              "tolerance = 1e-6"}),
                        "lm.toml")
                 .method.slab_points == 128);
}

BOOST_AUTO_TEST_CASE(BadInput_EveryMessageHasTheFileLineColumnForm) {
  // The form the CLI promises, on a sample of the cases above.
  const std::regex form(R"(^bad\.toml:\d+:\d+: [^\n]+; expected [^\n]+$)");
  for (const auto& text :
       {With(9, "type = 3"), With(2, "dof = 0"), With(2, "dof = \"one\""),
        With(18, "points = 10.5"), With(0, "", {"title = 7"}),
        With(0, "", {"[output]", "stride = 0"}),
        With(0, "", {"[output]", "diagnostics = [\"energy\", \"energy\"]"}),
        With(0, "", {"[output]", "diagnostics = [\"angular_momentum\"]"}),
        With(10, "k = [1.0]"), With(0, "", {"effect = 3"})}) {
    const std::string e = ErrorOf(text);
    BOOST_TEST(std::regex_match(e, form), e);
  }
}
