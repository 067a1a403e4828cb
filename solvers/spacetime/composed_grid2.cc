// SolveField for ComposedDensity<M, 2> on a grid of 2 axes (composed.h).
#include "solvers/spacetime/composed.h"

namespace vivp::spacetime {

VIVP_FIELD_SOLVE_GRID(1, 2);
VIVP_FIELD_SOLVE_GRID(2, 2);

}  // namespace vivp::spacetime
