#include "scene/scene.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "scene/reference.h"
#include "scene/registered.h"
#include "scene/run.h"
#include "core/sbp/builder.h"
#include "solvers/steppers/methods.h"

namespace vivp::scene {

namespace {

// Rothkopf & Nordström 2023, Fig. 14: the damped oscillator at late time
// (the scene of scenes/fig14_damped_late.toml).
constexpr std::string_view kDefaultScene =
    R"toml(# vivp's default scene: Rothkopf & Nordström 2023, Fig. 14
title = "Damped oscillator at late time (Rothkopf & Nordström 2023, Fig. 14)"

[system]
dof = 1

[[effect]]
type = "kinetic"
mass = 0.5

[[effect]]
type = "spring"
k = 1.0

[[effect]]
type = "damping"
xi = 0.00071

[initial]
x = [1.0]
v = [0.0]

[time]
end = 204.8
points = 2048

[method]
kind = "variational"
operator = "sbp42"
solver = "newton"

[output]
diagnostics = ["energy", "error"]
reference = "exact"
)toml";

// Global solves hold every node (and a banded LU) at once; beyond this a
// typo such as points = 1e9 would exhaust memory instead of failing.
constexpr long long kMaxGlobalPoints = 1LL << 22;
// Marching and steppers stream, but at ~10^7 points/s more than this is a
// run of hours: most likely a mistake.
constexpr long long kMaxPoints = 1LL << 28;

std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1,
                         diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string Join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// " (did you mean 'x'?)" when a valid name is close to the given one.
std::string Suggest(const std::string& given,
                    const std::vector<std::string>& valid) {
  std::string best;
  std::size_t best_distance = 3;  // at most two edits away
  for (const auto& v : valid) {
    const std::size_t d = EditDistance(given, v);
    if (d < best_distance) {
      best_distance = d;
      best = v;
    }
  }
  return best.empty() ? "" : " (did you mean '" + best + "'?)";
}

// Messages are one line: control characters from the file are shown escaped.
std::string OneLine(std::string_view s) {
  std::string out;
  for (const char c : s) {
    if (c == '\n')
      out += "\\n";
    else if (c == '\t')
      out += "\\t";
    else if (c == '\r')
      out += "\\r";
    else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned char>(c));
      out += buf;
    } else {
      out += c;
    }
  }
  return out;
}

std::string Quote(const std::string& s) { return "'" + OneLine(s) + "'"; }

// "1 finite number", "3 finite numbers".
std::string FiniteNumbers(int n) {
  return std::to_string(n) + (n == 1 ? " finite number" : " finite numbers");
}

std::string TypeName(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "a whole number";
    case toml::node_type::floating_point:
      return "a number";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    default:
      return "a date or time";
  }
}

