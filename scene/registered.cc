#include "scene/registered.h"

#include <algorithm>
#include <stdexcept>

#include "scene/catalogue.h"

namespace vivp::scene {

namespace {

// Function-local, so that registrations in any translation unit find it
// constructed whatever the order of static initialization.
std::vector<RegisteredLagrangian>& List() {
  static std::vector<RegisteredLagrangian> list;
  return list;
}

}  // namespace

void AddRegistered(RegisteredLagrangian r) {
  for (const auto& t : BuiltInEffects())
    if (t.name == r.type.name)
      throw std::logic_error("a Lagrangian registered as '" + r.type.name +
                             "', the name of a built-in effect");
  auto& all = List();
  const auto at =
      std::lower_bound(all.begin(), all.end(), r.type.name,
                       [](const RegisteredLagrangian& a, const std::string& n) {
                         return a.type.name < n;
                       });
  if (at != all.end() && at->type.name == r.type.name)
    throw std::logic_error("two Lagrangians registered as '" + r.type.name +
                           "'");
  all.insert(at, std::move(r));
}

const std::vector<RegisteredLagrangian>& RegisteredLagrangians() {
  return List();
}

const RegisteredLagrangian* FindRegistered(const std::string& name) {
  for (const auto& r : RegisteredLagrangians())
    if (r.type.name == name) return &r;
  return nullptr;
}

int RegisteredOrder(const EffectType& type) {
  const RegisteredLagrangian* r = FindRegistered(type.name);
  return r ? r->order : 0;
}

}  // namespace vivp::scene
