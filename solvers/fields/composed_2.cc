// SolveField for ComposedDensity<2> (composed.h).
#include "solvers/fields/composed.h"

namespace vivp::fields {

VIVP_FIELD_SOLVE(2);

}  // namespace vivp::fields
