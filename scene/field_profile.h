// The formulas of a field scene's named profiles (read_profile.cc reads
// [initial] with them): the initial φ and φ_t, and the exact solution when
// the scene's terms are those the profile solves. Private to scene/.
#pragma once

#include <toml++/toml.h>

#include <filesystem>
#include <string>

#include "scene/field_scene.h"
#include "scene/toml_reader.h"

namespace vivp::scene::detail {

struct ProfileFormulas {
  FieldFormula initial;
  FieldFormula exact;    // empty when there is none
  std::string no_exact;  // why not, for the 'error' diagnostic's refusal
};

// The named profile of s.initial (not csv) for the scene's terms; `initial`
// is the [initial] table, whose values a refusal points at.
ProfileFormulas MakeProfile(const TomlReader& r, const toml::table& initial,
                            const FieldScene& s);

// Reads s.phi0 and s.phi_t0 from the CSV file named at `file` (relative to
// `base`): one row per spatial point, φ_0 … φ_{m−1} then φ_t,0 … φ_t,m−1.
void ReadProfileCsv(const TomlReader& r, const toml::node& file,
                    const std::filesystem::path& base, FieldScene& s);

}  // namespace vivp::scene::detail
