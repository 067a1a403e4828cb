// The Lobatto element tables (lobatto.h), computed in long double and rounded
// to dyadic rationals of denominator 2^58: the coefficients of lgl16 reach
// 8 per unit step, which keeps every numerator below 2^62, and 2^−58 is far
// below double's rounding of them.
#include "core/sbp/lobatto.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

namespace vivp::sbp {

namespace {

constexpr std::int64_t kDenominator = std::int64_t(1) << 58;

Rational Dyadic(long double v) {
  return {static_cast<std::int64_t>(std::llround(v * kDenominator)),
          kDenominator};
}

// P_N(x) and P_{N−1}(x) by the three-term recurrence.
void Legendre(int N, long double x, long double& p, long double& p_prev) {
  long double a = 1.0L, b = x;
  for (int k = 2; k <= N; ++k) {
    const long double c = ((2 * k - 1) * x * b - (k - 1) * a) / k;
    a = b;
    b = c;
  }
  p = N == 0 ? 1.0L : b;
  p_prev = a;
}

// The n Gauss–Lobatto points of [−1, 1] and P_{n−1} at them.
void LobattoPoints(int n, std::vector<long double>& xi,
                   std::vector<long double>& p) {
  const int N = n - 1;
  xi.assign(n, 0.0L);
  p.assign(n, 0.0L);
  // The interior nodes are the roots of P'_N: Newton from the Chebyshev–
  // Gauss–Lobatto points, with (1 − x²)P'_N = N(P_{N−1} − xP_N) and
  // (1 − x²)P''_N = 2xP'_N − N(N + 1)P_N.
  for (int i = 0; i < n; ++i) {
    long double x = -std::cos(std::numbers::pi_v<long double> * i / N);
    if (i > 0 && i < N)
      for (int it = 0; it < 100; ++it) {
        long double pn, pm;
        Legendre(N, x, pn, pm);
        const long double d1 = N * (pm - x * pn) / (1 - x * x);
        const long double d2 = (2 * x * d1 - N * (N + 1) * pn) / (1 - x * x);
        const long double step = d1 / d2;
        x -= step;
        if (std::fabs(step) < 1e-30L) break;
      }
    xi[i] = x;
    long double pm;
    Legendre(N, x, p[i], pm);
  }
}

Coefficients Element(const char* name, int n) {
  const int N = n - 1;
  std::vector<long double> xi, p;
  LobattoPoints(n, xi, p);
  // Per unit step dt = (t_end − t_start)/N: the reference interval [−1, 1]
  // has N/2 steps, so D scales by 2/N and the weights 2/(N(N + 1)P_N²) by
  // N/2.
  Coefficients c{
      .name = name,
      .citation =
          "Gauss–Lobatto collocation; Gassner (2013), SIAM J. Sci. "
          "Comput. 35, A1233",
      .interior_order = N,
      .boundary_order = N,
      .min_points = n,
  };
  for (int i = 0; i < n / 2; ++i) {
    const long double w = 2.0L / (N * (N + 1) * p[i] * p[i]);
    c.norm_weights.push_back(Dyadic(w * N / 2));
    std::vector<Rational> row(n);
    for (int j = 0; j < n; ++j) {
      long double d = 0;
      if (i != j)
        d = p[i] / (p[j] * (xi[i] - xi[j]));
      else if (i == 0)
        d = -N * (N + 1) / 4.0L;
      row[j] = Dyadic(d * 2 / N);
    }
    c.boundary_block.push_back(std::move(row));
  }
  c.interior_stencil = {{0, 1}};
  c.max_points = n;
  for (int i = 0; i < n; ++i)
    c.node_offsets.push_back(Dyadic((xi[i] + 1) * N / 2));
  return c;
}

}  // namespace

std::vector<double> ElementInterpolation(std::string_view name,
                                         const std::vector<double>& at) {
  const Coefficients* element = nullptr;
  for (const Coefficients* c : ElementOperators())
    if (c->name == name) element = c;
  if (!element)
    throw std::invalid_argument("no interpolation for '" + std::string(name) +
                                "': it is not a spectral element (" +
                                ElementOperatorNameList() + ")");
  const int n = element->max_points, N = n - 1;
  std::vector<long double> xi, p;
  LobattoPoints(n, xi, p);
  std::vector<double> out;
  out.reserve(at.size() * std::size_t(n));
  for (double offset : at) {
    // The offset in the reference interval [−1, 1], which holds N/2 steps.
    const long double y = 2.0L * offset / N - 1;
    for (int i = 0; i < n; ++i) {
      long double l = 1;
      for (int k = 0; k < n; ++k)
        if (k != i) l *= (y - xi[k]) / (xi[i] - xi[k]);
      out.push_back(double(l));
    }
  }
  return out;
}

const std::vector<const Coefficients*>& ElementOperators() {
  // The measured rows (coefficients.h, Measured): the stability limit is the
  // largest Δt·ω, Δt the mean step, at which windows of the harmonic
  // oscillator marched over 400 steps stay bounded (max|x| < 1.5;
  // tests/sbp_lobatto_test). The estimate's order, which the step
  // controller assumes, is that of an element's difference from its halves
  // (solvers/variational/element_halves.h): 2n − 1 in theory, but error
  // control keeps elements long (up to half a period), where the slope of
  // the difference against the step, from one state at pericentre of
  // Kepler e = 0.9 and on the anharmonic oscillator, measured 9–15 for all
  // three between sign changes of the error; 10, the lower end. A larger
  // q, nearer the slope between a rejected pair and its retry (median
  // 19–21), saved rejections at moderate tolerances but stalled marches
  // where the estimate is at round-off (docs/performance.md §9). Not
  // measured for elements: Levenberg–Marquardt windows and fields.
  static const std::vector<Coefficients> tables = [] {
    std::vector<Coefficients> t{Element("lgl8", 8), Element("lgl12", 12),
                                Element("lgl16", 16)};
    const double limits[] = {1.20, 1.40, 1.50};
    for (std::size_t k = 0; k < t.size(); ++k)
      t[k].measured = {.stability_limit = limits[k],
                       .position_estimate = false,
                       .estimate_order = 10.0,
                       .lm_window_points = 0,
                       .field_values_at_once = 0};
    return t;
  }();
  static const std::vector<const Coefficients*> all = [] {
    std::vector<const Coefficients*> out;
    for (const Coefficients& c : tables) out.push_back(&c);
    return out;
  }();
  return all;
}

std::string ElementOperatorNameList() {
  std::string out;
  for (const Coefficients* c : ElementOperators())
    out += (out.empty() ? "" : ", ") + std::string(c->name);
  return out;
}

}  // namespace vivp::sbp
