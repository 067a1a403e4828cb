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
  BOOST_TEST_MESSAGE("Gauss of the action " << gauss << ", textbook "
                                            << textbook);
  BOOST_TEST(gauss < 1e-12);
}
