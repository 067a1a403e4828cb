// How a C++ Lagrangian becomes a scene type (registered.h): its double
// members a scene may set, and a run that hands L, behind its pointwise
// derivatives, to the scene runner compiled once per dimension
// (RunRegistered). lagrangians/register.h calls this for every
// registration.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/action/erased_problem.h"
#include "scene/registered.h"
#include "scene/run.h"

namespace vivp::scene {

namespace detail {
// L + the scene's built-in effects, solved as the scene says (run_impl.h;
// compiled for each d of VIVP_DIMS in run_dof.cc.in).
template <int D>
RunOutcome RunRegistered(const action::ErasedProblem<D>& user, const Scene& s,
                         RunSink& sink);
}  // namespace detail

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
    return detail::RunRegistered(action::Erase(user), s, sink);
  };
  return r;
}

}  // namespace vivp::scene