std::string FormatNumber(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  Scene Read(std::string_view text) {
    toml::table root;
    try {
      root = toml::parse(text, source_);
    } catch (const toml::parse_error& e) {
      const auto& at = e.source().begin;
      throw SceneError(Where(int(at.line), int(at.column)) +
                       OneLine(e.description()) +
                       "; expected a TOML scene (see 'vivp run --help')");
    }
    Scene s;
    s.source = source_;
    CheckKeys(
        root, "the top level",
        {"title", "system", "effect", "initial", "time", "method", "output"});
    if (const toml::node* t = root.get("title"))
      s.title = String(*t, "title", "a short text");
    ReadSystem(root, s);
    ReadEffects(root, s);
    ReadMethod(root, s);  // before [time]: the operator sets the minimum
    ReadInitial(root, s);
    ReadTime(root, s);
    ReadOutput(root, s);
    return s;
  }

 private:
  std::string source_;

  std::string Where(int line, int column) const {
    return source_ + ":" + std::to_string(std::max(line, 1)) + ":" +
           std::to_string(std::max(column, 1)) + ": ";
  }
  std::string Where(const toml::node& n) const {
    return Where(int(n.source().begin.line), int(n.source().begin.column));
  }
  [[noreturn]] void Fail(const toml::node& at, const std::string& what,
                         const std::string& expected) const {
    throw SceneError(Where(at) + what + "; " + expected);
  }
  [[noreturn]] void Fail(int line, int column, const std::string& what,
                         const std::string& expected) const {
    throw SceneError(Where(line, column) + what + "; " + expected);
  }

  void CheckKeys(const toml::table& t, const std::string& where,
                 const std::vector<std::string>& valid) const {
    for (const auto& [key, node] : t) {
      const std::string k(key.str());
      if (std::find(valid.begin(), valid.end(), k) == valid.end()) {
        const auto& pos = key.source().begin;
        Fail(int(pos.line), int(pos.column),
             "unknown key " + Quote(k) + " in " + where + Suggest(k, valid),
             "expected one of " + Join(valid));
      }
    }
  }

  const toml::table& Table(const toml::table& root, const std::string& name,
                           bool required) const {
    static const toml::table kEmpty;
    const toml::node* n = root.get(name);
    if (!n) {
      if (required)
        Fail(1, 1, "the scene has no [" + name + "] table",
             "expected a [" + name + "] section (see 'vivp run --help')");
      return kEmpty;
    }
    if (!n->is_table())
      Fail(*n, Quote(name) + " is " + TypeName(*n),
           "expected a [" + name + "] table");
    return *n->as_table();
  }

  const toml::node& Require(const toml::table& t, const std::string& table,
                            const std::string& key,
                            const std::string& expected) const {
    const toml::node* n = t.get(key);
    if (!n) {
      const auto& pos = t.source().begin;
      Fail(int(pos.line), int(pos.column),
           "[" + table + "] is missing " + Quote(key), "expected " + expected);
    }
    return *n;
  }

  std::string String(const toml::node& n, const std::string& key,
                     const std::string& expected) const {
    if (!n.is_string())
      Fail(n, Quote(key) + " must be a string, got " + TypeName(n),
           "expected " + expected);
    return std::string(*n.value<std::string_view>());
  }

  std::string Choice(const toml::node& n, const std::string& key,
                     const std::vector<std::string>& valid) const {
    const std::string v = String(n, key, "one of " + Join(valid));
    if (std::find(valid.begin(), valid.end(), v) == valid.end())
      Fail(n, Quote(v) + " is not a valid " + key + Suggest(v, valid),
           "expected one of " + Join(valid));
    return v;
  }

  double Number(const toml::node& n, const std::string& key,
                const std::string& expected) const {
    double v = 0;
    if (n.is_integer())
      v = double(*n.value<int64_t>());
    else if (n.is_floating_point())
      v = *n.value<double>();
    else
      Fail(n, Quote(key) + " must be a number, got " + TypeName(n),
           "expected " + expected);
    if (!std::isfinite(v))
      Fail(n, Quote(key) + " must be finite, got " + FormatNumber(v),
           "expected " + expected);
    return v;
  }

  long long Whole(const toml::node& n, const std::string& key,
                  long long minimum, const std::string& expected) const {
    if (!n.is_integer())
      Fail(n, Quote(key) + " must be a whole number, got " + TypeName(n),
           "expected " + expected);
    const long long v = *n.value<int64_t>();
    if (v < minimum)
      Fail(n, Quote(key) + " = " + std::to_string(v) + " is too small",
           "expected " + expected);
    return v;
  }

  std::vector<double> Numbers(const toml::node& n, const std::string& key,
                              std::size_t count,
                              const std::string& expected) const {
    const toml::array* a = n.as_array();
    if (!a)
      Fail(n, Quote(key) + " must be an array, got " + TypeName(n),
           "expected " + expected);
    if (a->size() != count)
      Fail(n,
           Quote(key) + " has " + std::to_string(a->size()) +
               (a->size() == 1 ? " entry" : " entries"),
           "expected " + expected);
    std::vector<double> out;
    for (const toml::node& e : *a) out.push_back(Number(e, key, expected));
    return out;
  }

  void ReadSystem(const toml::table& root, Scene& s) const {
    const toml::table& t = Table(root, "system", true);
    CheckKeys(t, "[system]", {"dof"});
    const toml::node& n =
        Require(t, "system", "dof", "dof = N, the number of coordinates");
    s.dof = int(std::min<long long>(Whole(n, "dof", 1, "a whole number >= 1"),
                                    1 << 20));
    dof_node_ = &n;
  }

  // The [[effect]] tables. The dof check waits for a registered Lagrangian,
  // which fixes its own.
  void ReadEffects(const toml::table& root, Scene& s) const {
    const toml::node* n = root.get("effect");
    if (!n)
      Fail(1, 1, "the scene lists no effect",
           "expected at least one [[effect]] table with a type, one of " +
               EffectNameList());
    const toml::array* list = n->as_array();
    if (!list || !list->is_array_of_tables())
      Fail(*n, "'effect' must be an array of tables",
           "expected [[effect]] sections, each with type = \"...\"");
    for (const toml::node& item : *list)
      s.effects.push_back(ReadEffect(*item.as_table(), s));
    const EffectType* registered = s.registered();
    int registered_count = 0;
    for (const auto& e : s.effects) registered_count += e.type->dof > 0;
    if (registered_count > 1)
      Fail(s.effects.back().line, s.effects.back().column,
           "a scene may use one registered Lagrangian, this one lists " +
               std::to_string(registered_count),
           "expected a single registered type");
    if (registered && s.dof != registered->dof)
      Fail(*dof_node_,
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
        Fail(*dof_node_,
             "dof = " + std::to_string(s.dof) +
                 " is not among the compiled sizes",
             "expected one of " + Join(names) +
                 " (add the size to VIVP_SCENE_DOFS in apps/CMakeLists.txt)");
      }
    }
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
      Fail(s.effects.front().line, s.effects.front().column,
           "the effects give no equation of motion (no kinetic energy and no "
           "first-order term)",
           "expected a 'kinetic' effect (second order) or 'growth' (first "
           "order)");
    s.order = kinetic ? 2 : 1;
  }

  EffectSpec ReadEffect(const toml::table& t, const Scene& s) const {
    EffectSpec spec;
    spec.line = int(t.source().begin.line);
    spec.column = int(t.source().begin.column);
    std::vector<std::string> names;
    for (const auto& type : EffectCatalogue()) names.push_back(type.name);
    const toml::node& type_node =
        Require(t, "[effect]", "type", "type = one of " + EffectNameList());
    const std::string type =
        String(type_node, "type", "one of " + EffectNameList());
    spec.type = FindEffectType(type);
    if (!spec.type)
      Fail(type_node,
           "unknown effect type " + Quote(type) + Suggest(type, names),
           "expected one of " + EffectNameList());
    std::vector<std::string> keys = {"type"};
    for (const auto& p : spec.type->parameters) keys.push_back(p.name);
    CheckKeys(t, "effect " + Quote(type), keys);
    const int given_exclusive = int(
        std::count_if(spec.type->exclusive.begin(), spec.type->exclusive.end(),
                      [&](const std::string& k) { return t.contains(k); }));
    if (given_exclusive > 1)
      Fail(
          t,
          "effect " + Quote(type) + " gives both " + Join(spec.type->exclusive),
          "expected at most one of them");
    for (const auto& p : spec.type->parameters) {
      if (const toml::node* n = t.get(p.name))
        spec.values[p.name] = Parameter(*n, type, p, s.dof);
      else if (!p.fallback.empty())
        spec.values[p.name] = Fallback(p, s.dof);
    }
    if (spec.type->exclusive.size() > 1 && given_exclusive == 1)
      for (const auto& k : spec.type->exclusive)
        if (!t.contains(k)) spec.values.erase(k);
    return spec;
  }

  std::vector<double> Fallback(const ParameterSpec& p, int dof) const {
    if (p.kind == ParameterKind::kVector)
      return std::vector<double>(std::size_t(dof), p.fallback[0]);
    if (p.kind == ParameterKind::kAxis && p.fallback[0] < 0)
      return {double(dof - 1)};
    return p.fallback;
  }

  std::vector<double> Parameter(const toml::node& n, const std::string& type,
                                const ParameterSpec& p, int dof) const {
    const std::string what = Quote(p.name) + " of effect " + Quote(type);
    const std::string expected =
        "expected " + DescribeKind(p.kind, dof) + " (" + p.meaning + ")";
    auto number = [&](const toml::node& e) {
      if (!e.is_integer() && !e.is_floating_point())
        Fail(e, what + " must be a number, got " + TypeName(e), expected);
      const double v =
          e.is_integer() ? double(*e.value<int64_t>()) : *e.value<double>();
      if (!std::isfinite(v))
        Fail(e, what + " must be finite, got " + FormatNumber(v), expected);
      return v;
    };
    switch (p.kind) {
      case ParameterKind::kReal:
        return {number(n)};
      case ParameterKind::kPositive: {
        const double v = number(n);
        if (!(v > 0))
          Fail(n, what + " must be positive, got " + FormatNumber(v), expected);
        return {v};
      }
      case ParameterKind::kNonNegative: {
        const double v = number(n);
        if (v < 0)
          Fail(n, what + " must not be negative, got " + FormatNumber(v),
               expected);
        return {v};
      }
      case ParameterKind::kBool:
        if (!n.is_boolean())
          Fail(n, what + " must be true or false, got " + TypeName(n),
               expected);
        return {*n.value<bool>() ? 1.0 : 0.0};
      case ParameterKind::kAxis: {
        if (!n.is_integer())
          Fail(n, what + " must be a whole number, got " + TypeName(n),
               expected);
        const long long v = *n.value<int64_t>();
        if (v < 0 || v >= dof)
          Fail(n, what + " = " + std::to_string(v) + " is not a coordinate",
               expected);
        return {double(v)};
      }
      case ParameterKind::kVector: {
        const toml::array* a = n.as_array();
        if (!a)
          Fail(n, what + " must be an array, got " + TypeName(n), expected);
        if (int(a->size()) != dof)
          Fail(n, what + " has " + std::to_string(a->size()) + " entries",
               expected);
        std::vector<double> out;
        for (const toml::node& e : *a) out.push_back(number(e));
        return out;
      }
      case ParameterKind::kMatrix: {
        const toml::array* a = n.as_array();
        if (!a || int(a->size()) != dof)
          Fail(n, what + " must have " + std::to_string(dof) + " rows",
               expected);
        std::vector<double> out;
        for (const toml::node& row : *a) {
          const toml::array* r = row.as_array();
          if (!r || int(r->size()) != dof)
            Fail(row,
                 what + ": every row must be an array of " +
                     std::to_string(dof) + " numbers",
                 expected);
          for (const toml::node& e : *r) out.push_back(number(e));
        }
        if (!SymmetricPositiveDefinite(out, dof))
          Fail(n, what + " is not symmetric positive definite", expected);
        return out;
      }
    }
    return {};
  }

  static bool SymmetricPositiveDefinite(const std::vector<double>& m, int d) {
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

  void ReadMethod(const toml::table& root, Scene& s) const {
    const toml::table& t = Table(root, "method", false);
    CheckKeys(t, "[method]",
              {"kind", "operator", "solver", "slab_points", "tolerance"});
    if (const toml::node* n = t.get("kind"))
      s.method.kind = Choice(*n, "kind", MethodKinds());
    if (!s.variational()) {
      for (const char* key : {"operator", "solver", "slab_points", "tolerance"})
        if (const toml::node* n = t.get(key))
          Fail(*n, Quote(key) + " applies to kind = \"variational\" only",
               "expected no " + Quote(key) + " for the stepper " +
                   Quote(s.method.kind));
      const std::string why = StepperUnavailable(s);
      if (!why.empty())
        Fail(*t.get("kind"), "kind = \"" + s.method.kind + "\" " + why,
             "expected kind = \"variational\"");
      return;
    }
    std::vector<std::string> ops(sbp::kOperatorNames.begin(),
                                 sbp::kOperatorNames.end());
    if (const toml::node* n = t.get("operator"))
      s.method.op = Choice(*n, "operator", ops);
    if (const toml::node* n = t.get("solver"))
      s.method.solver =
          Choice(*n, "solver", {"newton", "full-newton", "ceres-lm"});
    if (const toml::node* n = t.get("slab_points")) {
      const long long minimum = sbp::Table(s.method.op).min_points;
      s.method.slab_points =
          Whole(*n, "slab_points", 0,
                "0 (one global solve) or at least " + std::to_string(minimum) +
                    " for " + s.method.op);
      if (s.method.slab_points > 0 && s.method.slab_points < minimum)
        Fail(*n,
             "slab_points = " + std::to_string(s.method.slab_points) +
                 " is below the minimum of " + std::to_string(minimum) +
                 " for " + s.method.op,
             "expected 0 (one global solve) or at least " +
                 std::to_string(minimum));
      if (s.method.slab_points > 0 && s.method.solver == "ceres-lm")
        Fail(*n, "solver = \"ceres-lm\" solves globally and cannot march",
             "expected slab_points = 0, or solver = \"newton\"");
    }
    if (const toml::node* n = t.get("tolerance")) ReadTolerance(t, *n, s);
  }

  // tolerance = 1e-6 (absolute and relative) or {absolute = …, relative = …}.
  void ReadTolerance(const toml::table& method, const toml::node& n,
                     Scene& s) const {
    const std::string expected =
        "expected tolerance = 1e-6 (absolute and relative) or tolerance = "
        "{absolute = 1e-8, relative = 1e-6}, numbers in [0, 1) with at least "
        "one positive";
    auto value = [&](const toml::node& v, const std::string& key) {
      const double x = Number(v, key, "a number in [0, 1)");
      if (!(x >= 0 && x < 1))
        Fail(v, Quote(key) + " = " + FormatNumber(x) + " is outside [0, 1)",
             expected);
      return x;
    };
    Tolerance tol;
    if (const toml::table* tt = n.as_table()) {
      CheckKeys(*tt, "tolerance", {"absolute", "relative"});
      if (const toml::node* a = tt->get("absolute"))
        tol.absolute = value(*a, "absolute");
      if (const toml::node* r = tt->get("relative"))
        tol.relative = value(*r, "relative");
    } else {
      tol.absolute = tol.relative = value(n, "tolerance");
    }
    if (!tol.enabled()) Fail(n, "a tolerance of zero cannot be met", expected);
    // Double precision ends near 1e-14 relative; the windows' estimates
    // (round-off of the closure velocity) well before.
    if (tol.relative > 0 && tol.relative < 1e-14)
      Fail(n,
           "a relative tolerance of " + FormatNumber(tol.relative) +
               " is beyond double precision",
           "expected a relative tolerance of at least 1e-14 (or 0 with an "
           "absolute one)");
    if (s.method.solver == "ceres-lm")
      Fail(n, "solver = \"ceres-lm\" solves globally and cannot march",
           "expected no tolerance, or solver = \"newton\"");
    if (const toml::node* w = method.get("slab_points");
        w && s.method.slab_points == 0)
      Fail(*w,
           "slab_points = 0 asks for one global solve, but a tolerance "
           "marches in windows",
           "expected slab_points >= " +
               std::to_string(sbp::Table(s.method.op).min_points) +
               " or no slab_points (48)");
    if (s.method.slab_points == 0) s.method.slab_points = 48;
    s.method.tolerance = tol;
  }

  void ReadInitial(const toml::table& root, Scene& s) const {
    const toml::table& t = Table(root, "initial", true);
    CheckKeys(t, "[initial]", {"x", "v"});
    const std::string n = std::to_string(s.dof);
    const std::string array =
        "an array of " + FiniteNumbers(s.dof) + " (dof = " + n + ")";
    s.x0 = Numbers(
        Require(t, "initial", "x", "x = [...], " + n + " initial positions"),
        "x", std::size_t(s.dof), array);
    const toml::node* v = t.get("v");
    if (s.order == 2) {
      if (!v) {
        const auto& pos = t.source().begin;
        Fail(int(pos.line), int(pos.column),
             "[initial] has no velocity 'v' but the system is second order "
             "(it has kinetic energy)",
             "expected v = [...] with " + FiniteNumbers(s.dof));
      }
      s.v0 = Numbers(*v, "v", std::size_t(s.dof), array);
    } else if (v) {
      Fail(*v,
           "[initial] gives a velocity but the system is first order (no "
           "kinetic energy: the initial position fixes the solution)",
           "expected no 'v' in [initial]");
    }
  }

  void ReadTime(const toml::table& root, Scene& s) const {
    const toml::table& t = Table(root, "time", true);
    CheckKeys(t, "[time]", {"start", "end", "points"});
    if (const toml::node* n = t.get("start"))
      s.t_start = Number(*n, "start", "a finite start time");
    const toml::node& end =
        Require(t, "time", "end", "end = T, the final time");
    s.t_end = Number(end, "end", "a finite end time after start");
    if (!(s.t_end > s.t_start))
      Fail(end,
           "end = " + FormatNumber(s.t_end) +
               " is not after start = " + FormatNumber(s.t_start),
           "expected end > start");
    const long long minimum =
        s.variational() ? sbp::Table(s.method.op).min_points : 2;
    const std::string at_least =
        "at least " + std::to_string(minimum) +
        (s.variational() ? " for " + s.method.op : std::string(""));
    if (s.method.tolerance.enabled()) {
      // The march chooses the nodes.
      if (const toml::node* p = t.get("points"))
        Fail(*p,
             "points and [method] tolerance exclude each other: the tolerance "
             "chooses the grid",
             "expected no points (error control), or no tolerance (a uniform "
             "grid of that many points)");
      return;
    }
    const toml::node& points =
        Require(t, "time", "points",
                "points = N, the number of grid nodes (or [method] tolerance)");
    s.points = Whole(points, "points", 0, "a whole number, " + at_least);
    if (s.points < minimum)
      Fail(points,
           "points = " + std::to_string(s.points) + " is below the minimum",
           "expected " + at_least);
    const bool global = s.variational() && s.method.slab_points == 0;
    const long long maximum = global ? kMaxGlobalPoints : kMaxPoints;
    if (s.points > maximum)
      Fail(points,
           "points = " + std::to_string(s.points) + " is too many" +
               (global ? " for one global solve" : ""),
           "expected at most " + std::to_string(maximum) +
               (global ? " (or march: [method] slab_points = 48)" : ""));
    if (s.method.slab_points > s.points)
      Fail(*root.get("method")->as_table()->get("slab_points"),
           "slab_points = " + std::to_string(s.method.slab_points) +
               " exceeds points = " + std::to_string(s.points),
           "expected slab_points <= points");
  }

  void ReadOutput(const toml::table& root, Scene& s) const {
    const toml::table& t = Table(root, "output", false);
    CheckKeys(t, "[output]", {"diagnostics", "reference", "stride"});
    if (const toml::node* n = t.get("reference"))
      s.output.reference = Choice(*n, "reference", ReferenceNames());
    if (const toml::node* n = t.get("stride"))
      s.output.stride = Whole(*n, "stride", 1, "a whole number >= 1");
    if (const toml::node* n = t.get("diagnostics")) {
      const toml::array* a = n->as_array();
      if (!a)
        Fail(*n, "'diagnostics' must be an array, got " + TypeName(*n),
             "expected e.g. diagnostics = [\"energy\"], names from " +
                 Join(DiagnosticNames()));
      for (const toml::node& e : *a) {
        const std::string d = Choice(e, "diagnostic", DiagnosticNames());
        if (s.Wants(d))
          Fail(e, "diagnostic " + Quote(d) + " is listed twice",
               "expected each diagnostic once");
        if (d == "error" && s.output.reference == "none")
          Fail(e, "diagnostic 'error' needs a reference solution",
               "expected reference = \"exact\" or \"ode\" in [output]");
        if (d == "energy" && s.order == 1)
          Fail(e, "diagnostic 'energy' needs a second-order system",
               "expected a 'kinetic' effect, or no 'energy'");
        if (d == "angular_momentum" && s.dof != 2 && s.dof != 3)
          Fail(e,
               "diagnostic 'angular_momentum' needs dof = 2 or 3, not " +
                   std::to_string(s.dof),
               "expected dof = 2 or 3, or no 'angular_momentum'");
        s.output.diagnostics.push_back(d);
      }
    }
    if (s.output.reference == "exact") {
      const std::string why = ExactSolutionUnavailable(s);
      if (!why.empty())
        Fail(*t.get("reference"), "reference = \"exact\": " + why,
             "expected reference = \"ode\" (the Euler–Lagrange equations "
             "by automatic differentiation, integrated to 1e-13) or \"none\"");
    }
  }

  mutable const toml::node* dof_node_ = nullptr;
};

}  // namespace

