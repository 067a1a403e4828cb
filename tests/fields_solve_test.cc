// Fields solved from their action (core/action/field_system.h,
// solvers/spacetime), the structure of the solution: the Jacobian against
// differences of the residual, the reduced solution as the symmetric
// critical point of the full doubled action, the Noether identities that
// hold exactly and the energy's convergence.
#define BOOST_TEST_MODULE fields_solve
#include <ceres/jet.h>

#include <Eigen/Dense>
#include <array>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/action/field_charges.h"
#include "core/action/field_system.h"
#include "problems/fields/densities.h"
#include "problems/fields/exact.h"
#include "solvers/spacetime/solve.h"
#include "tests/fields_helpers.h"

using namespace vivp;
using namespace fields_test;

namespace {

// The system's Jacobian as a dense matrix.
struct DenseSink {
  Eigen::MatrixXd m;
  void Add(int r, int c, double v) { m(r, c) += v; }
};

// Data at the ends (core/action/field_boundary.h), natural unless given.
using Kinds = std::array<action::BoundaryKind, 2>;
constexpr Kinds kNatural = {action::BoundaryKind::kNatural,
                            action::BoundaryKind::kNatural};

template <class Density>
void CheckJacobian(const Density& density, const SpaceDerivative<double>& dx,
                   const char* op, int nt, Kinds kinds = kNatural) {
  constexpr int m = Density::kDim;
  const sbp::RegularizedOperator<double> dt(
      sbp::MakeOperator<double>(op, nt, 0.0, 0.4));
  const int n = dx.points() * m;
  std::vector<double> phi0(n), pi0(n);
  for (int k = 0; k < n; ++k) {
    phi0[k] = 0.3 * std::sin(1.3 * k);
    pi0[k] = 0.2 * std::cos(0.7 * k);
  }
  action::FieldSystem<Density> sys(density, dt, dx, phi0, pi0);
  for (int side = 0; side < 2; ++side)
    if (kinds[side] != action::BoundaryKind::kNatural) {
      std::vector<double> data(std::size_t(nt) * m);
      for (std::size_t k = 0; k < data.size(); ++k)
        data[k] = 0.4 * std::cos(0.9 * double(k) + side);
      sys.SetBoundary(side, kinds[side], data);
    }
  Eigen::VectorXd y(sys.size());
  for (int k = 0; k < sys.size(); ++k) y[k] = 0.5 * std::sin(0.37 * k + 0.1);
  DenseSink sink{Eigen::MatrixXd::Zero(sys.size(), sys.size())};
  sys.Jacobian(y.data(), sink);
  Eigen::VectorXd fp(sys.size()), fm(sys.size());
  double worst = 0, scale = sink.m.cwiseAbs().maxCoeff();
  for (int c = 0; c < sys.size(); ++c) {
    const double h = 1e-6;
    Eigen::VectorXd yp = y, ym = y;
    yp[c] += h;
    ym[c] -= h;
    sys.Residual(yp.data(), fp.data());
    sys.Residual(ym.data(), fm.data());
    const Eigen::VectorXd col = (fp - fm) / (2 * h);
    worst = std::max(worst, (col - sink.m.col(c)).cwiseAbs().maxCoeff());
  }
  BOOST_TEST_MESSAGE(op << " in time, " << dx.name() << " in space, m = " << m
                        << ", ends " << action::BoundaryName(kinds[0]) << "/"
                        << action::BoundaryName(kinds[1])
                        << ": max |J − ΔF/Δy| = " << worst << " of " << scale);
  BOOST_TEST(worst <= 1e-7 * scale);
}

}  // namespace

