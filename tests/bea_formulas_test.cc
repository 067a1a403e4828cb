// The backward-error engine reproduces the closed forms of docs/bea.md §3
// and §4 (McLachlan & Offen 2023, Section 4 and Appendix A) exactly --
// every comparison expands the difference to zero.
#define BOOST_TEST_MODULE bea_formulas
#include <boost/test/unit_test.hpp>

#include "solvers/bea/derivation.h"

using namespace vivp::bea;
using GiNaC::ex;
using GiNaC::numeric;

namespace {

bool Zero(const ex& e) { return GiNaC::expand(e).is_zero(); }

DeriveOptions AtOrder(int order,
                      PotentialModel model = PotentialModel::kGeneric,
                      std::optional<GiNaC::matrix> symmetry = std::nullopt) {
  DeriveOptions o;
  o.order = order;
  o.model = model;
  o.symmetry = symmetry;
  return o;
}

// Derivatives of the generic potential as vectors and tensors.
struct Tensors {
  JetSpace& jet;
  int d;
  ex U(std::initializer_list<int> idx) {
    std::vector<int> a(d, 0);
    for (int i : idx) ++a[i];
    return jet.U(a);
  }
  ex g(int i) { return U({i}); }
  ex S(int i, int j) { return U({i, j}); }
  ex v(int i) { return jet.X(i, 1); }
  ex Quadratic(const GiNaC::matrix& M, const std::vector<ex>& a,
               const std::vector<ex>& b) {
    ex s = 0;
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j) s += a[i] * M(i, j) * b[j];
    return s;
  }
  std::vector<ex> Grad() {
    std::vector<ex> out;
    for (int i = 0; i < d; ++i) out.push_back(g(i));
    return out;
  }
  std::vector<ex> Vel() {
    std::vector<ex> out;
    for (int i = 0; i < d; ++i) out.push_back(v(i));
    return out;
  }
  GiNaC::matrix Hessian() {
    GiNaC::matrix s(d, d);
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j) s(i, j) = S(i, j);
    return s;
  }
};

GiNaC::matrix M34(const GiNaC::matrix& A) {
  // M = 3A - 4I.
  return A.mul_scalar(3).sub(ScalarMatrix(4, A.rows()));
}

}  // namespace

BOOST_AUTO_TEST_CASE(
    StormerVerlet_ModifiedHamiltonianFormAndLagrangian_MatchAppendixA) {
  auto r = Derive(MakeStormerVerlet(1), AtOrder(4));
  JetSpace& jet = *r.jet;
  // docs/bea.md §4 writes W = -U; W^(k) = -U_k.
  const ex W1 = -jet.U({1}), W2 = -jet.U({2}), W3 = -jet.U({3}),
           W4 = -jet.U({4}), W = -jet.U({0}), v = r.v(0);
  const ex H[] = {
      v * v / 2 + W, 0, -numeric(1, 24) * (W1 * W1 + 2 * W2 * v * v), 0,
      -numeric(1, 720) * (3 * W1 * W1 * W2 + 2 * W2 * W2 * v * v +
                          6 * W1 * W3 * v * v - 3 * W4 * v * v * v * v)};
  const ex f[] = {1, 0, -W2 / 6, 0,
                  -numeric(1, 180) * (W2 * W2 + 3 * W1 * W3 - 3 * W4 * v * v)};
  const ex L[] = {v * v / 2 - W, 0, numeric(1, 24) * (W1 * W1 - 2 * W2 * v * v),
                  0,
                  numeric(1, 720) * (3 * W1 * W1 * W2 - 2 * W2 * W2 * v * v -
                                     6 * W1 * W3 * v * v + W4 * v * v * v * v)};
  BOOST_REQUIRE(r.modified_lagrangian);
  for (int p = 0; p <= 4; ++p) {
    BOOST_TEST(Zero(r.hamiltonian[p] - H[p]), "H at h^" << p);
    // omega = [[0, -f], [f, 0]] in the frame (x, x').
    BOOST_TEST(Zero(r.omega[1][0][p] - f[p]), "f at h^" << p);
    BOOST_TEST(Zero(r.omega[0][1][p] + f[p]), "-f at h^" << p);
    BOOST_TEST(Zero((*r.modified_lagrangian)[p] - L[p]), "L_mod at h^" << p);
  }
}