bool Scene::Wants(const std::string& diagnostic) const {
  return std::find(output.diagnostics.begin(), output.diagnostics.end(),
                   diagnostic) != output.diagnostics.end();
}

bool Scene::dissipative() const {
  return std::any_of(effects.begin(), effects.end(),
                     [](const EffectSpec& e) { return e.type->dissipative; });
}

const EffectType* Scene::registered() const {
  for (const auto& e : effects)
    if (e.type->dof > 0) return e.type;
  return nullptr;
}

Scene ParseScene(std::string_view text, const std::string& source) {
  return Reader(source).Read(text);
}

Scene ReadScene(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(file, ec))
    throw SceneError(file.string() + ":1:1: cannot read the scene file (" +
                     (std::filesystem::exists(file, ec) ? "not a readable file"
                                                        : "no such file") +
                     "); expected the path of a TOML scene file");
  const std::string text((std::istreambuf_iterator<char>(in)),
                         std::istreambuf_iterator<char>());
  return ParseScene(text, file.string());
}

std::string_view DefaultSceneText() { return kDefaultScene; }

const std::vector<std::string>& MethodKinds() {
  static const std::vector<std::string> kinds = [] {
    std::vector<std::string> k = {"variational"};
    for (const auto& m : steppers::MethodNames()) k.push_back(m);
    return k;
  }();
  return kinds;
}

