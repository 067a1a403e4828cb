// The distributed march (solvers/distributed/solve.h) on the ranks this test
// runs on — one under ctest, where the build without MPI and the MPI build
// alike run the slab code with itself as the only neighbour — against the
// one-process march (solvers/spacetime/solve.h): the same windows of a
// nonlinear field (sine-Gordon in 2 + 1 D, a breather-like bump on a
// periodic 32 × 24 grid, SBP42 in windows of 8) to the solves' round-off,
// for 2 and 3 axes; and the refusals, each naming its fix. The 1-rank and
// 2-rank runs of a scene through `mpirun` are tests/distributed_cli_test.sh.
#define BOOST_TEST_MODULE distributed_march
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/fields/densities.h"
#include "solvers/distributed/solve.h"
#include "solvers/spacetime/solve.h"

using vivp::sbp::SpaceDerivative;
using Grid = vivp::sbp::SpaceGrid<double>;
namespace dist = vivp::distributed;

namespace {

Grid Periodic(std::vector<int> n) {
  std::vector<SpaceDerivative<double>> axes;
  for (int p : n)
    axes.push_back(SpaceDerivative<double>::Periodic(4, p, -6, 12));
  return Grid(std::move(axes));
}

// A bump of height 1.5 that starts to move: nonlinear enough that the mode
// solve is a preconditioner (its Hessian varies with cos φ).
std::vector<double> Bump(const Grid& g, double height) {
  std::vector<double> phi(g.points());
  for (int j = 0; j < g.points(); ++j) {
    double r2 = 0;
    for (int a = 0; a < g.dim(); ++a) r2 += g.x(j, a) * g.x(j, a);
    phi[j] = height * std::exp(-r2 / 4);
  }
  return phi;
}

template <int d>
void Compare(std::vector<int> n) {
  const Grid g = Periodic(n);
  vivp::fields::SineGordonIn<d> density;
  const auto phi0 = Bump(g, 1.5);
  const auto pi0 = Bump(g, 0.3);
  const vivp::spacetime::FieldGrid time{
      .op = "sbp42", .points = 36, .t_end = 1.75, .window_points = 8};
  const auto one = vivp::spacetime::SolveField(density, g, time, phi0, pi0);
  const auto& comm = dist::Comm::World();
  const auto spread = dist::SolveField(comm, density, g, time, phi0, pi0);
  BOOST_REQUIRE(one.status.converged);
  BOOST_REQUIRE_MESSAGE(spread.status.converged, spread.status.reason);
  BOOST_TEST(spread.windows == one.windows);
  BOOST_TEST(!spread.unchecked.empty());
  double worst = 0, size = 0;
  for (std::size_t k = 0; k < one.end.phi.size(); ++k) {
    worst = std::max(worst, std::abs(one.end.phi[k] - spread.end.phi[k]));
    worst = std::max(worst, std::abs(one.end.phi_t[k] - spread.end.phi_t[k]));
    size = std::max(size, std::abs(one.end.phi[k]));
  }
  BOOST_TEST_MESSAGE(d << " axes on " << comm.size()
                       << " ranks: end states differ by " << worst << " (size "
                       << size << ")");
  // Both stop at round-off (32 ε of the largest unknown, newton.h) from
  // different starts: the predictor's path and the Taylor path.
  BOOST_TEST(worst < 1e-11 * std::max(1.0, size));
  if (comm.root()) {
    BOOST_REQUIRE(spread.phi.size() == one.phi.size());
    double slices = 0;
    for (std::size_t k = 0; k < one.phi.size(); ++k)
      slices = std::max(slices, std::abs(one.phi[k] - spread.phi[k]));
    BOOST_TEST(slices < 1e-11 * std::max(1.0, size));
  }
}

std::string Refusal(const Grid& g, vivp::spacetime::FieldSolveOptions o = {}) {
  vivp::fields::SineGordonIn<2> density;
  const vivp::spacetime::FieldGrid time{
      .op = "sbp42", .points = 8, .t_end = 0.2, .window_points = 8};
  try {
    dist::SolveField(dist::Comm::World(), density, g, time,
                     std::vector<double>(g.points()),
                     std::vector<double>(g.points()), o);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// MPI for the whole module when mpirun started it (comm.h).
struct MpiSession {
  MpiSession() {
    auto& suite = boost::unit_test::framework::master_test_suite();
    dist::Init(&suite.argc, &suite.argv);
  }
  ~MpiSession() { dist::Finalize(); }
};
BOOST_TEST_GLOBAL_FIXTURE(MpiSession);

}  // namespace

BOOST_AUTO_TEST_CASE(two_axes_match_one_process) { Compare<2>({32, 24}); }
BOOST_AUTO_TEST_CASE(three_axes_match_one_process) { Compare<3>({12, 10, 16}); }

BOOST_AUTO_TEST_CASE(refusals_name_the_fix) {
  const Grid interval({SpaceDerivative<double>::Periodic(4, 16, 0, 1),
                       SpaceDerivative<double>::Bounded("sbp42", 16, 0, 1)});
  const std::string why = Refusal(interval);
  BOOST_TEST_MESSAGE(why);
  BOOST_TEST(why.find("every axis must be periodic") != std::string::npos);
  vivp::spacetime::FieldSolveOptions o;
  o.tolerance = {1e-6, 1e-6};
  BOOST_TEST(Refusal(Periodic({16, 16}), o).find("error control") !=
             std::string::npos);
  // Grids that do not divide over the ranks, and slabs thinner than the
  // halo, need two ranks or more: tests/distributed_cli_test.sh.
  BOOST_TEST(Refusal(Grid(SpaceDerivative<double>::Periodic(4, 16, 0, 1)))
                 .find("one axis runs on one process") != std::string::npos);
}
