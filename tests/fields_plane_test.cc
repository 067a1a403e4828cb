// Fields in 2 + 1 (and 3 + 1) dimensions marched in windows
// (spacetime::SolveField on an sbp::SpaceGrid of two axes): the Klein–Gordon
// plane wave along (1, 2) against the semi-discrete wave (time orders) and the
// continuum wave (space orders per axis); the space-diagonalized solve in two
// dimensions against the sparse LU; a field constant along the second axis
// against the one-dimensional march; bad input refused.
#define BOOST_TEST_MODULE fields_plane
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "problems/fields/densities.h"
#include "problems/fields/exact.h"
#include "solvers/spacetime/power_spectrum.h"
#include "solvers/spacetime/solve.h"

namespace {

using vivp::sbp::SpaceDerivative;
using Grid = vivp::sbp::SpaceGrid<double>;
using vivp::spacetime::FieldGrid;
using vivp::spacetime::FieldSolution;
using vivp::spacetime::FieldSolveOptions;
using vivp::spacetime::SolveField;
using vivp::spacetime::WindowLinearSolver;
constexpr double kPi = std::numbers::pi;

// The plane wave cos(k·x − ωt) of the Klein–Gordon field (m = 1), k = (1, 2)
// on the periodic [0, 2π)², as initial data at t = 0.
struct PlaneWave {
  double kx = 1, ky = 2, omega = 0;
  double u(const Grid& g, double t, int j) const {
    return std::cos(kx * g.x(j, 0) + ky * g.x(j, 1) - omega * t);
  }
  double ut(const Grid& g, double t, int j) const {
    return omega * std::sin(kx * g.x(j, 0) + ky * g.x(j, 1) - omega * t);
  }
};

// σ(kh)/h of the periodic central differences of axis a: D e^{ikx} =
// iσ e^{ikx}/h.
double Symbol(const Grid& g, int a, double k) {
  const auto& p = *g.axis(a).periodic_operator();
  double sigma = 0;
  for (int l = 1; l <= p.half_width(); ++l)
    sigma += 2 * p.coefficient(l) * std::sin(l * k * p.dx());
  return sigma * p.inv_dx();
}

struct WaveErrors {
  double node, corrected;
  FieldSolution s;
};

// The plane wave marched to t_end in windows of `window` points; the errors
// of the last node and of the corrected end state against the wave whose
// frequency is `omega` (the semi-discrete or the continuum one).
WaveErrors MarchPlaneWave(const Grid& g, const char* op, long long nt,
                          double t_end, bool semi_discrete,
                          long long window = 9) {
  PlaneWave w;
  w.omega = semi_discrete ? std::sqrt(std::pow(Symbol(g, 0, w.kx), 2) +
                                      std::pow(Symbol(g, 1, w.ky), 2) + 1.0)
                          : std::sqrt(w.kx * w.kx + w.ky * w.ky + 1.0);
  std::vector<double> phi0(g.points()), pi0(g.points());
  for (int j = 0; j < g.points(); ++j) {
    phi0[j] = w.u(g, 0, j);
    pi0[j] = w.ut(g, 0, j);
  }
  FieldSolveOptions o;
  o.keep_field = false;
  const FieldGrid fg{
      .op = op, .points = nt, .t_end = t_end, .window_points = window};
  WaveErrors e{
      0, 0, SolveField(vivp::fields::KleinGordonIn<2>{}, g, fg, phi0, pi0, o)};
  BOOST_REQUIRE_MESSAGE(e.s.status.converged, e.s.status.reason);
  for (int j = 0; j < g.points(); ++j) {
    const double exact = w.u(g, t_end, j);
    e.node = std::max(e.node, std::abs(e.s.end_phi_node[j] - exact));
    e.corrected = std::max(e.corrected, std::abs(e.s.end.phi[j] - exact));
  }
  return e;
}

Grid Periodic2(int order_x, int nx, int order_y, int ny) {
  return Grid({SpaceDerivative<double>::Periodic(order_x, nx, 0.0, 2 * kPi),
               SpaceDerivative<double>::Periodic(order_y, ny, 0.0, 2 * kPi)});
}

double Slope(double e_coarse, double e_fine, double ratio) {
  return std::log(e_coarse / e_fine) / std::log(ratio);
}

}  // namespace

