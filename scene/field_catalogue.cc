// The names a field scene may use (its terms, profiles, diagnostics), the
// scene's own queries, the scene as JSON and the field part of the help.
#include <algorithm>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/sbp/builder.h"
#include "scene/field_scene.h"
#include "scene/spec_table.h"
#include "scene/text.h"

namespace vivp::scene {

const std::vector<EffectType>& FieldTermCatalogue() {
  static const std::vector<EffectType> terms = [] {
    std::vector<EffectType> t;
    detail::ForEachAlternative<fields::FieldTerm>(
        [&]<class E>() { t.push_back(detail::TypeOf<E>()); });
    return t;
  }();
  return terms;
}

fields::FieldTerm MakeFieldTerm(const EffectType& type,
                                const ParameterValues& values) {
  std::optional<fields::FieldTerm> made;
  detail::ForEachAlternative<fields::FieldTerm>([&]<class E>() {
    if (!made && E::Spec().name == type.name) made = detail::Build<E>(values);
  });
  if (!made)
    throw std::logic_error("term '" + type.name + "' has no term struct");
  return *made;
}

const std::vector<std::string>& FieldProfileNames() {
  static const std::vector<std::string> names = {
      "gaussian", "kink", "kink_antikink", "breather", "plane_wave", "csv"};
  return names;
}

const std::vector<std::string>& FieldDiagnosticNames() {
  static const std::vector<std::string> names = {
      "energy", "momentum", "charge", "error", "gauss", "gauss_textbook"};
  return names;
}

bool FieldScene::Gauge() const {
  return !Charged() &&
         std::any_of(terms.begin(), terms.end(), [](const ListedEffect& e) {
           return e.type->name == "maxwell";
         });
}

bool FieldScene::Charged() const {
  return std::any_of(terms.begin(), terms.end(), [](const ListedEffect& e) {
    return e.type->name == "scalar_qed" || e.type->name == "abelian_higgs";
  });
}

bool FieldScene::Wants(const std::string& diagnostic) const {
  return std::find(output.diagnostics.begin(), output.diagnostics.end(),
                   diagnostic) != output.diagnostics.end();
}

sbp::SpaceDerivative<double> FieldAxis::Space() const {
  if (boundary == "periodic")
    return sbp::SpaceDerivative<double>::Periodic(
        space_order, int(space_points), x0, x1 - x0);
  return sbp::SpaceDerivative<double>::Bounded(space_operator,
                                               int(space_points), x0, x1);
}

sbp::SpaceGrid<double> FieldScene::Grid() const {
  std::vector<sbp::SpaceDerivative<double>> axes;
  for (int a = 0; a < Dim(); ++a) axes.push_back(Axis(a).Space());
  return sbp::SpaceGrid<double>(std::move(axes));
}

spacetime::FieldBoundary FieldScene::Boundary() const {
  spacetime::FieldBoundary b;
  spacetime::FieldBoundarySide* sides[2] = {&b.left, &b.right};
  for (int a = 0; a < Dim(); ++a) {
    const FieldAxis& x = Axis(a);
    for (int side = 0; side < 2; ++side) {
      if (x.boundary == "periodic" || x.ends[side] == "natural") continue;
      const double v = x.boundary_values[side];
      // On a grid of d > 1 axes every end is a face with a normal slope
      // (the reader refuses dirichlet there).
      if (Dim() > 1) {
        b.faces.push_back(
            {a, side, [v](double, const double*, int) { return v; }});
        continue;
      }
      sides[side]->kind = x.ends[side] == "dirichlet"
                              ? action::BoundaryKind::kDirichlet
                              : action::BoundaryKind::kNeumann;
      sides[side]->value = [v](double, int) { return v; };
    }
  }
  return b;
}

std::vector<fields::FieldTerm> FieldScene::Terms() const {
  std::vector<fields::FieldTerm> out;
  for (const auto& t : terms) out.push_back(MakeFieldTerm(*t.type, t.values));
  return out;
}

nlohmann::json FieldSceneJson(const FieldScene& s) {
  nlohmann::json terms = nlohmann::json::array();
  for (const auto& t : s.terms) {
    nlohmann::json j = {{"type", t.type->name}};
    for (const auto& [name, v] : t.values) j[name] = v.at(0);
    terms.push_back(j);
  }
  auto axis = [](const FieldAxis& x) {
    nlohmann::json j = {{"domain", {x.x0, x.x1}},
                        {"points", x.space_points},
                        {"boundary", x.boundary}};
    if (x.boundary == "periodic") {
      j["space_order"] = x.space_order;
    } else {
      j["space_operator"] = x.space_operator;
      j["ends"] = x.ends;
      j["boundary_values"] = x.boundary_values;
    }
    return j;
  };
  nlohmann::json field = axis(s);
  field["components"] = s.components;
  if (s.Dim() > 1) {
    // One entry per axis, as the scene gives them.
    field = {{"components", s.components}, {"axes", nlohmann::json::array()}};
    for (int a = 0; a < s.Dim(); ++a) field["axes"].push_back(axis(s.Axis(a)));
  }
  nlohmann::json initial = {{"profile", s.initial.profile},
                            {"allow_jump", s.initial.allow_jump}};
  for (const auto& [name, v] : s.initial.parameters) initial[name] = v;
  for (const auto& [name, v] : s.initial.vectors) initial[name] = v;
  if (!s.initial.file.empty()) initial["file"] = s.initial.file;
  if (s.boundary == "periodic" && s.initial.profile != "csv")
    initial["jump"] = s.initial.jump;
  return {{"source", s.source},
          {"title", s.title},
          {"field", field},
          {"term", terms},
          {"initial", initial},
          {"exact", s.exact ? nlohmann::json(true) : nlohmann::json(false)},
          {"no_exact", s.no_exact},
          {"time", {{"end", s.t_end}, {"points", s.time_points}}},
          {"method",
           {{"operator", s.method.op},
            {"window_points", s.method.window_points},
            {"tolerance",
             s.method.tolerance.enabled()
                 ? nlohmann::json{{"absolute", s.method.tolerance.absolute},
                                  {"relative", s.method.tolerance.relative}}
                 : nlohmann::json(nullptr)},
            {"linear_solver", s.method.linear_solver}}},
          {"output",
           {{"diagnostics", s.output.diagnostics},
            {"stride", s.output.stride},
            {"format", s.output.format},
            {"phi_t", s.output.phi_t},
            {"heat_maps", s.output.heat_maps},
            {"spectra", s.output.spectra},
            {"animation", s.Dim() > 1 && s.output.animation}}}};
}

std::string FieldSchemaHelp() {
  std::ostringstream h;
  h << "Field scene (TOML; a [field] table instead of [system], "
       "docs/field_scenes.md):\n"
       "  [field]      components = 1     1, or 2 (a complex field)\n"
       "               domain = [x0, x1]  the spatial interval\n"
       "               points = Nx        spatial points\n"
       "               boundary = \"periodic\"  periodic | natural (φ_x = 0 "
       "weakly) |\n"
       "                          dirichlet | neumann, or [left, right]\n"
       "               boundary_values = [0, 0]  φ (dirichlet) or φ_x "
       "(neumann) at the ends\n"
       "               space_order = 8    periodic differences: 2, 4, 6, 8\n"
       "               space_operator = \"sbp42\"  on an interval: "
    << detail::Join(sbp::OperatorNames())
    << "\n"
       "  [[term]]     type = \"...\"       one table per density term\n"
       "  [initial]    profile = \"...\"    "
    << detail::Join(FieldProfileNames())
    << ", with its parameters\n"
       "               allow_jump = false periodic: run a profile that is "
       "not periodic\n"
       "  [time]       end = T, points = Nt\n"
       "  [method]     operator = \"sbp42\", window_points = 0 (0: global),\n"
       "               linear_solver = \"modes\" | \"sparse-lu\" | "
       "\"fourier\"\n"
       "  [output]     diagnostics = []   "
    << detail::Join(FieldDiagnosticNames())
    << "\n"
       "               stride = 1, format = \"csv\" | \"binary\" | \"hdf5\", "
       "phi_t = true\n"
       "               spectra = [t, ...]  periodic axes: P(k) of φ\n"
       "               heat_maps = [t, ...], animation = true  grids: PNG "
       "slices, field.gif\n"
       "  On 2 or 3 axes: domain = [[x0, x1], [y0, y1]], points = [NX, NY] "
       "(or N),\n"
       "  boundary, boundary_values, space_order and space_operator per axis "
       "(or one\n"
       "  for all); profiles gaussian, ring, oscillon, plane_wave (center, k "
       "per axis);\n"
       "  output in HDF5 (docs/field_scenes.md §8).\n"
       "  A 'maxwell' term (alone, every axis periodic): the components are "
       "the\n"
       "  potentials A₀ … A_d, linear_solver = \"fourier\", windows of 16; "
       "profile\n"
       "  plane_wave (k, amplitude); diagnostics gauss, gauss_textbook "
       "(docs/gauge.md).\n"
       "  'maxwell' + 'scalar_qed' (+ 'abelian_higgs'): a charged field on "
       "links, 1 or 2\n"
       "  periodic axes; profiles charge_pair (center, k, amplitude, width, "
       "electric),\n"
       "  on a square: vortex_pair (separation), vortex_collision (offset, "
       "speed,\n"
       "  transition); windows of equal Δt; diagnostics energy, charge, "
       "gauss,\n"
       "  gauss_textbook; the values are abs_phi, E_x [, E_y], rho; on two "
       "axes\n"
       "  vortices.csv and tracks.png (docs/field_scenes.md §8).\n\n"
       "Terms (parameter = default):\n";
  for (const auto& t : FieldTermCatalogue()) {
    h << "  " << t.name << ": " << t.formula;
    for (const auto& p : t.parameters)
      h << "; " << p.name << " = " << detail::FormatNumber(p.fallback.at(0));
    h << "\n";
  }
  return h.str();
}

}  // namespace vivp::scene
