// The scene's own queries, the embedded default scene, the names a scene
// may use, and the scene as JSON. The reader is in reader.cc and the
// section readers (sections.h); the help text in schema_help.cc.
#include "scene/scene.h"

#include <algorithm>

#include "solvers/steppers/methods.h"

namespace vivp::scene {

namespace {

// Rothkopf & Nordström 2023, Fig. 14: the damped oscillator at late time
// (the scene of scenes/fig14_damped_late.toml).
constexpr std::string_view kDefaultScene =
    R"toml(# vivp's default scene: Rothkopf & Nordström 2023, Fig. 14
title = "Damped oscillator at late time (Rothkopf & Nordström 2023, Fig. 14)"

[system]
dof = 1

[[effect]]
type = "kinetic"
mass = 0.5

[[effect]]
type = "spring"
k = 1.0

[[effect]]
type = "damping"
xi = 0.00071

[initial]
x = [1.0]
v = [0.0]

[time]
end = 204.8
points = 2048

[method]
kind = "variational"
operator = "sbp42"
solver = "newton"

[output]
diagnostics = ["energy", "error"]
reference = "exact"
)toml";

}  // namespace

bool Scene::Wants(const std::string& diagnostic) const {
  return std::find(output.diagnostics.begin(), output.diagnostics.end(),
                   diagnostic) != output.diagnostics.end();
}

bool Scene::dissipative() const {
  return std::any_of(effects.begin(), effects.end(),
                     [](const ListedEffect& e) { return e.type->dissipative; });
}

const EffectType* Scene::registered() const {
  for (const auto& e : effects)
    if (e.type->dof > 0) return e.type;
  return nullptr;
}

std::string_view DefaultSceneText() { return kDefaultScene; }

const std::vector<std::string>& MethodKinds() {
  static const std::vector<std::string> kinds = [] {
    std::vector<std::string> k = {"variational"};
    for (const auto& m : steppers::MethodNames()) k.push_back(m);
    return k;
  }();
  return kinds;
}

const std::vector<std::string>& DiagnosticNames() {
  static const std::vector<std::string> names = {"energy", "momentum",
                                                 "angular_momentum", "error"};
  return names;
}

const std::vector<std::string>& ReferenceNames() {
  static const std::vector<std::string> names = {"none", "exact", "ode"};
  return names;
}

nlohmann::json SceneJson(const Scene& s) {
  nlohmann::json effects = nlohmann::json::array();
  for (const auto& e : s.effects) {
    nlohmann::json j = {{"type", e.type->name}};
    for (const auto& p : e.type->parameters) {
      auto it = e.values.find(p.name);
      if (it == e.values.end()) continue;
      const auto& v = it->second;
      switch (p.kind) {
        case ParameterKind::kBool:
          j[p.name] = v[0] != 0;
          break;
        case ParameterKind::kAxis:
          j[p.name] = int(v[0]);
          break;
        case ParameterKind::kVector:
          j[p.name] = v;
          break;
        case ParameterKind::kMatrix: {
          nlohmann::json rows = nlohmann::json::array();
          for (int r = 0; r < s.dof; ++r)
            rows.push_back(std::vector<double>(v.begin() + r * s.dof,
                                               v.begin() + (r + 1) * s.dof));
          j[p.name] = rows;
          break;
        }
        default:
          j[p.name] = v[0];
      }
    }
    effects.push_back(j);
  }
  nlohmann::json initial = {{"x", s.x0}};
  if (s.order == 2) initial["v"] = s.v0;
  nlohmann::json method = {{"kind", s.method.kind}};
  if (s.variational()) {
    method["operator"] = s.method.op;
    method["solver"] = s.method.solver;
    method["slab_points"] = s.method.slab_points;
    if (s.method.tolerance.enabled())
      method["tolerance"] = {{"absolute", s.method.tolerance.absolute},
                             {"relative", s.method.tolerance.relative}};
  }
  return {{"source", s.source},
          {"title", s.title},
          {"system", {{"dof", s.dof}, {"order", s.order}}},
          {"effect", effects},
          {"initial", initial},
          {"time",
           {{"start", s.t_start},
            {"end", s.t_end},
            {"points", s.points > 0 ? nlohmann::json(s.points) : nullptr}}},
          {"method", method},
          {"output",
           {{"diagnostics", s.output.diagnostics},
            {"reference", s.output.reference},
            {"stride", s.output.stride}}}};
}

}  // namespace vivp::scene