BOOST_AUTO_TEST_CASE(
    StormerVerlet_AppendixALagrangian_AgreesWithMultistepAEqualsI) {
  // Both discrete Lagrangians differ by a total derivative: same H and omega.
  auto sv = Derive(MakeStormerVerlet(2), AtOrder(4));
  auto lmm = Derive(MakeMultistep({ScalarMatrix(1, 2)}), AtOrder(4));
  // The two results live on different jet spaces: compare after renaming.
  GiNaC::exmap rename;
  for (int i = 0; i < 2; ++i) {
    rename[lmm.x(i)] = sv.x(i);
    rename[lmm.v(i)] = sv.v(i);
  }
  for (int a = 0; a <= 3; ++a)
    for (int b = 0; b <= 3; ++b) {
      std::vector<int> idx(2);
      for (idx[0] = 0; idx[0] <= 6; ++idx[0])
        for (idx[1] = 0; idx[0] + idx[1] <= 6; ++idx[1])
          rename[lmm.jet->U(idx)] = sv.jet->U(idx);
    }
  for (int p = 0; p <= 4; ++p) {
    BOOST_TEST(Zero(lmm.hamiltonian[p].subs(rename) - sv.hamiltonian[p]));
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        BOOST_TEST(Zero(lmm.omega[a][b][p].subs(rename) - sv.omega[a][b][p]));
  }
}

namespace {

// Modified equation, H_2, H_4 and omega_2 of (4.1) with A = alpha I.
void CheckScalarLmm(int d) {
  GiNaC::symbol alpha("alpha");
  const GiNaC::matrix A = ScalarMatrix(alpha, d);
  auto r = Derive(MakeLmm4(A), AtOrder(4));
  Tensors t{*r.jet, d};
  const ex m = 3 * alpha - 4;
  const ex c1 = (15 * alpha * alpha - 30 * alpha + 16) / numeric(240);
  const ex c2 = (45 * alpha * alpha - 75 * alpha + 32) / numeric(720);
  auto g = t.Grad();
  auto v = t.Vel();
  for (int i = 0; i < d; ++i) {
    // x'' = g + h^2/12 M (S g + grad^3 U[v, v]).
    ex rhs = 0;
    for (int j = 0; j < d; ++j) {
      rhs += t.S(i, j) * g[j];
      for (int k = 0; k < d; ++k) rhs += t.U({i, j, k}) * v[j] * v[k];
    }
    BOOST_TEST(Zero(r.f[i][0] - g[i]));
    BOOST_TEST(Zero(r.f[i][2] - m / 12 * rhs), "f_2 component " << i);
  }
  ex gSg = 0, g3 = 0, u4 = 0, Sv2 = 0, vSv = 0, gg = 0;
  for (int i = 0; i < d; ++i) {
    gg += g[i] * g[i];
    ex Svi = 0;
    for (int j = 0; j < d; ++j) {
      gSg += g[i] * t.S(i, j) * g[j];
      vSv += v[i] * t.S(i, j) * v[j];
      Svi += t.S(i, j) * v[j];
      for (int k = 0; k < d; ++k) {
        g3 += t.U({i, j, k}) * g[i] * v[j] * v[k];
        for (int l = 0; l < d; ++l)
          u4 += t.U({i, j, k, l}) * v[i] * v[j] * v[k] * v[l];
      }
    }
    Sv2 += Svi * Svi;
  }
  // H_0 = |v|^2/2 - U.
  BOOST_TEST(Zero(r.hamiltonian[0] -
                  t.Quadratic(ScalarMatrix(numeric(1, 2), d), v, v) +
                  r.jet->Potential()));
  // H_2 = (1/24)[g^T M g - v^T (M S + S M) v].
  BOOST_TEST(Zero(r.hamiltonian[2] - (m * gg - 2 * m * vSv) / 24));
  // H_4 = c1 [g^T S g - 2 grad^3 U[g, v, v] - grad^4 U[v, v, v, v]] - c2
  // |Sv|^2.
  BOOST_TEST(Zero(r.hamiltonian[4] - (c1 * (gSg - 2 * g3 - u4) - c2 * Sv2)));
  // omega_2 = [[0, B], [-B, 0]], B = (1/12)(M S + S M); the x-x block vanishes.
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) {
      const ex B = m * t.S(i, j) / 6;
      BOOST_TEST(Zero(r.omega[i][j][2]), "x-x block " << i << j);
      BOOST_TEST(Zero(r.omega[i][d + j][2] - B), "x-v block " << i << j);
      BOOST_TEST(Zero(r.omega[d + i][j][2] + B), "v-x block " << i << j);
      BOOST_TEST(Zero(r.omega[d + i][d + j][2]), "v-v block " << i << j);
    }
  // A = alpha I: a first-order modified Lagrangian exists (Theorem 2.3).
  BOOST_REQUIRE(r.modified_lagrangian.has_value());
  BOOST_TEST(CheckLagrangianGeneratesF(r, *r.modified_lagrangian).passed);
}

}  // namespace