BOOST_AUTO_TEST_CASE(jacobian_matches_differences_of_the_residual) {
  CheckJacobian(fields::SineGordon{},
                SpaceDerivative<double>::Periodic(4, 7, 0.0, 3.0), "sbp42", 9);
  CheckJacobian(fields::ComplexPhi4{},
                SpaceDerivative<double>::Bounded("sbp42", 8, 0.0, 3.0), "sbp21",
                9);
  CheckJacobian(fields::Phi4{},
                SpaceDerivative<double>::Bounded("sbp21", 5, -1.0, 1.0),
                "sbp84", 17);
  using action::BoundaryKind;
  CheckJacobian(fields::ComplexPhi4{},
                SpaceDerivative<double>::Bounded("sbp42", 8, 0.0, 3.0), "sbp42",
                9, {BoundaryKind::kDirichlet, BoundaryKind::kNeumann});
  CheckJacobian(fields::SineGordon{},
                SpaceDerivative<double>::Bounded("sbp21", 5, -1.0, 1.0),
                "sbp21", 5, {BoundaryKind::kNeumann, BoundaryKind::kDirichlet});
}

namespace {

// The full doubled action of the field (core/action/field_system.h), written
// out directly: u = (φ1, φ2 time-major, then λ1 … λ4 per spatial point), one
// component.
template <class T, class Density>
T FullAction(const Density& density, const sbp::RegularizedOperator<double>& dt,
             const SpaceDerivative<double>& dx, const std::vector<double>& phi0,
             const std::vector<double>& pi0, const T* u) {
  const int nt = dt.points(), nx = dx.points(), grid = nt * nx;
  const auto& D = dt.base();
  T s(0.0);
  std::vector<T> col(nt), col_t(nt), row(nx), row_x(nx);
  std::vector<T> phi_t[2] = {std::vector<T>(grid), std::vector<T>(grid)};
  std::vector<T> phi_x[2] = {std::vector<T>(grid), std::vector<T>(grid)};
  for (int a = 0; a < 2; ++a) {
    const T* p = u + a * grid;
    for (int j = 0; j < nx; ++j) {
      for (int i = 0; i < nt; ++i) col[i] = p[i * nx + j];
      dt.Apply<T>(col, T(phi0[j]), col_t);
      for (int i = 0; i < nt; ++i) phi_t[a][i * nx + j] = col_t[i];
    }
    for (int i = 0; i < nt; ++i) {
      for (int j = 0; j < nx; ++j) row[j] = p[i * nx + j];
      dx.Apply<T>(row, row_x);
      for (int j = 0; j < nx; ++j) phi_x[a][i * nx + j] = row_x[j];
    }
    for (int k = 0; k < grid; ++k) {
      const T l = density(p + k, &phi_t[a][k], &phi_x[a][k]);
      const double w = D.NormWeight(k / nx) * dx.NormWeight(k % nx);
      s += (a == 0 ? w : -w) * l;
    }
  }
  const T* lambda = u + 2 * grid;
  for (int j = 0; j < nx; ++j) {
    std::vector<T> c1(nt), c2(nt);
    for (int i = 0; i < nt; ++i) {
      c1[i] = u[i * nx + j];
      c2[i] = u[grid + i * nx + j];
    }
    const T v1_0 = D.ApplyRow(0, c1.data());
    const T v1_n = D.ApplyRow(nt - 1, c1.data());
    const T v2_n = D.ApplyRow(nt - 1, c2.data());
    s += dx.NormWeight(j) *
         (lambda[j] * (c1[0] - phi0[j]) + lambda[nx + j] * (v1_0 - pi0[j]) +
          lambda[2 * nx + j] * (c1[nt - 1] - c2[nt - 1]) +
          lambda[3 * nx + j] * (v1_n - v2_n));
  }
  return s;
}

}  // namespace

