// How a C++ Lagrangian becomes a scene type (registered.h): the scene runner
// instantiated for the struct, and its double members a scene may set.
// lagrangians/register.h calls this for every registration.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "scene/registered.h"
#include "scene/run_impl.h"

namespace vivp::scene {

// What the scene runner solves for a registered L: L plus the scene's
// built-in effects. With no effects it is L itself, term for term, and the
// registry (lagrangians/register.h) solves that same type, so that a
// Lagrangian offered to both compiles the solvers once, not twice.
template <class L>
using SceneProblem = detail::WithUser<L>;

template <class L>
RegisteredLagrangian MakeRegistered(
    std::string name, std::string description,
    std::vector<std::pair<std::string, double L::*>> parameters = {}) {
  RegisteredLagrangian r;
  r.type.name = std::move(name);
  r.type.formula = std::move(description);
  r.type.dof = L::kDim;
  const L defaults{};
  for (const auto& [key, member] : parameters)
    r.type.parameters.push_back(
        {key, ParameterKind::kReal, {defaults.*member}, "member " + key});
  double x[L::kDim] = {}, v[L::kDim] = {};
  r.order = action::SystemOrder<double>(defaults, x, v);
  r.type.kinetic = r.order == 2;
  r.type.first_order = r.order == 1;
  r.type.dissipative = action::HasLambda<L>;
  const std::string type_name = r.type.name;
  r.run = [parameters, type_name](const Scene& s, RunSink& sink) {
    L user{};
    for (const auto& e : s.effects)
      if (e.type->name == type_name)
        for (const auto& [key, member] : parameters)
          user.*member = e.values.at(key).at(0);
    return detail::RunWithUser(user, s, sink);
  };
  return r;
}

}  // namespace vivp::scene
