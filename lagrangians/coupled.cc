#include "lagrangians/register.h"
#include "problems/coupled_oscillators.h"

namespace {
using vivp::problems::CoupledOscillators;
// Not a scene type: the effects kinetic + spring + chain.
const bool registered = vivp::Register<CoupledOscillators>(
    {
        .name = "coupled",
        .description = "two coupled oscillators (d = 2, normal modes exact)",
        .initial = {{1.0, 0.0}, {0.0, 0.3}},
        .exact =
            [](const CoupledOscillators& p, double t) {
              const auto s = p.Exact(t);
              return vivp::ExactState{{s.x[0], s.x[1]}, {s.v[0], s.v[1]}, {}};
            },
    },
    vivp::kNotInScenes);
}  // namespace
