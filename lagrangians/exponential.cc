#include "problems/exponential.h"

#include "lagrangians/register.h"

namespace {
// Not a scene type: the effect growth.
const bool registered = vivp::Register<vivp::problems::Exponential>(
    {
        .name = "exponential",
        .description = "first order ẋ = 5x/2, L = −5x²/4, Λ = ẋ₊x₋ (eq. 39)",
        .initial = {{1.0}, {}},
        .exact = vivp::ScalarExact<vivp::problems::Exponential>,
    },
    vivp::kNotInScenes);
}  // namespace
