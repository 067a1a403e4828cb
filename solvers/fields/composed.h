// The field solver for the composed densities of a field scene
// (problems/fields/terms.h), compiled once in this library for one and two
// components (composed_1.cc, composed_2.cc): the scene runner and the named
// field problems of studies/ call it without instantiating the solver again.
#pragma once

#include <string>
#include <vector>

#include "core/sbp/builder.h"
#include "core/sbp/space.h"
#include "problems/fields/terms.h"
#include "solvers/fields/solve.h"

namespace vivp::fields {

// The most values (time points × spatial points × components) that a scene
// or a study solves at once, in one global solve or one window; beyond it,
// march in windows. Measured per time operator (core/sbp,
// Measured::field_values_at_once).
inline long long MaxSolvedAtOnce(const std::string& op) {
  return sbp::Table(op).measured.field_values_at_once;
}

#define VIVP_FIELD_SOLVE(M)                                           \
  template FieldSolution SolveField<ComposedDensity<M>>(              \
      const ComposedDensity<M>&, const sbp::SpaceDerivative<double>&, \
      const FieldGrid&, std::vector<double>, std::vector<double>,     \
      const FieldSolveOptions&)

extern VIVP_FIELD_SOLVE(1);
extern VIVP_FIELD_SOLVE(2);

}  // namespace vivp::fields
