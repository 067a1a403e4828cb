// SolveField for ComposedDensity<1> (composed.h).
#include "solvers/fields/composed.h"

namespace vivp::fields {

VIVP_FIELD_SOLVE(1);

}  // namespace vivp::fields
