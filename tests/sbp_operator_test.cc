// The SBP operators of core/sbp: defining identity, accuracy (with a required
// failure one degree higher), quadrature, stencil apply vs. exported matrix,
// automatic differentiation through the stencil, and argument checks.
#define BOOST_TEST_MODULE sbp_operator
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/sbp/builder.h"
#include "core/sbp/regularized.h"

namespace bdata = boost::unit_test::data;
using vivp::sbp::MakeOperator;
using vivp::sbp::Operator;

namespace {

const char* const kNames[] = {"sbp21", "sbp42", "sbp63", "sbp84"};

template <class Real>
Real Eps() {
  return std::numeric_limits<Real>::epsilon();
}

// Largest degree q such that D t^k is exact at row i for every k <= q, judged
// against a round-off bound c * eps * sum_j |D_ij t_j^k|, plus the residual at
// degree q + 1. Long double keeps the gap between round-off and truncation
// wide for the high orders.
struct RowExactness {
  int degree;
  long double next_residual;
  long double next_bound;
};

RowExactness ExactDegree(const Operator<long double>& d, int i, int max_k) {
  const int n = d.points();
  for (int k = 0; k <= max_k + 1; ++k) {
    const auto row = d.row(i);
    long double value = 0, scale = 0;
    for (std::size_t j = 0; j < row.coeffs.size(); ++j) {
      const long double term =
          row.coeffs[j] * std::pow(d.t(row.first + static_cast<int>(j)), k);
      value += term;
      scale += std::fabs(term);
    }
    value /= d.dt();
    scale /= d.dt();
    const long double exact =
        k == 0 ? 0.0L : k * std::pow(d.t(i), static_cast<long double>(k - 1));
    const long double residual = std::fabs(value - exact);
    const long double bound = 64 * n * Eps<long double>() * (scale + 1);
    if (residual > bound) return {k - 1, residual, bound};
  }
  return {max_k + 1, 0, 0};
}

}  // namespace

BOOST_DATA_TEST_CASE(SbpProperty_HDPlusDtH_EqualsB, bdata::make(kNames), name) {
  const int min = vivp::sbp::Table(name).min_points;
  for (int n : {min, 2 * min, 64, 1000}) {
    const auto d = MakeOperator<double>(name, n, 0.0, 3.0);
    const Eigen::SparseMatrix<double> D = d.SparseD();
    const Eigen::VectorXd h = d.NormDiagonal();
    Eigen::MatrixXd residual =
        Eigen::MatrixXd(h.asDiagonal() * D) +
        Eigen::MatrixXd(Eigen::SparseMatrix<double>(D.transpose()) *
                        h.asDiagonal());
    residual(0, 0) += 1.0;
    residual(n - 1, n - 1) -= 1.0;
    const double hd_norm = Eigen::MatrixXd(h.asDiagonal() * D).norm();
    BOOST_TEST_CONTEXT(name << " N=" << n) {
      BOOST_TEST(residual.norm() <= 4 * n * Eps<double>() * hd_norm);
    }
  }
}

BOOST_DATA_TEST_CASE(Exactness_UpToOrder_AndFailsOneDegreeHigher,
                     bdata::make(kNames), name) {
  const auto& table = vivp::sbp::Table(name);
  const int p = table.interior_order, q = table.boundary_order;
  for (int n : {table.min_points + 1, 64}) {
    const auto d = MakeOperator<long double>(name, n, -1.0L, 2.0L);
    long double weakest_failure = std::numeric_limits<long double>::infinity();
    for (int i = 0; i < n; ++i) {
      const bool interior =
          i >= table.boundary_rows() && i < n - table.boundary_rows();
      const RowExactness r = ExactDegree(d, i, p);
      BOOST_TEST_CONTEXT(name << " N=" << n << " row " << i) {
        if (interior) {
          BOOST_TEST(r.degree == p);  // exact to p, and required to fail at p+1
          weakest_failure =
              std::min(weakest_failure, r.next_residual / r.next_bound);
        } else {
          BOOST_TEST(r.degree >= q);
        }
      }
    }
    // The failure at degree p+1 is truncation, far above round-off, in every
    // interior row.
    BOOST_TEST(weakest_failure > 100.0L, name << " N=" << n);
  }
}

