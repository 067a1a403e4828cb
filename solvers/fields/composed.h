// The field solver for the composed densities of a field scene
// (problems/fields/terms.h), compiled once in this library for one and two
// components (composed_1.cc, composed_2.cc): the scene runner and the named
// field problems of studies/ call it without instantiating the solver again.
#pragma once

#include <string>
#include <vector>

#include "core/sbp/space.h"
#include "problems/fields/terms.h"
#include "solvers/fields/solve.h"

namespace vivp::fields {

// The most values (time points × spatial points × components) that a scene
// or a study solves at once, in one global solve or one window; beyond it,
// march in windows. SBP21 has no fill (512 × 512 in 710 MB, docs/fields.md
// §8). The others fill: a global Klein–Gordon solve took 0.35 GB and 3.3 s
// at 257 × 128 with SBP42, 1.1 GB at 257 × 256, and 2.1 GB and 55 s at
// 257 × 256 with SBP84 (peak memory, `vivp converge --field klein_gordon`).
inline long long MaxSolvedAtOnce(const std::string& op) {
  return op == "sbp21" ? 1LL << 18 : 1LL << 15;
}

#define VIVP_FIELD_SOLVE(M)                                           \
  template FieldSolution SolveField<ComposedDensity<M>>(              \
      const ComposedDensity<M>&, const sbp::SpaceDerivative<double>&, \
      const FieldGrid&, std::vector<double>, std::vector<double>,     \
      const FieldSolveOptions&)

extern VIVP_FIELD_SOLVE(1);
extern VIVP_FIELD_SOLVE(2);

}  // namespace vivp::fields
