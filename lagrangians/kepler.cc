#include "problems/kepler.h"

#include <cmath>

#include "lagrangians/register.h"

namespace {
using vivp::problems::Kepler;
// Not a scene type: the effects kinetic + central.
const bool registered = vivp::Register<Kepler>(
    {
        .name = "kepler",
        .description =
            "planar Kepler e = 0.6 from pericentre (d = 2, period 2π)",
        .initial = vivp::CanonicalInitial(Kepler{}),
        .exact = vivp::CanonicalExact<Kepler>,
    },
    vivp::kNotInScenes);

// The hard case of error control: r from 0.1 to 1.9, the local time scale
// r^{3/2} varies by a factor of 83 over an orbit.
struct EccentricKepler : Kepler {
  EccentricKepler() { e = 0.9; }
};
// Not a scene type: kepler with e = 0.9.
const bool eccentric = vivp::Register<EccentricKepler>(
    {
        .name = "kepler_e09",
        .description =
            "planar Kepler e = 0.9 from pericentre, x(0) = (0.1, 0), "
            "ẋ(0) = (0, √19) (d = 2, period 2π)",
        .initial = {{0.1, 0.0}, {0.0, std::sqrt(19.0)}},
        .exact = vivp::CanonicalExact<EccentricKepler>,
    },
    vivp::kNotInScenes);
}  // namespace
