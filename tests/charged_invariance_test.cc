// The discrete action of a charged scalar field and its gauge field
// (core/action/charged_field.h, docs/gauge.md §7) is exactly invariant
// under a discrete gauge transformation α at every node, for every SBP
// operator in time, in 1 + 1 and 2 + 1 D:
//
//   φ → e^{iα}φ,  A_b → A_b + D_b⁺α,  χ → χ + α  (A₀ = Dχ → A₀ + Dα),
//
// with the data moved (φ₀, π₀ rotated by e^{iα(0)}, a_b and ȧ_b by D_b⁺α(0)
// and D_b⁺(Dα)(0)). The action is unchanged to round-off, the rows of A_b
// and χ are unchanged and those of φ rotate with it. The control: the same
// transformation with χ left in place, so that the transport phases no
// longer cancel, changes them far above round-off: the comparison does see
// a wrong transformation. The Jacobian is checked against central
// differences of the residual.
#define BOOST_TEST_MODULE charged_invariance
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <complex>
#include <random>
#include <string>
#include <vector>

#include "core/action/charged_field.h"
#include "core/sbp/builder.h"
#include "problems/fields/charged.h"
#include "tests/charged_helpers.h"

using Grid = vivp::sbp::SpaceGrid<double>;
using Model = vivp::fields::ScalarQed;
using vivp::action::Complex;

namespace {

template <int d>
struct Case {
  Model model;
  vivp::sbp::RegularizedOperator<double> dbar;
  Grid grid;
  std::vector<double> phi0, pi0, y;
  Case(const std::string& op, int nt, Grid g, std::mt19937& rng)
      : dbar(vivp::sbp::MakeOperator<double>(op, nt, 0.0, 0.05 * (nt - 1))),
        grid(std::move(g)) {
    model.mass2 = 0.7;
    model.lambda = 0.4;
    model.v2 = 1.3;
    model.coupling = [](double t) { return 1.0 + 0.3 * t; };
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const int m = vivp::action::ChargedFieldSystem<Model, d>::m;
    auto random = [&](std::size_t n) {
      std::vector<double> v(n);
      for (double& x : v) x = u(rng);
      return v;
    };
    phi0 = random(std::size_t(grid.points()) * m);
    pi0 = random(std::size_t(grid.points()) * m);
    const vivp::action::ChargedFieldSystem<Model, d> sys(model, dbar, grid,
                                                         phi0, pi0);
    y = random(std::size_t(sys.size()));
  }
};

struct Change {
  double action, rows;
};

// Relative change of the action and of the rows (those of φ rotated back)
// under a random gauge of amplitude `amp`.
template <int d>
Change Violation(const std::string& op, int nt, const Grid& g, double amp,
                 bool shift_chi = true) {
  using System = vivp::action::ChargedFieldSystem<Model, d>;
  std::mt19937 rng(271127);
  Case<d> c(op, nt, g, rng);
  const System before(c.model, c.dbar, c.grid, c.phi0, c.pi0);
  std::vector<double> alpha(std::size_t(nt) * g.points());
  std::uniform_real_distribution<double> u(-amp, amp);
  for (double& a : alpha) a = u(rng);
  auto moved = charged_test::Gauge<d>(before, c.y, alpha, shift_chi);
  const System after(c.model, c.dbar, c.grid, moved.phi0, moved.pi0);
  std::vector<double> f0(before.size()), f1(before.size());
  before.Residual(c.y.data(), f0.data());
  after.Residual(moved.y.data(), f1.data());
  charged_test::RotateRowsBack<d>(before, alpha, f1);
  double diff = 0, scale = 0;
  for (std::size_t k = 0; k < f0.size(); ++k) {
    diff = std::max(diff, std::abs(f1[k] - f0[k]));
    scale = std::max(scale, std::abs(f0[k]));
  }
  const double s0 = before.Action(c.y.data()),
               s1 = after.Action(moved.y.data());
  return {std::abs(s1 - s0) / std::abs(s0), diff / scale};
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_action_is_gauge_invariant_for_every_operator) {
  double worst_action = 0, worst_rows = 0;
  for (const std::string op : {"sbp21", "sbp42", "sbp63", "sbp84"})
    for (int nt : {16, 24}) {
      if (op == "sbp84" && nt < 16) continue;
      const Change one = Violation<1>(
          op, nt,
          Grid(vivp::sbp::SpaceDerivative<double>::Periodic(2, 9, 0, 3)), 1.0);
      const Change two = Violation<2>(
          op, nt,
          Grid({vivp::sbp::SpaceDerivative<double>::Periodic(2, 4, 0, 2),
                vivp::sbp::SpaceDerivative<double>::Periodic(2, 5, 0, 2.5)}),
          1.0);
      BOOST_TEST_MESSAGE(op << " Nt=" << nt << ": 1+1 D action " << one.action
                            << " rows " << one.rows << "; 2+1 D action "
                            << two.action << " rows " << two.rows);
      worst_action = std::max({worst_action, one.action, two.action});
      worst_rows = std::max({worst_rows, one.rows, two.rows});
    }
  BOOST_TEST_MESSAGE("largest relative change: action "
                     << worst_action << ", rows " << worst_rows);
  BOOST_TEST(worst_action < 1e-13);
  BOOST_TEST(worst_rows < 1e-12);
  const Change wrong = Violation<1>(
      "sbp42", 16,
      Grid(vivp::sbp::SpaceDerivative<double>::Periodic(2, 9, 0, 3)), 1.0,
      false);
  BOOST_TEST_MESSAGE("control, χ not shifted: action "
                     << wrong.action << ", rows " << wrong.rows);
  BOOST_TEST(wrong.rows > 1e-3);
}

BOOST_AUTO_TEST_CASE(the_jacobian_is_the_residuals_derivative) {
  using System = vivp::action::ChargedFieldSystem<Model, 2>;
  std::mt19937 rng(5);
  Case<2> c("sbp42", 12,
            Grid({vivp::sbp::SpaceDerivative<double>::Periodic(2, 3, 0, 1.5),
                  vivp::sbp::SpaceDerivative<double>::Periodic(2, 4, 0, 2)}),
            rng);
  const System sys(c.model, c.dbar, c.grid, c.phi0, c.pi0);
  const double err = charged_test::JacobianError(sys, c.y, rng);
  BOOST_TEST_MESSAGE("Jacobian against central differences: " << err);
  BOOST_TEST(err < 1e-7);
}
