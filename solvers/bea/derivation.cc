#include "solvers/bea/derivation.h"

#include <chrono>
#include <sstream>
#include <stdexcept>

#include "solvers/bea/lagrangians.h"
#include "solvers/bea/self_checks.h"

namespace vivp::bea {
namespace {

double Since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count();
}

// Ostrogradsky momenta p_k (k = 1..n) of one jet polynomial L, per component,
// and its Euler-Lagrange expression: p_n = dL/dx^(n), p_k = dL/dx^(k) -
// D_t p_{k+1}, E = dL/dx - D_t p_1.
struct Ostrogradsky {
  std::vector<std::vector<GiNaC::ex>> p;  // p[k][i], k = 1..n (p[0] unused)
  std::vector<GiNaC::ex> euler_lagrange;
};

Ostrogradsky Momenta(JetSpace& jet, const GiNaC::ex& L) {
  const int d = jet.dim();
  const int n = std::max(jet.JetOrder(L), 1);
  Ostrogradsky o;
  o.p.assign(n + 2, std::vector<GiNaC::ex>(d, 0));
  for (int k = n; k >= 1; --k)
    for (int i = 0; i < d; ++i)
      o.p[k][i] = GiNaC::expand(jet.Partial(L, i, k) -
                                jet.TotalDerivative(o.p[k + 1][i]));
  o.p.pop_back();
  for (int i = 0; i < d; ++i)
    o.euler_lagrange.push_back(
        GiNaC::expand(jet.Partial(L, i, 0) - jet.TotalDerivative(o.p[1][i])));
  return o;
}

// Rejects what Derive does not handle: an odd order or one below 2, an order
// above MaxOrder(method), a symmetry generator that is not d x d.
void ValidateOptions(const Method& method, const DeriveOptions& options) {
  const int N = options.order;
  const int d = method.dim;
  if (N < 2 || N % 2 != 0)
    throw std::invalid_argument(
        "order must be even and at least 2 (symmetric methods have only even "
        "powers of h), got " +
        std::to_string(N));
  if (N > MaxOrder(method)) {
    std::ostringstream msg;
    const int symbols = CoefficientSymbols(method);
    msg << "order " << N << " in dimension " << d;
    if (symbols > 1) msg << " with " << symbols << " symbolic coefficients";
    msg << " is beyond what the engine reaches in reasonable time (maximum "
        << MaxOrder(method)
        << "; cost grows roughly tenfold per h^2); ask for a lower order";
    if (symbols > 1) msg << " or give numeric coefficients";
    throw std::invalid_argument(msg.str());
  }
  if (options.symmetry &&
      (options.symmetry->rows() != static_cast<unsigned>(d) ||
       options.symmetry->cols() != static_cast<unsigned>(d)))
    throw std::invalid_argument("the symmetry generator must be d x d");
}

// Steps 1 and 2 (derivation.h): the multi-point discrete Lagrangian L_Δ
// (docs/bea.md §2) expanded as L_h = sum_p h^p L_p into r.lagrangian, and
// the Euler-Lagrange expressions E_p into r.euler_lagrange. Returns the
// Ostrogradsky momenta of every L_p as well.
std::vector<Ostrogradsky> LagrangianAndEulerLagrange(BeaResult& r,
                                                     const Method& method) {
  const int N = r.order;
  r.lagrangian = ExpandLagrangian(*r.jet, method, N);

  // Momenta and Euler-Lagrange expressions of every L_p.
  std::vector<Ostrogradsky> ostro;
  for (int p = 0; p <= N; ++p)
    ostro.push_back(Momenta(*r.jet, r.lagrangian[p]));
  for (int p = 0; p <= N; ++p)
    r.euler_lagrange.push_back(ostro[p].euler_lagrange);
  return ostro;
}

// grad U, the h^0 term of the modified equation, once E_0 is checked.
std::vector<GiNaC::ex> LeadingForce(BeaResult& r) {
  JetSpace& jet = *r.jet;
  const int d = jet.dim();
  // E_0 = grad U - x'' is required (L_0 = |x'|^2/2 + U, the consistency of
  // the method); it fixes the leading term of the modified equation.
  std::vector<GiNaC::ex> force(d);
  for (int i = 0; i < d; ++i) {
    force[i] = jet.Partial(jet.Potential(), i, 0);
    if (!GiNaC::expand(r.euler_lagrange[0][i] + jet.X(i, 2) - force[i])
             .is_zero())
      throw std::invalid_argument(
          "the h^0 Lagrangian is not |x'|^2/2 + U: the method is not "
          "consistent (need sum_j j^2 A_j = I)");
  }
  return force;
}

// Step 3 (derivation.h): the modified equation x'' = f(x, x'; h) into r.f,
// grad U + sum_{p>=1} h^p E_p with the higher derivatives in E_p replaced by
// derivatives of f (docs/bea.md §3 gives f to h^2), and the number of
// sweeps into r.sweeps.
void ModifiedEquation(BeaResult& r, const std::vector<GiNaC::ex>& force) {
  JetSpace& jet = *r.jet;
  const int N = r.order, d = jet.dim();
  // Fixed-point sweeps: sweep s is exact to h^(2s), so it is computed with
  // truncation 2s; each one re-derives the reduction x^(k)(x, x').
  r.f.assign(d, Series(N));
  for (int i = 0; i < d; ++i) r.f[i][0] = force[i];
  for (int s = 1; 2 * s <= N; ++s) {
    const int T = 2 * s;
    std::vector<Series> f_t;
    for (const auto& fi : r.f) f_t.push_back(fi.Truncated(T));
    std::vector<int> kept;
    for (int p = 1; p <= T; ++p)
      for (int i = 0; i < d; ++i)
        RequireOrders(jet, r.euler_lagrange[p][i], T - p, kept);
    Reduction red(jet, f_t, kept);
    std::vector<Series> next(d, Series(N));
    for (int i = 0; i < d; ++i) {
      next[i][0] = force[i];
      for (int p = 1; p <= T; ++p)
        if (!r.euler_lagrange[p][i].is_zero())
          AddShifted(next[i], red.Substitute(r.euler_lagrange[p][i], T - p), p);
    }
    r.f = next;
    r.sweeps = s;
  }
}

// The highest Ostrogradsky index n over all L_p (at least 1).
int MomentumCount(const std::vector<Ostrogradsky>& ostro) {
  int n = 1;
  for (const auto& o : ostro) n = std::max(n, static_cast<int>(o.p.size()) - 1);
  return n;
}

// The orders to which the final Reduction must know each x^(k), k >= 2 (see
// RequireOrders), for everything reduced to the 1-jet afterwards.
std::vector<int> RequiredOrders(BeaResult& r,
                                const std::vector<Ostrogradsky>& ostro,
                                const std::vector<Series>& scheme, int n) {
  JetSpace& jet = *r.jet;
  const int N = r.order, d = jet.dim();
  std::vector<int> kept;
  for (int k = 1; k <= n; ++k) {
    int pmin = N + 1;
    for (int p = 0; p <= N; ++p) {
      for (int i = 0; i < d; ++i)
        if (k < static_cast<int>(ostro[p].p.size()) &&
            !ostro[p].p[k][i].is_zero()) {
          RequireOrders(jet, ostro[p].p[k][i], N - p, kept);
          RequireOrders(jet, ostro[p].p[k][i] * jet.X(i, k), N - p, kept);
          pmin = std::min(pmin, p);
        }
    }
    if (pmin <= N) RequireOrders(jet, jet.X(0, k - 1), N - pmin, kept);
  }
  for (int p = 0; p <= N; ++p) {
    RequireOrders(jet, r.lagrangian[p], N - p, kept);
    for (int i = 0; i < d; ++i) {
      RequireOrders(jet, r.euler_lagrange[p][i], N - p, kept);
      RequireOrders(jet, scheme[i][p], N - p, kept);
    }
  }
  return kept;
}

// Ostrogradsky data on the 1-jet. P[k][i], Q[k][i] for k = 1..n.
struct Canonical {
  std::vector<std::vector<Series>> P, Q;
};

// Step 4 (derivation.h): the Ostrogradsky coordinates q_k = x^(k-1) and
// momenta p_k on the 1-jet, and the modified Hamiltonian H = sum_k p_k .
// x^(k) - L into r.hamiltonian (docs/bea.md §3 gives H_2 and H_4).
Canonical MomentaAndHamiltonian(BeaResult& r,
                                const std::vector<Ostrogradsky>& ostro,
                                Reduction& red, int n) {
  JetSpace& jet = *r.jet;
  const int N = r.order, d = jet.dim();
  Canonical c;
  c.P.assign(n + 1, std::vector<Series>(d, Series(N)));
  c.Q.assign(n + 1, std::vector<Series>(d, Series(N)));
  std::vector<GiNaC::ex> H(N + 1, 0);
  for (int p = 0; p <= N; ++p) {
    H[p] = -r.lagrangian[p];
    for (int k = 1; k < static_cast<int>(ostro[p].p.size()); ++k)
      for (int i = 0; i < d; ++i) {
        const GiNaC::ex& pk = ostro[p].p[k][i];
        if (pk.is_zero()) continue;
        H[p] += pk * jet.X(i, k);
        AddShifted(c.P[k][i], red.Substitute(pk, N - p), p);
      }
    H[p] = GiNaC::expand(H[p]);
  }
  for (int k = 1; k <= n; ++k)
    for (int i = 0; i < d; ++i)
      if (k - 1 <= red.max_k()) c.Q[k][i] = red.Of(i, k - 1).Truncated(N);
  r.hamiltonian = ReduceSeries(red, H, N);
  return c;
}

// Step 5 (derivation.h): the modified symplectic form in the frame (x, x'),
// McLachlan & Offen 2023 eq. (3.3) (docs/bea.md §3 gives omega_2).
std::vector<std::vector<Series>> SymplecticForm(JetSpace& jet,
                                                const Canonical& c, int N) {
  const int d = jet.dim(), n = static_cast<int>(c.P.size()) - 1;
  // omega_ab = sum_k (d_a P_k . d_b Q_k - d_a Q_k . d_b P_k), so that
  // omega (x', x'') = grad H (omega_0 = [[0, -I], [I, 0]]).
  auto partial = [&](const Series& s, int a) {
    return Map(s, [&](const GiNaC::ex& e) {
      return jet.Partial(e, a % d, a < d ? 0 : 1);
    });
  };
  std::vector<std::vector<Series>> omega(2 * d,
                                         std::vector<Series>(2 * d, Series(N)));
  std::vector<std::vector<std::vector<Series>>> dP(2 * d), dQ(2 * d);
  for (int a = 0; a < 2 * d; ++a) {
    dP[a].assign(n + 1, std::vector<Series>(d));
    dQ[a].assign(n + 1, std::vector<Series>(d));
    for (int k = 1; k <= n; ++k)
      for (int i = 0; i < d; ++i) {
        dP[a][k][i] = partial(c.P[k][i], a);
        dQ[a][k][i] = partial(c.Q[k][i], a);
      }
  }
  for (int a = 0; a < 2 * d; ++a)
    for (int b = a + 1; b < 2 * d; ++b) {
      Series w(N);
      for (int k = 1; k <= n; ++k)
        for (int i = 0; i < d; ++i) {
          if (c.P[k][i].IsZero()) continue;
          w += dP[a][k][i] * dQ[b][k][i] - dQ[a][k][i] * dP[b][k][i];
        }
      omega[a][b] = w;
      omega[b][a] = w * GiNaC::ex(-1);
    }
  return omega;
}

// Step 6 (derivation.h): the Noether charge sum_k p_k . G q_k of the linear
// symmetry x -> exp(sG) x (docs/bea.md §3 gives I for rotations).
Series NoetherCharge(const GiNaC::matrix& G, const Canonical& c, int N) {
  const int n = static_cast<int>(c.P.size()) - 1;
  const int d = static_cast<int>(G.rows());
  Series I(N);
  for (int k = 1; k <= n; ++k)
    for (int i = 0; i < d; ++i) {
      Series gq(N);
      for (int j = 0; j < d; ++j)
        if (!G(i, j).is_zero()) gq += c.Q[k][j] * G(i, j);
      I += c.P[k][i] * gq;
    }
  return I;
}

// First-order modified Lagrangian (Proposition 6.1): it exists when the
// fibres x = const are Lagrangian for omega (the x'-x' block vanishes); the
// fibre homotopy below also needs the x-x block to vanish at x' = 0.
bool LagrangianFibres(BeaResult& r) {
  JetSpace& jet = *r.jet;
  const int N = r.order, d = jet.dim();
  bool lagrangian_fibres = true;
  GiNaC::exmap at_rest;
  for (int i = 0; i < d; ++i) at_rest[jet.X(i, 1)] = 0;
  for (int a = 0; a < d && lagrangian_fibres; ++a)
    for (int b = a + 1; b < d && lagrangian_fibres; ++b) {
      lagrangian_fibres = r.omega[d + a][d + b].IsZero();
      for (int p = 0; p <= N && lagrangian_fibres; ++p)
        lagrangian_fibres =
            GiNaC::expand(r.omega[a][b][p].subs(at_rest)).is_zero();
    }
  return lagrangian_fibres;
}

// Step 7 (derivation.h), where LagrangianFibres(r) holds: the first-order
// modified Lagrangian in the original variables (docs/bea.md §3), L_mod =
// P . x' - H with the momentum P obtained from omega by the fibre homotopy.
Series FibreHomotopyLagrangian(BeaResult& r) {
  JetSpace& jet = *r.jet;
  const int N = r.order, d = jet.dim();
  Series L = r.hamiltonian * GiNaC::ex(-1);
  for (int i = 0; i < d; ++i) {
    // P_i(x, v) = int_0^1 sum_j omega[v_j][x_i](x, t v) v_j dt: a monomial of
    // v-degree m in omega gains the factor 1/(m + 1).
    Series Pi(N);
    for (int j = 0; j < d; ++j) {
      const Series& w = r.omega[d + j][i];
      for (int p = 0; p <= N; ++p) {
        const GiNaC::ex e = GiNaC::expand(w[p] * jet.X(j, 1));
        GiNaC::ex sum = 0;
        auto term = [&](const GiNaC::ex& t) {
          int deg = 0;
          for (int c = 0; c < d; ++c) deg += t.degree(jet.X(c, 1));
          sum += t / deg;  // deg >= 1: every term carries v_j
        };
        if (GiNaC::is_a<GiNaC::add>(e))
          for (std::size_t q = 0; q < e.nops(); ++q) term(e.op(q));
        else if (!e.is_zero())
          term(e);
        Pi[p] = GiNaC::expand(Pi[p] + sum);
      }
    }
    L += Pi * jet.X(i, 1);
  }
  return L;
}

}  // namespace

