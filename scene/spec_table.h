// The catalogue entry of a term struct with a Spec() table
// (problems/effect_parameters.h) and the struct built from values read:
// shared by the effects of point mechanics (catalogue.cc) and the terms of a
// field density (field_catalogue.cc). Private to scene/.
#pragma once

#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "scene/catalogue.h"

namespace vivp::scene::detail {

// The catalogue default of a parameter: its member's initializer.
template <class E>
std::vector<double> Fallback(const E& defaults,
                             const problems::Parameter<E>& p) {
  return std::visit(
      [&](auto member) -> std::vector<double> {
        const auto& value = defaults.*member;
        using V = std::remove_cvref_t<decltype(value)>;
        if constexpr (std::is_same_v<V, std::vector<double>>) {
          if (value.empty() && p.kind == ParameterKind::kVector) return {0.0};
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

// The struct with the values read (every parameter with a default is
// present; an optional one only when given).
template <class E>
E Build(const ParameterValues& values) {
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

// Calls f.template operator()<E>() for every alternative E of Variant.
template <class Variant, class F>
void ForEachAlternative(F&& f) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (f.template operator()<std::variant_alternative_t<I, Variant>>(), ...);
  }
  (std::make_index_sequence<std::variant_size_v<Variant>>{});
}

}  // namespace vivp::scene::detail