// The march in 2 + 1 D with the space-diagonalized window solve (windows of
// 9 points, 16² points, order-8 differences): against the semi-discrete
// plane wave the errors are the time discretization's, and their orders
// are those of one dimension — SBP21 2 at the last node and corrected,
// SBP42 3 at the last node and 4 corrected. The field is linear: every
// distinct spatial mode is factored once for the whole march.
BOOST_AUTO_TEST_CASE(plane_wave_marched_at_the_time_orders_of_one_dimension) {
  struct Expect {
    const char* op;
    double node_lo, node_hi, corrected_lo, corrected_hi;
  };
  const Grid g = Periodic2(8, 16, 8, 16);
  for (const Expect e : {Expect{"sbp21", 1.8, 2.3, 1.8, 2.3},
                         Expect{"sbp42", 2.7, 3.5, 3.6, 4.8}}) {
    std::vector<double> en, ec;
    for (long long nt : {33, 65, 129}) {
      const auto r = MarchPlaneWave(g, e.op, nt, 1.0, true);
      BOOST_TEST_MESSAGE(
          e.op << ", Nt = " << nt << ": last node " << r.node << ", corrected "
               << r.corrected << "; " << r.s.windows << " windows, "
               << r.s.mode_factorizations << " mode factorizations, fallbacks "
               << r.s.fallbacks);
      en.push_back(r.node);
      ec.push_back(r.corrected);
      // 9 distinct systems per axis (modes k and −k share one).
      BOOST_TEST(r.s.mode_factorizations == 81);
      BOOST_TEST(r.s.lu_factorizations == 0);
      BOOST_TEST(r.s.unchecked.empty());
    }
    const double pn = Slope(en[1], en[2], 2), pc = Slope(ec[1], ec[2], 2);
    BOOST_TEST_MESSAGE(e.op << ": order " << pn << " at the last node, " << pc
                            << " corrected");
    BOOST_TEST(pn >= e.node_lo);
    BOOST_TEST(pn <= e.node_hi);
    BOOST_TEST(pc >= e.corrected_lo);
    BOOST_TEST(pc <= e.corrected_hi);
  }
}

// Space order per axis: against the continuum plane wave, refining one axis
// (16 → 32 points, central differences of order 2q) while the other stays
// fine (64 points, order 8) and time is resolved (SBP63, Δt = 1/128), the
// error falls at order 2q of the refined axis.
BOOST_AUTO_TEST_CASE(space_order_two_q_on_each_axis) {
  for (int axis : {0, 1})
    for (int order : {2, 4, 6}) {
      double err[2];
      for (int r = 0; r < 2; ++r) {
        const int n = 16 << r;
        const Grid g =
            axis == 0 ? Periodic2(order, n, 8, 64) : Periodic2(8, 64, order, n);
        err[r] = MarchPlaneWave(g, "sbp63", 33, 0.25, false, 17).corrected;
      }
      const double p = Slope(err[0], err[1], 2);
      BOOST_TEST_MESSAGE("axis " << axis << ", order " << order << ": errors "
                                 << err[0] << ", " << err[1] << ", slope "
                                 << p);
      BOOST_TEST(p >= order - 0.3);
      BOOST_TEST(p <= order + 0.6);
    }
}

