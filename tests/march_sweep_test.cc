// Marching never returns a wrong branch as converged, across problems,
// operators, window lengths and grids: anharmonic oscillator (T = 10),
// pendulum (T = 20) and Kepler e = 0.6 (T = 10π), SBP21 … SBP84, windows of
// 32, 48 and 96 points, 28 uniform grids of 257 … 1985 points each (1008
// marches). Before every window started Newton from an order-5 predictor
// and was checked against it, these sweeps returned rows on another branch
// as converged (anharmonic, SBP42, 449 points, windows of 48: end error
// 1.39), aborted whole studies on a NaN handed from window to window
// (windows of 96), and needed 6 to 172 fallbacks per sweep.
//
// What a converged row must not be: an outlier of its own study. The
// literal test "above 100 times the median of the other rows" flags the
// coarse rows of every high-order operator, whose errors fall as a clean
// power law over the sweep's factor of 8 in Δt (Kepler, SBP84: 0.14 at 513
// points to 2.6e-7 at 1985, fitted order 9.7), so that number is reported,
// and the test asserts the criterion it stands for: no converged row is 100
// times above the geometric mean of its converged neighbours in the sweep
// (the grids are 64 points apart, at most 25 % in Δt, where an order-10
// method changes its error 10×). A row that did not converge must say why.
#define BOOST_TEST_MODULE march_sweep
#include <algorithm>
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "studies/registry.h"

using namespace vivp;
using namespace vivp::variational;
namespace bdata = boost::unit_test::data;

namespace {

struct Study {
  std::vector<long long> points;  // converged rows
  std::vector<double> errors;
  int not_converged = 0, fallbacks = 0, check_failures = 0;
  long long windows = 0;
};

Study Sweep(const std::string& problem, double t_end, const std::string& op,
            long long window) {
  const vivp::studies::NamedProblem& p = vivp::studies::FindProblem(problem);
  const vivp::studies::ExactState exact = p.exact(t_end);
  Study s;
  for (int k = 0; k < 28; ++k) {
    Grid g{.op = op, .points = 257 + 64 * k, .t_end = t_end};
    MarchOptions o;
    o.window_points = window;
    o.stabilize = false;  // a grid is the grid it names
    o.keep_trajectory = false;
    const MarchResult m = p.march(g, o, {});
    s.fallbacks += m.fallbacks;
    s.check_failures += m.check_failures;
    s.windows += m.window_count;
    if (!m.status.converged) {
      ++s.not_converged;
      BOOST_TEST(!m.status.reason.empty());
      BOOST_TEST(std::isfinite(m.failed_at));
      continue;
    }
    double e = 0;
    for (std::size_t c = 0; c < exact.x.size(); ++c)
      e = std::max(e, std::abs(m.end_position[c] - exact.x[c]));
    BOOST_TEST(std::isfinite(e));
    s.points.push_back(g.points);
    s.errors.push_back(e);
  }
  return s;
}

// The largest error over the geometric mean of its converged neighbours
// (one neighbour at the ends), for errors above round-off.
double WorstAgainstNeighbours(const Study& s) {
  double worst = 0;
  const std::size_t n = s.errors.size();
  for (std::size_t i = 0; i < n && n > 1; ++i) {
    if (!(s.errors[i] > 1e-12)) continue;
    const double left = i > 0 ? s.errors[i - 1] : s.errors[i + 1];
    const double right = i + 1 < n ? s.errors[i + 1] : s.errors[i - 1];
    const double mean =
        std::sqrt(std::max(left, 1e-16) * std::max(right, 1e-16));
    worst = std::max(worst, s.errors[i] / mean);
  }
  return worst;
}

// The literal criterion: rows above 100 times the median of the others.
int AboveHundredMedians(const Study& s) {
  int count = 0;
  for (std::size_t i = 0; i < s.errors.size(); ++i) {
    std::vector<double> others;
    for (std::size_t j = 0; j < s.errors.size(); ++j)
      if (j != i) others.push_back(s.errors[j]);
    if (others.empty()) continue;
    std::nth_element(others.begin(), others.begin() + others.size() / 2,
                     others.end());
    if (s.errors[i] > 100 * others[others.size() / 2] && s.errors[i] > 1e-12)
      ++count;
  }
  return count;
}

struct Case {
  const char* problem;
  double t_end;
};
std::ostream& operator<<(std::ostream& o, const Case& c) {
  return o << c.problem;
}

}  // namespace

BOOST_DATA_TEST_CASE(UniformSweeps_HaveNoConvergedOutlierAndNoAbort,
                     bdata::make({Case{"anharmonic", 10.0},
                                  Case{"pendulum", 20.0},
                                  Case{"kepler", 10 * M_PI}}) *
                         bdata::make({"sbp21", "sbp42", "sbp63", "sbp84"}) *
                         bdata::make({32, 48, 96}),
                     c, op, window) {
  Study s;
  BOOST_REQUIRE_NO_THROW(s = Sweep(c.problem, c.t_end, op, window));
  const double worst = WorstAgainstNeighbours(s);
  BOOST_TEST_MESSAGE(
      c.problem << " " << op << " W = " << window << ": " << s.errors.size()
                << " converged, " << s.not_converged << " not, " << s.fallbacks
                << " fallbacks (" << s.check_failures << " check failures) in "
                << s.windows << " windows; errors "
                << (s.errors.empty()
                        ? 0.0
                        : *std::min_element(s.errors.begin(), s.errors.end()))
                << " … "
                << (s.errors.empty()
                        ? 0.0
                        : *std::max_element(s.errors.begin(), s.errors.end()))
                << "; worst against neighbours " << worst
                << "; above 100 medians " << AboveHundredMedians(s));
  BOOST_TEST(worst <= 100.0);
  // Fallbacks near zero: measured at most 9 per study of 28 marches (Kepler
  // SBP42, coarse grids whose windows split once after a failed check).
  BOOST_TEST(s.fallbacks <= 12);
  // The finer half of every sweep converges for SBP42 and above.
  if (std::string(op) != "sbp21") BOOST_TEST(s.errors.size() >= 14u);
}
