// Space in d dimensions (core/sbp/space_grid.h) and its spatial modes
// (solvers/spacetime/grid_modes.h): the derivative along each axis against
// the exact one, the summation-by-parts identity of every axis with the
// other axes' weights, and the product basis: S u_q = s_q H u_q with
// u_pᵀ H u_q = δ_pq, for periodic and bounded axes, with and without points
// left out as data, in two and three dimensions; and the discrete action
// of a field on such a grid (core/action/field_system.h).
#define BOOST_TEST_MODULE fields_grid
#include <Eigen/Core>
#include <array>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/action/field_system.h"
#include "core/sbp/regularized.h"
#include "core/sbp/space_grid.h"
#include "solvers/spacetime/assembly.h"
#include "solvers/spacetime/grid_modes.h"
#include "solvers/spacetime/sparse_lu.h"

using vivp::sbp::SpaceDerivative;
using Grid = vivp::sbp::SpaceGrid<double>;
using vivp::spacetime::GridModes;

namespace {

constexpr double kPi = std::numbers::pi;

Grid PeriodicBounded(int nx, int ny) {
  return Grid({SpaceDerivative<double>::Periodic(8, nx, 0.0, 2 * kPi),
               SpaceDerivative<double>::Bounded("sbp42", ny, -1.0, 1.0)});
}

// A smooth field and its derivatives along x (periodic) and y.
double F(double x, double y) { return std::sin(x) * std::exp(0.5 * y); }
double Fx(double x, double y) { return std::cos(x) * std::exp(0.5 * y); }
double Fy(double x, double y) { return 0.5 * std::sin(x) * std::exp(0.5 * y); }

// max_j |(D_a u)_j − exact| on grid g.
double DerivativeError(const Grid& g, int a) {
  std::vector<double> u(g.points()), d(g.points());
  for (int j = 0; j < g.points(); ++j) u[j] = F(g.x(j, 0), g.x(j, 1));
  g.Apply<double>(a, u, d);
  double e = 0;
  for (int j = 0; j < g.points(); ++j) {
    const double exact =
        a == 0 ? Fx(g.x(j, 0), g.x(j, 1)) : Fy(g.x(j, 0), g.x(j, 1));
    e = std::max(e, std::abs(d[j] - exact));
  }
  return e;
}

// S u = Σ_a D_aᵀ H D_a u.
std::vector<double> Stiffness(const Grid& g, const std::vector<double>& u) {
  std::vector<double> s(g.points(), 0.0), d(g.points());
  for (int a = 0; a < g.dim(); ++a) {
    g.Apply<double>(a, u, d);
    g.AddTransposeH<double>(a, d, s);
  }
  return s;
}

// The largest violation of S u_q = s_q H u_q (relative to s_q + 1, over
// the kept points) and of u_pᵀ H u_q = δ_pq over every mode of m, and of
// the forward transform of H u_q being e_q.
struct BasisErrors {
  double eigen = 0, orthonormal = 0, forward = 0;
};
BasisErrors CheckBasis(const Grid& g, const GridModes& m,
                       const std::vector<char>& kept) {
  const int n = g.points(), count = m.count();
  std::vector<std::vector<double>> u(count, std::vector<double>(n, 0.0));
  BasisErrors e;
  for (int q = 0; q < count; ++q) {
    // Inverse of e_q (in mode q's block): column q of V.
    u[q][m.point_of(q)] = 1;
    m.Inverse(u[q].data(), 1, 1);
    for (int j = 0; j < n; ++j)
      if (!kept[j]) BOOST_REQUIRE(u[q][j] == 0.0);
    const auto s = Stiffness(g, u[q]);
    for (int j = 0; j < n; ++j)
      if (kept[j])
        e.eigen = std::max(
            e.eigen,
            std::abs(s[j] - m.eigenvalue(q) * g.NormWeight(j) * u[q][j]) /
                (m.eigenvalue(q) + 1));
  }
  for (int p = 0; p < count; ++p) {
    std::vector<double> hu(n);
    for (int j = 0; j < n; ++j) hu[j] = g.NormWeight(j) * u[p][j];
    for (int q = 0; q < count; ++q) {
      double dot = 0;
      for (int j = 0; j < n; ++j) dot += hu[j] * u[q][j];
      e.orthonormal = std::max(e.orthonormal, std::abs(dot - (p == q)));
    }
    m.Forward(hu.data(), 1, 1);
    for (int q = 0; q < count; ++q)
      e.forward = std::max(e.forward, std::abs(hu[m.point_of(q)] - (p == q)));
  }
  return e;
}

}  // namespace