// The reduced system assumes the critical point of the full doubled action
// has φ1 = φ2 and λ1 = λ2 = 0. Newton on the full action (gradient by AD,
// Hessian by differences of it), started away from that point, lands there
// to round-off and on the reduced solution.
BOOST_AUTO_TEST_CASE(full_action_critical_point_is_symmetric) {
  constexpr int kNt = 8, kNx = 5, kN = 2 * kNt * kNx + 4 * kNx;
  using Jet = ceres::Jet<double, kN>;
  const fields::SineGordon sg;
  const sbp::RegularizedOperator<double> dt(
      sbp::MakeOperator<double>("sbp42", kNt, 0.0, 0.5));
  const auto dx = SpaceDerivative<double>::Periodic(2, kNx, 0.0, 5.0);
  std::vector<double> phi0(kNx), pi0(kNx);
  for (int j = 0; j < kNx; ++j) {
    phi0[j] = 1.0 + 0.5 * std::sin(kTwoPi * j / kNx);
    pi0[j] = 0.3 * std::cos(kTwoPi * j / kNx);
  }
  const action::FieldSystem<fields::SineGordon> reduced(sg, dt, dx, phi0, pi0);
  std::vector<double> y(reduced.size(), 0.0);
  spacetime::SparseLuSolver lu;
  BOOST_REQUIRE(variational::Newton<double>(reduced, y, {}, lu).converged);

  auto gradient = [&](const Eigen::VectorXd& u) {
    std::vector<Jet> v(kN);
    for (int k = 0; k < kN; ++k) v[k] = Jet(u[k], k);
    const Jet s = FullAction(sg, dt, dx, phi0, pi0, v.data());
    return Eigen::VectorXd(s.v);
  };
  Eigen::VectorXd u(kN);
  const int grid = kNt * kNx;
  for (int i = 0; i < kNt; ++i)
    for (int j = 0; j < kNx; ++j) {
      const double p = y[reduced.Phi(i, j, 0)];
      u[i * kNx + j] = p + 0.02 * std::sin(1.0 + i + 3 * j);
      u[grid + i * kNx + j] = p - 0.02 * std::cos(2.0 + i * j);
    }
  for (int j = 0; j < kNx; ++j) {
    u[2 * grid + j] = 0.05;
    u[2 * grid + kNx + j] = -0.04;
    u[2 * grid + 2 * kNx + j] = y[reduced.Lambda3(j, 0)];
    u[2 * grid + 3 * kNx + j] = y[reduced.Lambda4(j, 0)];
  }
  double step = 1;
  int it = 0;
  for (; it < 30 && step > 1e-14; ++it) {
    Eigen::MatrixXd h(kN, kN);
    for (int k = 0; k < kN; ++k) {
      const double e = 1e-5;
      Eigen::VectorXd up = u, um = u;
      up[k] += e;
      um[k] -= e;
      h.col(k) = (gradient(up) - gradient(um)) / (2 * e);
    }
    const Eigen::VectorXd delta = h.fullPivLu().solve(gradient(u));
    u -= delta;
    step = delta.cwiseAbs().maxCoeff();
  }
  double asym = 0, l12 = 0, off = 0;
  for (int k = 0; k < grid; ++k)
    asym = std::max(asym, std::abs(u[k] - u[grid + k]));
  for (int j = 0; j < 2 * kNx; ++j)
    l12 = std::max(l12, std::abs(u[2 * grid + j]));
  for (int i = 0; i < kNt; ++i)
    for (int j = 0; j < kNx; ++j)
      off = std::max(off, std::abs(u[i * kNx + j] - y[reduced.Phi(i, j, 0)]));
  BOOST_TEST_MESSAGE("full action, " << it
                                     << " Newton steps from a start "
                                        "0.02 off: max|φ1 − φ2| = "
                                     << asym << ", max|λ1,2| = " << l12
                                     << ", max|φ1 − φ₊| = " << off);
  BOOST_TEST(step <= 1e-14);
  BOOST_TEST(it >= 2);
  BOOST_TEST(asym <= 1e-13);
  BOOST_TEST(l12 <= 1e-13);
  BOOST_TEST(off <= 1e-13);
}

