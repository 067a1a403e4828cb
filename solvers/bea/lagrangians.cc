#include "solvers/bea/lagrangians.h"

namespace vivp::bea {
namespace {

GiNaC::numeric Factorial(int n) { return GiNaC::factorial(GiNaC::numeric(n)); }

// scale (x(t + s h) - x(t)) = scale sum_{m >= 1} (s h)^m x^(m) / m!, per
// component.
std::vector<Series> Displacement(JetSpace& jet, const GiNaC::ex& s,
                                 const GiNaC::ex& scale, int order) {
  std::vector<Series> delta;
  for (int i = 0; i < jet.dim(); ++i) {
    Series d(order);
    for (int m = 1; m <= order; ++m)
      d[m] =
          GiNaC::expand(scale * GiNaC::pow(s, m) / Factorial(m) * jet.X(i, m));
    delta.push_back(d);
  }
  return delta;
}

// sum_j (1/2h^2)(x(t+jh) - x(t))^T A_j (x(t+jh) - x(t)), coefficient of h^p:
// 1/2 sum_j sum_{m+n=p+2} j^{p+2}/(m! n!) x^(m)T A_j x^(n).
std::vector<GiNaC::ex> Kinetic(JetSpace& jet,
                               const std::vector<GiNaC::matrix>& A, int order) {
  const int d = jet.dim();
  std::vector<GiNaC::ex> L(order + 1, 0);
  for (int p = 0; p <= order; ++p) {
    GiNaC::ex sum = 0;
    for (std::size_t jj = 0; jj < A.size(); ++jj) {
      const int j = static_cast<int>(jj) + 1;
      for (int m = 1; m <= p + 1; ++m) {
        const int n = p + 2 - m;
        GiNaC::ex q = 0;
        for (int r = 0; r < d; ++r)
          for (int c = 0; c < d; ++c)
            q += jet.X(r, m) * A[jj](r, c) * jet.X(c, n);
        sum += GiNaC::pow(j, p + 2) / (Factorial(m) * Factorial(n)) * q;
      }
    }
    L[p] = GiNaC::expand(sum / 2);
  }
  return L;
}

std::vector<GiNaC::matrix> Identity(int d) {
  GiNaC::matrix a(d, d);
  for (int i = 0; i < d; ++i) a(i, i) = 1;
  return {a};
}

}  // namespace

Series ShiftedPotential(JetSpace& jet, const GiNaC::ex& g,
                        const std::vector<Series>& delta) {
  const int order = delta.at(0).order();
  Series out(order, g);
  Series term(order, g);  // (delta . grad)^n g / n!
  for (int n = 1; n <= order; ++n) {
    Series next(order);
    for (int i = 0; i < jet.dim(); ++i)
      next += delta[i] * Map(term, [&](const GiNaC::ex& e) {
                return jet.Partial(e, i, 0);
              });
    term = next * GiNaC::numeric(1, n);
    out += term;
  }
  return out;
}

std::vector<GiNaC::ex> ExpandLagrangian(JetSpace& jet, const Method& method,
                                        int order) {
  const int d = jet.dim();
  std::vector<GiNaC::ex> L;
  switch (method.kind) {
    case MethodKind::kMultistep:
      L = Kinetic(jet, method.A, order);
      L[0] += jet.Potential();
      break;
    case MethodKind::kStormerVerlet: {
      // (U(x) + U(x(t+h)))/2 with U(x(t+h)) = sum_p h^p/p! D_t^p U.
      L = Kinetic(jet, Identity(d), order);
      GiNaC::ex dtu = jet.Potential();
      L[0] += dtu;
      for (int p = 1; p <= order; ++p) {
        dtu = jet.TotalDerivative(dtu);
        L[p] = GiNaC::expand(L[p] + dtu / (2 * Factorial(p)));
      }
      break;
    }
    case MethodKind::kMidpoint: {
      L = Kinetic(jet, Identity(d), order);
      // The midpoint (x(t) + x(t+h))/2 = x + (x(t+h) - x(t))/2.
      auto delta = Displacement(jet, 1, GiNaC::numeric(1, 2), order);
      Series u = ShiftedPotential(jet, jet.Potential(), delta);
      for (int p = 0; p <= order; ++p) L[p] = GiNaC::expand(L[p] + u[p]);
      break;
    }
  }
  return L;
}

std::vector<Series> ExpandScheme(JetSpace& jet, const Method& method,
                                 int order) {
  const int d = jet.dim();
  const std::vector<GiNaC::matrix> A =
      method.kind == MethodKind::kMultistep ? method.A : Identity(d);
  std::vector<Series> r;
  for (int i = 0; i < d; ++i) {
    // sum_j A_j (x(t+jh) - 2x + x(t-jh)) / h^2
    //   = sum_j sum_{m even >= 2} 2 j^m h^(m-2)/m! A_j x^(m).
    Series s(order);
    for (std::size_t jj = 0; jj < A.size(); ++jj) {
      const int j = static_cast<int>(jj) + 1;
      for (int m = 2; m - 2 <= order; m += 2) {
        GiNaC::ex q = 0;
        for (int c = 0; c < d; ++c) q += A[jj](i, c) * jet.X(c, m);
        s[m - 2] += 2 * GiNaC::pow(j, m) / Factorial(m) * q;
      }
    }
    for (int p = 0; p <= order; ++p) s[p] = GiNaC::expand(s[p]);
    r.push_back(s);
  }
  const GiNaC::ex u = jet.Potential();
  if (method.kind == MethodKind::kMidpoint) {
    // Discrete Euler-Lagrange equation of the midpoint Lagrangian: the force
    // is the mean of grad U at the two neighbouring midpoints.
    auto plus = Displacement(jet, 1, GiNaC::numeric(1, 2), order);
    auto minus = Displacement(jet, -1, GiNaC::numeric(1, 2), order);
    for (int i = 0; i < d; ++i) {
      const GiNaC::ex g = jet.Partial(u, i, 0);
      Series f =
          ShiftedPotential(jet, g, plus) + ShiftedPotential(jet, g, minus);
      r[i] -= f * GiNaC::numeric(1, 2);
    }
  } else {
    for (int i = 0; i < d; ++i) r[i][0] -= jet.Partial(u, i, 0);
  }
  return r;
}

}  // namespace vivp::bea
