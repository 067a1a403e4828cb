#include "scene/toml_reader.h"

#include <algorithm>
#include <cmath>

#include "scene/text.h"

namespace vivp::scene::detail {

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

std::string TomlReader::Where(int line, int column) const {
  return source_ + ":" + std::to_string(std::max(line, 1)) + ":" +
         std::to_string(std::max(column, 1)) + ": ";
}

std::string TomlReader::Where(const toml::node& n) const {
  return Where(int(n.source().begin.line), int(n.source().begin.column));
}

void TomlReader::Fail(const toml::node& at, const std::string& what,
                      const std::string& expected) const {
  throw SceneError(Where(at) + what + "; " + expected);
}

void TomlReader::Fail(int line, int column, const std::string& what,
                      const std::string& expected) const {
  throw SceneError(Where(line, column) + what + "; " + expected);
}

void TomlReader::CheckKeys(const toml::table& t, const std::string& where,
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

const toml::table& TomlReader::Table(const toml::table& root,
                                     const std::string& name,
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

const toml::node& TomlReader::Require(const toml::table& t,
                                      const std::string& table,
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

std::string TomlReader::String(const toml::node& n, const std::string& key,
                               const std::string& expected) const {
  if (!n.is_string())
    Fail(n, Quote(key) + " must be a string, got " + TypeName(n),
         "expected " + expected);
  return std::string(*n.value<std::string_view>());
}

std::string TomlReader::Choice(const toml::node& n, const std::string& key,
                               const std::vector<std::string>& valid) const {
  const std::string v = String(n, key, "one of " + Join(valid));
  if (std::find(valid.begin(), valid.end(), v) == valid.end())
    Fail(n, Quote(v) + " is not a valid " + key + Suggest(v, valid),
         "expected one of " + Join(valid));
  return v;
}

double TomlReader::Number(const toml::node& n, const std::string& key,
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

long long TomlReader::Whole(const toml::node& n, const std::string& key,
                            long long minimum,
                            const std::string& expected) const {
  if (!n.is_integer())
    Fail(n, Quote(key) + " must be a whole number, got " + TypeName(n),
         "expected " + expected);
  const long long v = *n.value<int64_t>();
  if (v < minimum)
    Fail(n, Quote(key) + " = " + std::to_string(v) + " is too small",
         "expected " + expected);
  return v;
}

std::vector<double> TomlReader::Numbers(const toml::node& n,
                                        const std::string& key,
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

}  // namespace vivp::scene::detail