// Noether identities that hold exactly at the discrete critical point (no
// discretization error, round-off only), derived by contracting the
// reduced equations with the symmetry's generator (docs/fields.md §6):
//  - shift φ → φ + ε of the wave equation (V = 0; D annihilates constants):
//    Σ_j Hˣ_j λ3(j) = −Σ_j Hˣ_j π₀(j), the total momentum density at T
//    carried by the multipliers equals the initial one;
//  - rotation of the complex |φ|⁴ field: the U(1) charge at T built from the
//    multipliers, Σ_j Hˣ_j [−λ3·Aφ_N − λ4·A(D_tφ)_N], equals the initial
//    Σ_j Hˣ_j π₀·Aφ₀ (A the rotation generator).
BOOST_AUTO_TEST_CASE(noether_identities_hold_exactly) {
  {
    const fields::Wave wave{1.0};
    const auto dx = SpaceDerivative<double>::Periodic(8, 32, 0.0, kTwoPi);
    const sbp::RegularizedOperator<double> dt(
        sbp::MakeOperator<double>("sbp42", 33, 0.0, 1.0));
    std::vector<double> phi0(32), pi0(32);
    for (int j = 0; j < 32; ++j) {
      phi0[j] = std::exp(std::sin(dx.x(j)));
      pi0[j] = 0.4 + std::cos(2 * dx.x(j));
    }
    const action::FieldSystem<fields::Wave> sys(wave, dt, dx, phi0, pi0);
    std::vector<double> y;
    spacetime::SparseLuSolver lu;
    BOOST_REQUIRE(variational::Newton<double>(sys, y, {}, lu).converged);
    double end = 0, start = 0;
    for (int j = 0; j < 32; ++j) {
      end += dx.NormWeight(j) * y[sys.Lambda3(j, 0)];
      start += dx.NormWeight(j) * pi0[j];
    }
    BOOST_TEST_MESSAGE("wave: Σ Hλ3 = " << end << ", −Σ Hπ₀ = " << -start
                                        << ", difference " << end + start);
    BOOST_TEST(std::abs(end + start) <= 1e-13 * std::abs(start));
  }
  {
    const fields::ComplexPhi4 field{1.0, 1.0};
    const auto dx = SpaceDerivative<double>::Bounded("sbp42", 33, -4.0, 4.0);
    const sbp::RegularizedOperator<double> dt(
        sbp::MakeOperator<double>("sbp42", 41, 0.0, 1.0));
    std::vector<double> phi0(66), pi0(66);
    for (int j = 0; j < 33; ++j) {
      const double x = dx.x(j), g = std::exp(-x * x);
      phi0[2 * j] = g * std::cos(x);
      phi0[2 * j + 1] = g * std::sin(x);
      pi0[2 * j] = -0.8 * phi0[2 * j + 1];
      pi0[2 * j + 1] = 0.8 * phi0[2 * j] + 0.1 * g;
    }
    const action::FieldSystem<fields::ComplexPhi4> sys(field, dt, dx, phi0,
                                                       pi0);
    std::vector<double> y;
    spacetime::SparseLuSolver lu;
    BOOST_REQUIRE(variational::Newton<double>(sys, y, {}, lu).converged);
    action::FieldValues<double> v;
    sys.Fields(y.data(), v);
    const int n = sys.time_points() - 1;
    double end = 0, start = 0;
    for (int j = 0; j < 33; ++j) {
      const double l3[2] = {y[sys.Lambda3(j, 0)], y[sys.Lambda3(j, 1)]};
      const double l4[2] = {y[sys.Lambda4(j, 0)], y[sys.Lambda4(j, 1)]};
      // (D_t φ)_N with the plain operator, as in the connection condition.
      double vn[2];
      for (int a = 0; a < 2; ++a) {
        std::vector<double> col(n + 1);
        for (int i = 0; i <= n; ++i) col[i] = y[sys.Phi(i, j, a)];
        vn[a] = dt.base().ApplyRow(n, col.data());
      }
      const double p0 = v.phi[sys.At(n, j, 0)], p1 = v.phi[sys.At(n, j, 1)];
      // Aφ = (−φ_1, φ_0).
      end += dx.NormWeight(j) *
             (-(l3[0] * -p1 + l3[1] * p0) - (l4[0] * -vn[1] + l4[1] * vn[0]));
      start += dx.NormWeight(j) *
               (pi0[2 * j] * -phi0[2 * j + 1] + pi0[2 * j + 1] * phi0[2 * j]);
    }
    BOOST_TEST_MESSAGE("complex φ⁴: charge from the multipliers "
                       << end << ", initial " << start << ", difference "
                       << end - start);
    BOOST_TEST(std::abs(end - start) <= 1e-13 * std::abs(start));
  }
}