BOOST_DATA_TEST_CASE(Quadrature_DegreeIsTwiceBoundaryOrderMinusOne,
                     bdata::make(kNames), name) {
  const auto& table = vivp::sbp::Table(name);
  const int expected = 2 * table.boundary_order - 1;
  for (int n : {table.min_points, 64}) {
    const auto d = MakeOperator<long double>(name, n, -1.0L, 2.0L);
    int degree = -1;
    for (int k = 0; k <= expected + 1; ++k) {
      std::vector<long double> f(n);
      for (int i = 0; i < n; ++i) f[i] = std::pow(d.t(i), k);
      const long double quad = d.Integrate(std::span<const long double>(f));
      const long double exact =
          (std::pow(2.0L, k + 1) - std::pow(-1.0L, k + 1)) / (k + 1);
      if (std::fabs(quad - exact) >
          64 * n * Eps<long double>() * std::pow(2.0L, k + 1))
        break;
      degree = k;
    }
    BOOST_TEST(degree == expected, name << " N=" << n);
  }
}

BOOST_DATA_TEST_CASE(Apply_EqualsExportedMatrix_AndTransposeToo,
                     bdata::make(kNames), name) {
  const auto& table = vivp::sbp::Table(name);
  for (int n : {table.min_points, table.min_points + 1, 100}) {
    const auto d = MakeOperator<double>(name, n, 0.5, 2.0);
    Eigen::VectorXd u = Eigen::VectorXd::Random(n);
    std::vector<double> us(u.data(), u.data() + n);
    const auto du = d.Apply(us);
    const auto dtu = d.ApplyTranspose(us);
    const Eigen::VectorXd ref = d.SparseD() * u;
    const Eigen::VectorXd reft = d.SparseD().transpose() * u;
    const double scale = d.SparseD().cwiseAbs().sum() / n;
    for (int i = 0; i < n; ++i) {
      BOOST_TEST(std::abs(du[i] - ref[i]) <= 16 * Eps<double>() * scale);
      BOOST_TEST(std::abs(dtu[i] - reft[i]) <= 16 * Eps<double>() * scale);
    }
    BOOST_TEST(Eigen::MatrixXd(d.SparseD()).isApprox(d.DenseD()));
  }
}

// Apply on plain numbers sums the closure rows column by column for all
// rows at once; ApplyRow and Apply on Jets one row at a time. Both add each
// row's terms in the order of its columns: the same bits, for every operator
// and the spectral elements, in double and long double.
template <class Real>
void CheckApplyEqualsApplyRowBitwise(const std::string& name, int n) {
  const auto d = MakeOperator<Real>(name, n, Real(0.25), Real(1.75));
  std::vector<Real> u(n);
  for (int i = 0; i < n; ++i) u[i] = std::sin(Real(1.3) * i) + Real(0.1) * i;
  const std::vector<Real> du = d.Apply(u);
  using Jet = ceres::Jet<double, 1>;
  std::vector<Jet> uj(n);
  for (int i = 0; i < n; ++i) uj[i] = Jet(double(u[i]), 0);
  const std::vector<Jet> duj = d.Apply(uj);
  // (Apply's interior rows take the antisymmetric form of the stencil,
  // ApplyRow's the difference form: other bits by design.)
  const int r = d.boundary_rows();
  int differ = 0;
  for (int i = 0; i < n; ++i) {
    if (i < r || i >= n - r) differ += du[i] != d.ApplyRow(i, u.data());
    if constexpr (std::is_same_v<Real, double>) differ += du[i] != duj[i].a;
  }
  BOOST_TEST(differ == 0, name << " N=" << n);
}

BOOST_AUTO_TEST_CASE(Apply_EqualsApplyRowBitwise_ClosuresAndElements) {
  for (const char* name : kNames) {
    const auto& table = vivp::sbp::Table(name);
    for (int n : {table.min_points, table.min_points + 1, 48, 100}) {
      CheckApplyEqualsApplyRowBitwise<double>(name, n);
      CheckApplyEqualsApplyRowBitwise<long double>(name, n);
    }
  }
  for (const vivp::sbp::Coefficients* t : vivp::sbp::ElementOperators()) {
    CheckApplyEqualsApplyRowBitwise<double>(std::string(t->name),
                                            t->max_points);
    CheckApplyEqualsApplyRowBitwise<long double>(std::string(t->name),
                                                 t->max_points);
  }
}

