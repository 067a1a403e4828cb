// [system] and the [[effect]] tables: the number of coordinates, each
// effect's type and parameters, and the order of the equations of motion.
#include <algorithm>
#include <cmath>

#include "scene/registered.h"
#include "scene/run.h"
#include "scene/sections.h"
#include "scene/text.h"

namespace vivp::scene::detail {

namespace {

bool SymmetricPositiveDefinite(const std::vector<double>& m, int d) {
  for (int r = 0; r < d; ++r)
    for (int c = 0; c < r; ++c)
      if (m[r * d + c] != m[c * d + r]) return false;
  // Cholesky: every pivot positive.
  std::vector<double> l(m);
  for (int j = 0; j < d; ++j) {
    double pivot = l[j * d + j];
    for (int k = 0; k < j; ++k) pivot -= l[j * d + k] * l[j * d + k];
    if (!(pivot > 0)) return false;
    const double root = std::sqrt(pivot);
    l[j * d + j] = root;
    for (int i = j + 1; i < d; ++i) {
      double v = l[i * d + j];
      for (int k = 0; k < j; ++k) v -= l[i * d + k] * l[j * d + k];
      l[i * d + j] = v / root;
    }
  }
  return true;
}

// The value of one parameter of an effect, checked against its kind; the
// messages name the parameter and the effect.
class ParameterReader {
 public:
  ParameterReader(const TomlReader& r, const std::string& noun,
                  const std::string& type, const ParameterSpec& p, int dof)
      : r_(r),
        what_(Quote(p.name) + " of " + noun + " " + Quote(type)),
        expected_("expected " + DescribeKind(p.kind, dof) + " (" + p.meaning +
                  ")"),
        dof_(dof) {}

  std::vector<double> Read(const toml::node& n, ParameterKind kind) const {
    switch (kind) {
      case ParameterKind::kReal:
        return {Number(n)};
      case ParameterKind::kPositive: {
        const double v = Number(n);
        if (!(v > 0))
          r_.Fail(n, what_ + " must be positive, got " + FormatNumber(v),
                  expected_);
        return {v};
      }
      case ParameterKind::kNonNegative: {
        const double v = Number(n);
        if (v < 0)
          r_.Fail(n, what_ + " must not be negative, got " + FormatNumber(v),
                  expected_);
        return {v};
      }
      case ParameterKind::kBool:
        if (!n.is_boolean())
          r_.Fail(n, what_ + " must be true or false, got " + TypeName(n),
                  expected_);
        return {*n.value<bool>() ? 1.0 : 0.0};
      case ParameterKind::kAxis:
        return {Axis(n)};
      case ParameterKind::kVector:
        return Vector(n);
      case ParameterKind::kMatrix:
        return Matrix(n);
    }
    return {};
  }

 private:
  double Number(const toml::node& e) const {
    if (!e.is_integer() && !e.is_floating_point())
      r_.Fail(e, what_ + " must be a number, got " + TypeName(e), expected_);
    const double v =
        e.is_integer() ? double(*e.value<int64_t>()) : *e.value<double>();
    if (!std::isfinite(v))
      r_.Fail(e, what_ + " must be finite, got " + FormatNumber(v), expected_);
    return v;
  }

  double Axis(const toml::node& n) const {
    if (!n.is_integer())
      r_.Fail(n, what_ + " must be a whole number, got " + TypeName(n),
              expected_);
    const long long v = *n.value<int64_t>();
    if (v < 0 || v >= dof_)
      r_.Fail(n, what_ + " = " + std::to_string(v) + " is not a coordinate",
              expected_);
    return double(v);
  }

  std::vector<double> Vector(const toml::node& n) const {
    const toml::array* a = n.as_array();
    if (!a)
      r_.Fail(n, what_ + " must be an array, got " + TypeName(n), expected_);
    if (int(a->size()) != dof_)
      r_.Fail(n, what_ + " has " + std::to_string(a->size()) + " entries",
              expected_);
    std::vector<double> out;
    for (const toml::node& e : *a) out.push_back(Number(e));
    return out;
  }

  std::vector<double> Matrix(const toml::node& n) const {
    const toml::array* a = n.as_array();
    if (!a || int(a->size()) != dof_)
      r_.Fail(n, what_ + " must have " + std::to_string(dof_) + " rows",
              expected_);
    std::vector<double> out;
    for (const toml::node& row : *a) {
      const toml::array* r = row.as_array();
      if (!r || int(r->size()) != dof_)
        r_.Fail(row,
                what_ + ": every row must be an array of " +
                    std::to_string(dof_) + " numbers",
                expected_);
      for (const toml::node& e : *r) out.push_back(Number(e));
    }
    if (!SymmetricPositiveDefinite(out, dof_))
      r_.Fail(n, what_ + " is not symmetric positive definite", expected_);
    return out;
  }

