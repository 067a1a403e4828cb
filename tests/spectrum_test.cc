// Spectrum analysis of D and D̄ (Rothkopf & Nordström 2023, Figs. 3-4;
// docs/method.md §2). Multiplicities are counts through ranks of nested
// null spaces, never thresholded eigenvalues.
#define BOOST_TEST_MODULE spectrum
#include "core/linalg/spectrum.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>
#include <limits>

#include "core/linalg/small_eigen.h"
#include "core/sbp/builder.h"
#include "core/sbp/regularized.h"

using vivp::linalg::AnalyzeSpectrum;
using vivp::linalg::Spectrum;
using vivp::sbp::MakeOperator;
using vivp::sbp::RegularizedOperator;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

Spectrum OfD(const char* name, int n) {
  return AnalyzeSpectrum(MakeOperator<double>(name, n).DenseD());
}

Spectrum OfDbar(const char* name, int n) {
  const RegularizedOperator<double> dbar(MakeOperator<double>(name, n), -1.0);
  return AnalyzeSpectrum(dbar.AffineMatrix(1.0));
}

}  // namespace

BOOST_AUTO_TEST_CASE(Sbp21At32_ZeroEigenvalueIsAJordanBlockOfSizeTwo) {
  const Spectrum s = OfD("sbp21", 32);
  BOOST_TEST(s.zero.algebraic_multiplicity == 2);
  BOOST_TEST(s.zero.geometric_multiplicity == 1);
  // Right null vector: the constant.
  const Eigen::VectorXd& r = s.right_null_vector;
  BOOST_TEST((r.array() - r.mean()).abs().maxCoeff() <= 64 * 32 * kEps);
  // Left null vector: the pi-mode (1, -2, 2, ..., 2, -1).
  Eigen::VectorXd pi_mode(32);
  for (int i = 0; i < 32; ++i) pi_mode[i] = (i % 2 ? -2.0 : 2.0);
  pi_mode[0] = 1.0;
  pi_mode[31] = -1.0;
  pi_mode.normalize();
  const Eigen::VectorXd& l = s.left_null_vector;
  const double sign = l.dot(pi_mode) > 0 ? 1.0 : -1.0;
  BOOST_TEST((sign * l - pi_mode).cwiseAbs().maxCoeff() <= 64 * 32 * kEps);
  // The eigensolver splits the double zero into a pair of size ~sqrt(eps)|D|
  // (measured: about 2e-6 against 1/dt = 31; docs/method.md §2).
  BOOST_TEST(std::abs(s.eigenvalues[0]) < 1e-4 * 31);
  BOOST_TEST(std::abs(s.eigenvalues[2]) > 1e-2);
}

BOOST_AUTO_TEST_CASE(Sbp21At32_DbarHasNoZeroModes_AndOneRealEigenvalueOne) {
  const Spectrum s = OfDbar("sbp21", 32);
  BOOST_TEST(s.zero.geometric_multiplicity == 0);
  BOOST_TEST(s.zero.algebraic_multiplicity == 0);
  BOOST_TEST(s.min_real_part > 0.0);
  BOOST_TEST(s.real_eigenvalues.size() == 1u);
  BOOST_TEST(std::abs(s.real_eigenvalues.at(0) - 1.0) <= 64 * kEps * 31);
  BOOST_TEST(std::abs(s.min_abs_eigenvalue - 1.0) <= 64 * kEps * 31);
}

BOOST_AUTO_TEST_CASE(Sbp42At32_DbarHasNoZeroModes_AndOneRealEigenvalueOne) {
  const Spectrum s = OfDbar("sbp42", 32);
  BOOST_TEST(s.zero.algebraic_multiplicity == 0);
  BOOST_TEST(s.min_real_part > 0.0);
  BOOST_TEST(s.real_eigenvalues.size() == 1u);
  BOOST_TEST(std::abs(s.real_eigenvalues.at(0) - 1.0) <= 64 * kEps * 31);
}

