// C++ Lagrangians usable from scenes by name (README "Effects"). A struct
// written as for SolveIvp (problems/, README "Add a Lagrangian") joins with
// one line in registered.cc:
//
//   Register<problems::Cyclotron>("cyclotron", "charge in a magnetic field",
//                                 {{"B", &problems::Cyclotron::B}}),
//
// after which `type = "cyclotron"` (with its listed parameters) is an effect
// of its own, alone or summed with the built-in effects. Registration
// instantiates the scene runner for the struct, once, in registered.cc.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "scene/catalogue.h"

namespace vivp::scene {

struct Scene;
class RunSink;
struct RunOutcome;

struct RegisteredLagrangian {
  EffectType type;  // dof fixed to the struct's kDim, parameters kReal
  int order = 2;    // from ∂²L/∂v² at the origin, or the struct's kOrder
  std::function<RunOutcome(const Scene&, RunSink&)> run;
};

const std::vector<RegisteredLagrangian>& RegisteredLagrangians();
const RegisteredLagrangian* FindRegistered(const std::string& name);
int RegisteredOrder(const EffectType& type);

}  // namespace vivp::scene
