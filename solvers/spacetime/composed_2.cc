// SolveField for ComposedDensity<2> (composed.h).
#include "solvers/spacetime/composed.h"

namespace vivp::spacetime {

VIVP_FIELD_SOLVE(2);

}  // namespace vivp::spacetime
