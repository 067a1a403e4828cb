// The cyclotron of README "Add a Lagrangian", known by name: `vivp converge
// --problem cyclotron` and the scene type "cyclotron" with its field B. The
// registration between the markers is shown in the README verbatim
// (tests/example_add_a_lagrangian.cc checks it).
#include "problems/cyclotron.h"

#include "lagrangians/register.h"

namespace {
using vivp::problems::Cyclotron;
// --- example ---
const bool registered = vivp::Register<Cyclotron>({
    .name = "cyclotron",
    .description = "L += ½|ẋ|² + ½B(x ẏ − y ẋ)  (charge in a magnetic field "
                   "B ẑ, problems/cyclotron.h)",
    .initial = {{1.0, 0.0}, {0.0, 2.0}},
    .parameters = {{"B", &Cyclotron::B}},
});
// --- end of example ---
}  // namespace