  const TomlReader& r_;
  const std::string what_;
  const std::string expected_;
  const int dof_;
};

std::vector<double> Fallback(const ParameterSpec& p, int dof) {
  if (p.kind == ParameterKind::kVector)
    return std::vector<double>(std::size_t(dof), p.fallback[0]);
  if (p.kind == ParameterKind::kAxis && p.fallback[0] < 0)
    return {double(dof - 1)};
  return p.fallback;
}

}  // namespace

// A table naming its type among `catalogue` (an [[effect]] or a [[term]],
// the noun of the messages) and giving that type's parameters.
ListedEffect ReadTypedTable(const TomlReader& r, const toml::table& t,
                            const std::vector<EffectType>& catalogue,
                            const std::string& noun, int dof) {
  ListedEffect spec;
  spec.line = int(t.source().begin.line);
  spec.column = int(t.source().begin.column);
  std::vector<std::string> names;
  for (const auto& type : catalogue) names.push_back(type.name);
  const toml::node& type_node =
      r.Require(t, "[" + noun + "]", "type", "type = one of " + Join(names));
  const std::string type = r.String(type_node, "type", "one of " + Join(names));
  for (const auto& c : catalogue)
    if (c.name == type) spec.type = &c;
  if (!spec.type)
    r.Fail(type_node,
           "unknown " + noun + " type " + Quote(type) + Suggest(type, names),
           "expected one of " + Join(names));
  std::vector<std::string> keys = {"type"};
  for (const auto& p : spec.type->parameters) keys.push_back(p.name);
  r.CheckKeys(t, noun + " " + Quote(type), keys);
  const int given_exclusive = int(
      std::count_if(spec.type->exclusive.begin(), spec.type->exclusive.end(),
                    [&](const std::string& k) { return t.contains(k); }));
  if (given_exclusive > 1)
    r.Fail(
        t,
        noun + " " + Quote(type) + " gives both " + Join(spec.type->exclusive),
        "expected at most one of them");
  for (const auto& p : spec.type->parameters) {
    if (const toml::node* n = t.get(p.name))
      spec.values[p.name] =
          ParameterReader(r, noun, type, p, dof).Read(*n, p.kind);
    else if (!p.fallback.empty())
      spec.values[p.name] = Fallback(p, dof);
  }
  if (spec.type->exclusive.size() > 1 && given_exclusive == 1)
    for (const auto& k : spec.type->exclusive)
      if (!t.contains(k)) spec.values.erase(k);
  return spec;
}

namespace {

// The dof fixed by [system] against the effects: a registered Lagrangian
// fixes its own, built-in effects need one of the compiled sizes.
void CheckDof(const TomlReader& r, const toml::node& dof_node, const Scene& s) {
  const EffectType* registered = s.registered();
  int registered_count = 0;
  for (const auto& e : s.effects) registered_count += e.type->dof > 0;
  if (registered_count > 1)
    r.Fail(s.effects.back().line, s.effects.back().column,
           "a scene may use one registered Lagrangian, this one lists " +
               std::to_string(registered_count),
           "expected a single registered type");
  if (registered && s.dof != registered->dof)
    r.Fail(dof_node,
           "dof = " + std::to_string(s.dof) +
               " but the registered Lagrangian " + Quote(registered->name) +
               " has " + std::to_string(registered->dof) +
               " degrees of freedom",
           "expected dof = " + std::to_string(registered->dof));
  if (!registered) {
    const auto& dofs = SupportedDofs();
    if (std::find(dofs.begin(), dofs.end(), s.dof) == dofs.end()) {
      std::vector<std::string> names;
      for (int d : dofs) names.push_back(std::to_string(d));
      r.Fail(
          dof_node,
          "dof = " + std::to_string(s.dof) + " is not among the compiled sizes",
          "expected one of " + Join(names) +
              " (configure with the size added to VIVP_DIMS, e.g. cmake "
              "-DVIVP_DIMS=\"1;2;3;8;4\")");
    }
  }
}

}  // namespace

const toml::node& ReadSystem(const TomlReader& r, const toml::table& root,
                             Scene& s) {
  const toml::table& t = r.Table(root, "system", true);
  r.CheckKeys(t, "[system]", {"dof"});
  const toml::node& n =
      r.Require(t, "system", "dof", "dof = N, the number of coordinates");
  s.dof = int(std::min<long long>(r.Whole(n, "dof", 1, "a whole number >= 1"),
                                  1 << 20));
  return n;
}

// The [[effect]] tables. The dof check waits for a registered Lagrangian,
// which fixes its own.
void ReadEffects(const TomlReader& r, const toml::table& root,
                 const toml::node& dof_node, Scene& s) {
  const toml::node* n = root.get("effect");
  if (!n)
    r.Fail(1, 1, "the scene lists no effect",
           "expected at least one [[effect]] table with a type, one of " +
               EffectNameList());
  const toml::array* list = n->as_array();
  if (!list || !list->is_array_of_tables())
    r.Fail(*n, "'effect' must be an array of tables",
           "expected [[effect]] sections, each with type = \"...\"");
  for (const toml::node& item : *list)
    s.effects.push_back(ReadTypedTable(r, *item.as_table(), EffectCatalogue(),
                                       "effect", s.dof));
  CheckDof(r, dof_node, s);
  // Second order when some term has kinetic energy; first order when a
  // growth term gives ẋ; neither leaves no equation of motion at all.
  bool kinetic = false, first = false;
  for (const auto& e : s.effects) {
    kinetic = kinetic || e.type->kinetic ||
              (e.type->dof > 0 && RegisteredOrder(*e.type) == 2);
    first = first || e.type->first_order ||
            (e.type->dof > 0 && RegisteredOrder(*e.type) == 1);
  }
  if (!kinetic && !first)
    r.Fail(s.effects.front().line, s.effects.front().column,
           "the effects give no equation of motion (no kinetic energy and no "
           "first-order term)",
           "expected a 'kinetic' effect (second order) or 'growth' (first "
           "order)");
  s.order = kinetic ? 2 : 1;
}

}  // namespace vivp::scene::detail
