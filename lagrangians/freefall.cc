#include "lagrangians/register.h"
#include "problems/free_fall.h"

namespace {
// Not a scene type: the effects kinetic + gravity.
const bool registered = vivp::Register<vivp::problems::FreeFall>(
    {
        .name = "freefall",
        .description = "free fall, L = ½ẋ² − x (eq. 24)",
        .initial = {{1.0}, {0.3}},
        .exact = vivp::ScalarExact<vivp::problems::FreeFall>,
    },
    vivp::kNotInScenes);
}  // namespace