const std::vector<std::string>& DiagnosticNames() {
  static const std::vector<std::string> names = {"energy", "momentum",
                                                 "angular_momentum", "error"};
  return names;
}

const std::vector<std::string>& ReferenceNames() {
  static const std::vector<std::string> names = {"none", "exact", "ode"};
  return names;
}

nlohmann::json SceneJson(const Scene& s) {
  nlohmann::json effects = nlohmann::json::array();
  for (const auto& e : s.effects) {
    nlohmann::json j = {{"type", e.type->name}};
    for (const auto& p : e.type->parameters) {
      auto it = e.values.find(p.name);
      if (it == e.values.end()) continue;
      const auto& v = it->second;
      switch (p.kind) {
        case ParameterKind::kBool:
          j[p.name] = v[0] != 0;
          break;
        case ParameterKind::kAxis:
          j[p.name] = int(v[0]);
          break;
        case ParameterKind::kVector:
          j[p.name] = v;
          break;
        case ParameterKind::kMatrix: {
          nlohmann::json rows = nlohmann::json::array();
          for (int r = 0; r < s.dof; ++r)
            rows.push_back(std::vector<double>(v.begin() + r * s.dof,
                                               v.begin() + (r + 1) * s.dof));
          j[p.name] = rows;
          break;
        }
        default:
          j[p.name] = v[0];
      }
    }
    effects.push_back(j);
  }
  nlohmann::json initial = {{"x", s.x0}};
  if (s.order == 2) initial["v"] = s.v0;
  nlohmann::json method = {{"kind", s.method.kind}};
  if (s.variational()) {
    method["operator"] = s.method.op;
    method["solver"] = s.method.solver;
    method["slab_points"] = s.method.slab_points;
    if (s.method.tolerance.enabled())
      method["tolerance"] = {{"absolute", s.method.tolerance.absolute},
                             {"relative", s.method.tolerance.relative}};
  }
  return {{"source", s.source},
          {"title", s.title},
          {"system", {{"dof", s.dof}, {"order", s.order}}},
          {"effect", effects},
          {"initial", initial},
          {"time",
           {{"start", s.t_start},
            {"end", s.t_end},
            {"points", s.points > 0 ? nlohmann::json(s.points) : nullptr}}},
          {"method", method},
          {"output",
           {{"diagnostics", s.output.diagnostics},
            {"reference", s.output.reference},
            {"stride", s.output.stride}}}};
}

