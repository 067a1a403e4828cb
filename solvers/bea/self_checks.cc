// Derive's self-checks (derivation.h): identities the derived modified
// quantities must satisfy to the truncation order.
#include "solvers/bea/self_checks.h"

#include <chrono>
#include <stdexcept>
#include <string>

namespace vivp::bea {
namespace {

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

// 3. The Taylor-expanded scheme vanishes along the modified equation.
SelfCheck CheckSchemeOnModifiedEquation(const std::vector<Series>& scheme,
                                        Reduction& red, int N) {
  std::vector<Series> res;
  for (const auto& s : scheme) {
    std::vector<GiNaC::ex> c(N + 1);
    for (int p = 0; p <= N; ++p) c[p] = s[p];
    res.push_back(ReduceSeries(red, c, N));
  }
  return Check(
      "the modified equation equals the Taylor expansion of the scheme", res);
}

}  // namespace

void RunSelfChecks(BeaResult& r, const std::vector<Series>& scheme,
                   Reduction& red, bool throw_on_failure) {
  const auto check_start = std::chrono::steady_clock::now();
  r.checks.push_back(CheckOddOrdersVanish(r));
  r.checks.push_back(CheckHamiltonianStructure(r));
  r.checks.push_back(CheckSchemeOnModifiedEquation(scheme, red, r.order));
  if (r.charge) r.checks.push_back(CheckChargeConserved(r));
  if (r.modified_lagrangian)
    r.checks.push_back(CheckLagrangianGeneratesF(r, *r.modified_lagrangian));
  r.check_seconds = std::chrono::duration<double>(
                        std::chrono::steady_clock::now() - check_start)
                        .count();
  if (throw_on_failure)
    for (const auto& c : r.checks)
      if (!c.passed)
        throw std::runtime_error("BEA self-check failed for " + r.method.name +
                                 " at h^" + std::to_string(c.failing_order) +
                                 ": " + c.name);
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
