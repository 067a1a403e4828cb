// A scene: a physical system stated as a sum of named effects, its initial
// data, the time span, the method and what to output (docs/scenes.md §2).
// Read from TOML (toml++); every value is checked here, so a scene that reads
// without an error can be solved. Bad input throws SceneError whose message is
//   FILE:LINE:COL: what is wrong; what is expected
//
//   title = "Damped oscillator"            # optional
//   [system]
//   dof = 1
//   [[effect]]                             # one table per effect
//   type = "kinetic"
//   mass = 0.5
//   [initial]
//   x = [1.0]
//   v = [0.0]                              # second-order systems only
//   [time]
//   start = 0.0                            # optional
//   end = 204.8
//   points = 2048                          # grid nodes, both ends included
//   [method]
//   kind = "variational"                   # or a stepper: rk4, gauss2, …
//   operator = "sbp42"                     # variational only
//   solver = "newton"                      # newton | full-newton | ceres-lm
//   slab_points = 0                        # march in windows (0: global)
//   tolerance = 1e-6                       # or {absolute = …, relative = …}:
//                                          # error control, no [time] points
//   [output]
//   diagnostics = ["energy"]               # energy, momentum,
//                                          # angular_momentum, error
//   reference = "none"                     # none | exact | ode
//   stride = 1                             # write every stride-th node
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "scene/catalogue.h"
#include "solvers/variational/step_control.h"

namespace vivp::scene {

struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// An effect as a scene lists it (an [[effect]] or a field's [[term]]
// table): its type in the catalogue, its parameter values, where it stands.
// (What a type declares of itself is problems::EffectSpec.)
struct ListedEffect {
  const EffectType* type = nullptr;
  ParameterValues values;  // every parameter of the type, defaults filled in
  int line = 0, column = 0;
};

struct Scene {
  std::string source;  // file name, for messages
  std::string title;
  int dof = 1;
  std::vector<ListedEffect> effects;
  std::vector<double> x0, v0;  // v0 empty for a first-order system
  int order = 2;               // 2: some effect has kinetic energy
  double t_start = 0, t_end = 1;
  long long points = 0;  // 0 under error control: the march chooses
  struct Method {
    std::string kind = "variational";
    std::string op = "sbp42";
    std::string solver = "newton";
    long long slab_points = 0;
    // Error control (variational): the windows' steps are chosen so that
    // every returned node is within absolute + relative·|value| of the local
    // flow; [time] points is then not given.
    variational::Tolerance tolerance;
  } method;
  struct Output {
    std::vector<std::string> diagnostics;
    std::string reference = "none";
    long long stride = 1;
  } output;

  bool variational() const { return method.kind == "variational"; }
  bool Wants(const std::string& diagnostic) const;
  bool dissipative() const;
  // The registered Lagrangian among the effects, or nullptr.
  const EffectType* registered() const;
};

// Parses and checks a scene. `source` names it in messages.
Scene ParseScene(std::string_view text, const std::string& source);
// Reads FILE and parses it; an unreadable file is a SceneError too.
Scene ReadScene(const std::filesystem::path& file);

// The embedded default scene: the late-time damped oscillator of Rothkopf &
// Nordström 2023, Fig. 14 (what `vivp run` without a scene runs).
std::string_view DefaultSceneText();

// The scene as parsed, defaults filled in (for summary.json).
nlohmann::json SceneJson(const Scene& scene);

// The methods a scene may name: "variational" and the steppers.
const std::vector<std::string>& MethodKinds();
const std::vector<std::string>& DiagnosticNames();
const std::vector<std::string>& ReferenceNames();

// The schema, the effect catalogue and the method kinds as text, for
// `vivp run --help`.
std::string SchemaHelp();

// The effect catalogue as the README's Markdown table (type, term,
// parameters with defaults), between the README's "effects table" markers:
// `vivp scene effects` prints it, scripts/update_readme_effects.sh puts it
// into the README, and a test checks that the README has it.
std::string EffectTableMarkdown();

}  // namespace vivp::scene