BOOST_DATA_TEST_CASE(Bandwidth_CoversEveryNonzero, bdata::make(kNames), name) {
  const auto d = MakeOperator<double>(name, 50);
  const Eigen::SparseMatrix<double> D = d.SparseD();
  int measured = 0;
  for (int k = 0; k < D.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(D, k); it; ++it)
      measured = std::max<int>(measured, std::abs(it.row() - it.col()));
  BOOST_TEST(d.Bandwidth() == measured);
}

BOOST_DATA_TEST_CASE(JetJacobianOfApply_EqualsD, bdata::make(kNames), name) {
  // Seed four unit directions at a time and read the columns of D back.
  constexpr int kLanes = 4;
  using Jet = ceres::Jet<double, kLanes>;
  const int n = 37;
  const auto d = MakeOperator<double>(name, n, 0.0, 2.0);
  const Eigen::MatrixXd dense = d.DenseD();
  Eigen::MatrixXd jac(n, n);
  for (int c0 = 0; c0 < n; c0 += kLanes) {
    std::vector<Jet> u(n);
    for (int i = 0; i < n; ++i) {
      u[i] = Jet(std::sin(i));
      if (i >= c0 && i < c0 + kLanes) u[i].v[i - c0] = 1.0;
    }
    const auto du = d.Apply(u);
    for (int i = 0; i < n; ++i)
      for (int l = 0; l < kLanes && c0 + l < n; ++l)
        jac(i, c0 + l) = du[i].v[l];
  }
  BOOST_TEST((jac - dense).cwiseAbs().maxCoeff() <=
             4 * Eps<double>() * dense.cwiseAbs().maxCoeff());
}

BOOST_AUTO_TEST_CASE(NestedJets_SecondDerivativeOfQuadraticForm) {
  // f(u) = (Du)_i^2 summed: d^2 f / du_a du_b = 2 (D^T D)_ab, read off a
  // Jet<Jet<double,2>,2> seeded in two entries.
  using Inner = ceres::Jet<double, 2>;
  using Outer = ceres::Jet<Inner, 2>;
  const int n = 20, a = 3, b = 5;
  const auto d = MakeOperator<double>("sbp42", n);
  std::vector<Outer> u(n);
  for (int i = 0; i < n; ++i)
    u[i] = vivp::autodiff::Lift<Outer>(std::cos(0.3 * i));
  u[a].a.v[0] = 1.0;
  u[a].v[0] = Inner(1.0);
  u[b].a.v[1] = 1.0;
  u[b].v[1] = Inner(1.0);
  const auto du = d.Apply(u);
  Outer f = vivp::autodiff::Lift<Outer>(0.0);
  for (const auto& x : du) f += x * x;
  const Eigen::MatrixXd dtd = d.DenseD().transpose() * d.DenseD();
  const double scale = dtd.cwiseAbs().maxCoeff();
  BOOST_TEST(std::abs(f.v[0].v[1] - 2 * dtd(a, b)) <=
             64 * Eps<double>() * scale);
  BOOST_TEST(std::abs(f.v[0].v[0] - 2 * dtd(a, a)) <=
             64 * Eps<double>() * scale);
  BOOST_TEST(std::abs(f.v[1].v[1] - 2 * dtd(b, b)) <=
             64 * Eps<double>() * scale);
}

