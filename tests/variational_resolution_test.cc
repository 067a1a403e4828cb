// The variational SBP discretization is conditionally stable (resolution.h):
// measured limits of Δt·ω, and an honest status beyond them.
#define BOOST_TEST_MODULE variational_resolution
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>
#include <stdexcept>
#include <string>

#include "core/sbp/builder.h"
#include "solvers/variational/march.h"

using namespace vivp;
using namespace vivp::variational;
namespace bdata = boost::unit_test::data;

// Named (not anonymous) namespace: the data-driven test case's lambdas
// capture it, and GCC warns (-Wsubobject-linkage) on anonymous types there.
namespace resolution_test {

// ẍ = −ω²x with ω² = k.
struct Spring {
  static constexpr int kDim = 1;
  double k = 1.0;
  template <class T>
  T operator()(const T* x, const T* v) const {
    return T(0.5) * v[0] * v[0] - T(0.5 * k) * x[0] * x[0];
  }
};

double MaxAbs(const vivp::variational::IvpSolution<double>& s) {
  return s.x1.cwiseAbs().maxCoeff();
}

}  // namespace resolution_test

using resolution_test::MaxAbs;
using resolution_test::Spring;

BOOST_DATA_TEST_CASE(StabilityLimit_IsWhereTheSolutionStopsBeingBounded,
                     bdata::make(vivp::sbp::OperatorNames()), op) {
  // Proves every registered operator's measured limit (core/sbp,
  // Measured::stability_limit): bounded (max|x| < 1.5 over 400 steps) at the
  // limit, unbounded 0.1 above it.
  const double limit = StabilityLimit(op);
  Spring s;
  auto solve = [&](double h_omega) {
    const Grid g{.op = op, .points = 400, .t_end = h_omega * 399};
    vivp::variational::SolveOptions o;
    return SolveIvp(s, {{1.0}, {0.0}}, g, o);
  };
  const auto at = solve(limit);
  BOOST_TEST(MaxAbs(at) < 1.5, op << " at the limit: " << MaxAbs(at));
  BOOST_TEST(at.status.converged, at.status.reason);
  const auto above = solve(limit + 0.1);
  BOOST_TEST(MaxAbs(above) > 1.5, op << " above the limit: " << MaxAbs(above));
  BOOST_TEST(!above.status.converged);
}

BOOST_AUTO_TEST_CASE(StabilityLimit_OfAnUnknownOperatorIsAnError) {
  // No default limit: an operator without a table is refused by name.
  BOOST_CHECK_EXCEPTION(
      StabilityLimit("sbp105"), std::invalid_argument, [](const auto& e) {
        return std::string(e.what()) ==
               "unknown SBP operator 'sbp105'; valid operators: sbp21, "
               "sbp42, sbp63, sbp84, and the spectral elements lgl8, lgl12, "
               "lgl16";
      });
}