namespace {

// Fitted orders of the energy error at interior slices and at the last one
// for an exact solution u of the density, T = 1, Nt = 33 … 257.
template <class Density, class U>
void CheckEnergy(const char* name, const Density& density, const U& u,
                 const SpaceDerivative<double>& dx) {
  const int nx = dx.points();
  const auto [phi0, pi0] = fields::InitialData(u, dx);
  const double e0 = action::ChargesOfSlice(density, dx, phi0, pi0).energy;
  struct Expect {
    const char* op;
    double interior, last;
  };
  for (const Expect e :
       {Expect{"sbp21", 2.0, 1.0}, Expect{"sbp42", 3.0, 2.0}}) {
    std::vector<double> h, interior, last;
    for (int nt : {33, 65, 129, 257}) {
      const auto s = Solve(density, u, dx, {e.op, nt, 1.0, 0});
      double worst = 0;
      const std::size_t slices = s.t.size();
      for (std::size_t k = 0; k < slices; ++k) {
        const std::span<const double> p(s.phi.data() + k * nx, nx);
        const std::span<const double> q(s.phi_t.data() + k * nx, nx);
        const double de =
            std::abs(action::ChargesOfSlice(density, dx, p, q).energy - e0);
        if (k + 1 < slices)
          worst = std::max(worst, de);
        else
          last.push_back(de);
      }
      h.push_back(1.0 / (nt - 1));
      interior.push_back(worst);
    }
    const double pi = Slope(h, interior), pl = Slope(h, last);
    BOOST_TEST_MESSAGE(name << ", " << e.op << ": energy error at interior "
                            << "slices " << interior.back() << " (order " << pi
                            << "), at the last slice " << last.back()
                            << " (order " << pl << ") of " << e0);
    BOOST_TEST(pi >= e.interior - 0.3);
    BOOST_TEST(pl >= e.last - 0.3);
    BOOST_TEST(pl <= pi - 0.5);
  }
}

}  // namespace

// The energy Σ_j Hˣ_j (π·φ_t − L) of every slice (core/action/
// field_charges.h, from the density) against the discrete energy of the
// exact initial data (the spatial error is not what is measured): at
// interior slices it converges with the scheme, at the last slice, where
// φ_t is the closure row of D̄, an order lower (as the end velocity in point
// mechanics). Klein–Gordon plane wave on 64 points of [0, 2π), sine-Gordon
// breather (ω = 0.5) on 64 points of [−20, 20), order-8 periodic
// differences.
BOOST_AUTO_TEST_CASE(energy_converges_at_interior_slices) {
  const fields::KleinGordon kg{1.0, 1.0};
  CheckEnergy("Klein–Gordon", kg, fields::KleinGordonPlaneWave{kg, 1.0, 1.0},
              SpaceDerivative<double>::Periodic(8, 64, 0.0, kTwoPi));
  CheckEnergy("sine-Gordon breather", fields::SineGordon{},
              fields::SineGordonBreather{0.5},
              SpaceDerivative<double>::Periodic(8, 64, -20.0, 40.0));
}