BOOST_AUTO_TEST_CASE(Factory_RejectsBadArguments_NamingTheValidRange) {
  auto message = [](auto&& make) -> std::string {
    try {
      make();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no exception";
  };
  BOOST_TEST(message([] { MakeOperator<double>("sbp42", 5); }) ==
             "sbp42 needs at least 8 points, got 5");
  BOOST_TEST(message([] { MakeOperator<double>("sbp84", 15); }) ==
             "sbp84 needs at least 16 points, got 15");
  BOOST_TEST(message([] { MakeOperator<double>("sbp21", -3); }) ==
             "sbp21 needs at least 2 points, got -3");
  BOOST_TEST(message([] { MakeOperator<double>("sbp99", 32); }) ==
             "unknown SBP operator 'sbp99'; valid operators: sbp21, sbp42, "
             "sbp63, sbp84, and the spectral elements lgl8, lgl12, lgl16");
  BOOST_TEST(message([] { MakeOperator<double>("sbp21", 32, 1.0, 1.0); }) ==
             "time interval [1, 1] is invalid; need finite values with t_end "
             "> t_start");
  BOOST_TEST(message([] {
               MakeOperator<double>("sbp21", 32, 0.0,
                                    std::numeric_limits<double>::quiet_NaN());
             }) ==
             "time interval [0, nan] is invalid; need finite values "
             "with t_end > t_start");
  BOOST_TEST(message([] {
               const auto d = MakeOperator<double>("sbp21", 4);
               std::vector<double> u(3);
               d.Apply(u);
             }) ==
             "sbp21 operator on 4 points applied to vectors of length 3 "
             "-> 3; both must have length 4");
  // The constructor itself refuses closures that would overlap.
  BOOST_TEST(message([] {
               vivp::sbp::Operator<double>(vivp::sbp::Table("sbp63"), 11, 0.0,
                                           1.0);
             }) ==
             "sbp63 needs at least 12 points for its two closures, got 11; "
             "build operators with MakeOperator");
}

BOOST_AUTO_TEST_CASE(MinimumGrid_IsSmallestWithoutOverlappingClosures) {
  for (const char* name : kNames) {
    const auto& t = vivp::sbp::Table(name);
    BOOST_TEST(t.min_points == 2 * t.boundary_rows(), name);
    for (const auto& row : t.boundary_block)
      BOOST_TEST(static_cast<int>(row.size()) <= t.min_points, name);
  }
}

// A march under error control moves its window's operator to each new step
// (Operator::Retime): the result is the operator built on the new interval,
// to the bit, and a bad interval is refused as MakeOperator refuses it.
BOOST_DATA_TEST_CASE(Retime_EqualsTheOperatorBuiltOnTheInterval,
                     bdata::make(kNames), name) {
  const int n = vivp::sbp::Table(name).min_points + 9;
  auto moved = MakeOperator<double>(name, n, 0.0, 1.0);
  vivp::sbp::RegularizedOperator<double> moved_bar(moved, -1.0);
  moved.Retime(0.25, 0.25 + 3e-3 * (n - 1));
  moved_bar.Retime(0.25, 0.25 + 3e-3 * (n - 1));
  const auto built = MakeOperator<double>(name, n, 0.25, 0.25 + 3e-3 * (n - 1));
  const vivp::sbp::RegularizedOperator<double> built_bar(built, -1.0);
  BOOST_TEST(moved.dt() == built.dt());
  BOOST_TEST(moved.inv_dt() == built.inv_dt());
  BOOST_TEST(moved.t(n - 1) == built.t(n - 1));
  BOOST_TEST(moved_bar.penalty() == built_bar.penalty());
  std::vector<double> u(n);
  for (int i = 0; i < n; ++i) u[i] = std::sin(0.7 * i) + 0.1 * i * i;
  const auto a = moved.Apply(u), b = built.Apply(u);
  const auto at = moved.ApplyTranspose(u), bt = built.ApplyTranspose(u);
  for (int i = 0; i < n; ++i) {
    BOOST_TEST(a[i] == b[i]);
    BOOST_TEST(at[i] == bt[i]);
    BOOST_TEST(moved.NormWeight(i) == built.NormWeight(i));
  }
  for (const auto& [t0, t1] :
       {std::pair{1.0, 1.0}, std::pair{1.0, 0.5},
        std::pair{0.0, std::numeric_limits<double>::infinity()}}) {
    std::string why;
    try {
      moved.Retime(t0, t1);
    } catch (const std::invalid_argument& e) {
      why = e.what();
    }
    BOOST_TEST(
        why.find("is invalid; need finite values with t_end > t_start") !=
        std::string::npos);
  }
  BOOST_TEST(moved.dt() == built.dt());  // a refused interval changes nothing
}
