// The field solver for the composed densities of a field scene
// (problems/fields/terms.h), compiled once in this library for one and two
// components on one axis (composed_1.cc, composed_2.cc) and on grids of two
// and three axes (composed_grid2.cc, composed_grid3.cc), and electromagnetism
// on grids (composed_gauge.cc): the scene runner and
// the named field problems of studies/ call it without instantiating the
// solver again.
#pragma once

#include <string>
#include <vector>

#include "core/sbp/builder.h"
#include "core/sbp/space.h"
#include "problems/fields/gauge.h"
#include "problems/fields/terms.h"
#include "solvers/spacetime/solve.h"
#include "solvers/spacetime/window_solver.h"

namespace vivp::spacetime {

// The most values (time points × spatial points × components) that a scene
// or a study solves at once, in one global solve or one window; beyond it,
// march in windows. The sparse LU fills (measured per time operator, core/sbp
// Measured::field_values_at_once); the mode solve does not, and its factors
// hold 10 (SBP42) to 21 (SBP84) values per unknown on the circle, twice that
// on an interval (bench/fields_bench, table 1): 2^23 unknowns, 8.4·10⁶
// (2048 × 4096), keep them under 2.9 GB (docs/fields.md §8).
inline long long MaxSolvedAtOnce(
    const std::string& op,
    WindowLinearSolver linear = WindowLinearSolver::kModes) {
  // The Fourier solve's factors are bounded apart (kFourierBytes).
  if (linear != WindowLinearSolver::kSparseLu) {
    sbp::Table(op);  // an unknown operator is an error here too
    return 1LL << 23;
  }
  return sbp::Table(op).measured.field_values_at_once;
}

#define VIVP_FIELD_SOLVE(M)                                                   \
  template FieldSolution SolveField<fields::ComposedDensity<M>>(              \
      const fields::ComposedDensity<M>&, const sbp::SpaceDerivative<double>&, \
      const FieldGrid&, std::vector<double>, std::vector<double>,             \
      const FieldSolveOptions&)

#define VIVP_FIELD_SOLVE_GRID(M, D)                                        \
  template FieldSolution SolveField<fields::ComposedDensity<M, D>>(        \
      const fields::ComposedDensity<M, D>&, const sbp::SpaceGrid<double>&, \
      const FieldGrid&, std::vector<double>, std::vector<double>,          \
      const FieldSolveOptions&)

#define VIVP_FIELD_SOLVE_GAUGE(D)                                 \
  template FieldSolution SolveField<fields::MaxwellIn<D>>(        \
      const fields::MaxwellIn<D>&, const sbp::SpaceGrid<double>&, \
      const FieldGrid&, std::vector<double>, std::vector<double>, \
      const FieldSolveOptions&)

extern VIVP_FIELD_SOLVE(1);
extern VIVP_FIELD_SOLVE(2);
extern VIVP_FIELD_SOLVE_GRID(1, 2);
extern VIVP_FIELD_SOLVE_GRID(2, 2);
extern VIVP_FIELD_SOLVE_GRID(1, 3);
extern VIVP_FIELD_SOLVE_GRID(2, 3);
extern VIVP_FIELD_SOLVE_GAUGE(2);
extern VIVP_FIELD_SOLVE_GAUGE(3);

}  // namespace vivp::spacetime
