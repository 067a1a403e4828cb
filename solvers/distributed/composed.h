// The distributed march (solve.h) for a field scene's composed densities on
// grids of two and three axes, compiled once in this library
// (composed_grid.cc), as solvers/spacetime/composed.h does for one process.
#pragma once

#include <vector>

#include "problems/fields/terms.h"
#include "solvers/distributed/solve.h"

namespace vivp::distributed {

#define VIVP_DISTRIBUTED_SOLVE(M, D)                                           \
  template spacetime::FieldSolution SolveField<fields::ComposedDensity<M, D>>( \
      const Comm&, const fields::ComposedDensity<M, D>&,                       \
      const sbp::SpaceGrid<double>&, const spacetime::FieldGrid&,              \
      std::vector<double>, std::vector<double>, spacetime::FieldSolveOptions)

extern VIVP_DISTRIBUTED_SOLVE(1, 2);
extern VIVP_DISTRIBUTED_SOLVE(2, 2);
extern VIVP_DISTRIBUTED_SOLVE(1, 3);
extern VIVP_DISTRIBUTED_SOLVE(2, 3);

}  // namespace vivp::distributed
