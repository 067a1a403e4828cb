// A field scene's [field] table: the components and the spatial axes. One
// axis takes single values (domain = [x0, x1], points = N, boundary = "…" or
// [left, right]); d = 2 or 3 axes take a list per key, one entry per axis,
// where a single value applies to every axis. The number of axes is the
// domain's; a list of another length is refused, since a value meant for
// one axis and read for another would silently change the problem.
#include <algorithm>

#include "core/sbp/builder.h"
#include "scene/field_sections.h"
#include "scene/sections.h"
#include "scene/text.h"

namespace vivp::scene::detail {

namespace {

constexpr long long kMaxSpacePoints = 1LL << 16;  // per axis
// Every slice of a 2+1- or 3+1-dimensional scene is kept in memory
// (kMaxFieldValues): 2^22 points is a 2048² plane or a 161³ lattice.
constexpr long long kMaxGridPoints = 1LL << 22;

std::string AxisName(int a, int d) {
  if (d == 1) return "";
  return std::string(" of axis ") + std::to_string(a) + " (" + "xyz"[a] + ")";
}

// The entry of `key` for axis a: the key's node itself when it is a single
// value (or the scene has one axis), else the a-th of a list of d entries.
// `single` says what a single value is (a scalar, or a pair for domain and
// boundary_values); d > 1 lists have one entry per axis.
const toml::node* AxisEntry(const TomlReader& r, const toml::table& t,
                            const std::string& key, int a, int d,
                            bool pair_is_single, const std::string& form) {
  const toml::node* n = t.get(key);
  if (!n || d == 1 || !n->is_array()) return n;
  const toml::array& list = *n->as_array();
  // A pair of numbers (domain, boundary_values) or of strings ([left,
  // right]) is one axis's value when its entries are not lists themselves.
  const bool nested = !list.empty() && list.get(0)->is_array();
  if (pair_is_single && !nested) return n;
  if (int(list.size()) != d)
    r.Fail(*n,
           Quote(key) + " has " + std::to_string(list.size()) +
               " entries but the domain has " + std::to_string(d) + " axes",
           "expected one entry per axis, " + key + " = " + form +
               ", or a single value for every axis");
  return list.get(std::size_t(a));
}

void ReadDomain(const TomlReader& r, const toml::node& d, FieldAxis& axis) {
  const std::string domain = "domain = [x0, x1], two finite numbers, x0 < x1";
  const std::vector<double> x = r.Numbers(d, "domain", 2, domain);
  if (!(x[1] > x[0]))
    r.Fail(d,
           "domain = [" + FormatNumber(x[0]) + ", " + FormatNumber(x[1]) +
               "] is empty",
           "expected " + domain);
  axis.x0 = x[0];
  axis.x1 = x[1];
}

// boundary = "periodic" | "natural" | "dirichlet" | "neumann", or [left,
// right] of the last three.
void ReadBoundary(const TomlReader& r, const toml::node* n, FieldAxis& s) {
  const std::vector<std::string> ends = {"natural", "dirichlet", "neumann"};
  if (n && n->is_array()) {
    const toml::array& a = *n->as_array();
    if (a.size() != 2)
      r.Fail(*n, "boundary has " + std::to_string(a.size()) + " entries",
             "expected [left, right], each one of " + Join(ends));
    for (int side = 0; side < 2; ++side)
      s.ends[side] = r.Choice(*a.get(side), "boundary", ends);
    s.boundary =
        s.ends[0] == s.ends[1] ? s.ends[0] : s.ends[0] + "/" + s.ends[1];
  } else if (n) {
    std::vector<std::string> all = {"periodic"};
    all.insert(all.end(), ends.begin(), ends.end());
    s.boundary = r.Choice(*n, "boundary", all);
    if (s.boundary != "periodic") s.ends = {s.boundary, s.boundary};
  }
}

// boundary_values = [left, right] where an end has data.
void ReadBoundaryValues(const TomlReader& r, const toml::node* v, int a, int d,
                        FieldAxis& s) {
  const bool data = s.boundary != "periodic" &&
                    (s.ends[0] != "natural" || s.ends[1] != "natural");
  const std::string expected =
      d == 1 ? "boundary_values = [left, right], φ at a dirichlet end or φ_x "
               "at a neumann one"
             : "boundary_values = [[left, right], …], the slope ∂φ along "
               "each axis at its neumann faces";
  if (!v) return;
  const std::vector<double> x = r.Numbers(*v, "boundary_values", 2, expected);
  if (!data && (d == 1 || x[0] != 0 || x[1] != 0))
    r.Fail(*v,
           "'boundary_values'" + AxisName(a, d) +
               " does not apply to boundary = \"" + s.boundary + "\"",
           d == 1 ? "expected boundary = \"dirichlet\" or \"neumann\" at an end"
                  : "expected [0, 0] for an axis without data, or boundary = "
                    "\"neumann\" on it");
  s.boundary_values = {x[0], x[1]};
}

// space_order on a periodic axis, space_operator on an interval; a value
// for the other kind is refused where it was given for this axis alone.
void ReadOperator(const TomlReader& r, const toml::table& t, int a, int d,
                  bool any_periodic, bool any_bounded, FieldAxis& s) {
  const bool periodic = s.boundary == "periodic";
  const std::string wrong = periodic ? "space_operator" : "space_order";
  const toml::node* list = t.get(wrong);
  const bool per_axis = list && d > 1 && list->is_array();
  if (list && (per_axis || !(periodic ? any_bounded : any_periodic))) {
    const toml::node* n = AxisEntry(r, t, wrong, a, d, false, "[…]");
    if (n)
      r.Fail(*n,
             Quote(wrong) + AxisName(a, d) +
                 " does not apply to boundary = \"" + s.boundary + "\"",
             periodic ? "expected space_order = 2, 4, 6 or 8 for periodic "
                        "differences, or boundary = \"natural\""
                      : "expected space_operator = one of " +
                            Join(sbp::OperatorNames()) + " on an interval");
  }
  if (periodic) {
    if (const toml::node* n =
            AxisEntry(r, t, "space_order", a, d, false, "[8, 8]")) {
      const long long q = r.Whole(*n, "space_order", 2, "2, 4, 6 or 8");
      if (q > 8 || q % 2)
        r.Fail(*n, "space_order = " + std::to_string(q) + " is not offered",
               "expected 2, 4, 6 or 8");
      s.space_order = int(q);
    }
  } else if (const toml::node* n = AxisEntry(r, t, "space_operator", a, d,
                                             false, "[\"sbp42\", …]")) {
    s.space_operator = r.Choice(*n, "space_operator", sbp::OperatorNames());
  }
}

void ReadSpacePoints(const TomlReader& r, const toml::node& n, int a, int d,
                     FieldAxis& s) {
  const bool periodic = s.boundary == "periodic";
  const long long minimum =
      periodic ? s.space_order + 1 : sbp::Table(s.space_operator).min_points;
  const std::string at_least =
      "at least " + std::to_string(minimum) +
      (periodic
           ? " for periodic differences of order " +
                 std::to_string(s.space_order) + " (or a lower space_order)"
           : " for the operator " + s.space_operator);
  s.space_points = r.Whole(n, "points", 0, "a whole number, " + at_least);
  if (s.space_points < minimum)
    r.Fail(n,
           "points = " + std::to_string(s.space_points) + AxisName(a, d) +
               " is too few for the spatial operator",
           "expected " + at_least);
  if (s.space_points > kMaxSpacePoints)
    r.Fail(n, "points = " + std::to_string(s.space_points) + " is too many",
           "expected at most " + std::to_string(kMaxSpacePoints));
  try {
    (void)s.Space();  // any remaining refusal of the operator, at points
  } catch (const std::invalid_argument& e) {
    r.Fail(n, OneLine(e.what()), "expected " + at_least);
  }
}

// The axes' count from the domain: [x0, x1] is one, [[x0, x1], …] d.
std::vector<const toml::node*> Domains(const TomlReader& r,
                                       const toml::node& d) {
  const toml::array* list = d.as_array();
  if (!list || list->empty() || !list->get(0)->is_array()) return {&d};
  if (list->size() > 3)
    r.Fail(d, "domain has " + std::to_string(list->size()) + " axes",
           "expected 1, 2 or 3 axes: [x0, x1] or [[x0, x1], [y0, y1], …]");
  std::vector<const toml::node*> out;
  for (const toml::node& e : *list) out.push_back(&e);
  return out;
}

}  // namespace

void ReadField(const TomlReader& r, const toml::table& root, FieldScene& s) {
  const toml::table& t = r.Table(root, "field", true);
  r.CheckKeys(t, "[field]",
              {"components", "domain", "points", "boundary", "boundary_values",
               "space_order", "space_operator"});
  if (const toml::node* n = t.get("components")) {
    const long long m =
        r.Whole(*n, "components", 1, "1 (a real field) or 2 (a complex one)");
    if (m > 2)
      r.Fail(*n, "components = " + std::to_string(m) + " is not supported",
             "expected 1 (a real field) or 2 (a complex field)");
    s.components = int(m);
  }
  const toml::node& domain =
      r.Require(t, "field", "domain",
                "domain = [x0, x1], or [[x0, x1], [y0, y1]] for two axes");
  const std::vector<const toml::node*> domains = Domains(r, domain);
  const int d = int(domains.size());
  std::vector<FieldAxis> axes(static_cast<std::size_t>(d));
  for (int a = 0; a < d; ++a) {
    ReadDomain(r, *domains[std::size_t(a)], axes[std::size_t(a)]);
    ReadBoundary(r,
                 AxisEntry(r, t, "boundary", a, d, false, "[\"periodic\", …]"),
                 axes[std::size_t(a)]);
  }
  const bool any_periodic = std::any_of(axes.begin(), axes.end(), [](auto& x) {
    return x.boundary == "periodic";
  });
  const bool any_bounded = std::any_of(axes.begin(), axes.end(), [](auto& x) {
    return x.boundary != "periodic";
  });
  const toml::node& points =
      r.Require(t, "field", "points",
                d == 1 ? "points = Nx, the spatial points"
                       : "points = [Nx, Ny, …], the spatial points per axis");
  for (int a = 0; a < d; ++a) {
    FieldAxis& axis = axes[std::size_t(a)];
    ReadBoundaryValues(
        r, AxisEntry(r, t, "boundary_values", a, d, true, "[[0, 0], …]"), a, d,
        axis);
    if (d > 1 && (axis.ends[0] == "dirichlet" || axis.ends[1] == "dirichlet"))
      r.Fail(*AxisEntry(r, t, "boundary", a, d, false, ""),
             "dirichlet faces" + AxisName(a, d) +
                 " are not offered on grids of 2 or 3 axes",
             "expected \"natural\" or \"neumann\" (a prescribed slope ∂φ "
             "along the axis) on that axis");
    ReadOperator(r, t, a, d, any_periodic, any_bounded, axis);
    ReadSpacePoints(r, *AxisEntry(r, t, "points", a, d, false, "[Nx, Ny, …]"),
                    a, d, axis);
  }
  static_cast<FieldAxis&>(s) = axes.front();
  s.cross_axes.assign(axes.begin() + 1, axes.end());
  if (s.GridPoints() > kMaxGridPoints)
    r.Fail(points, "the grid has " + std::to_string(s.GridPoints()) + " points",
           "expected at most " + std::to_string(kMaxGridPoints) +
               " points over all axes");
}

}  // namespace vivp::scene::detail
