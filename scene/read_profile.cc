// A field scene's [initial]: a named profile and its parameters (its
// formula, and its exact solution when the terms are those it solves), or a
// CSV file of samples; the initial data on the grid; on a periodic domain
// the jump of the profile's periodic continuation.
#include <ceres/jet.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "problems/fields/exact.h"
#include "problems/fields/profiles.h"
#include "scene/field_profile.h"
#include "scene/field_sections.h"
#include "scene/text.h"
#include "solvers/spacetime/input.h"

namespace vivp::scene::detail {

namespace {

// A profile's keys besides 'profile' and 'allow_jump', with defaults.
const std::vector<ProfileKey>& KeysOf(const std::string& profile) {
  static const std::map<std::string, std::vector<ProfileKey>> keys = {
      {"gaussian",
       {{"amplitude", 1.0, "A"},
        {"width", 1.0, "σ > 0"},
        {"center", 0.0, "ξ"},
        {"velocity", 0.0, "v, φ_t = −v φ_x"}}},
      {"kink", {{"position", 0.0, "x₀"}, {"velocity", 0.0, "v, |v| < 1"}}},
      {"kink_antikink",
       {{"velocity", 0.5, "v, 0 < |v| < 1"},
        {"position", 0.0, "the collision point"},
        {"collision_time", 0.0, "the time they meet"}}},
      {"breather", {{"omega", 0.5, "ω, 0 < ω < 1"}, {"position", 0.0, "x₀"}}},
      {"plane_wave", {{"k", 1.0, "wave number"}, {"amplitude", 1.0, "A"}}},
      {"csv", {}}};
  return keys.at(profile);
}

// Jump tolerance of a periodic continuation, relative to the profile's size:
// far below any discretization error the scene could resolve.
constexpr double kJumpTolerance = 1e-10;

void ComputeInitialData(const TomlReader& r, const toml::node& at,
                        const FieldFormula& formula, FieldScene& s) {
  const int m = s.components;
  const auto grid = s.Grid();
  s.phi0.assign(std::size_t(grid.points()) * m, 0.0);
  s.phi_t0.assign(s.phi0.size(), 0.0);
  double x[3];
  for (int j = 0; j < grid.points(); ++j) {
    for (int a = 0; a < grid.dim(); ++a) x[a] = grid.x(j, a);
    formula(0.0, x, &s.phi0[j * m], &s.phi_t0[j * m]);
    for (int a = 0; a < m; ++a)
      if (!std::isfinite(s.phi0[j * m + a]) ||
          !std::isfinite(s.phi_t0[j * m + a]))
        r.Fail(at,
               "the profile " + Quote(s.initial.profile) +
                   " is not finite at " +
                   (grid.dim() == 1 ? "x = " + FormatNumber(grid.x(j, 0))
                                    : spacetime::PointName(grid, j)),
               "expected parameters for which φ and φ_t are finite numbers");
  }
}

// The scale jumps are measured against: max(1, |φ0|, |φ_t0|) on the grid.
double ProfileSize(const FieldScene& s) {
  double size = 1;
  for (std::size_t k = 0; k < s.phi0.size(); ++k)
    size = std::max({size, std::abs(s.phi0[k]), std::abs(s.phi_t0[k])});
  return size;
}

// A jump in the initial data is refused, or with allow_jump a warning.
void RefuseOrWarnJump(const TomlReader& r, const toml::node& at,
                      const std::string& what, const std::string& expected,
                      FieldScene& s) {
  if (!s.initial.allow_jump) r.Fail(at, what, expected);
  s.warnings.push_back(r.Where(at) + what +
                       "; running it anyway (allow_jump = true)");
}

// |φ(x_last + Δx) − φ(x0)| and the same of φ_t, where the periodic grid
// continues the profile: a jump there is a discontinuity the periodic
// differences would differentiate. On a grid, along every periodic axis at
// each point of its first face.
void CheckPeriodicJump(const TomlReader& r, const toml::node& at,
                       const FieldFormula& formula, FieldScene& s) {
  const int m = s.components;
  const auto grid = s.Grid();
  std::vector<double> a(m), at_a(m), b(m), bt(m);
  double jump = 0, jump_t = 0, worst = 0, x[3];
  std::string where;
  for (int axis = 0; axis < grid.dim(); ++axis) {
    const FieldAxis& line = s.Axis(axis);
    if (line.boundary != "periodic") continue;
    double ja = 0;  // this axis's largest jump of φ or φ_t
    for (int j = 0; j < grid.points(); ++j) {
      if (grid.Coordinate(j, axis) != 0) continue;
      for (int c = 0; c < grid.dim(); ++c) x[c] = grid.x(j, c);
      formula(0.0, x, a.data(), at_a.data());
      x[axis] = line.x1;
      formula(0.0, x, b.data(), bt.data());
      for (int c = 0; c < m; ++c) {
        jump = std::max(jump, std::abs(b[c] - a[c]));
        jump_t = std::max(jump_t, std::abs(bt[c] - at_a[c]));
        ja = std::max({ja, std::abs(b[c] - a[c]), std::abs(bt[c] - at_a[c])});
      }
    }
    // The message names the axis of the largest jump.
    if (ja <= worst) continue;
    worst = ja;
    const std::string range =
        "[" + FormatNumber(line.x0) + ", " + FormatNumber(line.x1) + ")";
    where = grid.dim() == 1 ? range
                            : std::string("axis ") + "xyz"[axis] + " " + range;
  }
  s.initial.jump = jump;
  if (!(std::max(jump, jump_t) > kJumpTolerance * ProfileSize(s))) return;
  const std::string what =
      "the profile " + Quote(s.initial.profile) + " is not periodic on " +
      where +
      ": its periodic continuation jumps by |φ(x_last + Δx) − φ(x0)| = " +
      FormatNumber(jump) + " (|φ_t| by " + FormatNumber(jump_t) + ")";
  RefuseOrWarnJump(r, at, what,
                   "expected a periodic profile, boundary = \"natural\", or "
                   "allow_jump = true in [initial] to run it anyway",
                   s);
}

// At a Dirichlet end the data replace the profile's value: a difference
// there is a jump at t = 0 that the solve would launch as a wave.
void CheckDirichletData(const TomlReader& r, const toml::node& at,
                        FieldScene& s) {
  const int m = s.components;
  const long long nx = s.space_points;
  const double size = ProfileSize(s);
  for (int side = 0; side < 2; ++side) {
    if (s.boundary == "periodic" || s.ends[side] != "dirichlet") continue;
    const std::size_t j = side == 0 ? 0 : std::size_t(nx - 1);
    double jump = 0;
    for (int a = 0; a < m; ++a)
      jump =
          std::max(jump, std::abs(s.phi0[j * m + a] - s.boundary_values[side]));
    if (!(jump > kJumpTolerance * size)) continue;
    const std::string what = "the profile " + Quote(s.initial.profile) +
                             " is " + FormatNumber(s.phi0[j * m]) + " at the " +
                             (side == 0 ? "left" : "right") +
                             " end, the dirichlet value " +
                             FormatNumber(s.boundary_values[side]) +
                             " (a jump of " + FormatNumber(jump) + " at t = 0)";
    RefuseOrWarnJump(
        r, at, what,
        "expected boundary_values that match the profile at the ends, or "
        "allow_jump = true in [initial] to run it anyway",
        s);
  }
}

}  // namespace

// The keys of [initial] for the scene's profile: a number each, or on a
// grid of d axes one number per axis for the vector keys.
void ReadProfileKeys(const TomlReader& r, const toml::table& t,
                     const std::vector<ProfileKey>& keys, FieldScene& s) {
  const std::size_t d = std::size_t(s.Dim());
  for (const auto& k : keys) {
    const toml::node* n = t.get(k.name);
    if (!k.vector) {
      s.initial.parameters[k.name] =
          n ? r.Number(*n, k.name, "a finite number (" + k.meaning + ")")
            : k.fallback;
      continue;
    }
    s.initial.vectors[k.name] =
        n ? r.Numbers(*n, k.name, d,
                      k.name + " = [" +
                          std::string(d == 2 ? "x, y" : "x, y, z") + "], " +
                          k.meaning)
          : std::vector<double>(d, k.fallback);
  }
}

void ReadProfile(const TomlReader& r, const toml::table& root,
                 const std::filesystem::path& base, FieldScene& s) {
  const toml::table& t = r.Table(root, "initial", true);
  const bool grid = s.Dim() > 1;
  const auto& names = s.Charged() ? ChargedProfileNames(s.Dim())
                      : grid      ? ProfileNamesNd()
                                  : FieldProfileNames();
  const toml::node& p =
      r.Require(t, "initial", "profile", "profile = one of " + Join(names));
  s.initial.profile = r.Choice(p, "profile", names);
  const std::vector<ProfileKey> keys = s.Charged() ? ChargedProfileKeys(s)
                                       : grid ? ProfileKeysNd(s.initial.profile)
                                              : KeysOf(s.initial.profile);
  std::vector<std::string> valid = {"profile", "allow_jump"};
  for (const auto& k : keys) valid.push_back(k.name);
  if (s.initial.profile == "csv") valid.push_back("file");
  r.CheckKeys(t, "[initial] of profile " + Quote(s.initial.profile), valid);
  if (const toml::node* n = t.get("allow_jump")) {
    if (!n->is_boolean())
      r.Fail(*n, "'allow_jump' must be true or false, got " + TypeName(*n),
             "expected allow_jump = true to run a profile that is not "
             "periodic on a periodic domain or does not match dirichlet "
             "data");
    s.initial.allow_jump = *n->value<bool>();
  }
  ReadProfileKeys(r, t, keys, s);
  if (s.Charged() && grid) {  // relaxed on the lattice, not a formula
    return MakeVortexProfile(r, t, p, s);
  }
  if (s.initial.profile == "csv") {
    const toml::node& f =
        r.Require(t, "initial", "file",
                  "file = \"samples.csv\", one row φ, φ_t per spatial point");
    ReadProfileCsv(r, f, base, s);
    CheckDirichletData(r, f, s);
    s.no_exact = "a CSV profile has no exact solution";
    return;
  }
  const ProfileFormulas formulas =
      s.Charged() ? MakeChargedProfile(ProfileValues{r, t, s}, s)
      : grid      ? MakeProfileNd(r, t, s)
                  : MakeProfile(r, t, s);
  ComputeInitialData(r, p, formulas.initial, s);
  if (s.Charged()) CheckNeutral(r, p, s);
  if (s.boundary == "periodic" ||
      std::any_of(s.cross_axes.begin(), s.cross_axes.end(),
                  [](const FieldAxis& a) { return a.boundary == "periodic"; }))
    CheckPeriodicJump(r, p, formulas.initial, s);
  if (!grid) CheckDirichletData(r, p, s);
  s.exact = formulas.exact;
  s.no_exact = formulas.no_exact;
}

}  // namespace vivp::scene::detail
