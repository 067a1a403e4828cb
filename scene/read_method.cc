// [method]: the kind (variational or a stepper) and, for the variational
// method, the operator, the solver, the windows and the error control.
#include "core/sbp/builder.h"
#include "scene/run.h"
#include "scene/sections.h"
#include "scene/text.h"
#include "solvers/variational/solver_choice.h"

namespace vivp::scene::detail {

variational::Tolerance ReadTolerance(const TomlReader& r, const toml::node& n) {
  const std::string expected =
      "expected tolerance = 1e-6 (absolute and relative) or tolerance = "
      "{absolute = 1e-8, relative = 1e-6}, numbers in [0, 1) with at least "
      "one positive";
  auto value = [&](const toml::node& v, const std::string& key) {
    const double x = r.Number(v, key, "a number in [0, 1)");
    if (!(x >= 0 && x < 1))
      r.Fail(v, Quote(key) + " = " + FormatNumber(x) + " is outside [0, 1)",
             expected);
    return x;
  };
  variational::Tolerance tol;
  if (const toml::table* tt = n.as_table()) {
    r.CheckKeys(*tt, "tolerance", {"absolute", "relative"});
    if (const toml::node* a = tt->get("absolute"))
      tol.absolute = value(*a, "absolute");
    if (const toml::node* rel = tt->get("relative"))
      tol.relative = value(*rel, "relative");
  } else {
    tol.absolute = tol.relative = value(n, "tolerance");
  }
  if (!tol.enabled()) r.Fail(n, "a tolerance of zero cannot be met", expected);
  // Double precision ends near 1e-14 relative; the windows' estimates
  // (round-off of the closure velocity) well before.
  if (tol.relative > 0 && tol.relative < 1e-14)
    r.Fail(n,
           "a relative tolerance of " + FormatNumber(tol.relative) +
               " is beyond double precision",
           "expected a relative tolerance of at least 1e-14 (or 0 with an "
           "absolute one)");
  return tol;
}

namespace {

// The settings of a refusal as a scene writes them: `slab_points = 0`,
// `solver = "ceres-lm"`, and "a tolerance" when one is given.
class SceneSpelling : public variational::SettingSpelling {
 public:
  using Setting = variational::Setting;
  std::string Name(Setting s) const override {
    return s == Setting::kWindowPoints ? "slab_points"
                                       : variational::SettingName(s);
  }
  std::string With(Setting s, const std::string& value) const override {
    const bool text = s == Setting::kSolver || s == Setting::kOperator;
    return Name(s) + " = " + (text ? "\"" + value + "\"" : value);
  }
  std::string Given(Setting s) const override {
    return s == Setting::kTolerance ? "a tolerance" : Name(s);
  }
};

// The combination of solver, windows and tolerance, checked where the
// command line checks it (solver_choice.h), and the window it marches in:
// slab_points as given, else the solver's default (Ceres LM marches; a
// tolerance marches in 48 for Newton), else 0 for one global solve.
void ResolveWindow(const TomlReader& r, const toml::table& method, Scene& s) {
  const toml::node* slab = method.get("slab_points");
  const variational::SolveRequest request{
      .path = variational::ParseSolver(s.method.solver),
      .op = s.method.op,
      .window_points = slab ? s.method.slab_points : -1,
      .tolerance = s.method.tolerance.enabled()};
  const variational::Refusal refusal = CheckSolveRequest(request);
  // At the window when it is given, else at the solver that has no
  // default window.
  const toml::node* at = slab ? slab : method.get("solver");
  if (!refusal.ok()) {
    const variational::RefusalText text = Describe(refusal, SceneSpelling());
    r.Fail(at ? *at : *method.get("tolerance"), text.what, text.expected);
  }
  s.method.slab_points = WindowPoints(request);
}

}  // namespace

void ReadMethod(const TomlReader& r, const toml::table& root, Scene& s) {
  const toml::table& t = r.Table(root, "method", false);
  r.CheckKeys(t, "[method]",
              {"kind", "operator", "solver", "slab_points", "tolerance"});
  if (const toml::node* n = t.get("kind"))
    s.method.kind = r.Choice(*n, "kind", MethodKinds());
  if (!s.variational()) {
    for (const char* key : {"operator", "solver", "slab_points", "tolerance"})
      if (const toml::node* n = t.get(key))
        r.Fail(*n, Quote(key) + " applies to kind = \"variational\" only",
               "expected no " + Quote(key) + " for the stepper " +
                   Quote(s.method.kind));
    const std::string why = StepperUnavailable(s);
    if (!why.empty())
      r.Fail(*t.get("kind"), "kind = \"" + s.method.kind + "\" " + why,
             "expected kind = \"variational\"");
    return;
  }
  if (const toml::node* n = t.get("operator"))
    s.method.op = r.Choice(*n, "operator", sbp::OperatorNames());
  if (const toml::node* n = t.get("solver"))
    s.method.solver = r.Choice(*n, "solver", variational::SolverNames());
  if (const toml::node* n = t.get("slab_points"))
    s.method.slab_points =
        r.Whole(*n, "slab_points", 0,
                "0 (one global solve) or at least " +
                    std::to_string(sbp::Table(s.method.op).min_points) +
                    " for " + s.method.op);
  if (const toml::node* n = t.get("tolerance"))
    s.method.tolerance = ReadTolerance(r, *n);
  ResolveWindow(r, t, s);
}

}  // namespace vivp::scene::detail