// The derivative along each axis of a 2-D grid converges at the axis'
// order: order 8 on the periodic axis, SBP42's boundary order 2 (and
// interior 4) on the bounded one.
BOOST_AUTO_TEST_CASE(derivative_along_each_axis) {
  std::vector<double> ex, ey;
  for (int n : {16, 32}) {
    const Grid g = PeriodicBounded(n, 2 * n + 1);
    ex.push_back(DerivativeError(g, 0));
    ey.push_back(DerivativeError(g, 1));
  }
  const double px = std::log2(ex[0] / ex[1]), py = std::log2(ey[0] / ey[1]);
  BOOST_TEST_MESSAGE("x: " << ex[0] << " → " << ex[1] << " (order " << px
                           << "); y: " << ey[0] << " → " << ey[1] << " (order "
                           << py << ")");
  BOOST_TEST(px >= 7.0);
  BOOST_TEST(py >= 1.8);
}

// Σ_j H_j q_j (D_a u)_j = uᵀ (D_aᵀ H q) for any u, q, and ForRow holds the
// rows of Apply.
BOOST_AUTO_TEST_CASE(summation_by_parts_per_axis) {
  const Grid g({SpaceDerivative<double>::Bounded("sbp63", 13, 0.0, 1.0),
                SpaceDerivative<double>::Periodic(4, 9, 0.0, 2.0),
                SpaceDerivative<double>::Bounded("sbp42", 11, -1.0, 2.0)});
  const int n = g.points();
  std::vector<double> u(n), q(n), d(n);
  for (int j = 0; j < n; ++j) {
    u[j] = std::sin(0.37 * j + 0.1);
    q[j] = std::cos(0.91 * j * j + 0.3);
  }
  for (int a = 0; a < 3; ++a) {
    g.Apply<double>(a, u, d);
    double lhs = 0, rhs = 0, scale = 0;
    for (int j = 0; j < n; ++j) {
      lhs += g.NormWeight(j) * q[j] * d[j];
      scale += g.NormWeight(j) * std::abs(q[j] * d[j]);
    }
    std::vector<double> t(n, 0.0);
    g.AddTransposeH<double>(a, q, t);
    for (int j = 0; j < n; ++j) rhs += u[j] * t[j];
    BOOST_TEST_MESSAGE("axis " << a << ": " << lhs << " against " << rhs);
    BOOST_TEST(std::abs(lhs - rhs) <= 1e-13 * scale);
    double row = 0;
    for (int j = 0; j < n; ++j) {
      double r = 0;
      g.ForRow(a, j, [&](int l, double c) { r += c * u[l]; });
      row = std::max(row, std::abs(r - d[j]));
    }
    BOOST_TEST(row <= 1e-12);
  }
}