// The same in 3 + 1 D: the Klein–Gordon plane wave along (1, 2, 1) on the
// periodic [0, 2π)³ (8³ points, order-4 differences), SBP42 in windows of 9,
// against the semi-discrete wave: order 4 of the corrected end state, one
// factorization per distinct mode (5³) for the march.
BOOST_AUTO_TEST_CASE(plane_wave_in_three_dimensions) {
  const auto axis = SpaceDerivative<double>::Periodic(4, 8, 0.0, 2 * kPi);
  const Grid g({axis, axis, axis});
  const double k[3] = {1, 2, 1};
  double w2 = 1;
  for (int a = 0; a < 3; ++a) w2 += std::pow(Symbol(g, a, k[a]), 2);
  const double omega = std::sqrt(w2);
  auto wave = [&](double t, int j, bool velocity) {
    const double arg =
        k[0] * g.x(j, 0) + k[1] * g.x(j, 1) + k[2] * g.x(j, 2) - omega * t;
    return velocity ? omega * std::sin(arg) : std::cos(arg);
  };
  std::vector<double> phi0(g.points()), pi0(g.points());
  for (int j = 0; j < g.points(); ++j) {
    phi0[j] = wave(0, j, false);
    pi0[j] = wave(0, j, true);
  }
  std::vector<double> err;
  for (long long nt : {33, 65}) {
    const FieldGrid fg{
        .op = "sbp42", .points = nt, .t_end = 1.0, .window_points = 9};
    const auto s =
        SolveField(vivp::fields::KleinGordonIn<3>{}, g, fg, phi0, pi0);
    BOOST_REQUIRE_MESSAGE(s.status.converged, s.status.reason);
    double e = 0;
    for (int j = 0; j < g.points(); ++j)
      e = std::max(e, std::abs(s.end.phi[j] - wave(1.0, j, false)));
    BOOST_TEST_MESSAGE("3-D, Nt = " << nt << ": corrected error " << e << ", "
                                    << s.mode_factorizations
                                    << " mode factorizations");
    BOOST_TEST(s.mode_factorizations == 125);
    err.push_back(e);
  }
  const double p = Slope(err[0], err[1], 2);
  BOOST_TEST_MESSAGE("3-D: order " << p);
  BOOST_TEST(p >= 3.6);
  BOOST_TEST(p <= 4.8);
}

namespace {

// A bump of sine-Gordon on the periodic × interval grid, marched in two
// windows of 9 points with the given linear solver.
FieldSolution SineGordonBump(WindowLinearSolver linear) {
  const Grid g({SpaceDerivative<double>::Periodic(4, 10, -4.0, 4.0),
                SpaceDerivative<double>::Bounded("sbp42", 9, -3.0, 3.0)});
  std::vector<double> phi0(g.points()), pi0(g.points());
  for (int j = 0; j < g.points(); ++j) {
    const double x = g.x(j, 0), y = g.x(j, 1);
    phi0[j] = 2.0 * std::exp(-0.5 * (x * x + y * y));
    pi0[j] = 0.3 * std::sin(0.7 * x + 0.4 * y);
  }
  FieldSolveOptions o;
  o.linear = linear;
  const FieldGrid fg{
      .op = "sbp42", .points = 17, .t_end = 0.4, .window_points = 9};
  return SolveField(vivp::fields::SineGordonIn<2>{}, g, fg, phi0, pi0, o);
}

}  // namespace

// The space-diagonalized solve in two dimensions (real FFT along x, the
// SBP42 eigenbasis along y with its natural ends) preconditions the
// nonlinear sine-Gordon windows: the march agrees with the sparse LU's.
BOOST_AUTO_TEST_CASE(modes_agree_with_the_sparse_lu_in_two_dimensions) {
  const FieldSolution a = SineGordonBump(WindowLinearSolver::kModes);
  const FieldSolution b = SineGordonBump(WindowLinearSolver::kSparseLu);
  BOOST_REQUIRE_MESSAGE(a.status.converged, a.status.reason);
  BOOST_REQUIRE_MESSAGE(b.status.converged, b.status.reason);
  BOOST_REQUIRE(a.phi.size() == b.phi.size());
  double diff = 0, scale = 0;
  for (std::size_t k = 0; k < a.phi.size(); ++k) {
    diff = std::max(diff, std::abs(a.phi[k] - b.phi[k]));
    diff = std::max(diff, std::abs(a.phi_t[k] - b.phi_t[k]));
    scale = std::max(scale, std::abs(b.phi[k]));
  }
  BOOST_TEST_MESSAGE("modes against sparse LU: "
                     << diff / scale << " relative; fallbacks " << a.fallbacks);
  BOOST_TEST(diff / scale <= 1e-11);
  BOOST_TEST(a.fallbacks == 0);
  BOOST_TEST(a.lu_factorizations == 0);
}

