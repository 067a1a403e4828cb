// The formulas of a field scene's named profiles (read_profile.cc reads
// [initial] with them): the initial φ and φ_t, and the exact solution when
// the scene's terms are those the profile solves. Private to scene/.
#pragma once

#include <toml++/toml.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>

#include "scene/field_scene.h"
#include "scene/toml_reader.h"

namespace vivp::scene::detail {

// The scene's terms by name, for matching a profile's equation.
struct TermSet {
  const FieldScene& s;
  bool Has(const std::string& name) const {
    return std::any_of(
        s.terms.begin(), s.terms.end(),
        [&](const ListedEffect& e) { return e.type->name == name; });
  }
  // The parameter of a listed term, or `fallback` when the term is absent.
  double Value(const std::string& term, const std::string& key,
               double fallback) const {
    for (const auto& e : s.terms)
      if (e.type->name == term) return e.values.at(key).at(0);
    return fallback;
  }
  // Exactly these terms (each is listed at most once).
  bool Are(std::set<std::string> names) const {
    if (names.size() != s.terms.size()) return false;
    for (const auto& e : s.terms)
      if (!names.count(e.type->name)) return false;
    return true;
  }
  bool Within(std::set<std::string> names) const {
    for (const auto& e : s.terms)
      if (!names.count(e.type->name)) return false;
    return true;
  }
};

// The value a profile parameter was read with, and its node for refusals.
struct ProfileValues {
  const TomlReader& r;
  const toml::table& t;
  const FieldScene& s;
  double operator[](const std::string& key) const {
    return s.initial.parameters.at(key);
  }
  [[noreturn]] void Fail(const std::string& key, const std::string& what,
                         const std::string& expected) const {
    const toml::node* n = t.get(key);
    r.Fail(n ? *n : *t.get("profile"), what, "expected " + expected);
  }
};

struct ProfileFormulas {
  FieldFormula initial;
  FieldFormula exact;    // empty when there is none
  std::string no_exact;  // why not, for the 'error' diagnostic's refusal
};

// The frequency of the plane wave φ = A cos(k·x − ωt) (and φ₁ = A sin(…)
// for two components) under the scene's terms, |k|² given: ω² = c²|k|² +
// w(A²) with ∂V/∂φ_a = w(|φ|²)·φ_a, w = m² + λ_q|φ|² + λ_4(|φ|² − v²) (the
// quartic terms only for two components, where |φ| = A is constant), and
// whether the wave is then an exact solution of the terms. Refuses an ω²
// that is not a finite number ≥ 0.
struct PlaneWaveFrequency {
  double omega;
  bool exact;
};
PlaneWaveFrequency PlaneWaveOmega(const ProfileValues& p, const TermSet& terms,
                                  double k2);

// The named profile of s.initial (not csv) for the scene's terms; `initial`
// is the [initial] table, whose values a refusal points at.
ProfileFormulas MakeProfile(const TomlReader& r, const toml::table& initial,
                            const FieldScene& s);

// The profiles of a grid of d = 2 or 3 axes (field_profile_nd.cc): their
// keys with defaults (a vector key has one entry per axis), and their
// formulas.
struct ProfileKey {
  std::string name;
  double fallback;
  std::string meaning;
  bool vector = false;  // one value per axis: center, k
};
const std::vector<ProfileKey>& ProfileKeysNd(const std::string& profile);
const std::vector<std::string>& ProfileNamesNd();
ProfileFormulas MakeProfileNd(const TomlReader& r, const toml::table& initial,
                              const FieldScene& s);

// The profiles of a charged field (read_charged.cc): their names and keys,
// the formula of (Re φ, Im φ, A_b) and (Re π, Im π, ∂_tA_b), and the
// refusal of data with a net charge on the circle (one axis; a vortex
// start is checked when the run relaxes it).
const std::vector<std::string>& ChargedProfileNames(int d);
std::vector<ProfileKey> ChargedProfileKeys(const FieldScene& s);
ProfileFormulas MakeChargedProfile(const ProfileValues& p, const FieldScene& s);
void CheckNeutral(const TomlReader& r, const toml::node& at,
                  const FieldScene& s);
// On two axes: the checks of the vortex profile named in s.initial (its keys
// read from `t`; refusals at `at`) and s.where_initial; s.phi0 stays empty
// until the run relaxes the start (charged_scene.h).
void MakeVortexProfile(const TomlReader& r, const toml::table& t,
                       const toml::node& at, FieldScene& s);

// Reads s.phi0 and s.phi_t0 from the CSV file named at `file` (relative to
// `base`): one row per spatial point, φ_0 … φ_{m−1} then φ_t,0 … φ_t,m−1.
void ReadProfileCsv(const TomlReader& r, const toml::node& file,
                    const std::filesystem::path& base, FieldScene& s);

}  // namespace vivp::scene::detail
