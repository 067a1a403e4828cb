// Fields on an interval with boundary data (core/action/field_boundary.h):
// Dirichlet data by multipliers and Neumann data as the natural condition
// with data, their order against an exact solution with time-dependent data,
// and the refusals.
#define BOOST_TEST_MODULE fields_boundary
#include <ceres/jet.h>

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/action/field_boundary.h"
#include "problems/fields/densities.h"
#include "problems/fields/exact.h"
#include "solvers/spacetime/solve.h"
#include "tests/fields_helpers.h"

using namespace vivp;
using namespace fields_test;

// Boundary data by multipliers (core/action/field_boundary.h): the
// sine-Gordon kink moving at v = 0.5 on [−4, 4] to T = 2, its exact value
// (Dirichlet) or slope (Neumann) prescribed at both ends as functions of t,
// SBP42 in time (129 points, windows of 16, so each window takes its own
// data) and in space. The fitted order in Δx at t = T, reported with the
// floor of the natural condition's test above.
BOOST_AUTO_TEST_CASE(dirichlet_and_neumann_data_by_multipliers) {
  const fields::SineGordon sg;
  const fields::SineGordonKink kink{0.5, 0.0};
  const auto slope = [&](double t, double x) {
    using J = ceres::Jet<double, 1>;
    return kink(J(t), J(x, 0)).v[0];
  };
  using action::BoundaryKind;
  for (const BoundaryKind kind :
       {BoundaryKind::kDirichlet, BoundaryKind::kNeumann}) {
    const bool dirichlet = kind == BoundaryKind::kDirichlet;
    spacetime::FieldSolveOptions options;
    options.boundary.left = {kind, [&](double t, int) {
                               return dirichlet ? kink(t, -4.0)
                                                : slope(t, -4.0);
                             }};
    options.boundary.right = {kind, [&](double t, int) {
                                return dirichlet ? kink(t, 4.0) : slope(t, 4.0);
                              }};
    std::vector<double> h, err;
    double boundary = 0;
    for (int nx : {21, 31, 41, 61}) {
      const auto dx = SpaceDerivative<double>::Bounded("sbp42", nx, -4.0, 4.0);
      const auto s = Solve(sg, kink, dx, {"sbp42", 129, 2.0, 16}, options);
      h.push_back(dx.dx());
      err.push_back(EndErrors(s, kink, dx, 2.0).second);
      if (dirichlet)  // the data hold at every kept slice
        for (std::size_t k = 0; k < s.t.size(); ++k)
          boundary =
              std::max({boundary, std::abs(s.phi[k * nx] - kink(s.t[k], -4.0)),
                        std::abs(s.phi[k * nx + nx - 1] - kink(s.t[k], 4.0))});
    }
    const double p = Slope(h, err);
    BOOST_TEST_MESSAGE(action::BoundaryName(kind)
                       << ": fitted order in space " << p << " (error "
                       << err.front() << " at 21 points, " << err.back()
                       << " at 61)");
    BOOST_TEST(p >= 2.7);
    BOOST_TEST(err.back() <= 1e-3);
    BOOST_TEST(boundary <= 1e-13);
  }
  // The data matter: with the natural condition φ_x = 0 instead, the same
  // run misses the kink by far more.
  const auto dx = SpaceDerivative<double>::Bounded("sbp42", 61, -4.0, 4.0);
  const auto s = Solve(sg, kink, dx, {"sbp42", 129, 2.0, 16});
  const double natural = EndErrors(s, kink, dx, 2.0).second;
  BOOST_TEST_MESSAGE("natural: error " << natural << " at 61 points");
  BOOST_TEST(natural >= 10 * 3.5e-4);
}

// L = ½φ_t² − ½(1 + φ²)φ_x²: a flux that depends on φ.
struct Stiffening {
  static constexpr int kDim = 1;
  template <class T>
  T operator()(const T* p, const T* pt, const T* px) const {
    return T(0.5) * pt[0] * pt[0] -
           T(0.5) * (1.0 + p[0] * p[0]) * px[0] * px[0];
  }
};

BOOST_AUTO_TEST_CASE(boundary_data_are_refused_with_their_reason) {
  const fields::SineGordon sg;
  const auto dx = SpaceDerivative<double>::Periodic(2, 8, 0.0, 1.0);
  std::vector<double> ok(8, 0.0);
  // None on the circle, finite, and Neumann data only for a
  // flux that depends on φ_x alone.
  using action::BoundaryKind;
  spacetime::FieldSolveOptions dirichlet;
  dirichlet.boundary.left = {BoundaryKind::kDirichlet, {}};
  BOOST_TEST(Refused(
      [&] {
        spacetime::SolveField(sg, dx, {"sbp42", 9, 1.0, 0}, ok, ok, dirichlet);
      },
      "a dirichlet boundary needs an interval"));
  const auto interval = SpaceDerivative<double>::Bounded("sbp21", 8, 0, 1);
  dirichlet.boundary.right = {BoundaryKind::kDirichlet,
                              [](double t, int) { return 1 / (t - 0.5); }};
  BOOST_TEST(Refused(
      [&] {
        spacetime::SolveField(sg, interval, {"sbp21", 3, 1.0, 0}, ok, ok,
                              dirichlet);
      },
      "right dirichlet data: non-finite value at t = 0.5"));
  spacetime::FieldSolveOptions neumann;
  neumann.boundary.left = {BoundaryKind::kNeumann, {}};
  BOOST_TEST(Refused(
      [&] {
        spacetime::SolveField(Stiffening{}, interval, {"sbp21", 9, 1.0, 0}, ok,
                              ok, neumann);
      },
      "flux ∂L/∂φ_x depends on φ_x alone"));
}