// Exact dimensions of ker(D^k), k = 1, 2, ..., until they stop growing, from
// rank computations over the rationals (the last entry is the algebraic
// multiplicity; the first the geometric one).
struct JordanCase {
  const char* name;
  int n;
  std::vector<int> kernel_dimensions;
};

std::ostream& operator<<(std::ostream& os, const JordanCase& c) {
  return os << c.name << " N=" << c.n;
}

const JordanCase kJordanCases[] = {
    // N = 64: the values of docs/method.md §2 (2, 4, 4, 6).
    {"sbp21", 64, {1, 2}},
    {"sbp42", 64, {1, 2, 3, 4}},
    {"sbp63", 64, {1, 2, 3, 4}},
    {"sbp84", 64, {1, 2, 3, 4, 5, 6}},
    {"sbp21", 16, {1, 2}},
    {"sbp42", 16, {1, 2, 3, 4}},
    {"sbp63", 16, {1, 2, 3, 4}},
    {"sbp84", 16, {1, 2, 3, 4, 5, 6}},
    {"sbp21", 32, {1, 2}},
    {"sbp42", 32, {1, 2, 3, 4}},
    {"sbp63", 32, {1, 2, 3, 4}},
    {"sbp84", 32, {1, 2, 3, 4, 5, 6}},
    // Odd N changes the chain: 3, 3, 5, 5 instead of 2, 4, 4, 6 (measured
    // here, confirmed by exact rational ranks; docs/method.md §2 gives the
    // values at N = 64).
    {"sbp21", 17, {1, 2, 3}},
    {"sbp42", 17, {1, 2, 3}},
    {"sbp63", 17, {1, 2, 3, 4, 5}},
    {"sbp84", 17, {1, 2, 3, 4, 5}},
};

BOOST_DATA_TEST_CASE(JordanStructure_MatchesExactRanks_AndDbarHasNoZeroModes,
                     boost::unit_test::data::make(kJordanCases), c) {
  const Spectrum s = OfD(c.name, c.n);
  BOOST_TEST(s.zero.kernel_dimensions == c.kernel_dimensions,
             boost::test_tools::per_element());
  BOOST_TEST(s.zero.geometric_multiplicity == 1);
  BOOST_TEST(s.zero.algebraic_multiplicity == c.kernel_dimensions.back());
  const Spectrum sbar = OfDbar(c.name, c.n);
  BOOST_TEST(sbar.zero.geometric_multiplicity == 0);
  BOOST_TEST(sbar.min_real_part > 0.0);
  // The real eigenvalues of D̄: the affine eigenvalue 1 alone for even N;
  // odd N adds one more, above 1 (measured at N = 17: 4.159, 5.783, 6.249,
  // 7.883 for SBP21/42/63/84; reported in docs/method.md §2).
  const auto& real = sbar.real_eigenvalues;
  BOOST_TEST_MESSAGE(c.name << " N = " << c.n << ": " << real.size()
                            << " real eigenvalue(s) of D̄, largest "
                            << *std::max_element(real.begin(), real.end()));
  BOOST_TEST(real.size() == (c.n % 2 == 1 ? 2u : 1u));
  BOOST_TEST(std::count_if(real.begin(), real.end(), [](double v) {
               return std::abs(v - 1.0) <= 1e-8;
             }) == 1);
  if (c.n % 2 == 1)
    BOOST_TEST(*std::max_element(real.begin(), real.end()) > 2.0);
}

