#include "scene/catalogue.h"

#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>

#include "scene/registered.h"

namespace vivp::scene {

namespace {

using K = ParameterKind;

// The catalogue default of a parameter: its member's initializer.
template <class E>
std::vector<double> Fallback(const E& defaults,
                             const problems::Parameter<E>& p) {
  return std::visit(
      [&](auto member) -> std::vector<double> {
        const auto& value = defaults.*member;
        using V = std::remove_cvref_t<decltype(value)>;
        if constexpr (std::is_same_v<V, std::vector<double>>) {
          if (value.empty() && p.kind == K::kVector) return {0.0};
          return value;
        } else {
          return {double(value)};
        }
      },
      p.member);
}

template <class E>
EffectType TypeOf() {
  const problems::EffectSpec<E> spec = E::Spec();
  const E defaults{};
  EffectType t;
  t.name = spec.name;
  t.formula = spec.formula;
  for (const auto& p : spec.parameters)
    t.parameters.push_back({p.name, p.kind, Fallback(defaults, p), p.meaning});
  t.dissipative = problems::HasLambdaTerm<E>;
  t.kinetic = spec.kinetic;
  t.first_order = spec.first_order;
  t.exclusive = spec.exclusive;
  return t;
}

// The effect struct with the values read (every parameter with a default is
// present; an optional one only when given).
template <class E>
problems::Effect Build(const ParameterValues& values) {
  E e{};
  for (const auto& p : E::Spec().parameters) {
    const auto it = values.find(p.name);
    if (it == values.end()) continue;
    std::visit(
        [&](auto member) {
          auto& field = e.*member;
          using V = std::remove_cvref_t<decltype(field)>;
          if constexpr (std::is_same_v<V, std::vector<double>>)
            field = it->second;
          else if constexpr (std::is_same_v<V, bool>)
            field = it->second.at(0) != 0;
          else
            field = V(it->second.at(0));
        },
        p.member);
  }
  return e;
}

// Calls f.template operator()<E>() for every alternative E of Effect.
template <class F>
void ForEachEffect(F&& f) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (f.template operator()<std::variant_alternative_t<I, problems::Effect>>(),
     ...);
  }
  (std::make_index_sequence<std::variant_size_v<problems::Effect>>{});
}

}  // namespace

const std::vector<EffectType>& BuiltInEffects() {
  static const std::vector<EffectType> built_in = [] {
    std::vector<EffectType> t;
    ForEachEffect([&]<class E>() { t.push_back(TypeOf<E>()); });
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
    if (!made && E::Spec().name == type.name) made = Build<E>(v);
  });
  if (!made)
    throw std::logic_error("effect '" + type.name +
                           "' has no built-in effect struct");
  return *made;
}
}  // namespace vivp::scene
