// Error control of time-slab marching (MarchOptions::tolerance): every
// window's Δt is chosen from its embedded error estimates, so the grid
// follows the solution. Kepler e = 0.9 over ten orbits is the hard case: r
// runs from 0.1 to 1.9 and a uniform grid fine enough for pericentre wastes
// its points elsewhere.
#define BOOST_TEST_MODULE error_control
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "core/linalg/fit.h"
#include "problems/kepler.h"
#include "studies/bench_problems.h"
#include "studies/registry.h"

using namespace vivp;
using namespace vivp::variational;
using namespace vivp::studies;
namespace bdata = boost::unit_test::data;

namespace {

constexpr double kTenOrbits = 20 * M_PI;

MarchResult KeplerE09(const std::string& op, const MarchOptions& o,
                      long long points = 0) {
  const Grid g{.op = op, .points = points, .t_end = kTenOrbits};
  return vivp::studies::FindProblem("kepler_e09").march(g, o, {});
}

}  // namespace

BOOST_DATA_TEST_CASE(KeplerE09_TolerancedRun_EndsWithinTenTimesTheTolerance,
                     bdata::make({"sbp42", "sbp63", "sbp84"}), op) {
  // Measured end errors (position, velocity) at tolerance 1e-6: SBP42
  // 5.0e-8, 1.1e-6; SBP63 5.4e-11, 1.2e-9; SBP84 9.4e-10, 2.1e-8 — with
  // 57708, 38641 and 11889 nodes (4 December). Energy and angular momentum
  // over every node are reported and bounded by the same 1e-5.
  MarchOptions o;
  o.tolerance = {1e-6, 1e-6};
  const MarchResult m = KeplerE09(op, o);
  BOOST_TEST_REQUIRE(m.status.converged, m.status.reason);
  problems::Kepler k;
  k.e = 0.9;
  const std::vector<double> exact = k.Exact(kTenOrbits);
  double ex = 0, ev = 0;
  for (int c = 0; c < 2; ++c) {
    ex = std::max(ex, std::abs(m.end_position[c] - exact[c]));
    ev = std::max(ev, std::abs(m.end_velocity[c] - exact[2 + c]));
  }
  const double q0[2] = {0.1, 0.0}, p0[2] = {0.0, std::sqrt(19.0)};
  const double h0 = k.Hamiltonian(q0, p0), l0 = k.Invariants(q0, p0)[0];
  double dh = 0, dl = 0;
  for (Eigen::Index i = 0; i < m.x.rows(); ++i) {
    const double q[2] = {m.x(i, 0), m.x(i, 1)}, v[2] = {m.v(i, 0), m.v(i, 1)};
    dh = std::max(dh, std::abs(k.Hamiltonian(q, v) - h0));
    dl = std::max(dl, std::abs(k.Invariants(q, v)[0] - l0));
  }
  BOOST_TEST_MESSAGE(op << " at 1e-6: " << m.points << " nodes, "
                        << m.window_count << " windows, " << m.rejected
                        << " rejected; end error x " << ex << ", v " << ev
                        << "; max |ΔH| " << dh << ", max |Δℓ| " << dl
                        << "; Δt from " << m.min_step << " to " << m.max_step);
  BOOST_TEST(ex <= 1e-5);
  BOOST_TEST(ev <= 1e-5);
  BOOST_TEST(dh <= 1e-5);
  BOOST_TEST(dl <= 1e-5);
  // The grid follows r^{3/2}: steps at apocentre far above pericentre's.
  BOOST_TEST(m.max_step > 20 * m.min_step);
  // Nodes are returned in order, the last exactly at t_end.
  for (std::size_t i = 1; i < m.t.size(); ++i)
    BOOST_TEST_REQUIRE(m.t[i] > m.t[i - 1]);
  BOOST_TEST(m.t.back() == kTenOrbits);
  BOOST_TEST(m.points == (long long)m.t.size());
}

BOOST_AUTO_TEST_CASE(KeplerE09_Uniform4001Sbp42_FailsTheAPosterioriCheck) {
  // Without a tolerance, the 4001-point SBP42 grid the march used to return
  // as converged (end error 5.7, angular momentum off by 0.5): its first
  // window deviates from the predictor by 19 % of the orbit's size.
  MarchOptions o;
  const MarchResult m = KeplerE09("sbp42", o, 4001);
  BOOST_TEST(!m.status.converged);
  BOOST_TEST(m.status.reason.find("was solved but rejected: under-resolved") !=
                 std::string::npos,
             m.status.reason);
  BOOST_TEST(m.failed_at == 0.0);
  BOOST_TEST(std::isfinite(m.last_residual));
}

