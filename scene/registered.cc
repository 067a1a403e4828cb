#include "scene/registered.h"

#include <utility>

#include "scene/run_impl.h"
#include "problems/cyclotron.h"

namespace vivp::scene {

namespace {

// One registration: the struct L by name, with the double members a scene
// may set. Instantiates the scene runner for L.
template <class L>
RegisteredLagrangian Register(
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

}  // namespace

// Add a C++ Lagrangian to the scenes here: one line each.
const std::vector<RegisteredLagrangian>& RegisteredLagrangians() {
  static const std::vector<RegisteredLagrangian> list = {
      Register<problems::Cyclotron>(
          "cyclotron",
          "L += ½|ẋ|² + ½B(x ẏ − y ẋ)  (charge in a magnetic field B ẑ, "
          "problems/cyclotron.h)",
          {{"B", &problems::Cyclotron::B}}),
  };
  return list;
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
