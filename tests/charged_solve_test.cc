// One window of scalar electrodynamics in 1 + 1 D (core/action/
// charged_field.h) solved by Newton with damped normal equations
// (solvers/spacetime/normal_solver.h): a pair of opposite charges at rest on
// a periodic line, no gauge condition, A₀ free at every node.
#define BOOST_TEST_MODULE charged_solve
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "core/action/charged_observables.h"
#include "core/sbp/builder.h"
#include "problems/fields/charged.h"
#include "solvers/spacetime/charged_march.h"
#include "solvers/spacetime/normal_solver.h"
#include "solvers/variational/newton.h"

using Grid = vivp::sbp::SpaceGrid<double>;
using Model = vivp::fields::ScalarQed;
using System = vivp::action::ChargedFieldSystem<Model, 1>;

BOOST_AUTO_TEST_CASE(a_window_solves_with_gauss_law_at_every_node) {
  Model model;
  model.mass2 = 1.0;
  model.coupling = [](double) { return 0.5; };
  const int n = 64, nt = 16;
  const double length = 20;
  const Grid grid(
      vivp::sbp::SpaceDerivative<double>::Periodic(2, n, 0, length));
  const vivp::sbp::RegularizedOperator<double> dbar(
      vivp::sbp::MakeOperator<double>("sbp42", nt, 0.0, 1.0));
  std::vector<double> phi0(n * System::m), pi0(n * System::m);
  for (int j = 0; j < n; ++j) {
    const double x = grid.x(j, 0);
    const double g1 = 0.5 * std::exp(-std::pow((x - 6) / 1.5, 2));
    const double g2 = 0.5 * std::exp(-std::pow((x - 14) / 1.5, 2));
    phi0[j * System::m + System::kRe] = g1 + g2;
    pi0[j * System::m + System::kIm] = -g1 + g2;  // e^{∓it}: opposite charges
  }
  const System sys(model, dbar, grid, phi0, pi0);
  std::vector<double> y(sys.size(), 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < nt; ++i)
      for (int a = 0; a < System::kChi; ++a)
        y[sys.Phi(i, j, a)] =
            phi0[j * System::m + a] + dbar.base().t(i) * pi0[j * System::m + a];
  vivp::spacetime::NormalEquationsSolver solver;
  vivp::variational::NewtonOptions options;
  options.refinement_steps = 0;
  const auto report =
      vivp::variational::Newton<double>(sys, y, options, solver);
  BOOST_TEST_MESSAGE("converged " << report.converged << " (" << report.reason
                                  << ") in " << report.iterations
                                  << " iterations, residual "
                                  << report.last_residual);
  BOOST_TEST(report.converged);
  const auto obs = vivp::action::ObserveWindow(sys, y.data());
  const double gauss =
      *std::max_element(obs.gauss_action.begin(), obs.gauss_action.end());
  const double textbook =
      *std::max_element(obs.gauss_textbook.begin(), obs.gauss_textbook.end());
  const double rows =
      *std::max_element(obs.gauss_rows.begin(), obs.gauss_rows.end());
  BOOST_TEST_MESSAGE("Gauss of the action " << gauss << " (χ's rows " << rows
                                            << "), textbook " << textbook);
  BOOST_TEST(gauss < 1e-12);
}

// Bad input is refused with the reason: a coupling that is not finite or
// zero, non-finite data, an interval axis, and data with a net charge on a
// torus (where Gauss's law has no solution).
BOOST_AUTO_TEST_CASE(bad_input_is_refused_with_the_reason) {
  const Grid grid(vivp::sbp::SpaceDerivative<double>::Periodic(2, 8, 0, 4));
  const vivp::sbp::RegularizedOperator<double> dbar(
      vivp::sbp::MakeOperator<double>("sbp21", 8, 0.0, 0.5));
  std::vector<double> phi0(8 * System::m, 0.1), pi0(8 * System::m, 0.0);
  auto refused = [&](const Model& model, const std::vector<double>& phi,
                     const Grid& g, const std::string& words) {
    try {
      const System sys(model, dbar, g, phi, pi0);
    } catch (const std::invalid_argument& e) {
      BOOST_TEST_MESSAGE(e.what());
      return std::string(e.what()).find(words) != std::string::npos;
    }
    return false;
  };
  Model zero;
  zero.coupling = [](double t) { return t < 0.3 ? 1.0 : 0.0; };
  BOOST_TEST(refused(zero, phi0, grid, "coupling e(t) at t = 0.3"));
  Model nan;
  nan.coupling = [](double) { return std::nan(""); };
  BOOST_TEST(refused(nan, phi0, grid, "must be finite and nonzero"));
  std::vector<double> bad = phi0;
  bad[5] = INFINITY;
  BOOST_TEST(refused(Model{}, bad, grid, "non-finite value at entry 5"));
  const Grid interval(
      vivp::sbp::SpaceDerivative<double>::Bounded("sbp21", 8, 0, 4));
  BOOST_TEST(refused(Model{}, phi0, interval, "needs periodic axes"));
  // One charge alone on the circle: φ = 0.1, π = −0.1i φ everywhere.
  std::vector<double> pi(8 * System::m, 0.0);
  for (int j = 0; j < 8; ++j) pi[j * System::m + System::kIm] = -0.01;
  vivp::spacetime::ChargedMarchOptions o;
  o.time_operator = "sbp21";
  o.window = 8;
  const auto r = vivp::spacetime::MarchCharged<Model, 1>(
      Model{}, grid, phi0, pi, o, [](auto&&...) {});
  BOOST_TEST_MESSAGE(r.reason);
  BOOST_TEST(!r.ok);
  BOOST_TEST(r.reason.find("neutral") != std::string::npos);
}
