// Error control for fields (docs/error_control.md, docs/fields.md §7): the
// march of point mechanics with a field's window, whose embedded estimate is
// each spatial point's multipliers λ4, λ3. The largest errors over every
// kept slice follow the tolerance; no window is accepted unchecked; and the
// space-diagonalized solve of a linear density factors each spatial mode's
// time system once for a uniform march.
#define BOOST_TEST_MODULE fields_error_control
#include <ceres/jet.h>

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "core/action/field_boundary.h"
#include "problems/fields/densities.h"
#include "problems/fields/exact.h"
#include "solvers/spacetime/solve.h"
#include "tests/fields_helpers.h"

using namespace vivp;
using namespace fields_test;

namespace {

struct Row {
  double tol, max_phi, max_phi_t;
  long long points;
  int rejected;
  std::vector<double> end_phi, end_phi_t;  // the corrected end state
};

const std::vector<double> kTolerances = {1e-4, 1e-5, 1e-6, 1e-7, 1e-8};

// One march per tolerance to T; the largest errors of φ and φ_t over every
// kept slice against the exact solution u.
template <class Density, class U>
std::vector<Row> Sweep(const char* name, const Density& density, const U& u,
                       const SpaceDerivative<double>& dx, const char* op,
                       double t_end,
                       const spacetime::FieldSolveOptions& base = {},
                       const std::vector<double>& tolerances = kTolerances) {
  std::vector<Row> rows;
  for (const double tol : tolerances) {
    auto o = base;
    o.tolerance = {.absolute = tol, .relative = tol};
    const auto s = Solve(density, u, dx,
                         {.op = op, .t_end = t_end, .window_points = 16}, o);
    // Every window was compared with the independent integration.
    BOOST_TEST(s.unchecked.empty(), s.unchecked);
    BOOST_TEST(s.min_step > 0);
    Row r{tol, 0, 0, s.points, s.rejected, s.end.phi, s.end.phi_t};
    const int nx = dx.points();
    for (std::size_t k = 0; k < s.t.size(); ++k)
      for (int j = 0; j < nx; ++j) {
        using J = ceres::Jet<double, 1>;
        const J exact = u(J(s.t[k], 0), J(dx.x(j)));
        r.max_phi = std::max(r.max_phi, std::abs(s.phi[k * nx + j] - exact.a));
        r.max_phi_t =
            std::max(r.max_phi_t, std::abs(s.phi_t[k * nx + j] - exact.v[0]));
      }
    BOOST_TEST_MESSAGE(name << " " << op << " tolerance " << tol << ": "
                            << s.points << " points, " << s.windows
                            << " windows, " << s.rejected << " rejected, "
                            << s.check_failures
                            << " failed checks; max error φ " << r.max_phi
                            << ", φ_t " << r.max_phi_t);
    rows.push_back(r);
  }
  return rows;
}

// The tolerance bounds each window's local error (docs/error_control.md);
// the largest global error over every kept slice is of its size: φ's is far
// below it, φ_t's (the SBP closure's velocity, the binding one) within a few
// times it — measured 0.09 … 2.2 (SBP42) and 0.002 … 0.09 (SBP63) here,
// against 0.01 … 34 on point-mechanics sweeps. The nodes grow as the
// tolerance shrinks, and the velocity error follows the tolerance with a
// fitted slope near one: error control does what it says, not by luck of a
// fine grid.
void Tracks(const std::vector<Row>& rows, double floor) {
  std::vector<double> tol, err;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    BOOST_TEST_MESSAGE("tolerance " << r.tol << ": error/tolerance φ "
                                    << r.max_phi / r.tol << ", φ_t "
                                    << r.max_phi_t / r.tol);
    BOOST_TEST(r.max_phi <= 0.01 * r.tol);
    BOOST_TEST(r.max_phi_t <= 4 * r.tol);
    if (i > 0) BOOST_TEST(r.points > rows[i - 1].points);
    if (r.max_phi_t > floor) {
      tol.push_back(r.tol);
      err.push_back(r.max_phi_t);
    }
  }
  BOOST_REQUIRE(tol.size() >= 2);
  const double slope = Slope(tol, err);
  BOOST_TEST_MESSAGE("max error φ_t against the tolerance: slope " << slope);
  BOOST_TEST(slope >= 0.7);
  BOOST_TEST(slope <= 1.5);
}

}  // namespace

