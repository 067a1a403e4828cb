#include "solvers/bea/derivation.h"

#include <chrono>
#include <sstream>
#include <stdexcept>

#include "solvers/bea/lagrangians.h"

namespace vivp::bea {
namespace {

double Since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count();
}

// out += h^shift * s (s truncated so that the sum stays at out.order()).
void AddShifted(Series& out, const Series& s, int shift) {
  for (int p = 0; p + shift <= out.order() && p <= s.order(); ++p)
    if (!s[p].is_zero()) out[p + shift] = GiNaC::expand(out[p + shift] + s[p]);
}

// sum_p h^p reduce(c_p): a jet polynomial series reduced to the 1-jet.
Series ReduceSeries(Reduction& red, const std::vector<GiNaC::ex>& c,
                    int order) {
  Series out(order);
  for (int p = 0; p < static_cast<int>(c.size()) && p <= order; ++p)
    if (!c[p].is_zero()) AddShifted(out, red.Substitute(c[p], order - p), p);
  return out;
}

SelfCheck Check(const std::string& name, const std::vector<Series>& residual) {
  SelfCheck c{name, true, -1};
  for (const auto& s : residual)
    for (int p = 0; p <= s.order(); ++p)
      if (!GiNaC::expand(s[p]).is_zero()) {
        c.passed = false;
        if (c.failing_order < 0 || p < c.failing_order) c.failing_order = p;
      }
  return c;
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

BeaResult Derive(const Method& method, const DeriveOptions& options) {
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
  r.lagrangian = ExpandLagrangian(jet, method, N);

  // Momenta and Euler-Lagrange expressions of every L_p.
  std::vector<Ostrogradsky> ostro;
  for (int p = 0; p <= N; ++p) ostro.push_back(Momenta(jet, r.lagrangian[p]));
  for (int p = 0; p <= N; ++p)
    r.euler_lagrange.push_back(ostro[p].euler_lagrange);

  lap("lagrangian and Euler-Lagrange");
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
  lap("modified equation");
  // Everything reduced below: Euler-Lagrange terms, momenta (p_k is O(h^pmin)
  // so q_k = x^(k-1) is needed to order N - pmin), Hamiltonian terms and the
  // Taylor-expanded scheme.
  const auto scheme = ExpandScheme(jet, method, N);
  std::vector<int> kept;
  int n = 1;
  for (const auto& o : ostro) n = std::max(n, static_cast<int>(o.p.size()) - 1);
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
  Reduction red(jet, r.f, kept);
  lap("reduction");

  // Ostrogradsky data on the 1-jet. P[k][i], Q[k][i] for k = 1..n.
  std::vector<std::vector<Series>> P(n + 1, std::vector<Series>(d, Series(N)));
  std::vector<std::vector<Series>> Q(n + 1, std::vector<Series>(d, Series(N)));
  std::vector<GiNaC::ex> H(N + 1, 0);
  for (int p = 0; p <= N; ++p) {
    H[p] = -r.lagrangian[p];
    for (int k = 1; k < static_cast<int>(ostro[p].p.size()); ++k)
      for (int i = 0; i < d; ++i) {
        const GiNaC::ex& pk = ostro[p].p[k][i];
        if (pk.is_zero()) continue;
        H[p] += pk * jet.X(i, k);
        AddShifted(P[k][i], red.Substitute(pk, N - p), p);
      }
    H[p] = GiNaC::expand(H[p]);
  }
  for (int k = 1; k <= n; ++k)
    for (int i = 0; i < d; ++i)
      if (k - 1 <= red.max_k()) Q[k][i] = red.Of(i, k - 1).Truncated(N);
  r.hamiltonian = ReduceSeries(red, H, N);
  lap("momenta and Hamiltonian");

  // omega_ab = sum_k (d_a P_k . d_b Q_k - d_a Q_k . d_b P_k), so that
  // omega (x', x'') = grad H (omega_0 = [[0, -I], [I, 0]]).
  auto partial = [&](const Series& s, int a) {
    return Map(s, [&](const GiNaC::ex& e) {
      return jet.Partial(e, a % d, a < d ? 0 : 1);
    });
  };
  r.omega.assign(2 * d, std::vector<Series>(2 * d, Series(N)));
  std::vector<std::vector<std::vector<Series>>> dP(2 * d), dQ(2 * d);
  for (int a = 0; a < 2 * d; ++a) {
    dP[a].assign(n + 1, std::vector<Series>(d));
    dQ[a].assign(n + 1, std::vector<Series>(d));
    for (int k = 1; k <= n; ++k)
      for (int i = 0; i < d; ++i) {
        dP[a][k][i] = partial(P[k][i], a);
        dQ[a][k][i] = partial(Q[k][i], a);
      }
  }
  for (int a = 0; a < 2 * d; ++a)
    for (int b = a + 1; b < 2 * d; ++b) {
      Series w(N);
      for (int k = 1; k <= n; ++k)
        for (int i = 0; i < d; ++i) {
          if (P[k][i].IsZero()) continue;
          w += dP[a][k][i] * dQ[b][k][i] - dQ[a][k][i] * dP[b][k][i];
        }
      r.omega[a][b] = w;
      r.omega[b][a] = w * GiNaC::ex(-1);
    }

  lap("symplectic form");
  if (options.symmetry) {
    const auto& G = *options.symmetry;
    Series I(N);
    for (int k = 1; k <= n; ++k)
      for (int i = 0; i < d; ++i) {
        Series gq(N);
        for (int c = 0; c < d; ++c)
          if (!G(i, c).is_zero()) gq += Q[k][c] * G(i, c);
        I += P[k][i] * gq;
      }
    r.charge = I;
  }

  // First-order modified Lagrangian (Proposition 6.1): it exists when the
  // fibres x = const are Lagrangian for omega (the x'-x' block vanishes); the
  // fibre homotopy below also needs the x-x block to vanish at x' = 0.
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
  if (lagrangian_fibres) {
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
    r.modified_lagrangian = L;
  }
  r.seconds = Since(start);

  if (options.self_checks) {
    const auto check_start = std::chrono::steady_clock::now();
    r.checks.push_back(CheckOddOrdersVanish(r));
    r.checks.push_back(CheckHamiltonianStructure(r));
    // 3. The Taylor-expanded scheme vanishes along the modified equation.
    {
      std::vector<Series> res;
      for (const auto& s : scheme) {
        std::vector<GiNaC::ex> c(N + 1);
        for (int p = 0; p <= N; ++p) c[p] = s[p];
        res.push_back(ReduceSeries(red, c, N));
      }
      r.checks.push_back(Check(
          "the modified equation equals the Taylor expansion of the scheme",
          res));
    }
    if (r.charge) r.checks.push_back(CheckChargeConserved(r));
    if (r.modified_lagrangian)
      r.checks.push_back(CheckLagrangianGeneratesF(r, *r.modified_lagrangian));
    r.check_seconds = Since(check_start);
    if (options.throw_on_failed_check)
      for (const auto& c : r.checks)
        if (!c.passed)
          throw std::runtime_error("BEA self-check failed for " + method.name +
                                   " at h^" + std::to_string(c.failing_order) +
                                   ": " + c.name);
  }
  return r;
}

// 1. The odd orders of the Euler-Lagrange expansion vanish identically.
SelfCheck CheckOddOrdersVanish(const BeaResult& r) {
  const int N = r.order, d = r.jet->dim();
  std::vector<Series> odd;
  for (int p = 1; p <= N; p += 2) {
    Series s(0);
    for (int i = 0; i < d; ++i) {
      s[0] = r.euler_lagrange[p][i];
      odd.push_back(s);
    }
  }
  auto c = Check("odd orders of the Euler-Lagrange expansion vanish", odd);
  // Check reports order 0 (each residual is one term); the order that fails
  // is the lowest odd p with a nonzero E_p.
  if (!c.passed) {
    c.failing_order = -1;
    for (int p = 1; p <= N && c.failing_order < 0; p += 2)
      for (int i = 0; i < d; ++i)
        if (!GiNaC::expand(r.euler_lagrange[p][i]).is_zero()) {
          c.failing_order = p;
          break;
        }
  }
  return c;
}

// 2. ω (x', f) = ∇H to the truncation order.
SelfCheck CheckHamiltonianStructure(BeaResult& r) {
  JetSpace& jet = *r.jet;
  const int N = r.order, d = jet.dim();
  auto partial = [&](const Series& s, int a) {
    return Map(s, [&](const GiNaC::ex& e) {
      return jet.Partial(e, a % d, a < d ? 0 : 1);
    });
  };
  std::vector<Series> res;
  for (int a = 0; a < 2 * d; ++a) {
    Series s = partial(r.hamiltonian, a) * GiNaC::ex(-1);
    for (int b = 0; b < 2 * d; ++b) {
      if (b == a) continue;
      const Series zdot = b < d ? Series(N, jet.X(b, 1)) : r.f[b - d];
      s += r.omega[a][b] * zdot;
    }
    res.push_back(s);
  }
  return Check(
      "Hamilton's equations with the modified structure reproduce the "
      "modified equation",
      res);
}

// 4. The modified charge is conserved by the modified flow.
SelfCheck CheckChargeConserved(BeaResult& r) {
  if (!r.charge)
    throw std::invalid_argument("CheckChargeConserved: no charge derived");
  Reduction red(*r.jet, r.f, {});
  return Check("the modified charge is conserved by the modified flow",
               {red.Derivative(*r.charge, r.order)});
}

SelfCheck CheckLagrangianGeneratesF(BeaResult& r, const Series& lagrangian) {
  JetSpace& jet = *r.jet;
  const int d = jet.dim();
  const int N = std::min(r.order, lagrangian.order());
  std::vector<Series> f;
  for (const auto& fi : r.f) f.push_back(fi.Truncated(N));
  Reduction red(jet, f, {});
  std::vector<Series> res;
  for (int i = 0; i < d; ++i) {
    const Series px = Map(lagrangian.Truncated(N), [&](const GiNaC::ex& e) {
      return jet.Partial(e, i, 0);
    });
    const Series pv = Map(lagrangian.Truncated(N), [&](const GiNaC::ex& e) {
      return jet.Partial(e, i, 1);
    });
    res.push_back(px - red.Derivative(pv, N));
  }
  return Check("the modified Lagrangian generates the modified equation", res);
}

}  // namespace vivp::bea