// The step control's frequency estimate: the largest real part among the
// eigenvalues of M⁻¹K (at least 0), in closed form for two coordinates.
// Against Eigen's general eigensolver on M⁻¹K, over random symmetric K and
// symmetric positive definite M (a plane orbit's Hessian blocks) and random
// general pairs, the closed form agrees to a relative 1e-12 (measured: at
// most 6.9e-15 over these draws); the complex and the singular cases by
// their exact values.
BOOST_AUTO_TEST_CASE(LargestGeneralizedEigenvalue_TwoCoordinates) {
  using vivp::linalg::LargestGeneralizedEigenvalue;
  auto general = [](const Eigen::MatrixXd& k, const Eigen::MatrixXd& m) {
    const Eigen::VectorXcd ev = (m.fullPivLu().solve(k)).eigenvalues();
    double largest = 0;
    for (Eigen::Index i = 0; i < ev.size(); ++i)
      largest = std::max(largest, ev[i].real());
    return largest;
  };
  std::srand(7);
  double worst = 0;
  for (int draw = 0; draw < 2000; ++draw) {
    Eigen::MatrixXd k = Eigen::MatrixXd::Random(2, 2);
    Eigen::MatrixXd m = Eigen::MatrixXd::Random(2, 2);
    if (draw % 2 == 0) {
      k = (k + k.transpose()).eval();
      m = (m * m.transpose() + 0.1 * Eigen::MatrixXd::Identity(2, 2)).eval();
    }
    const double ref = general(k, m);
    const double got = LargestGeneralizedEigenvalue(k, m);
    const double scale = (m.fullPivLu().solve(k)).cwiseAbs().maxCoeff();
    worst = std::max(worst, std::abs(got - ref) / scale);
  }
  BOOST_TEST_MESSAGE("closed form against the general path: " << worst);
  BOOST_TEST(worst <= 1e-12);
  Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(2, 2);
  Eigen::MatrixXd rotation(2, 2), spiral(2, 2), singular(2, 2), k(2, 2);
  rotation << 0, 1, -1, 0;  // eigenvalues ±i: real part 0
  spiral << 1, 2, -2, 1;    // 1 ± 2i
  BOOST_TEST(LargestGeneralizedEigenvalue(rotation, identity) == 0.0);
  BOOST_TEST(LargestGeneralizedEigenvalue(spiral, identity) == 1.0);
  // A singular nonzero M takes the general path (full-pivoting LU).
  singular << 1, 1, 1, 1;
  k << 2, 0, 0, 3;
  BOOST_TEST(LargestGeneralizedEigenvalue(k, singular) == general(k, singular));
}

// The closed forms on fixed-size blocks (as the step control asks, without
// the heap) give the same bits as through dynamic matrices.
BOOST_AUTO_TEST_CASE(LargestOfFew_FixedSizeSameBits) {
  using vivp::linalg::LargestGeneralizedEigenvalue;
  using vivp::linalg::LargestOfFew;
  std::srand(11);
  for (int draw = 0; draw < 500; ++draw) {
    const Eigen::Matrix2d k = Eigen::Matrix2d::Random();
    const Eigen::Matrix2d m = Eigen::Matrix2d::Random();
    double fixed = -1;
    BOOST_REQUIRE(LargestOfFew(k, m, fixed));
    BOOST_TEST(fixed == LargestGeneralizedEigenvalue(k, m));
    const Eigen::Matrix<double, 1, 1> k1 = k.topLeftCorner<1, 1>();
    const Eigen::Matrix<double, 1, 1> m1 = m.topLeftCorner<1, 1>();
    BOOST_REQUIRE(LargestOfFew(k1, m1, fixed));
    BOOST_TEST(fixed == LargestGeneralizedEigenvalue(k1, m1));
  }
  // No closed form: three coordinates, a zero 1 × 1 mass, a singular 2 × 2.
  double unused = 0;
  BOOST_TEST(!LargestOfFew(Eigen::Matrix3d::Identity().eval(),
                           Eigen::Matrix3d::Identity().eval(), unused));
  BOOST_TEST(!LargestOfFew(Eigen::Matrix<double, 1, 1>::Ones().eval(),
                           Eigen::Matrix<double, 1, 1>::Zero().eval(), unused));
  BOOST_TEST(!LargestOfFew(Eigen::Matrix2d::Identity().eval(),
                           Eigen::Matrix2d::Ones().eval(), unused));
}
