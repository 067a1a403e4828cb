// The banded LU of a window's Newton (solvers/variational/banded_lu.h)
// against LAPACK's, and the window engine's solver that keeps a
// factorization's inverse for many chord steps (step_scaled_lu.h); the
// mass solve of each window's multiplier-corrected end (end_state.h).
#define BOOST_TEST_MODULE banded_lu
#include "solvers/variational/banded_lu.h"

#include <Eigen/Core>
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "core/linalg/banded.h"
#include "solvers/variational/end_state.h"
#include "solvers/variational/step_scaled_lu.h"

// LAPACK's banded LU, the reference of BandedSubstitution_EqualsLapack.
extern "C" {
void dgbtrf_(const int* m, const int* n, const int* kl, const int* ku,
             double* ab, const int* ldab, int* ipiv, int* info);
void dgbtrs_(const char* trans, const int* n, const int* kl, const int* ku,
             const int* nrhs, const double* ab, const int* ldab,
             const int* ipiv, double* b, const int* ldb, int* info,
             std::size_t trans_len);
}

using namespace vivp;

// The per-window banded LU (BandedLu::FactorBand and Substitute) against
// LAPACK's dgbtrf and dgbtrs, over band shapes from a marched window's (n
// about 50) to wider and degenerate ones (kl = 0, n smaller than the band):
// the same operations in the same order, so the same solution to round-off
// (a BLAS with fused multiply-adds rounds differently), and a small
// residual; and a singular band refused. The `narrow` shapes are a window's:
// wide at the ends (closure rows, multipliers) and narrow inside, where the
// factorization sweeps only the entries that can be nonzero.
BOOST_AUTO_TEST_CASE(BandedSubstitution_EqualsLapack) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  struct Shape {
    int n, kl, ku;
    int narrow = -1;  // ≥ 0: inside the first and last 10 rows, |i − j| ≤ it
  };
  for (const Shape sh :
       {Shape{52, 5, 5}, Shape{52, 9, 3}, Shape{200, 12, 12}, Shape{30, 0, 4},
        Shape{7, 6, 6}, Shape{1, 0, 0}, Shape{100, 26, 18, 17},
        Shape{100, 14, 6, 3}, Shape{60, 8, 8, 0}}) {
    linalg::BandedMatrix<double> a(sh.n, sh.kl, sh.ku);
    for (int i = 0; i < sh.n; ++i)
      for (int j = std::max(0, i - sh.kl); j <= std::min(sh.n - 1, i + sh.ku);
           ++j) {
        const bool inside = i >= 10 && i < sh.n - 10;
        if (sh.narrow >= 0 && inside && std::abs(i - j) > sh.narrow) continue;
        a.Add(i, j, u(rng) + (i == j ? 0.5 : 0.0));
      }
    const linalg::BandedMatrix<double> original = a;
    std::vector<double> b(sh.n);
    for (double& v : b) v = u(rng);
    variational::BandedLu<double> lu;
    BOOST_TEST_REQUIRE(lu.Factor(a));
    std::vector<double> ours = b, lapack = b, ab(original.size());
    lu.Solve(ours.data());
    int kl = sh.kl, ku = sh.ku, ld = a.leading_dimension(), n = sh.n, nrhs = 1,
        info = 0;
    std::vector<int> pivots(n);
    linalg::BandedMatrix<double> again = original;
    dgbtrf_(&n, &n, &kl, &ku, again.data(), &ld, pivots.data(), &info);
    BOOST_TEST_REQUIRE(info == 0);
    const char trans = 'N';
    dgbtrs_(&trans, &n, &kl, &ku, &nrhs, again.data(), &ld, pivots.data(),
            lapack.data(), &n, &info, 1);
    BOOST_TEST_REQUIRE(info == 0);
    double scale = 0, difference = 0, residual = 0;
    original.Multiply(ours.data(), ab.data());
    for (int i = 0; i < n; ++i) {
      scale = std::max(scale, std::abs(lapack[i]));
      difference = std::max(difference, std::abs(ours[i] - lapack[i]));
      residual = std::max(residual, std::abs(ab[i] - b[i]));
    }
    BOOST_TEST_INFO("n = " << n << ", kl = " << kl << ", ku = " << ku);
    BOOST_TEST(difference <= 1e-13 * scale);
    BOOST_TEST(residual <= 1e-12 * scale);
  }
  // A zero column makes the band singular: no factors.
  linalg::BandedMatrix<double> singular(6, 2, 2);
  for (int i = 0; i < 6; ++i)
    for (int j = std::max(0, i - 2); j <= std::min(5, i + 2); ++j)
      if (j != 3) singular.Add(i, j, u(rng) + (i == j ? 0.5 : 0.0));
  variational::BandedLu<double> lu;
  BOOST_TEST(!lu.Factor(singular));
}