std::string SchemaHelp() {
  std::ostringstream h;
  h << "Scene file (TOML):\n"
       "  title = \"...\"                 optional\n"
       "  [system]     dof = N            number of coordinates\n"
       "  [[effect]]   type = \"...\"       one table per effect, with its "
       "parameters\n"
       "  [initial]    x = [...]          N positions\n"
       "               v = [...]          N velocities (second-order systems "
       "only)\n"
       "  [time]       start = 0.0        optional\n"
       "               end = T            final time, > start\n"
       "               points = Nt        grid nodes, both ends included (not "
       "with a tolerance)\n"
       "  [method]     kind = \"variational\" | "
    << Join(steppers::MethodNames())
    << "\n"
       "               operator = \"sbp42\"  sbp21 | sbp42 | sbp63 | sbp84 "
       "(variational)\n"
       "               solver = \"newton\"   newton | full-newton | ceres-lm "
       "(variational)\n"
       "               slab_points = 0    march in windows of this many "
       "points (0: global)\n"
       "               tolerance = 1e-6   error control (variational): every "
       "node within\n"
       "                                  absolute + relative·|value| of the "
       "local flow;\n"
       "                                  or {absolute = ..., relative = ...}; "
       "no [time] points\n"
       "  [output]     diagnostics = []   energy, momentum, angular_momentum, "
       "error\n"
       "               reference = \"none\" none | exact (closed form) | ode "
       "(Euler–Lagrange by AD, integrated to 1e-13)\n"
       "               stride = 1         write every stride-th node\n\n"
       "Effects (parameter = default):\n";
  for (const auto& t : EffectCatalogue()) {
    h << "  " << t.name << ": " << t.formula << "\n   ";
    for (const auto& p : t.parameters) {
      h << " " << p.name;
      if (!p.fallback.empty() && p.kind != ParameterKind::kMatrix) {
        if (p.kind == ParameterKind::kBool)
          h << " = " << (p.fallback[0] != 0 ? "true" : "false");
        else if (p.kind == ParameterKind::kAxis && p.fallback[0] < 0)
          h << " = last";
        else
          h << " = " << FormatNumber(p.fallback[0])
            << (p.kind == ParameterKind::kVector ? " (each)" : "");
      } else {
        h << " (optional)";
      }
      h << ";";
    }
    if (t.dof > 0) h << " [registered C++ Lagrangian, dof = " << t.dof << "]";
    h << "\n";
  }
  return h.str();
}

}  // namespace vivp::scene
