// The spectral elements (core/sbp/lobatto.h): SBP, exact on polynomials of
// their degree, the order 2n − 2 of a march's end state, the measured
// stability limits and the refusals of everything an element cannot do.
// Their error control: element_error_control_test.
#define BOOST_TEST_MODULE sbp_lobatto
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/action/reduced_system.h"
#include "core/linalg/fit.h"
#include "core/sbp/builder.h"
#include "core/sbp/space.h"
#include "problems/anharmonic.h"
#include "solvers/variational/end_state.h"
#include "solvers/variational/march.h"
#include "solvers/variational/newton.h"

using namespace vivp;
namespace bdata = boost::unit_test::data;

namespace lobatto_test {

std::vector<std::string> Elements() {
  std::vector<std::string> out;
  for (const sbp::Coefficients* c : sbp::ElementOperators())
    out.emplace_back(c->name);
  return out;
}

// ẍ = −x.
struct Spring {
  static constexpr int kDim = 1;
  static constexpr bool kConstantMass = true;
  template <class T>
  T operator()(const T* x, const T* v) const {
    return T(0.5) * v[0] * v[0] - T(0.5) * x[0] * x[0];
  }
};

// Windows of one element marched by hand (the reduced system, Newton, the
// multiplier-corrected hand-off), without the march's resolution check:
// max|x| of the harmonic oscillator over at least 400 steps of Δt·ω = r.
double MaxAbsOfSpring(const std::string& op, double r) {
  const int n = sbp::Table(op).max_points;
  const Spring s;
  double x = 1, v = 0, largest = 0;
  for (int w = 0; w < (400 + n - 2) / (n - 1); ++w) {
    const sbp::RegularizedOperator<double> dbar(
        sbp::MakeOperator<double>(op, n, 0.0, r * (n - 1)), -1.0);
    const action::ReducedSystem<Spring, double> system(s, dbar, {x}, {v}, 2);
    std::vector<double> y(system.size(), 0.0);
    for (int i = 0; i < n; ++i) y[system.X(i, 0)] = x;
    if (!variational::Newton<double>(system, y).converged) return INFINITY;
    std::vector<double> xs(n);
    for (int i = 0; i < n; ++i) {
      xs[i] = y[system.X(i, 0)];
      largest = std::max(largest, std::abs(xs[i]));
    }
    const double xn = xs[n - 1], vn = dbar.base().ApplyRow(n - 1, xs.data());
    const double l3 = y[system.Lambda3(0)], l4 = y[system.Lambda4(0)];
    const auto e = variational::CorrectEnd<double>(s, 2, &xn, &vn, &l3, &l4);
    x = e.position[0];
    v = e.velocity[0];
  }
  return largest;
}

std::string Message(const auto& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no exception)";
}

}  // namespace lobatto_test

using lobatto_test::Elements;