// The Klein–Gordon plane wave cos(x − √2 t) on the circle, periodic
// differences of order 8 on 64 points (spatial error 1e-11), SBP42 and SBP63.
BOOST_AUTO_TEST_CASE(klein_gordon_errors_follow_the_tolerance) {
  const auto dx = SpaceDerivative<double>::Periodic(8, 64, 0.0, kTwoPi);
  const fields::KleinGordonPlaneWave wave;
  for (const char* op : {"sbp42", "sbp63"})
    Tracks(Sweep("Klein–Gordon", fields::KleinGordon{}, wave, dx, op, 1.0),
           1e-9);
}

// The sine-Gordon kink moving at v = 0.5 on [−4, 4] with its exact values
// as Dirichlet data at both ends, SBP63 in space on 81 points. Against the
// exact solution the errors stop at the spatial error (2e-5 here), which no
// time step removes; so the time error is measured against a march on the
// same spatial grid at tolerance 1e-10 (1e-11 is refused: below the
// round-off of the velocity estimate): the corrected end state's error stays
// below the tolerance (measured 0.01 … 0.27 of it) and falls with it, by 380
// over four decades (fitted slope 0.64; the hand-off state is better than
// the nodes the tolerance bounds, as in point mechanics). The data are not
// solved for, and the windows are checked on the interior points.
BOOST_AUTO_TEST_CASE(dirichlet_kink_end_error_follows_the_tolerance) {
  const auto dx = SpaceDerivative<double>::Bounded("sbp63", 81, -4.0, 4.0);
  const fields::SineGordonKink kink{0.5, 0.0};
  spacetime::FieldSolveOptions o;
  o.boundary.left = {action::BoundaryKind::kDirichlet,
                     [&](double t, int) { return kink(t, -4.0); }};
  o.boundary.right = {action::BoundaryKind::kDirichlet,
                      [&](double t, int) { return kink(t, 4.0); }};
  const fields::SineGordon sg;
  const Row ref = Sweep("reference", sg, kink, dx, "sbp42", 1.0, o, {1e-10})[0];
  const auto rows =
      Sweep("sine-Gordon kink, Dirichlet", sg, kink, dx, "sbp42", 1.0, o);
  std::vector<double> tol, err;
  for (const Row& r : rows) {
    double e = 0;
    for (std::size_t k = 0; k < ref.end_phi.size(); ++k)
      e = std::max({e, std::abs(r.end_phi[k] - ref.end_phi[k]),
                    std::abs(r.end_phi_t[k] - ref.end_phi_t[k])});
    BOOST_TEST_MESSAGE("tolerance " << r.tol << ": end error " << e
                                    << " against the reference, ratio "
                                    << e / r.tol);
    BOOST_TEST(e <= r.tol);
    tol.push_back(r.tol);
    err.push_back(e);
  }
  BOOST_TEST_MESSAGE("end error against the tolerance: slope "
                     << Slope(tol, err));
  BOOST_TEST(err.back() <= 0.01 * err.front());
  BOOST_TEST(rows.back().points > rows.front().points);
}

// A linear density on a uniform grid: the mode solve factors each distinct
// spatial mode's banded time system once for the whole march, whatever the
// number of windows (33 distinct systems for 64 periodic points: the
// eigenvalues of modes k and 64 − k are equal).
BOOST_AUTO_TEST_CASE(linear_march_factors_each_mode_once) {
  const auto dx = SpaceDerivative<double>::Periodic(8, 64, 0.0, kTwoPi);
  const fields::KleinGordonPlaneWave wave;
  const auto s =
      Solve(fields::KleinGordon{}, wave, dx,
            {.op = "sbp42", .points = 301, .t_end = 3.0, .window_points = 16});
  BOOST_TEST_MESSAGE(s.windows << " windows, " << s.mode_factorizations
                               << " mode factorizations, "
                               << s.lu_factorizations << " LU factorizations, "
                               << s.fallbacks << " fallbacks");
  BOOST_TEST(s.windows == 20);
  BOOST_TEST(s.mode_factorizations == 33);
  BOOST_TEST(s.lu_factorizations == 0);
  BOOST_TEST(s.fallbacks == 0);
}
