// Time-slab marching and its hard cases (docs/method.md §8).
#define BOOST_TEST_MODULE march
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "core/action/erased_problem.h"
#include "core/linalg/fit.h"
#include "problems/anharmonic.h"
#include "problems/damped_oscillator.h"
#include "problems/kepler.h"
#include "solvers/variational/solve.h"
#include "studies/registry.h"

using namespace vivp;
using namespace vivp::variational;
namespace bdata = boost::unit_test::data;

namespace {

// The solver templates for these problems are compiled once, in the
// registry (same problems, same initial data: damped x = 1, v = 0;
// anharmonic x = 1, v = 0.3; Kepler e = 0.6 from pericentre).
MarchResult March(const char* name, const Grid& g, const MarchOptions& o,
                  const NodeObserver& observer = {}) {
  return vivp::studies::FindProblem(name).march(g, o, observer);
}

double EndError(const MarchResult& r, double exact) {
  return std::abs(r.end_position[0] - exact);
}

}  // namespace

BOOST_DATA_TEST_CASE(DampedSbp42_MarchedWindowsMatchTheGlobalCorrectedEnd,
                     bdata::make({16, 32, 64, 128}), window) {
  // Proves: handing off the multiplier-corrected state loses nothing against
  // one global solve (T = 204.8, Δt = 0.0125; global corrected end 4.65e-7).
  problems::DampedOscillator p;
  const Grid g{.op = "sbp42", .points = 16385, .t_end = 204.8};
  const double exact = p.Exact(204.8).x;
  const auto global = vivp::studies::FindProblem("damped").solve(g, {});
  const double global_error = std::abs(global.corrected.position[0] - exact);
  MarchOptions o;
  o.window_points = window;
  const MarchResult r = March("damped", g, o);
  BOOST_TEST(r.status.converged, r.status.reason);
  BOOST_TEST(r.fallbacks == 0);
  BOOST_TEST(EndError(r, exact) <= 2 * global_error,
             "marched " << EndError(r, exact) << " global " << global_error);
  BOOST_TEST(r.t.size() == 16385u);  // every node once
}

BOOST_DATA_TEST_CASE(DampedMarch_KeepsTheGlobalOrder,
                     bdata::make({"sbp21", "sbp42"}), op) {
  // Proves: the march converges at the operator's order of the corrected
  // state (4 for SBP42, 2 for SBP21), not at the hand-off's.
  problems::DampedOscillator p;
  std::vector<double> dt, err;
  // Three step sizes around Δt = 0.0125. SBP21's phase error over 33 periods
  // is not yet asymptotic at Δt = 0.05 (slope 2.10 on 0.05…0.0125), so its
  // range starts one halving later; SBP42 on 0.025…0.00625 gives 4.46
  // (the error falls faster than h⁴ there).
  const bool sbp21 = std::string(op) == "sbp21";
  const std::vector<long long> grids =
      sbp21 ? std::vector<long long>{8193, 16385, 32769}
            : std::vector<long long>{4097, 8193, 16385};
  for (long long n : grids) {
    const Grid g{.op = op, .points = n, .t_end = 204.8};
    MarchOptions o;
    o.window_points = 32;
    const MarchResult r = March("damped", g, o);
    BOOST_TEST(r.status.converged);
    dt.push_back(204.8 / double(n - 1));
    err.push_back(EndError(r, p.Exact(204.8).x));
  }
  const double order = vivp::linalg::FitPowerLaw(dt, err).order;
  BOOST_TEST_MESSAGE(op << " marched order " << order);
  const double expected = std::string(op) == "sbp42" ? 4.0 : 2.0;
  const double tolerance = std::string(op) == "sbp42" ? 0.2 : 0.1;
  BOOST_TEST(std::abs(order - expected) <= tolerance, op << " order " << order);
}

