#include "problems/anharmonic.h"

#include "lagrangians/register.h"

namespace {
// Not a scene type: the effects kinetic + quartic.
const bool registered = vivp::Register<vivp::problems::Anharmonic>(
    {
        .name = "anharmonic",
        .description = "anharmonic oscillator, L = ½ẋ² − 5x⁴ (eq. 33)",
        .initial = {{1.0}, {0.3}},
        .exact = vivp::ScalarExact<vivp::problems::Anharmonic>,
    },
    vivp::kNotInScenes);
}  // namespace
