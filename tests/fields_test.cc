// Fields in 1+1 dimensions, first pieces: the periodic central differences
// (core/sbp/periodic.h) — fitted orders, exact skew-symmetry, automatic
// differentiation through the stencil, argument checks — the Lagrangian
// densities of problems/fields (their derivatives against the field
// equations they stand for) and the exact solutions (they solve those
// equations; the kink's topological charge).
#define BOOST_TEST_MODULE fields
#include <ceres/jet.h>

#include <algorithm>
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/autodiff/pointwise.h"
#include "core/sbp/periodic.h"
#include "problems/fields/densities.h"
#include "problems/fields/exact.h"

namespace bdata = boost::unit_test::data;
using vivp::sbp::PeriodicOperator;

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// max_j |(Du)_j − u'(x_j)| for u = exp(sin x) on [0, 2π).
double MaxError(int order, int n) {
  const PeriodicOperator<double> d(order, n, kTwoPi);
  std::vector<double> u(n), du(n);
  for (int j = 0; j < n; ++j) u[j] = std::exp(std::sin(j * d.dx()));
  d.Apply<double>(u, du);
  double e = 0;
  for (int j = 0; j < n; ++j) {
    const double x = j * d.dx();
    e = std::max(e, std::abs(du[j] - std::cos(x) * std::exp(std::sin(x))));
  }
  return e;
}

// Least-squares slope of log(error) against log(Δx).
double FittedOrder(int order, const std::vector<int>& ns) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int n : ns) {
    const double x = std::log(kTwoPi / n), y = std::log(MaxError(order, n));
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double m = double(ns.size());
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

}  // namespace

BOOST_DATA_TEST_CASE(periodic_difference_order, bdata::make({2, 4, 6, 8}),
                     order) {
  // Grids in the asymptotic range (exp(sin x) has a broad spectrum: on
  // 24–64 points order 8 fits 7.64) and far above round-off (order 8 at
  // n = 128: about 1e-9).
  const double p = FittedOrder(order, {48, 64, 96, 128});
  for (int n : {48, 128})
    BOOST_TEST_MESSAGE("  n = " << n << ": max error " << MaxError(order, n));
  BOOST_TEST_MESSAGE("order " << order << ": fitted " << p);
  BOOST_TEST(p >= order - 0.3);
  BOOST_TEST(p <= order + 1.5);  // not accidentally superconvergent
}

BOOST_DATA_TEST_CASE(periodic_difference_is_skew, bdata::make({2, 4, 6, 8}),
                     order) {
  // D column by column from unit vectors: D + Dᵀ = 0 exactly (the stencil's
  // coefficients enter antisymmetrically), so with H = Δx·I the SBP property
  // has no boundary term. Counted, not summed.
  const int n = order + 3;
  const PeriodicOperator<double> d(order, n, 3.0);
  std::vector<std::vector<double>> m(n, std::vector<double>(n));
  std::vector<double> e(n), col(n);
  for (int k = 0; k < n; ++k) {
    std::fill(e.begin(), e.end(), 0.0);
    e[k] = 1;
    d.Apply<double>(e, col);
    for (int i = 0; i < n; ++i) m[i][k] = col[i];
  }
  int violations = 0, nonzero = 0;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) {
      violations += m[i][k] + m[k][i] != 0.0;
      nonzero += m[i][k] != 0.0;
    }
  BOOST_TEST(violations == 0);
  BOOST_TEST(nonzero == n * order);  // q entries each side of every row
}

BOOST_DATA_TEST_CASE(periodic_apply_matches_pointwise, bdata::make({2, 8}),
                     order) {
  // Apply reads the interior without wrapping indices; it must agree with
  // the wrapped single-point form to the last bit.
  const PeriodicOperator<double> d(order, 40, 5.0);
  std::vector<double> u(40), du(40);
  for (int j = 0; j < 40; ++j) u[j] = std::sin(0.7 * j) + 0.1 * j * j;
  d.Apply<double>(u, du);
  int differ = 0;
  for (int j = 0; j < 40; ++j) differ += du[j] != d.ApplyAt(u.data(), j);
  BOOST_TEST(differ == 0);
}

BOOST_AUTO_TEST_CASE(periodic_difference_differentiates_through_jets) {
  using Jet = ceres::Jet<double, 2>;
  const PeriodicOperator<double> d(8, 16, 2.0);
  std::vector<Jet> u(16);
  for (int j = 0; j < 16; ++j) u[j] = Jet(std::cos(j * 0.3));
  u[5].v[0] = 1;  // ∂/∂u_5
  u[1].v[1] = 1;  // ∂/∂u_1, across the periodic seam for row 14
  const Jet r3 = d.ApplyAt(u.data(), 3);
  const Jet r14 = d.ApplyAt(u.data(), 14);
  BOOST_TEST(r3.v[0] == d.coefficient(2) * d.inv_dx());
  BOOST_TEST(r14.v[1] == d.coefficient(3) * d.inv_dx());
}