BOOST_AUTO_TEST_CASE(
    Lmm4ScalarCoefficients_ModifiedEquationH2H4Omega2_MatchSection4InDimension1) {
  CheckScalarLmm(1);
}

BOOST_AUTO_TEST_CASE(
    Lmm4ScalarCoefficients_ModifiedEquationH2H4Omega2_MatchSection4InDimension2) {
  CheckScalarLmm(2);
}

BOOST_AUTO_TEST_CASE(Lmm4SymmetricMatrix_H2AndOmega2IncludingC_MatchSection4) {
  GiNaC::symbol a11("a11"), a12("a12"), a22("a22");
  const GiNaC::matrix A = SymmetricMatrix2(a11, a12, a22);
  auto r = Derive(MakeLmm4(A), AtOrder(4));
  Tensors t{*r.jet, 2};
  const GiNaC::matrix M = M34(A);
  const GiNaC::matrix S = t.Hessian();
  const GiNaC::matrix MS_SM = M.mul(S).add(S.mul(M));
  auto g = t.Grad();
  auto v = t.Vel();
  // H_2 = (1/24)[g^T M g - v^T (M S + S M) v].
  BOOST_TEST(Zero(r.hamiltonian[2] -
                  (t.Quadratic(M, g, g) - t.Quadratic(MS_SM, v, v)) / 24));
  // c = 1/4 v . grad [a12 (U,22 - U,11) + (a11 - a22) U,12].
  const ex phi = a12 * (t.S(1, 1) - t.S(0, 0)) + (a11 - a22) * t.S(0, 1);
  ex c = 0;
  for (int i = 0; i < 2; ++i) c += v[i] * r.jet->Partial(phi, i, 0) / 4;
  // omega_2 = [[c J, B], [-B, 0]], J = [[0, 1], [-1, 0]], B = (MS + SM)/12.
  BOOST_TEST(Zero(r.omega[0][1][2] - c));
  BOOST_TEST(Zero(r.omega[1][0][2] + c));
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      BOOST_TEST(Zero(r.omega[i][2 + j][2] - MS_SM(i, j) / 12));
      BOOST_TEST(Zero(r.omega[2 + i][j][2] + MS_SM(i, j) / 12));
      BOOST_TEST(Zero(r.omega[2 + i][2 + j][2]));
    }
  // Proposition 6.1: the fibres x = const stop being Lagrangian at h^4 (the
  // x'-x' block of omega_4 is nonzero), so there is no first-order L_mod in x.
  BOOST_TEST(!Zero(r.omega[2][3][4]));
  BOOST_TEST(!r.modified_lagrangian.has_value());
}

BOOST_AUTO_TEST_CASE(
    Lmm4ScalarCoefficients_ModifiedAngularMomentum_MatchesSection4) {
  GiNaC::symbol alpha("alpha");
  GiNaC::matrix rotation(2, 2);
  rotation(0, 1) = -1;
  rotation(1, 0) = 1;
  auto r = Derive(MakeLmm4(ScalarMatrix(alpha, 2)),
                  AtOrder(4, PotentialModel::kRadial, rotation));
  BOOST_REQUIRE(r.charge);
  JetSpace& jet = *r.jet;
  const ex x1 = r.x(0), x2 = r.x(1), v1 = r.v(0), v2 = r.v(1);
  const ex ell = x1 * v2 - x2 * v1;
  const ex rr = x1 * x1 + x2 * x2, xv = x1 * v1 + x2 * v2,
           vv = v1 * v1 + v2 * v2;
  const ex c1 = (15 * alpha * alpha - 30 * alpha + 16) / numeric(240);
  const ex c2 = (45 * alpha * alpha - 75 * alpha + 32) / numeric(720);
  const ex V1 = jet.V(1), V2 = jet.V(2), V3 = jet.V(3);
  const ex I2 = ell * (4 - 3 * alpha) * V1 / 6;
  const ex I4 = -ell * (2 * c2 * V1 * V1 + 8 * c1 * (rr * V1 * V2 + vv * V2) +
                        16 * c1 * xv * xv * V3);
  BOOST_TEST(Zero((*r.charge)[0] - ell));
  BOOST_TEST(Zero((*r.charge)[1]));
  BOOST_TEST(Zero((*r.charge)[2] - I2));
  BOOST_TEST(Zero((*r.charge)[3]));
  BOOST_TEST(Zero((*r.charge)[4] - I4));
}
