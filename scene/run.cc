#include "scene/run.h"

#include <stdexcept>
#include <string>

#include "core/action/precompiled_dims.h"
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

// The sizes with a run_dof file (VIVP_DIMS in CMake).
RunOutcome Dispatch(const Scene& s, RunSink& sink) {
#define VIVP_RUN_DIM(D) \
  if (s.dof == D) return RunEffects<D>(s, sink);
  VIVP_PRECOMPILED_DIMS(VIVP_RUN_DIM)
#undef VIVP_RUN_DIM
  throw std::invalid_argument("dof = " + std::to_string(s.dof) +
                              " is not among the compiled sizes");
}

}  // namespace detail

const std::vector<int>& SupportedDofs() {
#define VIVP_LIST_DIM(D) D,
  static const std::vector<int> dofs = {VIVP_PRECOMPILED_DIMS(VIVP_LIST_DIM)};
#undef VIVP_LIST_DIM
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
  return detail::Dispatch(s, sink);
}

}  // namespace vivp::scene
