// README "Add a Lagrangian": the struct of problems/cyclotron.h and the solve
// below are shown there verbatim; the test checks the trajectory against the
// exact circle.
#include "problems/cyclotron.h"
#include "solvers/variational/solve_ivp.h"

// --- example ---
vivp::variational::IvpSolution<double> Gyrate() {
  return vivp::variational::SolveIvp(
      vivp::problems::Cyclotron{}, {.x = {1.0, 0.0}, .v = {0.0, -2.0}},
      {.op = "sbp42", .points = 400, .t_end = 3.0});
}
// --- end of example ---

#define BOOST_TEST_MODULE example_add_a_lagrangian
#include <boost/test/unit_test.hpp>
#include <string>

#include "tests/readme_quote.h"

BOOST_AUTO_TEST_CASE(CyclotronExample_FollowsTheExactCircle) {
  // With ẋ(0) = (0, −B·1) the charge circles the origin at radius 1 and
  // angular velocity −B: x = (cos Bt, −sin Bt).
  const auto s = Gyrate();
  BOOST_TEST(s.status.converged, s.status.reason);
  double worst = 0;
  for (int i = 0; i < s.points(); ++i) {
    worst = std::max(worst, std::abs(s.x1(i, 0) - std::cos(2.0 * s.t[i])));
    worst = std::max(worst, std::abs(s.x1(i, 1) + std::sin(2.0 * s.t[i])));
  }
  BOOST_TEST_MESSAGE("max deviation from the exact circle: " << worst);
  BOOST_TEST(worst <= 1e-5);
  BOOST_TEST(worst > 0.0);  // a discretization, not a copy of the answer
}

BOOST_AUTO_TEST_CASE(Readme_ShowsTheCompiledExampleVerbatim) {
  for (const char* file : {"/problems/cyclotron.h", "/lagrangians/cyclotron.cc",
                           "/tests/example_add_a_lagrangian.cc"})
    BOOST_TEST(readme_quote::ReadmeShows(
                   readme_quote::Example(std::string(VIVP_SOURCE_DIR) + file)),
               "README does not show the example of " << file);
}
