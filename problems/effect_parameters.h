// What an effect (effects.h) declares about itself next to its formula: its
// scene name, the term it adds in the README's notation, and its parameter
// table — name, kind (which also fixes the allowed range), the member it
// sets, and its meaning. The default is the member's initializer, so it is
// written once. The scene catalogue, reader, help text, summary and the
// README's effect table are generated from these tables (scene/catalogue.h).
#pragma once

#include <string>
#include <variant>
#include <vector>

namespace vivp::problems {

enum class ParameterKind {
  kReal,         // any finite number
  kPositive,     // finite, > 0
  kNonNegative,  // finite, >= 0
  kVector,       // dof finite numbers; an empty default means 0 in each
  kMatrix,       // dof x dof finite numbers, symmetric positive definite;
                 // an empty default means "not given" (optional)
  kBool,
  kAxis,  // a coordinate index 0 … dof−1; −1 means the last coordinate
};

template <class E>
struct Parameter {
  std::string name;
  ParameterKind kind;
  std::variant<double E::*, int E::*, bool E::*, std::vector<double> E::*>
      member;
  std::string meaning;
};

template <class E>
struct EffectSpec {
  std::string name;
  std::string formula;
  std::vector<Parameter<E>> parameters;
  bool kinetic = false;      // gives ∂²L/∂v² (a second-order system)
  bool first_order = false;  // gives a first-order system
  // Parameters of which at most one may be given (kinetic: mass, matrix).
  std::vector<std::string> exclusive = {};
};

}  // namespace vivp::problems
