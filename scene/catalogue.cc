#include "scene/catalogue.h"

#include <stdexcept>
#include <utility>

#include "scene/registered.h"

namespace vivp::scene {

namespace {

using K = ParameterKind;

EffectType Type(std::string name, std::string formula,
                std::vector<ParameterSpec> parameters) {
  EffectType t;
  t.name = std::move(name);
  t.formula = std::move(formula);
  t.parameters = std::move(parameters);
  return t;
}

std::vector<EffectType> BuiltIn() {
  std::vector<EffectType> t;
  t.push_back(Type("kinetic", "L += ½ m|ẋ|²  (or ½ ẋᵀMẋ with a mass matrix M)",
                   {{"mass", K::kPositive, {1.0}, "scalar mass m"},
                    {"matrix",
                     K::kMatrix,
                     {},
                     "symmetric positive definite M, dof rows (instead of "
                     "mass)"}}));
  t.back().kinetic = true;
  t.back().exclusive = {"mass", "matrix"};
  t.push_back(
      Type("gravity", "L −= m g x_axis  (uniform field along −axis)",
           {{"mass", K::kPositive, {1.0}, "mass m"},
            {"g", K::kReal, {1.0}, "field strength g"},
            {"axis", K::kAxis, {-1.0}, "coordinate index (default: last)"}}));
  t.push_back(Type("spring", "L −= ½ k|x − c|²",
                   {{"k", K::kNonNegative, {1.0}, "stiffness k"},
                    {"centre", K::kVector, {0.0}, "rest point c"}}));
  t.push_back(Type("quartic",
                   "L −= ¼ κ|x|⁴  (anharmonic, Rothkopf & Nordström 2023, "
                   "eq. 33)",
                   {{"kappa", K::kNonNegative, {1.0}, "strength κ"}}));
  t.push_back(Type("pendulum", "L += s cos x_axis  (ẍ = −(s/m) sin x)",
                   {{"strength", K::kPositive, {1.0}, "s = m g ℓ"},
                    {"axis", K::kAxis, {0.0}, "angle coordinate"}}));
  t.push_back(Type("central", "L += k/|x|  (Kepler attraction)",
                   {{"k", K::kPositive, {1.0}, "strength k"}}));
  t.push_back(Type("gaussian_well",
                   "L += a exp(−|x|²/2)  (McLachlan & Offen 2023: ẍ = ∇U)",
                   {{"amplitude", K::kReal, {1.0}, "depth a"}}));
  t.push_back(
      Type("chain",
           "L −= Σ_bonds ½ k Δ² + ¼ β Δ⁴, Δ = x_{i+1} − x_i  (FPU; "
           "walls x_{−1} = x_dof = 0 with fixed_ends)",
           {{"k", K::kNonNegative, {1.0}, "bond stiffness k"},
            {"beta", K::kReal, {0.0}, "quartic bond part β"},
            {"fixed_ends", K::kBool, {1.0}, "bonds to walls at both ends"}}));
  t.push_back(Type("damping",
                   "Λ = −ξ ẋ₊·x₋  (friction force −ξẋ, Rothkopf & "
                   "Nordström 2023, eq. 40)",
                   {{"xi", K::kNonNegative, {0.1}, "friction coefficient ξ"}}));
  t.back().dissipative = true;
  t.push_back(Type("growth",
                   "L −= ½ κ|x|², Λ = ẋ₊·x₋  (first order ẋ = κx, "
                   "Rothkopf & Nordström 2023, eqs. 37–38)",
                   {{"kappa", K::kReal, {1.0}, "rate κ"}}));
  t.back().dissipative = true;
  t.back().first_order = true;
  return t;
}

double Get(const ParameterValues& v, const std::string& name) {
  return v.at(name).at(0);
}

}  // namespace

const std::vector<EffectType>& BuiltInEffects() {
  static const std::vector<EffectType> built_in = BuiltIn();
  return built_in;
}

// Built once, at first use after static initialization, when every
// registration is in.
const std::vector<EffectType>& EffectCatalogue() {
  static const std::vector<EffectType> catalogue = [] {
    std::vector<EffectType> all = BuiltInEffects();
    for (const auto& r : RegisteredLagrangians()) all.push_back(r.type);
    return all;
  }();
  return catalogue;
}

const EffectType* FindEffectType(const std::string& name) {
  for (const auto& t : EffectCatalogue())
    if (t.name == name) return &t;
  return nullptr;
}

std::string EffectNameList() {
  std::string out;
  for (const auto& t : EffectCatalogue())
    out += (out.empty() ? "" : ", ") + t.name;
  return out;
}

std::string DescribeKind(ParameterKind kind, int dof) {
  const std::string n = std::to_string(dof);
  switch (kind) {
    case K::kReal:
      return "a finite number";
    case K::kPositive:
      return "a finite number > 0";
    case K::kNonNegative:
      return "a finite number >= 0";
    case K::kVector:
      return "an array of " + n + " finite numbers";
    case K::kMatrix:
      return "a symmetric positive definite " + n + "x" + n +
             " array of arrays";
    case K::kBool:
      return "true or false";
    case K::kAxis:
      return "a whole number from 0 to " + std::to_string(dof - 1);
  }
  return "?";
}

problems::Effect MakeEffect(const EffectType& type, const ParameterValues& v) {
  namespace e = problems::effects;
  const std::string& n = type.name;
  if (n == "kinetic") {
    e::Kinetic k{Get(v, "mass"), {}};
    if (auto it = v.find("matrix"); it != v.end()) k.matrix = it->second;
    return k;
  }
  if (n == "gravity")
    return e::Gravity{Get(v, "mass"), Get(v, "g"), int(Get(v, "axis"))};
  if (n == "spring") return e::Spring{Get(v, "k"), v.at("centre")};
  if (n == "quartic") return e::Quartic{Get(v, "kappa")};
  if (n == "pendulum")
    return e::Pendulum{Get(v, "strength"), int(Get(v, "axis"))};
  if (n == "central") return e::Central{Get(v, "k")};
  if (n == "gaussian_well") return e::GaussianWell{Get(v, "amplitude")};
  if (n == "chain")
    return e::Chain{Get(v, "k"), Get(v, "beta"), Get(v, "fixed_ends") != 0};
  if (n == "damping") return e::Damping{Get(v, "xi")};
  if (n == "growth") return e::Growth{Get(v, "kappa")};
  throw std::logic_error("effect '" + n + "' has no built-in effect struct");
}

}  // namespace vivp::scene
