#include "scene/run.h"

#include <utility>

#include "problems/composed.h"
#include "scene/registered.h"

namespace vivp::scene {

namespace detail {

template <int D>
RunOutcome RunEffects(const Scene& s, RunSink& sink);  // run_dof.cc.in

std::vector<problems::Effect> BuiltInEffects(const Scene& s) {
  std::vector<problems::Effect> out;
  for (const auto& e : s.effects)
    if (e.type->dof == 0) out.push_back(MakeEffect(*e.type, e.values));
  return out;
}

// VIVP_SCENE_DOFS (set by CMake) lists the sizes with a run_dof file.
template <int... Ds>
RunOutcome Dispatch(const Scene& s, RunSink& sink,
                    std::integer_sequence<int, Ds...>) {
  RunOutcome out;
  const bool found =
      ((s.dof == Ds ? (out = RunEffects<Ds>(s, sink), true) : false) || ...);
  if (!found)
    throw std::invalid_argument("dof = " + std::to_string(s.dof) +
                                " is not among the compiled sizes");
  return out;
}

}  // namespace detail

const std::vector<int>& SupportedDofs() {
  static const std::vector<int> dofs = {VIVP_SCENE_DOFS};
  return dofs;
}

std::string StepperUnavailable(const Scene& s) {
  if (const EffectType* r = s.registered())
    return "needs a Hamiltonian H(q, p), which the registered Lagrangian '" +
           r->name + "' does not provide";
  for (const auto& e : s.effects)
    if (e.type->dissipative)
      return "needs a Hamiltonian system, but effect '" + e.type->name +
             "' is dissipative (a Λ term)";
  if (s.order != 2) return "needs a second-order system with kinetic energy";
  return "";
}

RunOutcome RunScene(const Scene& s, RunSink& sink) {
  if (const EffectType* type = s.registered())
    return FindRegistered(type->name)->run(s, sink);
  return detail::Dispatch(s, sink,
                          std::integer_sequence<int, VIVP_SCENE_DOFS>{});
}

}  // namespace vivp::scene