BOOST_AUTO_TEST_CASE(periodic_difference_rejects_bad_arguments) {
  BOOST_CHECK_THROW(PeriodicOperator<double>(5, 32, 1.0),
                    std::invalid_argument);
  BOOST_CHECK_THROW(PeriodicOperator<double>(8, 8, 1.0), std::invalid_argument);
  BOOST_CHECK_NO_THROW(PeriodicOperator<double>(8, 9, 1.0));
  BOOST_CHECK_THROW(PeriodicOperator<double>(2, 16, 0.0),
                    std::invalid_argument);
  BOOST_CHECK_THROW(
      PeriodicOperator<double>(2, 16, std::numeric_limits<double>::infinity()),
      std::invalid_argument);
  BOOST_CHECK_THROW(
      PeriodicOperator<double>(2, 16, std::numeric_limits<double>::quiet_NaN()),
      std::invalid_argument);
  try {
    PeriodicOperator<double>(8, 5, 1.0);
  } catch (const std::invalid_argument& e) {
    BOOST_TEST(std::string(e.what()).find("at least 9 points") !=
               std::string::npos);
  }
}

namespace {

// ∂L/∂(φ, φ_t, φ_x) of a one-component density at a point, by AD.
template <class L>
Eigen::Vector3d Derivatives(const L& l, double phi, double phi_t,
                            double phi_x) {
  const double z[3] = {phi, phi_t, phi_x};
  return vivp::autodiff::Gradient<double, 3>(
             [&](const auto* s) { return l(s, s + 1, s + 2); }, z)
      .second;
}

void CheckOne(const Eigen::Vector3d& g, double phi_t, double phi_x, double c,
              double v_prime) {
  const double tol = 8 * std::numeric_limits<double>::epsilon();
  BOOST_TEST(std::abs(g[1] - phi_t) <= tol * std::abs(phi_t));
  BOOST_TEST(std::abs(g[2] + c * c * phi_x) <= tol * std::abs(c * c * phi_x));
  BOOST_TEST(std::abs(g[0] + v_prime) <= tol * (1 + std::abs(v_prime)));
}

}  // namespace

BOOST_AUTO_TEST_CASE(densities_give_their_field_equations) {
  // ∂L/∂φ_t = φ_t, ∂L/∂φ_x = −c²φ_x, ∂L/∂φ = −V′(φ): the Euler–Lagrange
  // equation φ_tt = c²φ_xx − V′(φ) of each density.
  const double phi = 0.7, pt = -0.3, px = 1.9;
  CheckOne(Derivatives(vivp::fields::Wave{.c = 2.0}, phi, pt, px), pt, px, 2.0,
           0.0);
  CheckOne(Derivatives(vivp::fields::KleinGordon{.mass = 1.5, .c = 0.5}, phi,
                       pt, px),
           pt, px, 0.5, 1.5 * 1.5 * phi);
  CheckOne(Derivatives(vivp::fields::SineGordon{}, phi, pt, px), pt, px, 1.0,
           std::sin(phi));
  CheckOne(
      Derivatives(vivp::fields::Phi4{.lambda = 2.0, .v = 1.2}, phi, pt, px), pt,
      px, 1.0, 2.0 * phi * (phi * phi - 1.44));

  // The complex field: V′ = (m² + λ|φ|²) φ_a per component.
  const vivp::fields::ComplexPhi4 c{.mass = 0.8, .lambda = 1.3};
  const double z[6] = {0.4, -0.9, 0.2, 0.5, -1.1, 0.3};  // φ, φ_t, φ_x
  const auto g = vivp::autodiff::Gradient<double, 6>(
                     [&](const auto* s) { return c(s, s + 2, s + 4); }, z)
                     .second;
  const double r2 = z[0] * z[0] + z[1] * z[1];
  for (int a = 0; a < 2; ++a) {
    const double tol = 8 * std::numeric_limits<double>::epsilon();
    BOOST_TEST(std::abs(g[2 + a] - z[2 + a]) <= tol);
    BOOST_TEST(std::abs(g[4 + a] + z[4 + a]) <= tol);
    const double vp = (0.8 * 0.8 + 1.3 * r2) * z[a];
    BOOST_TEST(std::abs(g[a] + vp) <= tol * (1 + std::abs(vp)));
  }
}

