// The distributed march for ComposedDensity<M, d>, d = 2, 3 (composed.h).
#include "solvers/distributed/composed.h"

namespace vivp::distributed {

VIVP_DISTRIBUTED_SOLVE(1, 2);
VIVP_DISTRIBUTED_SOLVE(2, 2);
VIVP_DISTRIBUTED_SOLVE(1, 3);
VIVP_DISTRIBUTED_SOLVE(2, 3);

}  // namespace vivp::distributed
