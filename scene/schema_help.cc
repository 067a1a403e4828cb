// The schema, the effect catalogue and the method kinds as text, for
// `vivp run --help`.
#include <sstream>

#include "core/sbp/builder.h"
#include "scene/scene.h"
#include "scene/text.h"
#include "solvers/steppers/methods.h"

namespace vivp::scene {

std::string SchemaHelp() {
  std::string operators;  // "sbp21 | sbp42 | sbp63 | sbp84"
  for (const auto& n : sbp::OperatorNames())
    operators += (operators.empty() ? "" : " | ") + n;
  std::ostringstream h;
  h << "Scene file (TOML):\n"
       "  title = \"...\"                 optional\n"
       "  [system]     dof = N            number of coordinates\n"
       "  [[effect]]   type = \"...\"       one table per effect, with its "
       "parameters\n"
       "  [initial]    x = [...]          N positions\n"
       "               v = [...]          N velocities (second-order systems "
       "only)\n"
       "  [time]       start = 0.0        optional\n"
       "               end = T            final time, > start\n"
       "               points = Nt        grid nodes, both ends included (not "
       "with a tolerance)\n"
       "  [method]     kind = \"variational\" | "
    << detail::Join(steppers::MethodNames())
    << "\n"
       "               operator = \"sbp42\"  "
    << operators
    << " (variational)\n"
       "               solver = \"newton\"   newton | full-newton | ceres-lm "
       "(variational)\n"
       "               slab_points = 0    march in windows of this many "
       "points (0: global;\n"
       "                                  ceres-lm without it: its measured "
       "window)\n"
       "               tolerance = 1e-6   error control (variational): every "
       "node within\n"
       "                                  absolute + relative·|value| of the "
       "local flow;\n"
       "                                  or {absolute = ..., relative = ...}; "
       "no [time] points\n"
       "  [output]     diagnostics = []   energy, momentum, angular_momentum, "
       "error\n"
       "               reference = \"none\" none | exact (closed form) | ode "
       "(Euler–Lagrange by AD, integrated to 1e-13)\n"
       "               stride = 1         write every stride-th node\n\n"
       "Effects (parameter = default):\n";
  for (const auto& t : EffectCatalogue()) {
    h << "  " << t.name << ": " << t.formula << "\n   ";
    for (const auto& p : t.parameters) {
      h << " " << p.name;
      if (!p.fallback.empty() && p.kind != ParameterKind::kMatrix) {
        if (p.kind == ParameterKind::kBool)
          h << " = " << (p.fallback[0] != 0 ? "true" : "false");
        else if (p.kind == ParameterKind::kAxis && p.fallback[0] < 0)
          h << " = last";
        else
          h << " = " << detail::FormatNumber(p.fallback[0])
            << (p.kind == ParameterKind::kVector ? " (each)" : "");
      } else {
        h << " (optional)";
      }
      h << ";";
    }
    if (t.dof > 0) h << " [registered C++ Lagrangian, dof = " << t.dof << "]";
    h << "\n";
  }
  return h.str();
}

namespace {

// A parameter's default as the README writes it.
std::string MarkdownDefault(const ParameterSpec& p) {
  if (p.fallback.empty()) return "optional";
  switch (p.kind) {
    case ParameterKind::kBool:
      return p.fallback[0] != 0 ? "true" : "false";
    case ParameterKind::kAxis:
      return p.fallback[0] < 0 ? "last coordinate"
                               : detail::FormatNumber(p.fallback[0]);
    case ParameterKind::kVector:
      return detail::FormatNumber(p.fallback[0]) + " in each coordinate";
    default:
      return detail::FormatNumber(p.fallback[0]);
  }
}

// "|" would end a table cell.
std::string Cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

}  // namespace

std::string EffectTableMarkdown() {
  std::ostringstream m;
  m << "| type | term | parameters (default) |\n|---|---|---|\n";
  for (const auto& t : EffectCatalogue()) {
    m << "| `" << t.name << "` | " << Cell(t.formula) << " | ";
    for (std::size_t i = 0; i < t.parameters.size(); ++i) {
      const auto& p = t.parameters[i];
      m << (i ? ", " : "") << "`" << p.name << "` " << Cell(p.meaning) << " ("
        << MarkdownDefault(p) << ")";
    }
    if (t.dof > 0) m << " — a registered C++ Lagrangian, dof = " << t.dof;
    m << " |\n";
  }
  return m.str();
}

}  // namespace vivp::scene
