// ParseScene, ParseAnyScene and the readers of files: TOML to a checked
// point-mechanics Scene (section by section, sections.h) or FieldScene
// (field_sections.h), told apart by their tables.
#include <toml++/toml.h>

#include <fstream>
#include <iterator>

#include "scene/field_scene.h"
#include "scene/field_sections.h"
#include "scene/scene.h"
#include "scene/sections.h"
#include "scene/text.h"
#include "scene/toml_reader.h"

namespace vivp::scene {

namespace {

toml::table ParseToml(const detail::TomlReader& r, std::string_view text) {
  try {
    return toml::parse(text, r.source());
  } catch (const toml::parse_error& e) {
    const auto& at = e.source().begin;
    throw SceneError(r.Where(int(at.line), int(at.column)) +
                     detail::OneLine(e.description()) +
                     "; expected a TOML scene (see 'vivp run --help')");
  }
}

// Whether the file is a field scene ([field] or [[term]]) rather than a
// point-mechanics one ([system], [[effect]]); a file with tables of both
// kinds is refused at the first table of the kind that came second.
bool IsFieldScene(const detail::TomlReader& r, const toml::table& root) {
  const toml::node* field = nullptr;
  const toml::node* mechanics = nullptr;
  std::string field_name, mechanics_name;
  for (const char* k : {"field", "term"})
    if (const toml::node* n = root.get(k); n && !field) {
      field = n;
      field_name = k;
    }
  for (const char* k : {"system", "effect"})
    if (const toml::node* n = root.get(k); n && !mechanics) {
      mechanics = n;
      mechanics_name = k;
    }
  if (field && mechanics) {
    auto line = [](const toml::node* n) { return n->source().begin.line; };
    const bool field_first = line(field) <= line(mechanics);
    const toml::node* second = field_first ? mechanics : field;
    auto table = [](const std::string& k) {
      return k == "term" || k == "effect" ? "[[" + k + "]]" : "[" + k + "]";
    };
    r.Fail(*second,
           "the scene mixes " + table(field_name) + " (a field) with " +
               table(mechanics_name) + " (point mechanics)",
           "expected either [field] with [[term]] tables or [system] with "
           "[[effect]] tables, not both (docs/field_scenes.md)");
  }
  return field != nullptr;
}

Scene MechanicsScene(const detail::TomlReader& r, const toml::table& root) {
  Scene s;
  s.source = r.source();
  r.CheckKeys(
      root, "the top level",
      {"title", "system", "effect", "initial", "time", "method", "output"});
  if (const toml::node* t = root.get("title"))
    s.title = r.String(*t, "title", "a short text");
  const toml::node& dof_node = detail::ReadSystem(r, root, s);
  detail::ReadEffects(r, root, dof_node, s);
  // [method] before [time]: the operator sets the minimum
  detail::ReadMethod(r, root, s);
  detail::ReadInitial(r, root, s);
  detail::ReadTime(r, root, s);
  detail::ReadOutput(r, root, s);
  return s;
}

std::string ReadText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(file, ec))
    throw SceneError(file.string() + ":1:1: cannot read the scene file (" +
                     (std::filesystem::exists(file, ec) ? "not a readable file"
                                                        : "no such file") +
                     "); expected the path of a TOML scene file");
  return std::string((std::istreambuf_iterator<char>(in)),
                     std::istreambuf_iterator<char>());
}

}  // namespace

Scene ParseScene(std::string_view text, const std::string& source) {
  const detail::TomlReader r(source);
  const toml::table root = ParseToml(r, text);
  if (IsFieldScene(r, root))
    r.Fail(1, 1, "this is a field scene ([field], [[term]])",
           "expected a point-mechanics scene here ([system], [[effect]]); "
           "'vivp run' reads both");
  return MechanicsScene(r, root);
}

AnyScene ParseAnyScene(std::string_view text, const std::string& source) {
  const detail::TomlReader r(source);
  const toml::table root = ParseToml(r, text);
  if (IsFieldScene(r, root)) return detail::ReadFieldScene(r, root);
  return MechanicsScene(r, root);
}

Scene ReadScene(const std::filesystem::path& file) {
  return ParseScene(ReadText(file), file.string());
}

AnyScene ReadAnyScene(const std::filesystem::path& file) {
  return ParseAnyScene(ReadText(file), file.string());
}

}  // namespace vivp::scene
