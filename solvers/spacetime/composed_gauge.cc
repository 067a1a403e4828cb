// SolveField for electromagnetism on grids of 2 and 3 axes (composed.h):
// a field scene's 'maxwell' term.
#include "solvers/spacetime/composed.h"

namespace vivp::spacetime {

VIVP_FIELD_SOLVE_GAUGE(2);
VIVP_FIELD_SOLVE_GAUGE(3);

}  // namespace vivp::spacetime