BOOST_DATA_TEST_CASE(elements_are_sbp_operators_exact_to_their_degree,
                     bdata::make(Elements()), op) {
  const int n = sbp::Table(op).max_points;
  const double t0 = 0.3, t1 = 1.0;
  const auto D = sbp::MakeOperator<double>(op, n, t0, t1);
  const Eigen::MatrixXd d = D.DenseD();
  const Eigen::VectorXd h = D.NormDiagonal();
  // H D + Dᵀ H = B = diag(−1, 0, …, 0, 1), to rounding of entries of size
  // max|H D| (the coefficients are rounded once, to 2^−58, then to double).
  const Eigen::MatrixXd hd = h.asDiagonal() * d;
  Eigen::MatrixXd b = hd + hd.transpose();
  b(0, 0) += 1;
  b(n - 1, n - 1) -= 1;
  const double eps = std::numeric_limits<double>::epsilon();
  BOOST_TEST(b.cwiseAbs().maxCoeff() <= 8 * eps * hd.cwiseAbs().maxCoeff(),
             op << ": |HD + DᵀH − B| = " << b.cwiseAbs().maxCoeff());
  // Nodes: the ends, increasing, symmetric about the middle.
  BOOST_TEST(D.t(0) == t0);
  BOOST_TEST(std::abs(D.t(n - 1) - t1) <= 2 * eps);
  for (int i = 0; i + 1 < n; ++i) {
    BOOST_TEST(D.t(i + 1) > D.t(i));
    BOOST_TEST(std::abs(D.t(i) + D.t(n - 1 - i) - (t0 + t1)) <= 8 * eps);
  }
  // D differentiates t^k exactly for k ≤ n − 1 and H integrates t^k exactly
  // for k ≤ 2n − 3 (Lobatto quadrature), up to the rounding of sums of
  // terms of size Σ|D_ij| and Σ H_ii.
  const std::vector<double> t = D.Grid();
  const double row_sum = d.cwiseAbs().rowwise().sum().maxCoeff();
  for (int k = 0; k <= 2 * n - 3; ++k) {
    std::vector<double> u(n);
    for (int i = 0; i < n; ++i) u[i] = std::pow(t[i], k);
    if (k <= n - 1) {
      const std::vector<double> du = D.Apply(u);
      for (int i = 0; i < n; ++i)
        BOOST_TEST(std::abs(du[i] - k * std::pow(t[i], k - 1)) <=
                       64 * n * eps * row_sum,
                   op << " d/dt t^" << k << " at node " << i);
    }
    double q = 0;
    for (int i = 0; i < n; ++i) q += h[i] * u[i];
    const double exact = (std::pow(t1, k + 1) - std::pow(t0, k + 1)) / (k + 1);
    BOOST_TEST(std::abs(q - exact) <= 8 * n * eps, op << " ∫t^" << k);
  }
}

namespace lobatto_test {

// The end error of (x, ẋ) of the anharmonic oscillator (κ = 20) at t = 10,
// marched in `elements` uniform elements of `op`.
double AnharmonicEndError(const std::string& op, int elements) {
  const problems::Anharmonic p;
  const int n = sbp::Table(op).max_points;
  const variational::Grid g{
      .op = op, .points = elements * (n - 1) + 1, .t_end = 10.0};
  const auto m = variational::MarchIvp(p, {{p.x0}, {p.v0}}, g);
  BOOST_TEST_REQUIRE(m.status.converged, m.status.reason);
  // The trajectory's nodes at the first element's Gauss–Lobatto times.
  const auto D = sbp::MakeOperator<double>(op, n, 0.0, 10.0 / elements);
  for (int i = 0; i < n; ++i) BOOST_TEST(std::abs(m.t[i] - D.t(i)) <= 1e-15);
  const auto exact = p.Exact(10.0);
  return std::max(std::abs(m.end_position[0] - exact.x),
                  std::abs(m.end_velocity[0] - exact.v));
}

}  // namespace lobatto_test

BOOST_AUTO_TEST_CASE(end_state_converges_with_order_2n_minus_2) {
  // lgl8, 40 … 96 elements: the least-squares slope of log(error) against
  // log(element length), 2n − 2 = 14 in theory (measured 14.4; the errors
  // 7.5e-7 … 3.3e-12 oscillate about the line, since the end error sums
  // local errors of different phase over the orbit).
  std::vector<double> h, err;
  for (int e : {40, 48, 56, 64, 80, 96}) {
    h.push_back(10.0 / e);
    err.push_back(lobatto_test::AnharmonicEndError("lgl8", e));
  }
  const linalg::PowerLawFit fit = linalg::FitPowerLaw(h, err);
  BOOST_TEST(fit.points_used == 6);
  const double slope = fit.order;
  BOOST_TEST(std::abs(slope - 14.0) <= 1.0, "lgl8: order " << slope);
  // The larger elements reach round-off before their asymptotic range
  // (fitted slopes 17.5–19.5 for lgl12 and 25 for lgl16 against 22 and 30):
  // what they buy is accuracy per node. About 330 nodes each (measured:
  // 7.3e-8, 9.6e-11, 6.8e-14).
  const double e8 = lobatto_test::AnharmonicEndError("lgl8", 48);
  const double e12 = lobatto_test::AnharmonicEndError("lgl12", 30);
  const double e16 = lobatto_test::AnharmonicEndError("lgl16", 22);
  BOOST_TEST(e12 < e8 / 100, e12 << " against " << e8);
  BOOST_TEST(e16 < e12 / 100, e16 << " against " << e12);
}

