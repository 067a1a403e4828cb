// [output]: the diagnostics, the reference solution and the stride, each
// checked against the system it is for.
#include <algorithm>

#include "scene/reference.h"
#include "scene/sections.h"
#include "scene/text.h"

namespace vivp::scene::detail {

std::vector<std::string> ReadDiagnosticList(
    const TomlReader& r, const toml::node& n,
    const std::vector<std::string>& valid,
    const std::function<void(const toml::node&, const std::string&)>& check) {
  const toml::array* a = n.as_array();
  if (!a)
    r.Fail(
        n, "'diagnostics' must be an array, got " + TypeName(n),
        "expected e.g. diagnostics = [\"energy\"], names from " + Join(valid));
  std::vector<std::string> out;
  for (const toml::node& e : *a) {
    const std::string d = r.Choice(e, "diagnostic", valid);
    if (std::find(out.begin(), out.end(), d) != out.end())
      r.Fail(e, "diagnostic " + Quote(d) + " is listed twice",
             "expected each diagnostic once");
    check(e, d);
    out.push_back(d);
  }
  return out;
}

void ReadOutput(const TomlReader& r, const toml::table& root, Scene& s) {
  const toml::table& t = r.Table(root, "output", false);
  r.CheckKeys(t, "[output]", {"diagnostics", "reference", "stride"});
  if (const toml::node* n = t.get("reference"))
    s.output.reference = r.Choice(*n, "reference", ReferenceNames());
  if (const toml::node* n = t.get("stride"))
    s.output.stride = r.Whole(*n, "stride", 1, "a whole number >= 1");
  if (const toml::node* n = t.get("diagnostics"))
    s.output.diagnostics = ReadDiagnosticList(
        r, *n, DiagnosticNames(),
        [&](const toml::node& e, const std::string& d) {
          if (d == "error" && s.output.reference == "none")
            r.Fail(e, "diagnostic 'error' needs a reference solution",
                   "expected reference = \"exact\" or \"ode\" in [output]");
          if (d == "energy" && s.order == 1)
            r.Fail(e, "diagnostic 'energy' needs a second-order system",
                   "expected a 'kinetic' effect, or no 'energy'");
          if (d == "angular_momentum" && s.dof != 2 && s.dof != 3)
            r.Fail(e,
                   "diagnostic 'angular_momentum' needs dof = 2 or 3, not " +
                       std::to_string(s.dof),
                   "expected dof = 2 or 3, or no 'angular_momentum'");
        });
  if (s.output.reference == "exact") {
    const std::string why = ExactSolutionUnavailable(s);
    if (!why.empty())
      r.Fail(*t.get("reference"), "reference = \"exact\": " + why,
             "expected reference = \"ode\" (the Euler–Lagrange equations "
             "by automatic differentiation, integrated to 1e-13) or \"none\"");
  }
}

}  // namespace vivp::scene::detail
