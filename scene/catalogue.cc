#include "scene/catalogue.h"

#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>

#include "scene/registered.h"
#include "scene/spec_table.h"

namespace vivp::scene {

namespace {

using K = ParameterKind;

// Calls f.template operator()<E>() for every alternative E of Effect.
template <class F>
void ForEachEffect(F&& f) {
  detail::ForEachAlternative<problems::Effect>(f);
}

}  // namespace

const std::vector<EffectType>& BuiltInEffects() {
  static const std::vector<EffectType> built_in = [] {
    std::vector<EffectType> t;
    ForEachEffect([&]<class E>() { t.push_back(detail::TypeOf<E>()); });
    return t;
  }();
  return built_in;
}
// Built once, at first use after static initialization, when every
// registration is in.
const std::vector<EffectType>& EffectCatalogue() {
  static const std::vector<EffectType> catalogue = [] {
    std::vector<EffectType> all = BuiltInEffects();
    for (const auto& r : RegisteredLagrangians()) all.push_back(r.type);
    return all;
  }();
  return catalogue;
}

const EffectType* FindEffectType(const std::string& name) {
  for (const auto& t : EffectCatalogue())
    if (t.name == name) return &t;
  return nullptr;
}

std::string EffectNameList() {
  std::string out;
  for (const auto& t : EffectCatalogue())
    out += (out.empty() ? "" : ", ") + t.name;
  return out;
}

std::string DescribeKind(ParameterKind kind, int dof) {
  const std::string n = std::to_string(dof);
  switch (kind) {
    case K::kReal:
      return "a finite number";
    case K::kPositive:
      return "a finite number > 0";
    case K::kNonNegative:
      return "a finite number >= 0";
    case K::kVector:
      return "an array of " + n + " finite numbers";
    case K::kMatrix:
      return "a symmetric positive definite " + n + "x" + n +
             " array of arrays";
    case K::kBool:
      return "true or false";
    case K::kAxis:
      return "a whole number from 0 to " + std::to_string(dof - 1);
  }
  return "?";
}

problems::Effect MakeEffect(const EffectType& type, const ParameterValues& v) {
  std::optional<problems::Effect> made;
  ForEachEffect([&]<class E>() {
    if (!made && E::Spec().name == type.name) made = detail::Build<E>(v);
  });
  if (!made)
    throw std::logic_error("effect '" + type.name +
                           "' has no built-in effect struct");
  return *made;
}
}  // namespace vivp::scene
