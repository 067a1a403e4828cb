// The variational SBP discretization is conditionally stable (resolution.h):
// measured limits of Δt·ω, and an honest status beyond them.
#define BOOST_TEST_MODULE variational_resolution
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>

#include "solvers/variational/march.h"

using namespace vivp;
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

double MaxAbs(const IvpSolution<double>& s) {
  return s.x1.cwiseAbs().maxCoeff();
}

}  // namespace resolution_test

using resolution_test::MaxAbs;
using resolution_test::Spring;

BOOST_DATA_TEST_CASE(StabilityLimit_IsWhereTheSolutionStopsBeingBounded,
                     bdata::make({"sbp21", "sbp42", "sbp63", "sbp84"}), op) {
  // Proves the table in resolution.h: bounded (max|x| < 1.5 over 400 steps)
  // at the limit, unbounded 0.1 above it.
  const double limit = StabilityLimit(op);
  Spring s;
  auto solve = [&](double h_omega) {
    const Grid g{.op = op, .points = 400, .t_end = h_omega * 399};
    SolveOptions o;
    return SolveIvp(s, {{1.0}, {0.0}}, g, o);
  };
  const auto at = solve(limit);
  BOOST_TEST(MaxAbs(at) < 1.5, op << " at the limit: " << MaxAbs(at));
  BOOST_TEST(at.status.converged, at.status.reason);
  const auto above = solve(limit + 0.1);
  BOOST_TEST(MaxAbs(above) > 1.5, op << " above the limit: " << MaxAbs(above));
  BOOST_TEST(!above.status.converged);
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
  BOOST_TEST(r.status.reason.find("under-resolved: dt*omega = 10.0") !=
             std::string::npos, r.status.reason);
  BOOST_TEST(r.status.reason.find("use at least 1001 points") !=
             std::string::npos, r.status.reason);
  // Marching inherits it: the first window reports, the march stops.
  MarchOptions mo;
  mo.window_points = 32;
  mo.max_split_depth = 0;
  const auto m = MarchIvp(s, {{1.0}, {0.0}}, g, mo);
  BOOST_TEST(!m.status.converged);
  BOOST_TEST(m.status.reason.find("under-resolved") != std::string::npos);
}