BOOST_AUTO_TEST_CASE(AnharmonicSbp42_MarchesToTenWithoutFallback) {
  // Proves: where one global Newton solve from the linear guess diverges
  // (docs/method.md §8), windows of <= 32 points converge unaided, at
  // order 4.
  problems::Anharmonic a;
  std::vector<double> dt, err;
  for (long long n : {1025, 2049, 4097}) {
    const Grid g{.op = "sbp42", .points = n, .t_end = 10.0};
    MarchOptions o;
    o.window_points = 32;
    const MarchResult r = March("anharmonic", g, o);
    BOOST_TEST(r.status.converged, r.status.reason);
    BOOST_TEST(r.fallbacks == 0);
    dt.push_back(10.0 / double(n - 1));
    err.push_back(EndError(r, a.Exact(10.0).x));
  }
  BOOST_TEST(err.back() <= 1e-7, "error at dt ≈ 0.0024: " << err.back());
  const double order = vivp::linalg::FitPowerLaw(dt, err).order;
  BOOST_TEST(std::abs(order - 4.0) <= 0.2, "order " << order);
}

BOOST_AUTO_TEST_CASE(NaiveHandOff_DivergesOnTheDampedOscillator) {
  // Proves why the corrected hand-off is the default: handing over
  // (x_N, (Dx)_N) puts the O(Δt²) end-derivative error into every window's
  // initial velocity, and the march leaves the solution.
  problems::DampedOscillator p;
  for (long long n : {2049, 4097}) {
    const Grid g{.op = "sbp42", .points = n, .t_end = 204.8};
    MarchOptions naive, corrected;
    naive.window_points = corrected.window_points = 32;
    naive.hand_off = HandOff::kNaive;
    auto max_error = [&](const MarchResult& r) {
      double m = 0;
      for (std::size_t i = 0; i < r.t.size(); ++i)
        m = std::max(m, std::abs(r.x(i, 0) - p.Exact(r.t[i]).x));
      return m;
    };
    const double e_naive = max_error(March("damped", g, naive));
    const double e_good = max_error(March("damped", g, corrected));
    BOOST_TEST(e_naive > 0.1, "Nt " << n << " naive max error " << e_naive);
    BOOST_TEST(e_naive > 50 * e_good);
  }
}

BOOST_AUTO_TEST_CASE(Observer_SeesEveryNodeOnceInOrder) {
  const Grid g{.op = "sbp42", .points = 1001, .t_end = 10.0};
  MarchOptions o;
  o.window_points = 40;
  o.keep_trajectory = false;
  std::vector<double> seen;
  const MarchResult r =
      March("damped", g, o,
            [&](double t, const double*, const double*) { seen.push_back(t); });
  BOOST_TEST(r.status.converged);
  BOOST_TEST(r.t.empty());  // nothing stored when streaming
  BOOST_TEST(seen.size() == 1001u);
  for (std::size_t i = 1; i < seen.size(); ++i)
    BOOST_TEST(seen[i] > seen[i - 1]);
  BOOST_TEST(std::abs(seen.back() - 10.0) <= 1e-12);
}

