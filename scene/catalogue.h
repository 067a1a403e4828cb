// The effects a scene may list (README "Effects"), by name: each with its
// formula, its parameters (kind, default, meaning) and a builder for the effect
// struct of problems/effects.h — all generated from the effects' own tables
// (Spec(), problems/effect_parameters.h). The scene reader checks a scene
// against this table, `vivp run --help` and the README print it, and a C++
// Lagrangian registered in lagrangians/ (registered.h) joins it as one more
// effect type.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "problems/composed.h"

namespace vivp::scene {

using ParameterKind = problems::ParameterKind;

struct ParameterSpec {
  std::string name;
  ParameterKind kind;
  // Default value: one number (a vector default is that number repeated, an
  // axis default −1 means the last coordinate); empty: optional, and absent
  // means "not used" (e.g. kinetic's matrix).
  std::vector<double> fallback;
  std::string meaning;
};

// Parameter values as read: numbers (a matrix row-major, a bool 0/1).
using ParameterValues = std::map<std::string, std::vector<double>>;

struct EffectType {
  std::string name;
  std::string formula;  // the term it adds, in the README's notation
  std::vector<ParameterSpec> parameters;
  bool dissipative = false;  // a Λ term
  bool kinetic = false;      // gives ∂²L/∂v² (a second-order system)
  bool first_order = false;  // gives a first-order system
  int dof = 0;               // fixed number of DOF (registered), 0: any
  // Parameters of which at most one may be given (kinetic: mass, matrix).
  std::vector<std::string> exclusive;
};

// The effects vivp ships (problems::Effect), without the registered
// Lagrangians.
const std::vector<EffectType>& BuiltInEffects();
const std::vector<EffectType>& EffectCatalogue();
// nullptr when no effect has that name.
const EffectType* FindEffectType(const std::string& name);
std::string EffectNameList();

// The effect struct for built-in types (not for registered Lagrangians):
// every parameter of `values` is present (defaults filled in) and checked.
problems::Effect MakeEffect(const EffectType& type,
                            const ParameterValues& values);

// A short text naming the kind, for messages: "a positive number".
std::string DescribeKind(ParameterKind kind, int dof);

}  // namespace vivp::scene
