// Checkpoint and restart of a field march (solvers/spacetime/checkpoint.h):
// a march stopped at a window boundary and resumed from its checkpoint
// gives the fields of the uninterrupted march bit for bit (in 2 + 1 D and in
// 1 + 1 D with Dirichlet data); a checkpoint that does not fit the run is
// refused with its reason.
#define BOOST_TEST_MODULE fields_checkpoint
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "problems/fields/densities.h"
#include "problems/fields/exact.h"
#include "solvers/spacetime/solve.h"

namespace {

using vivp::sbp::SpaceDerivative;
using Grid = vivp::sbp::SpaceGrid<double>;
using vivp::spacetime::FieldCheckpoint;
using vivp::spacetime::FieldGrid;
using vivp::spacetime::FieldSolution;
using vivp::spacetime::FieldSolveOptions;
using vivp::spacetime::SolveField;

// Thrown by a checkpoint callback: the run is "killed" there.
struct Killed {};

// Runs the march uninterrupted, then again killed after the checkpoint at
// `node`, then resumed from that checkpoint; checks that every kept slice
// from the node on and the end state are bit-identical.
template <class Density>
void CheckRestart(const Density& density, const Grid& g, const FieldGrid& fg,
                  const std::vector<double>& phi0,
                  const std::vector<double>& pi0, FieldSolveOptions o,
                  long long node) {
  const FieldSolution whole = SolveField(density, g, fg, phi0, pi0, o);
  BOOST_REQUIRE_MESSAGE(whole.status.converged, whole.status.reason);
  std::optional<FieldCheckpoint> saved;
  o.on_checkpoint = [&](const FieldCheckpoint& c) {
    if (c.node != node) return;
    saved = c;
    throw Killed{};
  };
  BOOST_CHECK_THROW(SolveField(density, g, fg, phi0, pi0, o), Killed);
  BOOST_REQUIRE(saved.has_value());
  o.on_checkpoint = nullptr;
  o.resume = &*saved;
  const FieldSolution resumed = SolveField(density, g, fg, phi0, pi0, o);
  BOOST_REQUIRE_MESSAGE(resumed.status.converged, resumed.status.reason);
  // The kept slices of the whole run from the checkpoint's node on.
  const std::size_t n = whole.phi.size() / whole.t.size();
  const std::size_t first = std::size_t(node);
  BOOST_REQUIRE_EQUAL(resumed.t.size(), whole.t.size() - first);
  long long differ = 0;
  for (std::size_t k = 0; k < resumed.phi.size(); ++k) {
    differ += resumed.phi[k] != whole.phi[first * n + k];
    differ += resumed.phi_t[k] != whole.phi_t[first * n + k];
  }
  for (std::size_t k = 0; k < n; ++k) {
    differ += resumed.end.phi[k] != whole.end.phi[k];
    differ += resumed.end.phi_t[k] != whole.end.phi_t[k];
  }
  BOOST_TEST_MESSAGE("resumed at node "
                     << node << " (t = " << saved->t
                     << "): " << resumed.t.size()
                     << " slices, values that differ: " << differ);
  BOOST_TEST(differ == 0);
  BOOST_TEST(resumed.t.front() == whole.t[first]);
}

Grid Plane() {
  return Grid({SpaceDerivative<double>::Periodic(4, 16, -8.0, 16.0),
               SpaceDerivative<double>::Bounded("sbp42", 12, -5.0, 5.0)});
}

void Bump(const Grid& g, std::vector<double>& phi0, std::vector<double>& pi0) {
  phi0.resize(g.points());
  pi0.resize(g.points());
  for (int j = 0; j < g.points(); ++j) {
    const double x = g.x(j, 0), y = g.x(j, 1);
    phi0[j] = 3.0 * std::exp(-0.3 * (x * x + y * y));
    pi0[j] = 0.2 * std::cos(0.5 * x - 0.3 * y);
  }
}

}  // namespace

