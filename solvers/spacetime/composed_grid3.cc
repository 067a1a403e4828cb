// SolveField for ComposedDensity<M, 3> on a grid of 3 axes (composed.h).
#include "solvers/spacetime/composed.h"

namespace vivp::spacetime {

VIVP_FIELD_SOLVE_GRID(1, 3);
VIVP_FIELD_SOLVE_GRID(2, 3);

}  // namespace vivp::spacetime