BOOST_DATA_TEST_CASE(stability_limit_is_where_the_march_stops_being_bounded,
                     bdata::make(Elements()), op) {
  // The measured limit (lobatto.cc): bounded at it (max|x| < 1.5 over 400
  // steps), unbounded 0.1 above it; the march itself refuses windows beyond
  // it, as it does for every operator (resolution.h).
  const double limit = variational::StabilityLimit(op);
  const double at = lobatto_test::MaxAbsOfSpring(op, limit);
  const double above = lobatto_test::MaxAbsOfSpring(op, limit + 0.1);
  BOOST_TEST(at < 1.5, op << " at the limit: " << at);
  BOOST_TEST(above > 1.5, op << " above the limit: " << above);
  // A march refuses such windows: at the limit the a-posteriori check sees
  // nodes several percent off an independent integration, beyond it also
  // the resolution check; at half the limit it is accepted.
  const int n = sbp::Table(op).max_points;
  const auto march = [&](double r) {
    const variational::Grid g{
        .op = op, .points = 8 * (n - 1) + 1, .t_end = r * 8 * (n - 1)};
    return variational::MarchIvp(lobatto_test::Spring{}, {{1.0}, {0.0}}, g);
  };
  const auto half = march(limit / 2);
  BOOST_TEST(half.status.converged, half.status.reason);
  for (double r : {limit, limit + 0.1}) {
    const auto refused = march(r);
    BOOST_TEST(!refused.status.converged);
    BOOST_TEST(
        refused.status.reason.find("under-resolved") != std::string::npos,
        refused.status.reason);
  }
}

BOOST_AUTO_TEST_CASE(what_an_element_cannot_do_is_refused_by_name) {
  using lobatto_test::Message;
  BOOST_TEST(Message([] { sbp::MakeOperator<double>("lgl8", 9); }) ==
             "lgl8 is one spectral element of exactly 8 points, got 9; march "
             "in windows of 8 points");
  BOOST_TEST(Message([] {
               sbp::Operator<double>(sbp::Table("lgl8"), 16, 0.0, 1.0);
             }) ==
             "lgl8 is one spectral element of exactly 8 points, got 16; "
             "build operators with MakeOperator");
  BOOST_TEST(
      Message([] { sbp::SpaceDerivative<double>::Bounded("lgl8", 8, 0, 1); }) ==
      "lgl8 is a spectral element in time; a space axis takes sbp21, sbp42, "
      "sbp63, sbp84");
  BOOST_TEST(!sbp::IsElement("sbp84"));
  BOOST_TEST(sbp::IsElement("lgl12"));
  const problems::Anharmonic p;
  const auto march = [&](long long points, variational::MarchOptions o) {
    const variational::Grid g{.op = "lgl8", .points = points, .t_end = 1.0};
    return Message([&] { variational::MarchIvp(p, {{p.x0}, {p.v0}}, g, o); });
  };
  BOOST_TEST(march(52, {}) ==
             "lgl8 is a spectral element of 8 points: the steps must be a "
             "multiple of 7, got 51; use 49 or 56");
  BOOST_TEST(march(4, {}) ==
             "lgl8 is a spectral element of 8 points: the steps must be a "
             "multiple of 7, got 3; use 7");
  variational::MarchOptions window;
  window.window_points = 15;
  BOOST_TEST(march(50, window) ==
             "lgl8 is a spectral element of 8 points: it marches in windows "
             "of 8 points, got 15; leave the window at its default");
  // Under a tolerance the window is still the element, and the grid's
  // points do not matter.
  window.tolerance = {1e-8, 1e-8};
  BOOST_TEST(march(50, window) ==
             "lgl8 is a spectral element of 8 points: it marches in windows "
             "of 8 points, got 15; leave the window at its default");
  variational::MarchOptions tolerance;
  tolerance.tolerance = {1e-8, 1e-8};
  BOOST_TEST(march(50, tolerance) == "(no exception)");
}