// Sine-Gordon in 2 + 1 D (a nonlinear field: Newton's chord steps run on the
// factorization an earlier window left), SBP42 in windows of 9, killed
// after the fourth window and resumed.
BOOST_AUTO_TEST_CASE(a_resumed_march_is_bit_identical_in_two_dimensions) {
  const Grid g = Plane();
  std::vector<double> phi0, pi0;
  Bump(g, phi0, pi0);
  const FieldGrid fg{
      .op = "sbp42", .points = 65, .t_end = 2.0, .window_points = 9};
  CheckRestart(vivp::fields::SineGordonIn<2>{}, g, fg, phi0, pi0, {}, 32);
}

// The moving sine-Gordon kink in 1 + 1 D between Dirichlet ends that follow
// the exact solution (data that depend on t), SBP63 in windows of 13.
BOOST_AUTO_TEST_CASE(a_resumed_march_is_bit_identical_with_boundary_data) {
  const auto dx = SpaceDerivative<double>::Bounded("sbp42", 41, -8.0, 8.0);
  const vivp::fields::SineGordonKink kink{.velocity = 0.5, .x0 = -1.0};
  const auto [phi0, pi0] = vivp::fields::InitialData(kink, dx);
  FieldSolveOptions o;
  o.boundary.left = {vivp::action::BoundaryKind::kDirichlet,
                     [kink](double t, int) { return kink(t, -8.0); }};
  o.boundary.right = {vivp::action::BoundaryKind::kDirichlet,
                      [kink](double t, int) { return kink(t, 8.0); }};
  const FieldGrid fg{
      .op = "sbp63", .points = 97, .t_end = 3.0, .window_points = 13};
  CheckRestart(vivp::fields::SineGordon{}, Grid(dx), fg, phi0, pi0, o, 48);
}

// A checkpoint that does not fit the run, a corrupted one, and checkpoints
// of an error-controlled march are refused.
BOOST_AUTO_TEST_CASE(a_checkpoint_that_does_not_fit_is_refused) {
  const Grid g = Plane();
  std::vector<double> phi0, pi0;
  Bump(g, phi0, pi0);
  const FieldGrid fg{
      .op = "sbp42", .points = 33, .t_end = 1.0, .window_points = 9};
  const vivp::fields::SineGordonIn<2> sg;
  std::vector<FieldCheckpoint> all;
  FieldSolveOptions o;
  o.on_checkpoint = [&](const FieldCheckpoint& c) { all.push_back(c); };
  BOOST_REQUIRE(SolveField(sg, g, fg, phi0, pi0, o).status.converged);
  BOOST_REQUIRE_EQUAL(all.size(), 3u);  // nodes 8, 16, 24
  auto refused = [&](FieldCheckpoint c, const FieldGrid& grid,
                     FieldSolveOptions opts = {}) {
    opts.resume = &c;
    try {
      SolveField(sg, g, grid, phi0, pi0, opts);
    } catch (const std::invalid_argument& e) {
      BOOST_TEST_MESSAGE(e.what());
      return true;
    }
    return false;
  };
  FieldGrid other = fg;
  other.op = "sbp21";
  BOOST_TEST(refused(all[0], other));
  other = fg;
  other.window_points = 5;
  BOOST_TEST(refused(all[0], other));
  other = fg;
  other.points = 65;
  BOOST_TEST(refused(all[0], other));
  FieldCheckpoint bad = all[1];
  bad.phi[5] = NAN;
  BOOST_TEST(refused(bad, fg));
  bad = all[1];
  bad.node = 12;
  BOOST_TEST(refused(bad, fg));
  bad = all[1];
  bad.phi.pop_back();
  BOOST_TEST(refused(bad, fg));
  for (double f : {0.0, 2.0, double(NAN)}) {
    bad = all[1];
    bad.carry.predictor_factor = f;
    BOOST_TEST(refused(bad, fg), "predictor factor " << f);
  }
  FieldSolveOptions adaptive;
  adaptive.tolerance = {1e-6, 1e-6};
  BOOST_TEST(refused(all[0], fg, adaptive));
}