// The window engine's solver keeps a factorization's explicit inverse once it
// has served 2n substitutions (n ≤ kMaxInverse): before, the substitution's
// solution; after, the product's, which solves the system to round-off as
// well. Dense bands, as a spectral element's (lgl8 with one and two
// coordinates, lgl16 with two), and one size above the largest, which keeps
// substituting.
BOOST_AUTO_TEST_CASE(StepScaledLu_InverseForManySolves) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  using variational::detail::StepScaledLu;
  for (const int n :
       {10, 20, StepScaledLu::kMaxInverse, StepScaledLu::kMaxInverse + 1}) {
    // The band covers the matrix; a dense copy gives ‖A‖∞ and A x.
    Eigen::MatrixXd dense(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) dense(i, j) = u(rng) + (i == j ? 3.0 : 0.0);
    StepScaledLu solver(1, n - 2, false);
    solver.jac = linalg::BandedMatrix<double>(n, n - 1, n - 1);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) solver.jac.Add(i, j, dense(i, j));
    linalg::BandedMatrix<double> copy = solver.jac;
    const linalg::BandedMatrix<double> pristine = solver.jac;
    variational::BandedLu<double> lu;
    BOOST_TEST_REQUIRE(lu.Factor(copy));
    BOOST_TEST_REQUIRE(solver.Factorize());
    const double norm = dense.cwiseAbs().rowwise().sum().maxCoeff();
    const bool kept = n <= StepScaledLu::kMaxInverse;
    for (int k = 1; k <= 3 * n; ++k) {
      const Eigen::VectorXd b =
          Eigen::VectorXd::NullaryExpr(n, [&] { return u(rng); });
      Eigen::VectorXd x = b, reference = b;
      solver.Solve(x.data());
      lu.Solve(reference.data());
      BOOST_TEST_INFO("n = " << n << ", solve " << k);
      BOOST_TEST(solver.inverted() == (kept && k >= 2 * n));
      const double size = x.cwiseAbs().maxCoeff();
      const double residual = (dense * x - b).cwiseAbs().maxCoeff();
      const double difference = (x - reference).cwiseAbs().maxCoeff();
      // Before the inverse, the substitution itself (the same bits); after,
      // a backward error of a few n·ε.
      if (!solver.inverted()) BOOST_TEST(difference == 0.0);
      BOOST_TEST(residual <= 4 * n * 2.2e-16 * norm * size);
    }
    // A factorization after one that served 2n substitutions is inverted
    // at its first (a march's factorizations are alike); one after a
    // factorization that served fewer waits for 2n again.
    int served = 3 * n;
    for (const int serves : {1, 2 * n, 5}) {
      solver.jac = pristine;  // factored in place
      BOOST_TEST_REQUIRE(solver.Factorize());
      const Eigen::VectorXd b =
          Eigen::VectorXd::NullaryExpr(n, [&] { return u(rng); });
      for (int k = 1; k <= serves; ++k) {
        Eigen::VectorXd x = b;
        solver.Solve(x.data());
        if (k > 1) continue;
        BOOST_TEST_INFO("n = " << n << ", after a factorization that served "
                               << served);
        BOOST_TEST(solver.inverted() == (kept && served >= 2 * n));
        BOOST_TEST((dense * x - b).cwiseAbs().maxCoeff() <=
                   4 * n * 2.2e-16 * norm * x.cwiseAbs().maxCoeff());
      }
      served = serves;
    }
  }
}

// MassSolve: M⁻¹b by the closed-form inverse up to four coordinates, within
// a few ε·cond(M) of the full-pivoting LU it replaced; exact for M = I; a
// mass too close to singular for the cofactors takes the LU itself (the same
// bits).
template <int d>
void CheckMassSolve(std::mt19937& rng) {
  using Mat = Eigen::Matrix<double, d, d>;
  using Vec = Eigen::Matrix<double, d, 1>;
  std::uniform_real_distribution<double> u(-1, 1);
  const auto random_vec = [&] {
    Vec v;
    for (int i = 0; i < d; ++i) v[i] = u(rng);
    return v;
  };
  double worst = 0;
  for (int draw = 0; draw < 200; ++draw) {
    Mat a;
    for (int i = 0; i < d; ++i) a.col(i) = random_vec();
    const Mat m = a * a.transpose() + 0.1 * Mat::Identity();  // a mass
    const Vec b = random_vec();
    const Vec x = variational::MassSolve<double, d>(m)(b);
    const Vec ref = m.fullPivLu().solve(b);
    const double cond = m.norm() * m.inverse().norm();
    worst = std::max(worst, (x - ref).cwiseAbs().maxCoeff() /
                                (cond * ref.cwiseAbs().maxCoeff()));
  }
  BOOST_TEST_MESSAGE("d = " << d << ": |x - x_LU| / (cond |x|) " << worst);
  BOOST_TEST(worst <= 16 * 2.2e-16);
  const Vec b = random_vec();
  BOOST_TEST((variational::MassSolve<double, d>(Mat::Identity())(b) == b));
  const Mat singular = d == 1 ? Mat::Zero() : Mat::Ones();
  BOOST_TEST((variational::MassSolve<double, d>(singular)(b) ==
              Vec(singular.fullPivLu().solve(b))));
}

BOOST_AUTO_TEST_CASE(MassSolve_ClosedFormAgreesWithLu) {
  std::mt19937 rng(5);
  CheckMassSolve<1>(rng);
  CheckMassSolve<2>(rng);
  CheckMassSolve<3>(rng);
  CheckMassSolve<4>(rng);
}