// The product basis of a periodic × bounded grid (every point kept), a
// bounded × bounded grid with its x faces left out (Dirichlet data there),
// and a periodic³ grid.
BOOST_AUTO_TEST_CASE(product_basis_diagonalizes_the_stiffness) {
  struct Case {
    const char* name;
    Grid grid;
    std::vector<int> first, count;
  };
  const Grid pb = PeriodicBounded(10, 9);
  const Grid bb({SpaceDerivative<double>::Bounded("sbp42", 9, 0.0, 1.0),
                 SpaceDerivative<double>::Bounded("sbp63", 13, 0.0, 2.0)});
  const Grid ppp({SpaceDerivative<double>::Periodic(4, 6, 0.0, 1.0),
                  SpaceDerivative<double>::Periodic(2, 5, 0.0, 2.0),
                  SpaceDerivative<double>::Periodic(4, 8, 0.0, 3.0)});
  const Case cases[] = {{"periodic × sbp42", pb, {0, 0}, {10, 9}},
                        {"sbp42 × sbp63, x faces out", bb, {1, 0}, {7, 13}},
                        {"periodic³", ppp, {0, 0, 0}, {6, 5, 8}}};
  for (const Case& c : cases) {
    const GridModes m(c.grid, c.first, c.count);
    std::vector<char> kept(c.grid.points(), 1);
    for (int j = 0; j < c.grid.points(); ++j)
      for (int a = 0; a < c.grid.dim(); ++a) {
        const int k = c.grid.Coordinate(j, a);
        if (k < c.first[a] || k >= c.first[a] + c.count[a]) kept[j] = 0;
      }
    const BasisErrors e = CheckBasis(c.grid, m, kept);
    BOOST_TEST_MESSAGE(c.name << ": " << m.count() << " modes, " << m.distinct()
                              << " time systems; S u = s H u " << e.eigen
                              << ", orthonormality " << e.orthonormal
                              << ", forward " << e.forward);
    BOOST_TEST(e.eigen <= 1e-11, c.name);
    BOOST_TEST(e.orthonormal <= 1e-12, c.name);
    BOOST_TEST(e.forward <= 1e-12, c.name);
  }
}

// Bad grids are refused with their reason.
BOOST_AUTO_TEST_CASE(bad_grids_are_refused) {
  BOOST_CHECK_THROW(Grid(std::vector<SpaceDerivative<double>>{}),
                    std::invalid_argument);
  const auto ax = SpaceDerivative<double>::Periodic(2, 4, 0.0, 1.0);
  BOOST_CHECK_THROW(Grid({ax, ax, ax, ax}), std::invalid_argument);
  const Grid g = PeriodicBounded(10, 9);
  const std::vector<int> first{0}, count{10};
  BOOST_CHECK_THROW(GridModes(g, first, count), std::invalid_argument);
  const std::vector<int> f2{0, 5}, c2{10, 5};
  BOOST_CHECK_THROW(GridModes(g, f2, c2), std::invalid_argument);
}

