// docs/fields.md §1: a Lagrangian density written by hand and the
// space-time field solved from its action; shown there verbatim (the README's
// "Add a field density" points to it). The test checks the moving φ⁴ kink
// against the exact tanh[γ(x − vt)].
#include <cmath>
#include <vector>

#include "core/sbp/space.h"
#include "solvers/spacetime/solve.h"

// --- example ---
// ℒ = ½φ_t² − ½φ_x² − ½(φ² − 1)², the φ⁴ field, for any scalar type T.
struct Phi4Density {
  static constexpr int kDim = 1;
  template <class T>
  T operator()(const T* phi, const T* phi_t, const T* phi_x) const {
    const T w = phi[0] * phi[0] - 1.0;
    return 0.5 * phi_t[0] * phi_t[0] - 0.5 * phi_x[0] * phi_x[0] - 0.5 * w * w;
  }
};

// A kink moving at v = 0.3 on [−20, 20]: SBP42 in space (natural boundary
// condition) and in time, 161 time points to t = 4, windows of 16.
vivp::spacetime::FieldSolution MovingKink(double v = 0.3) {
  auto dx = vivp::sbp::SpaceDerivative<double>::Bounded("sbp42", 201, -20, 20);
  const double g = 1 / std::sqrt(1 - v * v);
  std::vector<double> phi0, pi0;
  for (int j = 0; j < dx.points(); ++j) {
    phi0.push_back(std::tanh(g * dx.x(j)));
    pi0.push_back(-g * v / std::pow(std::cosh(g * dx.x(j)), 2));
  }
  return vivp::spacetime::SolveField(Phi4Density{}, dx, {"sbp42", 161, 4.0, 16},
                                     phi0, pi0);
}
// --- end of example ---

#define BOOST_TEST_MODULE example_field_density
#include <boost/test/unit_test.hpp>
#include <string>

#include "tests/readme_quote.h"

BOOST_AUTO_TEST_CASE(MovingKink_FollowsTheExactKink) {
  const double v = 0.3, g = 1 / std::sqrt(1 - v * v);
  const auto s = MovingKink(v);
  BOOST_TEST_REQUIRE(s.status.converged, s.status.reason);
  const int nx = s.nx;
  double worst = 0;
  for (std::size_t k = 0; k < s.t.size(); ++k)
    for (int j = 0; j < nx; ++j) {
      const double x = -20 + 0.2 * j;
      worst = std::max(
          worst, std::abs(s.phi[k * nx + j] - std::tanh(g * (x - v * s.t[k]))));
    }
  // The kink's centre at T: the zero of φ between the nodes around it.
  const std::vector<double> last(s.phi.end() - nx, s.phi.end());
  int j = 0;
  while (j + 1 < nx && last[j + 1] < 0) ++j;
  const double centre = -20 + 0.2 * (j + last[j] / (last[j] - last[j + 1]));
  BOOST_TEST_MESSAGE("max |φ − tanh γ(x − vt)| = "
                     << worst << "; centre at t = 4: " << centre
                     << " (exact 1.2)");
  BOOST_TEST(worst <= 2e-3);  // measured 1.3e-3 (Δx = 0.2, Δt = 0.025)
  BOOST_TEST(worst > 0.0);    // a discretization, not a copy of the answer
  BOOST_TEST(std::abs(centre - v * 4) <= 2e-3);
}

BOOST_AUTO_TEST_CASE(Docs_ShowTheCompiledExampleVerbatim) {
  const std::string file =
      std::string(VIVP_SOURCE_DIR) + "/tests/example_field_density.cc";
  const std::string code = readme_quote::Example(file);
  BOOST_TEST(readme_quote::DocShows("docs/fields.md", code),
             "docs/fields.md does not show " << file);
  int lines = 0;
  for (char c : code) lines += c == '\n';
  BOOST_TEST(lines <= 30);
}
