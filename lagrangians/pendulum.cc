#include "problems/pendulum.h"

#include "lagrangians/register.h"

namespace {
using vivp::problems::Pendulum;
// Not a scene type: the effects kinetic + pendulum.
const bool registered = vivp::Register<Pendulum>(
    {
        .name = "pendulum",
        .description = "pendulum, L = ½ẋ² + cos x, x(0) = 0, ẋ(0) = 1",
        .initial = vivp::CanonicalInitial(Pendulum{}),
        .exact = vivp::CanonicalExact<Pendulum>,
    },
    vivp::kNotInScenes);
}  // namespace