// Measured (bench/bea_bench): d = 1 reaches h^10 in 0.3 s; d = 2 costs about
// tenfold per h^2 (general symbolic A: 0.25 s at h^4, 5.6 s at h^6 plus
// 0.7 s of self-checks).
int CoefficientSymbols(const Method& method) {
  GiNaC::exset symbols;
  for (const GiNaC::matrix& a : method.A)
    for (unsigned k = 0; k < a.nops(); ++k)
      for (GiNaC::const_preorder_iterator it = a.op(k).preorder_begin();
           it != a.op(k).preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it)) symbols.insert(*it);
  return static_cast<int>(symbols.size());
}

int MaxOrder(const Method& method) {
  const int dim = method.dim;
  const int base = dim <= 1 ? 10 : dim == 2 ? 8 : 6;
  // Each further free coefficient multiplies the expression swell.
  return CoefficientSymbols(method) > 1 ? base - 2 : base;
}

GiNaC::matrix PlaneRotation() {
  GiNaC::matrix g(2, 2);
  g(0, 1) = -1;
  g(1, 0) = 1;
  return g;
}

// Runs the steps listed in derivation.h in order (r.stage_seconds times them
// up to the symplectic form), then the self-checks.
BeaResult Derive(const Method& method, const DeriveOptions& options) {
  ValidateOptions(method, options);
  const int N = options.order;
  const int d = method.dim;

  const auto start = std::chrono::steady_clock::now();
  BeaResult r;
  r.jet = std::make_shared<JetSpace>(d, options.model);
  JetSpace& jet = *r.jet;
  r.method = method;
  r.order = N;
  auto stage = std::chrono::steady_clock::now();
  auto lap = [&](const std::string& name) {
    r.stage_seconds.emplace_back(name, Since(stage));
    stage = std::chrono::steady_clock::now();
  };
  const auto ostro = LagrangianAndEulerLagrange(r, method);
  lap("lagrangian and Euler-Lagrange");
  ModifiedEquation(r, LeadingForce(r));
  lap("modified equation");
  // Everything reduced below: Euler-Lagrange terms, momenta (p_k is O(h^pmin)
  // so q_k = x^(k-1) is needed to order N - pmin), Hamiltonian terms and the
  // Taylor-expanded scheme.
  const auto scheme = ExpandScheme(jet, method, N);
  const int n = MomentumCount(ostro);
  Reduction red(jet, r.f, RequiredOrders(r, ostro, scheme, n));
  lap("reduction");
  const Canonical pq = MomentaAndHamiltonian(r, ostro, red, n);
  lap("momenta and Hamiltonian");
  r.omega = SymplecticForm(jet, pq, N);
  lap("symplectic form");
  if (options.symmetry) r.charge = NoetherCharge(*options.symmetry, pq, N);
  if (LagrangianFibres(r)) r.modified_lagrangian = FibreHomotopyLagrangian(r);
  r.seconds = Since(start);

  if (options.self_checks)
    RunSelfChecks(r, scheme, red, options.throw_on_failed_check);
  return r;
}

}  // namespace vivp::bea
