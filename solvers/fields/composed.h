// The field solver for the composed densities of a field scene
// (problems/fields/terms.h), compiled once in this library for one and two
// components (composed_1.cc, composed_2.cc): the scene runner and the named
// field problems of studies/ call it without instantiating the solver again.
#pragma once

#include <vector>

#include "core/sbp/space.h"
#include "problems/fields/terms.h"
#include "solvers/fields/solve.h"

namespace vivp::fields {

#define VIVP_FIELD_SOLVE(M)                                           \
  template FieldSolution SolveField<ComposedDensity<M>>(              \
      const ComposedDensity<M>&, const sbp::SpaceDerivative<double>&, \
      const FieldGrid&, std::vector<double>, std::vector<double>,     \
      const FieldSolveOptions&)

extern VIVP_FIELD_SOLVE(1);
extern VIVP_FIELD_SOLVE(2);

}  // namespace vivp::fields
