// The regularized operator D̄ (Rothkopf & Nordström 2023, Sec. 3.2, eq. 29
// corrected as in docs/method.md §3).
#define BOOST_TEST_MODULE sbp_regularized
#include <boost/test/unit_test.hpp>
#include <limits>

#include "core/sbp/builder.h"
#include "core/sbp/regularized.h"

using vivp::sbp::MakeOperator;
using vivp::sbp::RegularizedOperator;

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();
}

BOOST_AUTO_TEST_CASE(Sbp21TopLeftEntry_IsPlusOneOverDt) {
  // Eq. (29) with sigma0 = -1: -1/dt - 2 sigma0/dt = +1/dt (the printed
  // -sigma0/(2 dt) is a typo), and the shift column holds sigma0 (2/dt) x_i.
  const auto d = MakeOperator<double>("sbp21", 32);
  const RegularizedOperator<double> dbar(d, -1.0);
  const double x_i = 0.7;
  const Eigen::MatrixXd m = dbar.AffineMatrix(x_i);
  const double dt = d.dt();
  BOOST_TEST(std::abs(m(0, 0) - 1.0 / dt) <= 4 * kEps / dt);
  BOOST_TEST(std::abs(m(0, 1) - 1.0 / dt) <= 4 * kEps / dt);
  BOOST_TEST(std::abs(m(0, 32) - (-1.0) * 2.0 / dt * x_i) <= 4 * kEps / dt);
  BOOST_TEST(m(32, 32) == 1.0);
  BOOST_TEST(m.row(32).head(32).cwiseAbs().maxCoeff() == 0.0);
  // Every other row is plain D.
  BOOST_TEST((m.block(1, 0, 31, 32) - d.DenseD().bottomRows(31)).norm() == 0.0);
}

BOOST_AUTO_TEST_CASE(Apply_EqualsAffineMatrixTimesAffineVector) {
  for (const char* name : {"sbp21", "sbp42", "sbp63", "sbp84"}) {
    for (double sigma0 : {-1.0, -0.5, -2.0}) {
      const int n = 40;
      const auto d = MakeOperator<double>(name, n, 0.0, 2.0);
      const RegularizedOperator<double> dbar(d, sigma0);
      const double x_i = 1.3;
      std::vector<double> x(n);
      for (int i = 0; i < n; ++i) x[i] = std::exp(-0.4 * d.t(i)) + 0.01 * i;
      std::vector<double> out(n);
      dbar.Apply(std::span<const double>(x), x_i, std::span<double>(out));
      Eigen::VectorXd xbar(n + 1);
      for (int i = 0; i < n; ++i) xbar[i] = x[i];
      xbar[n] = 1.0;
      const Eigen::VectorXd ref = dbar.AffineMatrix(x_i) * xbar;
      const double scale = dbar.AffineMatrix(x_i).cwiseAbs().maxCoeff();
      for (int i = 0; i < n; ++i) {
        BOOST_TEST(std::abs(out[i] - ref[i]) <= 32 * kEps * scale,
                   name << " sigma0=" << sigma0 << " row " << i);
        BOOST_TEST(std::abs(dbar.ApplyRow(i, x.data(), x_i) - ref[i]) <=
                   32 * kEps * scale);
      }
      BOOST_TEST(ref[n] == 1.0);  // the affine entry stays one
    }
  }
}

BOOST_AUTO_TEST_CASE(ConstantCompatibleWithInitialValue_IsAnnihilated) {
  // D̄ still annihilates the constant path x = x_i (paper, after Fig. 4).
  for (const char* name : {"sbp21", "sbp42", "sbp63", "sbp84"}) {
    const auto d = MakeOperator<double>(name, 33);
    const RegularizedOperator<double> dbar(d);
    const std::vector<double> x(33, 0.25);
    std::vector<double> out(33);
    dbar.Apply(std::span<const double>(x), 0.25, std::span<double>(out));
    const double scale = d.DenseD().cwiseAbs().maxCoeff();
    for (double v : out) BOOST_TEST(std::abs(v) <= 64 * kEps * scale, name);
  }
}

BOOST_AUTO_TEST_CASE(NonFiniteSigma0_IsRejected) {
  const auto d = MakeOperator<double>("sbp21", 8);
  BOOST_CHECK_THROW(
      RegularizedOperator<double>(d, std::numeric_limits<double>::infinity()),
      std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(JetsThroughDbar_GiveDerivativeIncludingPenalty) {
  using Jet = ceres::Jet<double, 1>;
  const int n = 16;
  const auto d = MakeOperator<double>("sbp42", n);
  const RegularizedOperator<double> dbar(d);
  std::vector<Jet> x(n);
  for (int i = 0; i < n; ++i) x[i] = Jet(0.1 * i);
  x[0].v[0] = 1.0;  // d/dx_0
  const Jet row0 = dbar.ApplyRow(0, x.data(), Jet(0.0));
  const double expected = d.DenseD()(0, 0) + dbar.penalty();
  BOOST_TEST(std::abs(row0.v[0] - expected) <= 8 * kEps * std::abs(expected));
  BOOST_TEST(std::abs(dbar.penalty() - 1.0 / (17.0 / 48.0 * d.dt())) <=
             8 * kEps * dbar.penalty());
}
