// ParseScene and ReadScene: TOML to a checked Scene, section by section
// (sections.h).
#include <toml++/toml.h>

#include <fstream>
#include <iterator>

#include "scene/scene.h"
#include "scene/sections.h"
#include "scene/text.h"
#include "scene/toml_reader.h"

namespace vivp::scene {

Scene ParseScene(std::string_view text, const std::string& source) {
  const detail::TomlReader r(source);
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    const auto& at = e.source().begin;
    throw SceneError(r.Where(int(at.line), int(at.column)) +
                     detail::OneLine(e.description()) +
                     "; expected a TOML scene (see 'vivp run --help')");
  }
  Scene s;
  s.source = source;
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

Scene ReadScene(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(file, ec))
    throw SceneError(file.string() + ":1:1: cannot read the scene file (" +
                     (std::filesystem::exists(file, ec) ? "not a readable file"
                                                        : "no such file") +
                     "); expected the path of a TOML scene file");
  const std::string text((std::istreambuf_iterator<char>(in)),
                         std::istreambuf_iterator<char>());
  return ParseScene(text, file.string());
}

}  // namespace vivp::scene