// A field that does not vary along the second axis is the one-dimensional
// field: the sine-Gordon kink moving at v = 0.5 on an SBP42 interval with
// natural ends, marched on x alone and on x × (a periodic circle of 4
// points), agree to rounding.
BOOST_AUTO_TEST_CASE(a_field_constant_along_y_is_the_one_dimensional_field) {
  const auto x = SpaceDerivative<double>::Bounded("sbp42", 41, -10.0, 10.0);
  const Grid g({x, SpaceDerivative<double>::Periodic(2, 4, 0.0, 1.0)});
  const auto [p1, v1] = vivp::fields::InitialData(
      vivp::fields::SineGordonKink{.velocity = 0.5, .x0 = -2.0}, x);
  std::vector<double> p2(g.points()), v2(g.points());
  for (int j = 0; j < g.points(); ++j) {
    p2[j] = p1[g.Coordinate(j, 0)];
    v2[j] = v1[g.Coordinate(j, 0)];
  }
  const FieldGrid fg{
      .op = "sbp42", .points = 49, .t_end = 2.0, .window_points = 13};
  const auto a = SolveField(vivp::fields::SineGordon{}, x, fg, p1, v1);
  const auto b = SolveField(vivp::fields::SineGordonIn<2>{}, g, fg, p2, v2);
  BOOST_REQUIRE_MESSAGE(a.status.converged, a.status.reason);
  BOOST_REQUIRE_MESSAGE(b.status.converged, b.status.reason);
  double diff = 0;
  for (int j = 0; j < g.points(); ++j) {
    const int i = g.Coordinate(j, 0);
    diff = std::max(diff, std::abs(a.end.phi[i] - b.end.phi[j]));
    diff = std::max(diff, std::abs(a.end.phi_t[i] - b.end.phi_t[j]));
  }
  BOOST_TEST_MESSAGE("1-D against 2-D: " << diff);
  BOOST_TEST(diff <= 1e-12);
}