namespace {

// L = ½φ_t² − ½|∇φ|² − ½m²φ² in two spatial dimensions.
struct KleinGordon2 {
  static constexpr int kDim = 1;
  static constexpr int kSpaceDim = 2;
  double mass = 1.0;
  template <class T>
  T operator()(const T* p, const T* pt, const T* g) const {
    return T(0.5) * pt[0] * pt[0] - T(0.5) * (g[0] * g[0] + g[1] * g[1]) -
           T(0.5 * mass * mass) * p[0] * p[0];
  }
};

// The plane wave cos(k·x − ωt), ω² = |k|² + m², k = (1, 2) on the periodic
// [0, 2π)²: one Newton step of the global space-time solve (the field is
// linear) by the sparse LU, then the error at t = T of the last node and
// of the corrected end state φ_N + λ4 (M = 1). Returns {last node,
// corrected, worst residual after the step}.
std::array<double, 3> PlaneWave2(const char* op, int nt, int nx) {
  const Grid g({SpaceDerivative<double>::Periodic(8, nx, 0.0, 2 * kPi),
                SpaceDerivative<double>::Periodic(8, nx, 0.0, 2 * kPi)});
  // The semi-discrete plane wave: D_b of e^{ik_b x} is iσ(k_b h)/h, σ the
  // symbol Σ_l 2c_l sin(lθ) of the central differences, so the method of
  // lines' solution is cos(k·x − ω_h t) with ω_h² = Σ_b (σ(k_b h)/h)² + m²:
  // against it the error is the time discretization's alone.
  const auto& p = *g.axis(0).periodic_operator();
  auto symbol = [&](double k) {
    double sigma = 0;
    for (int l = 1; l <= p.half_width(); ++l)
      sigma += 2 * p.coefficient(l) * std::sin(l * k * p.dx());
    return sigma * p.inv_dx();
  };
  const double kx = 1, ky = 2;
  const double omega =
      std::sqrt(std::pow(symbol(kx), 2) + std::pow(symbol(ky), 2) + 1.0);
  const double t_end = 0.5;
  auto u = [&](double t, int j) {
    return std::cos(kx * g.x(j, 0) + ky * g.x(j, 1) - omega * t);
  };
  auto ut = [&](double t, int j) {
    return omega * std::sin(kx * g.x(j, 0) + ky * g.x(j, 1) - omega * t);
  };
  std::vector<double> phi0(g.points()), pi0(g.points());
  for (int j = 0; j < g.points(); ++j) {
    phi0[j] = u(0, j);
    pi0[j] = ut(0, j);
  }
  const vivp::sbp::RegularizedOperator<double> dt(
      vivp::sbp::MakeOperator<double>(op, nt, 0.0, t_end));
  const KleinGordon2 density;
  vivp::action::FieldSystem<KleinGordon2> sys(density, dt, g, phi0, pi0);
  const int n = sys.size();
  Eigen::VectorXd y = Eigen::VectorXd::Zero(n), f(n), dy;
  for (int j = 0; j < g.points(); ++j)
    for (int i = 0; i < nt; ++i) y[sys.Phi(i, j, 0)] = phi0[j];
  sys.Residual(y.data(), f.data());
  vivp::spacetime::PatternedMatrix jac;
  jac.Assemble(n, [&](auto& sink) { sys.Jacobian(y.data(), sink); });
  vivp::spacetime::SparseLu lu;
  lu.Analyze(jac.matrix());
  BOOST_REQUIRE(lu.Factorize(jac.matrix()));
  lu.Solve(f, dy);
  y -= dy;
  sys.Residual(y.data(), f.data());
  double node = 0, corrected = 0;
  for (int j = 0; j < g.points(); ++j) {
    const double last = y[sys.Phi(nt - 1, j, 0)];
    node = std::max(node, std::abs(last - u(t_end, j)));
    corrected = std::max(corrected,
                         std::abs(last + y[sys.Lambda4(j, 0)] - u(t_end, j)));
  }
  return {node, corrected, f.cwiseAbs().maxCoeff()};
}

}  // namespace

// The discrete action of a field in 2 + 1 dimensions (action::FieldSystem
// on a SpaceGrid of two periodic axes, order-8 differences on 12² points):
// the Klein–Gordon plane wave along (1, 2), solved globally, against the
// semi-discrete plane wave converges in Δt at the orders of one dimension —
// SBP21 2 at the last node and corrected, SBP42 3 at the last node and 4
// corrected.
BOOST_AUTO_TEST_CASE(klein_gordon_plane_wave_in_two_dimensions) {
  struct Expect {
    const char* op;
    double node_lo, node_hi, corrected_lo, corrected_hi;
  };
  for (const Expect e : {Expect{"sbp21", 1.8, 2.3, 1.8, 2.3},
                         Expect{"sbp42", 2.7, 3.5, 3.6, 4.8}}) {
    std::vector<double> h, en, ec;
    for (int nt : {17, 33, 65}) {
      const auto r = PlaneWave2(e.op, nt, 12);
      BOOST_TEST_MESSAGE(e.op << ", Nt = " << nt << ": last node " << r[0]
                              << ", corrected " << r[1] << ", residual "
                              << r[2]);
      BOOST_TEST(r[2] <= 1e-9);
      h.push_back(0.5 / (nt - 1));
      en.push_back(r[0]);
      ec.push_back(r[1]);
    }
    const double pn = std::log(en[1] / en[2]) / std::log(h[1] / h[2]);
    const double pc = std::log(ec[1] / ec[2]) / std::log(h[1] / h[2]);
    BOOST_TEST_MESSAGE(e.op << ": order " << pn << " at the last node, " << pc
                            << " corrected");
    BOOST_TEST(pn >= e.node_lo);
    BOOST_TEST(pn <= e.node_hi);
    BOOST_TEST(pc >= e.corrected_lo);
    BOOST_TEST(pc <= e.corrected_hi);
  }
}