namespace {

// φ_tt − c²φ_xx + V′(φ) at (t, x), with φ_tt, φ_xx by AD of the exact
// formula and V′ = −∂L/∂φ by AD of the density; scale = the sum of the three
// terms' sizes there.
template <class Solution, class Density>
std::pair<double, double> FieldEquationResidual(const Solution& s,
                                                const Density& l, double c,
                                                double t, double x) {
  const double z[2] = {t, x};
  const auto h = vivp::autodiff::Hessian<double, 2>(
      [&](const auto* v) { return s(v[0], v[1]); }, z);
  const double phi = h.value, phi_t = h.gradient[0], phi_x = h.gradient[1];
  const auto g = Derivatives(l, phi, phi_t, phi_x);  // g[0] = −V′(φ)
  const double tt = h.hessian(0, 0), xx = h.hessian(1, 1);
  return {std::abs(tt - c * c * xx - g[0]),
          std::abs(tt) + c * c * std::abs(xx) + std::abs(g[0])};
}

// The largest residual over a grid of space-time points, relative to the
// largest term anywhere on it: far from a kink's core the terms are
// differences of O(1) numbers (φ² − v² as φ → ±v), so a pointwise ratio
// would measure that cancellation, not the formula.
template <class Solution, class Density>
double WorstResidual(const Solution& s, const Density& l, double c) {
  double worst = 0, scale = 0;
  for (double t : {0.0, 0.37, 1.3, 2.9})
    for (double x : {-7.3, -2.1, -0.4, 0.25, 1.7, 5.5}) {
      const auto [r, size] = FieldEquationResidual(s, l, c, t, x);
      worst = std::max(worst, r);
      scale = std::max(scale, size);
    }
  return worst / scale;
}

}  // namespace

BOOST_AUTO_TEST_CASE(exact_solutions_solve_their_field_equations) {
  // Relative to the equation's largest term, at 24 space-time points each:
  // round-off, not a truncation error.
  using namespace vivp::fields;
  const double tol = 1e-12;
  const KleinGordonPlaneWave kg{
      .density = {.mass = 1.0, .c = 1.0}, .amplitude = 0.3, .k = 1.0};
  BOOST_TEST(WorstResidual(kg, kg.density, 1.0) <= tol);
  BOOST_TEST(
      WorstResidual(SineGordonKink{.velocity = 0.5}, SineGordon{}, 1.0) <= tol);
  BOOST_TEST(WorstResidual(SineGordonBreather{.omega = 0.5}, SineGordon{},
                           1.0) <= tol);
  BOOST_TEST(WorstResidual(SineGordonKinkAntikink{.velocity = 0.5},
                           SineGordon{}, 1.0) <= tol);
  const Phi4Kink phi4{.density = {.lambda = 2.0, .v = 1.0}, .velocity = 0.3};
  BOOST_TEST(WorstResidual(phi4, phi4.density, 1.0) <= tol);
  const WaveGaussian wave{.density = {.c = 1.5}, .sigma = 0.8};
  BOOST_TEST(WorstResidual(wave, wave.density, 1.5) <= tol);
}

BOOST_AUTO_TEST_CASE(sine_gordon_kink_carries_unit_charge) {
  // Q = [φ(+∞) − φ(−∞)]/2π: 1 for the kink, 0 for the kink–antikink pair.
  const vivp::fields::SineGordonKink kink{.velocity = 0.5};
  const vivp::fields::SineGordonKinkAntikink pair{.velocity = 0.5};
  for (double t : {0.0, 3.0}) {
    BOOST_TEST(std::abs((kink(t, 60.0) - kink(t, -60.0)) / kTwoPi - 1) <=
               1e-12);
    BOOST_TEST(std::abs(pair(t, 60.0) - pair(t, -60.0)) <= 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(exact_solutions_refuse_parameters_without_a_solution) {
  // |v| ≥ 1, ω outside (0, 1), a pair at rest: an error, not NaN.
  using namespace vivp::fields;
  BOOST_CHECK_THROW(SineGordonKink{.velocity = 1.0}(0.0, 0.0),
                    std::invalid_argument);
  BOOST_CHECK_THROW(Phi4Kink{.velocity = -1.5}(0.0, 0.0),
                    std::invalid_argument);
  BOOST_CHECK_THROW(SineGordonBreather{.omega = 1.0}(0.0, 0.0),
                    std::invalid_argument);
  BOOST_CHECK_THROW(SineGordonBreather{.omega = 0.0}(0.0, 0.0),
                    std::invalid_argument);
  BOOST_CHECK_THROW(SineGordonKinkAntikink{.velocity = 0.0}(0.0, 0.0),
                    std::invalid_argument);
  BOOST_CHECK_THROW(
      SineGordonKink{.velocity = std::numeric_limits<double>::quiet_NaN()}(0.0,
                                                                           0.0),
      std::invalid_argument);
}