// Bad input: a grid whose axes do not match the density, end data in two
// dimensions, faces that do not exist or twice or with non-finite slopes,
// initial data of the wrong size or not finite.
BOOST_AUTO_TEST_CASE(bad_input_is_refused) {
  const Grid g = Periodic2(4, 8, 4, 8);
  std::vector<double> phi0(g.points(), 0.1), pi0(g.points(), 0.0);
  const FieldGrid fg{.op = "sbp42", .points = 9, .t_end = 0.5};
  BOOST_CHECK_THROW(SolveField(vivp::fields::SineGordon{}, g, fg, phi0, pi0),
                    std::invalid_argument);
  FieldSolveOptions o;
  o.boundary.left.kind = vivp::action::BoundaryKind::kDirichlet;
  BOOST_CHECK_THROW(
      SolveField(vivp::fields::SineGordonIn<2>{}, g, fg, phi0, pi0, o),
      std::invalid_argument);
  // Neumann faces: none on a periodic axis, no axis beyond the grid's, each
  // face once.
  for (const auto& faces :
       {std::vector<vivp::spacetime::FieldFace>{{0, 0, {}}},
        std::vector<vivp::spacetime::FieldFace>{{2, 1, {}}}}) {
    FieldSolveOptions f;
    f.boundary.faces = faces;
    BOOST_CHECK_THROW(
        SolveField(vivp::fields::SineGordonIn<2>{}, g, fg, phi0, pi0, f),
        std::invalid_argument);
  }
  {
    const Grid b({SpaceDerivative<double>::Bounded("sbp42", 9, 0.0, 1.0),
                  SpaceDerivative<double>::Periodic(4, 8, 0.0, 1.0)});
    std::vector<double> p(b.points(), 0.1), v(b.points(), 0.0);
    FieldSolveOptions f;
    f.boundary.faces = {{0, 1, {}}, {0, 1, {}}};
    BOOST_CHECK_THROW(
        SolveField(vivp::fields::SineGordonIn<2>{}, b, fg, p, v, f),
        std::invalid_argument);
    f.boundary.faces = {{0, 1, [](double, const double*, int) { return NAN; }}};
    BOOST_CHECK_THROW(
        SolveField(vivp::fields::SineGordonIn<2>{}, b, fg, p, v, f),
        std::invalid_argument);
    f.boundary.faces = {{0, 1, [](double, const double*, int) { return 0.0; }}};
    const FieldGrid short_run{.op = "sbp42", .points = 9, .t_end = 0.05};
    const auto ok =
        SolveField(vivp::fields::SineGordonIn<2>{}, b, short_run, p, v, f);
    BOOST_TEST(ok.status.converged, ok.status.reason);
  }
  std::vector<double> short_phi(g.points() - 1, 0.0);
  BOOST_CHECK_THROW(
      SolveField(vivp::fields::SineGordonIn<2>{}, g, fg, short_phi, pi0),
      std::invalid_argument);
  phi0[37] = NAN;
  try {
    SolveField(vivp::fields::SineGordonIn<2>{}, g, fg, phi0, pi0);
    BOOST_FAIL("a non-finite value was accepted");
  } catch (const std::invalid_argument& e) {
    BOOST_TEST_MESSAGE(e.what());
    BOOST_TEST(std::string(e.what()).find("(x, y) = (") != std::string::npos);
  }
}

// The power spectrum of a slice (power_spectrum.h): the plane wave
// cos(x + 2y) on the periodic [0, 2π)² (16² points) puts all its power in
// the bin of |k| = √5, and the bins sum to the slice's mean square
// (Parseval); a grid with an interval axis is refused.
BOOST_AUTO_TEST_CASE(power_spectrum_of_a_plane_wave) {
  const Grid g = Periodic2(4, 16, 4, 16);
  std::vector<double> phi(2 * g.points());
  double mean_square = 0;
  for (int j = 0; j < g.points(); ++j) {
    phi[2 * j] = std::cos(g.x(j, 0) + 2 * g.x(j, 1));
    phi[2 * j + 1] = 1.0;  // the other component: constant
    mean_square += phi[2 * j] * phi[2 * j] / g.points();
  }
  const auto bins = vivp::spacetime::PowerSpectrum(g, phi, 2, 0);
  double total = 0, at = 0;
  for (const auto& b : bins) {
    total += b.power;
    if (std::abs(b.k - std::sqrt(5.0)) <= 0.5) at += b.power;
  }
  BOOST_TEST_MESSAGE("power " << total << " (mean square " << mean_square
                              << "), in the bin of √5 " << at);
  BOOST_TEST(std::abs(total - mean_square) <= 1e-14);
  BOOST_TEST(std::abs(at - 0.5) <= 1e-14);
  const auto flat = vivp::spacetime::PowerSpectrum(g, phi, 2, 1);
  BOOST_TEST(std::abs(flat[0].power - 1.0) <= 1e-14);
  const Grid bounded({SpaceDerivative<double>::Bounded("sbp42", 9, 0.0, 1.0),
                      SpaceDerivative<double>::Periodic(4, 8, 0.0, 1.0)});
  std::vector<double> b(bounded.points(), 0.0);
  BOOST_CHECK_THROW(vivp::spacetime::PowerSpectrum(bounded, b),
                    std::invalid_argument);
  BOOST_CHECK_THROW(vivp::spacetime::PowerSpectrum(g, phi, 1),
                    std::invalid_argument);
}
