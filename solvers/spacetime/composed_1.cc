// SolveField for ComposedDensity<1> (composed.h).
#include "solvers/spacetime/composed.h"

namespace vivp::spacetime {

VIVP_FIELD_SOLVE(1);

}  // namespace vivp::spacetime
