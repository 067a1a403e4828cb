// docs/error_control.md, "Error control in code": the solve below is shown
// there verbatim; the test checks it against the exact orbit.
#include "problems/kepler.h"
#include "solvers/variational/march.h"

// --- example ---
// Kepler e = 0.9 for ten orbits, to a tolerance instead of a step count.
vivp::variational::MarchResult TenOrbits() {
  vivp::problems::Kepler orbit;
  orbit.e = 0.9;
  vivp::variational::MarchOptions options;
  options.tolerance = {.absolute = 1e-6, .relative = 1e-6};
  return vivp::variational::MarchIvp(
      orbit, {.x = {0.1, 0.0}, .v = {0.0, std::sqrt(19.0)}},
      {.op = "sbp84", .t_end = 20 * M_PI}, options);
}
// --- end of example ---

#define BOOST_TEST_MODULE example_error_control
#include <boost/test/unit_test.hpp>
#include <string>

#include "tests/readme_quote.h"

BOOST_AUTO_TEST_CASE(TenOrbitsExample_EndsOnTheExactOrbit) {
  const vivp::variational::MarchResult m = TenOrbits();
  BOOST_TEST_REQUIRE(m.status.converged, m.status.reason);
  vivp::problems::Kepler orbit;
  orbit.e = 0.9;
  const std::vector<double> exact = orbit.Exact(20 * M_PI);
  double error = 0;
  for (int c = 0; c < 2; ++c)
    error = std::max({error, std::abs(m.end_position[c] - exact[c]),
                      std::abs(m.end_velocity[c] - exact[2 + c])});
  BOOST_TEST_MESSAGE("end error " << error << " with " << m.points << " nodes");
  BOOST_TEST(error <= 1e-5);     // measured 6.9e-9
  BOOST_TEST(m.points < 40000);  // measured 20493; uniform: 256001 for 2e-10
}

BOOST_AUTO_TEST_CASE(Docs_ShowTheCompiledExampleVerbatim) {
  BOOST_TEST(readme_quote::DocShows(
                 "docs/error_control.md",
                 readme_quote::Example(VIVP_SOURCE_DIR
                                       "/tests/example_error_control.cc")),
             "docs/error_control.md does not show the example");
}
