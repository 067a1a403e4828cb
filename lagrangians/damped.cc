#include "lagrangians/register.h"
#include "problems/damped_oscillator.h"

namespace {
// Not a scene type: the effects kinetic + spring + damping.
const bool registered = vivp::Register<vivp::problems::DampedOscillator>(
    {
        .name = "damped",
        .description = "damped oscillator μ = 0.5, κ = 1, ξ = 0.00071 (eq. 43)",
        .initial = {{1.0}, {0.0}},
        .exact = vivp::ScalarExact<vivp::problems::DampedOscillator>,
    },
    vivp::kNotInScenes);
}  // namespace
