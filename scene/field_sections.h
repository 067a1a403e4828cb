// The readers of a field scene's sections (field_scene.h), called by
// ParseAnyScene (reader.cc) in this order: [field], [[term]], [method] (the
// operator sets the minimum of time points), [time], [initial] (the profile
// needs the grid and the terms), [output] (the error needs the profile's
// exact solution). Each throws a SceneError at the offending value.
#pragma once

#include <toml++/toml.h>

#include <filesystem>

#include "scene/field_scene.h"
#include "scene/toml_reader.h"

namespace vivp::scene::detail {

void ReadField(const TomlReader& r, const toml::table& root, FieldScene& s);
void ReadTerms(const TomlReader& r, const toml::table& root, FieldScene& s);
void ReadFieldMethod(const TomlReader& r, const toml::table& root,
                     FieldScene& s);
void ReadFieldTime(const TomlReader& r, const toml::table& root, FieldScene& s);
// A CSV profile's path is relative to `base`, the scene file's directory.
void ReadProfile(const TomlReader& r, const toml::table& root,
                 const std::filesystem::path& base, FieldScene& s);
void ReadFieldOutput(const TomlReader& r, const toml::table& root,
                     FieldScene& s);

// Charged matter (read_charged.cc): the terms and grid of a scene with
// 'scalar_qed' or 'abelian_higgs' (after ReadTerms), its [method] (the
// table `t`; after the operator is read) and its [time] points (the table
// `t`), whole windows of equal Δt.
void ReadChargedField(const TomlReader& r, const toml::table& root,
                      FieldScene& s);
void ReadChargedMethod(const TomlReader& r, const toml::table& t,
                       FieldScene& s);
void ReadChargedPoints(const TomlReader& r, const toml::table& t,
                       FieldScene& s);

// The field scene of a parsed TOML file that has a [field] table.
FieldScene ReadFieldScene(const TomlReader& r, const toml::table& root);

}  // namespace vivp::scene::detail