BOOST_AUTO_TEST_CASE(ImpossibleWindow_IsReportedWithReason) {
  // One Newton iteration without refinement cannot solve the anharmonic
  // window; with no splitting allowed the march must say so, not return a
  // silent answer.
  const Grid g{.op = "sbp42", .points = 257, .t_end = 10.0};
  MarchOptions o;
  o.window_points = 64;
  o.max_split_depth = 0;
  o.solve.newton.max_iterations = 1;
  o.solve.newton.refinement_steps = 0;
  const MarchResult r = March("anharmonic", g, o);
  BOOST_TEST(!r.status.converged);
  BOOST_TEST(r.status.reason.find("did not converge") != std::string::npos);
  BOOST_TEST(r.status.reason.find("no convergence in 1 iterations") !=
             std::string::npos);
  // ... and with the residual it left.
  BOOST_TEST_MESSAGE("reason: " << r.status.reason);
  BOOST_TEST(std::isfinite(r.last_residual));
  BOOST_TEST(r.last_residual > 1e-8);  // far from a solution after 1 step
  BOOST_TEST(r.status.reason.find("last residual") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(WindowBelowOperatorMinimum_IsRejected) {
  MarchOptions o;
  o.window_points = 5;
  BOOST_CHECK_EXCEPTION(
      March("damped", {.op = "sbp42", .points = 100}, o), std::invalid_argument,
      [](const auto& e) {
        return std::string(e.what()).find("below the minimum of sbp42 (8)") !=
               std::string::npos;
      });
}

// Declares a constant mass it does not have (∂²L/∂ẋ² = 1 + x²): the march
// must stop with an error that names the declaration, whichever check sees
// it first, not use M⁻¹ ∂L/∂x in its predictor and go on.
struct MisdeclaredMass {
  static constexpr int kDim = 1;
  static constexpr bool kConstantMass = true;
  template <class T>
  T operator()(const T* x, const T* v) const {
    return T(0.5) * (T(1) + x[0] * x[0]) * v[0] * v[0] - T(0.5) * x[0] * x[0];
  }
};

BOOST_DATA_TEST_CASE(WrongConstantMassDeclaration_FailsByName,
                     bdata::make({0.0, 0.3}), v0) {
  const auto problem = vivp::action::Erase(MisdeclaredMass{});
  std::string message;
  try {
    const MarchResult r =
        Solve(problem, {.x = {1.0}, .v = {v0}},
              {.op = "sbp42", .points = 200, .t_end = 4.0}, MarchOptions{});
    message = r.status.converged ? "converged" : r.status.reason;
  } catch (const std::invalid_argument& e) {
    message = e.what();
  }
  BOOST_TEST_MESSAGE("v0 = " << v0 << ": " << message);
  BOOST_TEST(message.find("kConstantMass") != std::string::npos, message);
}

// A path that does not check the declaration (Ceres' LM) takes no shortcut:
// the misdeclared Lagrangian marches as its undeclared twin, to the bit.
struct UndeclaredMass {
  static constexpr int kDim = 1;
  template <class T>
  T operator()(const T* x, const T* v) const {
    return MisdeclaredMass{}(x, v);
  }
};

BOOST_AUTO_TEST_CASE(UncheckedPath_IgnoresTheConstantMassDeclaration) {
  MarchOptions o;
  o.solve.path = Path::kCeresLm;
  const Grid g{.op = "sbp42", .points = 120, .t_end = 2.0};
  const InitialData s{.x = {1.0}, .v = {0.0}};
  const MarchResult declared = Solve(action::Erase(MisdeclaredMass{}), s, g, o);
  const MarchResult twin = Solve(action::Erase(UndeclaredMass{}), s, g, o);
  BOOST_TEST(declared.status.converged, declared.status.reason);
  BOOST_TEST(declared.end_position[0] == twin.end_position[0]);
  BOOST_TEST(declared.end_velocity[0] == twin.end_velocity[0]);
}

BOOST_AUTO_TEST_CASE(LongHorizon_DampedTo10000AndKepler100Periods) {
  // Proves: marching stays bounded and on the invariants over long runs.
  // Damped oscillator to T = 10⁴ (≈2250 periods) at Δt = 0.1: the energy
  // follows the exact decay.
  problems::DampedOscillator p;
  MarchOptions o;
  o.window_points = 32;
  const auto r =
      March("damped", {.op = "sbp42", .points = 100001, .t_end = 1e4}, o);
  BOOST_TEST(r.status.converged, r.status.reason);
  double max_energy_error = 0;
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    const auto e = p.Exact(r.t[i]);
    max_energy_error =
        std::max(max_energy_error,
                 std::abs(p.Energy(r.x(i, 0), r.v(i, 0)) - p.Energy(e.x, e.v)));
  }
  BOOST_TEST_MESSAGE("damped T = 1e4: max energy error " << max_energy_error);
  BOOST_TEST(max_energy_error <= 1e-3);  // measured 6.6e-4 (E from 0.5 to 0.0)

  // Kepler e = 0.6 over 100 periods at Δt = π/100: energy and angular
  // momentum errors stay bounded (node velocities are Dx: order 2 there).
  problems::Kepler k;
  const auto y0 = k.Initial();
  const double T = 200 * M_PI;
  const auto m =
      March("kepler", {.op = "sbp42", .points = 10001 * 2 - 1, .t_end = T}, o);
  BOOST_TEST(m.status.converged, m.status.reason);
  const double l0 = k.Invariants(y0.data(), y0.data() + 2)[0];
  double max_h = 0, max_l = 0, max_h_first = 0;
  for (std::size_t i = 0; i < m.t.size(); ++i) {
    const double q[2] = {m.x(i, 0), m.x(i, 1)}, v[2] = {m.v(i, 0), m.v(i, 1)};
    const double dh = std::abs(k.Hamiltonian(q, v) + 0.5);
    max_h = std::max(max_h, dh);
    if (m.t[i] <= 2 * M_PI) max_h_first = std::max(max_h_first, dh);
    max_l = std::max(max_l, std::abs(k.Invariants(q, v)[0] - l0));
  }
  BOOST_TEST_MESSAGE("Kepler 100 periods: max |ΔH| "
                     << max_h << " (first period " << max_h_first
                     << "), max |Δℓ| " << max_l);
  // Bounded: the worst energy error over 100 periods is within a small
  // factor of the first period's (no secular drift).
  BOOST_TEST(max_h <= 3 * max_h_first);
  BOOST_TEST(max_l <= 1e-2);
}

BOOST_AUTO_TEST_CASE(ExtremeGrid_DampedMarchedOver2To20Points) {
  // Proves: marching handles Nt = 2²⁰ streamed (the peak RSS, 4.3 MB
  // streamed against 208 MB for the global solve, is measured by
  // bench/march_bench). Δt = 0.0125, T = 13107.2 (≈ 2950 periods): the
  // handed-off corrected end state stays on the exact decay.
  MarchOptions o;
  o.window_points = 48;
  o.keep_trajectory = false;
  const double dt = 0.0125;
  const long long n = (1LL << 20) + 1;
  long long seen = 0;
  const auto r =
      March("damped", {.op = "sbp42", .points = n, .t_end = dt * double(n - 1)},
            o, [&](double, const double*, const double*) { ++seen; });
  BOOST_TEST_REQUIRE(r.status.converged, r.status.reason);
  BOOST_TEST(seen == n);
  BOOST_TEST(r.fallbacks == 0);
  BOOST_TEST(r.t.empty());  // streamed: nothing kept
  const auto exact =
      vivp::studies::FindProblem("damped").exact(dt * double(n - 1));
  const double error = std::abs(r.end_position[0] - exact.x[0]);
  BOOST_TEST_MESSAGE("damped, Nt = 2^20 + 1 marched: corrected end error "
                     << error);
  BOOST_TEST(error <= 1e-8);  // measured 4.3e-9
}

BOOST_AUTO_TEST_CASE(FitOrders_LeaveOutRowsThatDidNotConverge) {
  // Proves: a grid size whose solve did not converge (its "error" is that of
  // an unconverged iterate, here 10) does not enter the fitted order; the
  // converged rows follow C·h⁴ and give 4. With one converged row there is
  // no order (NaN, reported as n/a by `vivp converge`).
  vivp::studies::ConvergenceStudy study;
  for (long long n : {32, 64, 128, 256}) {
    vivp::studies::ConvergenceRow r;
    r.points = n;
    r.dt = r.dt_true = 1.0 / double(n);
    r.err_x = r.err_v = r.err_x_corrected = r.err_p_corrected =
        std::pow(r.dt, 4);
    r.converged = n != 32;
    if (!r.converged) r.err_x = r.err_v = r.err_x_corrected = 10;
    study.rows.push_back(r);
  }
  FitOrders(study, 1e-300);
  BOOST_TEST(study.orders.x == 4.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(study.orders.x_corrected == 4.0,
             boost::test_tools::tolerance(1e-12));
  study.rows.resize(2);  // 32 (not converged) and 64
  FitOrders(study, 1e-300);
  BOOST_TEST(std::isnan(study.orders.x));
}

BOOST_DATA_TEST_CASE(GivenWindows_MarchTheWindowsOfErrorControlAgain,
                     bdata::make({"sbp84", "lgl8"}), op) {
  // Proves: the windows a march under error control accepted, marched
  // again without it (MarchOptions::given_windows), give the same nodes and
  // the same end state to Newton's stopping level — what lets the bench
  // price the machinery apart from the solves — and a uniform grid's own
  // windows give its march bit for bit.
  const Grid g{.op = op, .t_end = 6.0};
  MarchOptions o;
  o.tolerance = {1e-7, 1e-7};
  const MarchResult a = March("kepler_e09", g, o);
  BOOST_TEST_REQUIRE(a.status.converged, a.status.reason);
  MarchOptions w;
  w.given_windows = AcceptedWindows(a, g);
  const MarchResult r = March("kepler_e09", g, w);
  BOOST_TEST_REQUIRE(r.status.converged, r.status.reason);
  BOOST_TEST(r.window_count == a.window_count);
  BOOST_TEST_REQUIRE(r.t.size() == a.t.size());
  double dt = 0, dx = 0;
  for (std::size_t i = 0; i < r.t.size(); ++i)
    dt = std::max(dt, std::abs(r.t[i] - a.t[i]));
  for (int c = 0; c < 2; ++c)
    dx = std::max({dx, std::abs(r.end_position[c] - a.end_position[c]),
                   std::abs(r.end_velocity[c] - a.end_velocity[c])});
  BOOST_TEST_MESSAGE(op << ": node times " << dt << " apart, end state " << dx);
  BOOST_TEST(dt <= 1e-13);
  // Newton's solution to its stopping level from two starts (measured
  // 5.7e-13 for SBP84, 1.4e-14 for lgl8), against a tolerance of 1e-7.
  BOOST_TEST(dx <= 1e-10);
  // A uniform grid's windows, given.
  MarchOptions uo;
  uo.window_points = a.windows.front().points;
  const Grid u{
      .op = op, .points = 1 + 40 * (uo.window_points - 1), .t_end = 6.0};
  const MarchResult m = March("kepler_e09", u, uo);
  BOOST_TEST_REQUIRE(m.status.converged, m.status.reason);
  MarchOptions b = uo;
  b.given_windows = AcceptedWindows(m, u);
  const MarchResult s = March("kepler_e09", u, b);
  BOOST_TEST_REQUIRE(s.status.converged, s.status.reason);
  for (int c = 0; c < 2; ++c) {
    BOOST_TEST(s.end_position[c] == m.end_position[c]);
    BOOST_TEST(s.end_velocity[c] == m.end_velocity[c]);
  }
}

BOOST_AUTO_TEST_CASE(GivenWindows_BadWindowsAreRejected) {
  const auto rejects = [&](const char* op, std::vector<GivenWindow> windows,
                           bool tolerance, const char* says,
                           long long start_node = 0) {
    MarchOptions o;
    o.given_windows = std::move(windows);
    o.start_node = start_node;
    if (tolerance) o.tolerance = {1e-6, 1e-6};
    BOOST_CHECK_EXCEPTION(
        March("damped", {.op = op, .t_end = 1.0}, o), std::invalid_argument,
        [&](const std::invalid_argument& e) {
          BOOST_TEST_MESSAGE(e.what());
          return std::string(e.what()).find(says) != std::string::npos;
        });
  };
  rejects("sbp42", {{0.5, 20}, {0.4, 20}, {1.0, 20}}, false,
          "is not after the window before's end, 0.5");
  rejects("sbp42", {{0.5, 20}, {0.9, 20}}, false, "which is not t_end = 1");
  rejects("sbp42", {{1.0, 20}, {1.0, 20}}, false, "is not before t_end = 1");
  rejects("sbp42", {{0.0, 20}, {1.0, 20}}, false, "is not after t_start = 0");
  rejects("sbp42", {{NAN, 20}, {1.0, 20}}, false, "is not finite");
  rejects("sbp42", {{0.5, 3}, {1.0, 20}}, false, "points, below 8");
  rejects("lgl8", {{0.5, 8}, {1.0, 9}}, false, "not 8, the element's size");
  rejects("sbp42", {{1.0, 20}}, true, "chooses its own");
  rejects("sbp42", {{0.5, 20}, {1.0, 20}}, false, "start_node 5", 5);
}
