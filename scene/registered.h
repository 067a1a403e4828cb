// C++ Lagrangians usable from scenes by name (README "Effects"): a struct
// written as for SolveIvp and registered in its own file in lagrangians/
// (lagrangians/register.h) is a scene type of its own, alone or summed with
// the built-in effects, with the members it lists as parameters.
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

// Adds a registration (scene/register_lagrangian.h makes one). Throws
// std::logic_error if the name is taken, by a built-in effect or another
// registration.
void AddRegistered(RegisteredLagrangian r);
// Every registration, in the order of their names.
const std::vector<RegisteredLagrangian>& RegisteredLagrangians();
const RegisteredLagrangian* FindRegistered(const std::string& name);
int RegisteredOrder(const EffectType& type);

}  // namespace vivp::scene