BOOST_AUTO_TEST_CASE(StiffSpring_AtTenTimesTheStepIsReportedNotHidden) {
  // κ = 10⁴ (ω = 100) at Δt = 0.1: Δt·ω = 10. No NaN, and the status says
  // why the (unbounded) discrete solution is not an answer.
  Spring s;
  s.k = 1e4;
  const Grid g{.op = "sbp42", .points = 101, .t_end = 10.0};
  const auto r = SolveIvp(s, {{1.0}, {0.0}}, g);
  BOOST_TEST(r.x1.allFinite());
  BOOST_TEST(!r.status.converged);
  BOOST_TEST(r.status.reason.find("under-resolved: dt*omega = 10 exceeds") !=
                 std::string::npos,
             r.status.reason);
  BOOST_TEST(
      r.status.reason.find("use at least 1001 points") != std::string::npos,
      r.status.reason);
  // Marching without stabilization inherits it: the first window reports,
  // the march stops.
  vivp::variational::MarchOptions mo;
  mo.window_points = 32;
  mo.max_split_depth = 0;
  mo.stabilize = false;
  const auto m = MarchIvp(s, {{1.0}, {0.0}}, g, mo);
  BOOST_TEST(!m.status.converged);
  BOOST_TEST(m.status.reason.find("under-resolved") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(StiffSpring_MarchStaysBoundedOnARefinedGrid) {
  // Proves the stiff hard case of marching: at Δt·ω = 10 the default march
  // solves each window on a grid refined to Δt·ω ≤ half the limit (×20 for
  // SBP42); there a window of 31 requested steps spans 11 periods and
  // deviates from the exact local flow by 17 %, more than its own error
  // estimates allow (the checks of window_solve.h), so the march, which
  // already chooses the solve grid, refines on until the windows pass (×40
  // fails the consistency check too; ×64, Δt·ω = 0.16, the limit
  // max_refinement). It returns the requested grid and stays on the energy
  // of the oscillation (E = ½v² + ½κx², exact value 5000 throughout;
  // measured max|x| 1.000, energy error 0.18 % at the returned nodes before
  // the last, whose velocity is the closure row (Dx)_N, and 0.002 % for the
  // handed-off end state, whose velocity is M⁻¹(−λ3)).
  Spring s;
  s.k = 1e4;
  const Grid g{.op = "sbp42", .points = 101, .t_end = 10.0};
  vivp::variational::MarchOptions mo;
  mo.window_points = 32;
  const auto m = MarchIvp(s, {{1.0}, {0.0}}, g, mo);
  BOOST_TEST(m.status.converged, m.status.reason);
  BOOST_TEST(m.refinement == 64);
  BOOST_TEST(m.status.reason.find("refined x64") != std::string::npos);
  BOOST_TEST(m.t.size() == 101u);
  BOOST_TEST(m.x.allFinite());
  auto energy_error = [&](double x, double v) {
    return std::abs(0.5 * v * v + 0.5 * s.k * x * x - 5000.0) / 5000.0;
  };
  double max_x = 0, max_de = 0;
  for (Eigen::Index i = 0; i + 1 < m.x.rows(); ++i) {
    max_x = std::max(max_x, std::abs(m.x(i, 0)));
    max_de = std::max(max_de, energy_error(m.x(i, 0), m.v(i, 0)));
  }
  const double end_de = energy_error(m.end_position[0], m.end_velocity[0]);
  BOOST_TEST_MESSAGE("stiff march: max|x| "
                     << max_x << ", max rel. energy error " << max_de
                     << ", at the end state " << end_de);
  BOOST_TEST(max_x <= 1.01);
  BOOST_TEST(max_de <= 0.01);
  BOOST_TEST(end_de <= 1e-3);
}

BOOST_AUTO_TEST_CASE(UnderResolutionAdvice_ComesFromTheFirstState) {
  // SBP42 (limit Δt·ω = 1) on 101 points over [0, 10], Δt = 0.1. Within the
  // limit at both states: no complaint.
  const Grid grid{.op = "sbp42", .points = 101, .t_start = 0.0, .t_end = 10.0};
  BOOST_TEST(detail::UnderResolution(grid, 5.0, 9.0).empty());
  // Over it at the first state (Δt·ω = 3): the points that ω asks for,
  // ⌈T·ω / limit⌉ + 1 = 301.
  const std::string start = detail::UnderResolution(grid, 30.0, 40.0);
  BOOST_TEST(start.find("dt*omega = 4 exceeds the stability limit 1") !=
             std::string::npos);
  BOOST_TEST(start.find("use at least 301 points") != std::string::npos);
  // Within it at the first state (0.5) and far over at the last (1e5): the
  // solution grew on the way, and the last state's ω, which came from the
  // grown solution, must not set the advice (it would ask for 1e7 points);
  // twice the points, 201, and a check of the end state instead.
  const std::string grew = detail::UnderResolution(grid, 5.0, 1e6);
  BOOST_TEST(grew.find("dt*omega = 1e+05") != std::string::npos);
  BOOST_TEST(grew.find("grew on the way") != std::string::npos);
  BOOST_TEST(grew.find("at least 201") != std::string::npos);
  BOOST_TEST(grew.find("10000001") == std::string::npos);
}
