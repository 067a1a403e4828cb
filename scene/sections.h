// The readers of a scene's sections, called by ParseScene (reader.cc) in
// this order: [system], [[effect]], [method] (before [time]: the operator
// sets the minimum of points), [initial], [time], [output]. Each checks its
// section against what the earlier ones fixed and fills its part of the
// scene; a bad value throws a SceneError (toml_reader.h).
#pragma once

#include <toml++/toml.h>

#include <functional>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "scene/toml_reader.h"

namespace vivp::scene::detail {

// [system]: the number of coordinates. Returns the node of `dof`, which the
// effects' check of it points at.
const toml::node& ReadSystem(const TomlReader& r, const toml::table& root,
                             Scene& s);
// The [[effect]] tables and the order of the system they make.
void ReadEffects(const TomlReader& r, const toml::table& root,
                 const toml::node& dof_node, Scene& s);
void ReadMethod(const TomlReader& r, const toml::table& root, Scene& s);
// tolerance = 1e-6 (absolute and relative) or {absolute = …, relative = …}
// at n, for a point or a field scene's [method].
variational::Tolerance ReadTolerance(const TomlReader& r, const toml::node& n);
void ReadInitial(const TomlReader& r, const toml::table& root, Scene& s);
void ReadTime(const TomlReader& r, const toml::table& root, Scene& s);
void ReadOutput(const TomlReader& r, const toml::table& root, Scene& s);

// The array of diagnostics at `n`: distinct names from `valid`, each passed
// to `check`, which refuses one the scene cannot have at its node.
std::vector<std::string> ReadDiagnosticList(
    const TomlReader& r, const toml::node& n,
    const std::vector<std::string>& valid,
    const std::function<void(const toml::node&, const std::string&)>& check);

// A table naming its type among `catalogue` (an [[effect]] or a field's
// [[term]], the noun of the messages) and giving that type's parameters,
// each checked against its kind (dof: the length of vector parameters).
ListedEffect ReadTypedTable(const TomlReader& r, const toml::table& t,
                            const std::vector<EffectType>& catalogue,
                            const std::string& noun, int dof);

}  // namespace vivp::scene::detail