BOOST_DATA_TEST_CASE(ToleranceSweep_AchievedErrorTracksTheTolerance,
                     bdata::make({"kepler_e09", "anharmonic"}) *
                         bdata::make({"sbp42", "sbp63", "sbp84"}),
                     problem, op) {
  // Tolerances 1e-3 … 1e-8. What the tolerance bounds is the local error of
  // every returned node, and the velocity of a window's last nodes (the SBP
  // closure) is the binding one: the largest node velocity error follows
  // the tolerance with a fitted slope of 1.1–1.5 and stays within 40 times
  // it. Positions and the handed-off end state are more accurate still: the
  // end position error stays below twice the tolerance.
  //
  // Except Kepler at 1e-3, where the error accumulated over ten orbits at
  // pericentre speed 4.4 dominates, and is as sensitive to the step sequence
  // as an orbit's phase is: perturbations of the window solves at the level
  // of round-off (the factorization kept as a chord start within a step
  // ratio of 1, 1.25, 1.5, 2, 3, 4, 6 or any; at every ratio and tolerance
  // every solve within 3.3e-14 relative of a fresh Newton solve from its
  // result, the order of newton.h's 64 ε stop on stalled chord steps) gave
  // 11,469–11,751 nodes and, for SBP42, end position errors of 1.06–2.69
  // and largest velocity errors of 24–62 times the tolerance. There the
  // bounds are 4 and 80; from 1e-4 on, over all six marches, the same
  // perturbations moved no ratio past 0.37 and 10.
  const double t_end = std::string(problem) == "kepler_e09" ? kTenOrbits : 10;
  const std::vector<double> tolerances = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
  const vivp::studies::ConvergenceStudy s = RunToleranceStudy(
      FindProblem(problem), {.op = op, .t_end = t_end}, tolerances, {}, 48);
  for (const auto& r : s.rows) {
    BOOST_TEST_REQUIRE(r.converged, r.tolerance << ": " << r.reason);
    BOOST_TEST_MESSAGE(problem << " " << op << " tol " << r.tolerance << ": "
                               << r.points << " nodes, end error "
                               << r.err_x_corrected << ", node errors x "
                               << r.max_error << ", v " << r.max_error_v);
    const bool global =
        std::string(problem) == "kepler_e09" && r.tolerance >= 1e-3;
    BOOST_TEST(r.err_x_corrected <= (global ? 4 : 2) * r.tolerance);
    BOOST_TEST(r.max_error_v <= (global ? 80 : 40) * r.tolerance);
  }
  BOOST_TEST_MESSAGE(problem << " " << op << ": velocity tracking slope "
                             << s.tracking_max_v.slope << ", ratio "
                             << s.tracking_max_v.min_ratio << " … "
                             << s.tracking_max_v.max_ratio);
  BOOST_TEST(s.tracking_max_v.slope >= 0.8);
  BOOST_TEST(s.tracking_max_v.slope <= 1.6);
  // Tighter tolerances take more nodes.
  for (std::size_t i = 1; i < s.rows.size(); ++i)
    BOOST_TEST(s.rows[i].points > s.rows[i - 1].points);
}

BOOST_DATA_TEST_CASE(windows_are_fitted_to_a_rising_frequency,
                     bdata::make({"kepler_e09", "anharmonic"}) *
                         bdata::make({"sbp63", "sbp84"}),
                     problem, op) {
  // A window is shortened before its solve where the fastest frequency at
  // its predicted far end rises more than 1.25-fold over the start's and
  // the last window's (march_adaptive.h). Approaching pericentre of Kepler
  // e = 0.9 (three orbits, 1e-5) SBP84's estimate rose 10–20-fold from one
  // window to the next at the same step, and 30 windows were rejected
  // against 105 accepted; on the anharmonic oscillator (t = 10, 1e-6) a
  // window after a zero crossing grew its step and was rejected, 20 against
  // 162. Fitted: 9 of 101 and 3 of 161 (SBP63: 17 of 233, 19 of 627), each
  // node's time in order, the last at T exactly, the end position within
  // ten times the tolerance.
  const bool kepler = std::string(problem) == "kepler_e09";
  const double tol = kepler ? 1e-5 : 1e-6, t_end = kepler ? 6 * M_PI : 10;
  MarchOptions o;
  o.tolerance = {tol, tol};
  const NamedProblem& named = FindProblem(problem);
  const MarchResult m = named.march({.op = op, .t_end = t_end}, o, {});
  BOOST_TEST_REQUIRE(m.status.converged, m.status.reason);
  const ExactState exact = named.exact(t_end);
  double ex = 0;
  for (std::size_t c = 0; c < exact.x.size(); ++c)
    ex = std::max(ex, std::abs(m.end_position[c] - exact.x[c]));
  BOOST_TEST_MESSAGE(problem << " " << op << ": " << m.rejected << " of "
                             << m.window_count
                             << " windows rejected, end error " << ex);
  BOOST_TEST(8 * m.rejected <= m.window_count,
             m.rejected << " of " << m.window_count);
  BOOST_TEST(ex <= 10 * tol);
  for (std::size_t i = 1; i < m.t.size(); ++i)
    BOOST_TEST_REQUIRE(m.t[i] > m.t[i - 1]);
  BOOST_TEST(m.t.back() == t_end);
}

// `vivp bench`'s default sweep of an adaptive method runs the tolerances
// 1e-3 … 1e-13 as those literals read, so that each of its rows is the march
// `--steps TOL` runs (below 1e-9 an end error moves with the tolerance's last
// bit).
BOOST_AUTO_TEST_CASE(bench_sweep_tolerances_are_the_decimal_literals) {
  std::vector<double> asked;
  BenchProblem p;
  p.measure = [&](const std::string&, double tol, int) {
    asked.push_back(tol);
    return WorkPoint{};
  };
  Sweep(p, "odeint_dopri5", 5, 1e9);
  const std::vector<double> expected = {1e-3, 1e-4,  1e-5,  1e-6,  1e-7, 1e-8,
                                        1e-9, 1e-10, 1e-11, 1e-12, 1e-13};
  BOOST_TEST(asked == expected, boost::test_tools::per_element());
}
