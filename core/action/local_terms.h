// Second-order calculus of the small nonlinear pieces of a lattice gauge
// action (charged_field.h): a complex quantity q of a few real unknowns —
// a covariant difference, a parallel transport along a stencil — with its
// first and second derivatives, and the real terms built from it (|q|²,
// Re(λ̄ q)) added into a residual and a Jacobian with a weight. Every piece
// touches a handful of unknowns, so the derivatives are exact and local;
// nothing here differentiates over a window's unknowns.
#pragma once

#include <Eigen/Core>
#include <cassert>
#include <complex>

namespace vivp::action {

using Complex = std::complex<double>;

// A complex q(u) of n ≤ kMax real unknowns u_a at global positions
// index[a], with dq/du_a and d²q/du_a du_b.
struct LocalComplex {
  static constexpr int kMax = 40;
  int n = 0;
  int index[kMax];
  Complex value;
  Eigen::Matrix<Complex, Eigen::Dynamic, 1, 0, kMax, 1> d;
  Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic, 0, kMax, kMax> dd;

  // Position of global unknown g among the local ones, added if new.
  int Slot(int g) {
    for (int a = 0; a < n; ++a)
      if (index[a] == g) return a;
    assert(n < kMax);
    index[n] = g;
    return n++;
  }
  void Reset(int capacity) {
    n = 0;
    value = 0;
    d.setZero(capacity);
    dd.setZero(capacity, capacity);
  }
};

// A real term's gradient and Hessian over its local unknowns.
struct LocalReal {
  static constexpr int kMax = LocalComplex::kMax;
  int n = 0;
  int index[kMax];
  double value = 0;
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMax, 1> g;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMax, kMax> h;
};

// |q|²: gradient 2Re(q̄ q_a), Hessian 2Re(q̄_a q_b) + 2Re(q̄ q_ab).
inline void SquaredNorm(const LocalComplex& q, LocalReal& out) {
  out.n = q.n;
  for (int a = 0; a < q.n; ++a) out.index[a] = q.index[a];
  out.value = std::norm(q.value);
  out.g.resize(q.n);
  out.h.resize(q.n, q.n);
  const auto dq = q.d.head(q.n);
  out.g = 2.0 * (std::conj(q.value) * dq).real();
  out.h = 2.0 * (dq.conjugate() * dq.transpose()).real() +
          2.0 * (std::conj(q.value) * q.dd.topLeftCorner(q.n, q.n)).real();
}

// Adds weight·(gradient, Hessian) of a term into f (if not null) and the
// Jacobian sink (if not null): f[index[a]] += w g_a, J(index[a], index[b])
// += w h_ab. The sink receives every pair, zero or not, so that its
// pattern does not depend on the values.
template <class Sink>
void AddTerm(const LocalReal& t, double weight, double* f, Sink* sink) {
  if (f)
    for (int a = 0; a < t.n; ++a) f[t.index[a]] += weight * t.g[a];
  if (sink)
    for (int a = 0; a < t.n; ++a)
      for (int b = 0; b < t.n; ++b)
        sink->Add(t.index[a], t.index[b], weight * t.h(a, b));
}

// The term Re(λ̄ q) = λ_r Re q + λ_i Im q with λ = (y[lr], y[li]) unknowns
// too (an end connection of the doubled action): into f the derivatives in
// q's unknowns, into the sink those and the columns of λ.
template <class Sink>
void AddProjection(const LocalComplex& q, int lr, int li, const double* y,
                   double weight, double* f, Sink* sink) {
  const Complex lambda(y[lr], y[li]);
  for (int a = 0; a < q.n; ++a) {
    if (f) f[q.index[a]] += weight * (std::conj(lambda) * q.d[a]).real();
    if (!sink) continue;
    for (int b = 0; b < q.n; ++b)
      sink->Add(q.index[a], q.index[b],
                weight * (std::conj(lambda) * q.dd(a, b)).real());
    sink->Add(q.index[a], lr, weight * q.d[a].real());
    sink->Add(q.index[a], li, weight * q.d[a].imag());
  }
}

// A transported combination along a row of a time stencil,
//
//   w = e^{iχ_A} (Σ_k c_k e^{−iχ_k} φ_k + s),
//
// over the unknowns (Re φ_k, Im φ_k, χ_k) of the nodes k and the anchor's
// χ_A (anchor < 0: no anchor, w = Σ): the covariant difference of a charged
// field with A₀ = Dχ (the temporal Wilson line, docs/gauge.md §7). re(k),
// im(k), chi(k) give the global positions, value(k) φ_k and chi_value(k) χ_k.
template <class Re, class Im, class Chi, class Value, class ChiValue>
void Transport(int first, const double* c, int count, int anchor, Complex s,
               Re re, Im im, Chi chi, Value value, ChiValue chi_value,
               LocalComplex& q) {
  q.Reset(3 * count + 1);
  Complex sum = s;
  const Complex I(0, 1);
  for (int e = 0; e < count; ++e) {
    const int k = first + e;
    const Complex rot = std::polar(1.0, -chi_value(k));
    const Complex u = rot * value(k);
    sum += c[e] * u;
    const int ar = q.Slot(re(k)), ai = q.Slot(im(k)), ac = q.Slot(chi(k));
    q.d[ar] += c[e] * rot;
    q.d[ai] += I * c[e] * rot;
    q.d[ac] += -I * c[e] * u;
    q.dd(ar, ac) += -I * c[e] * rot;
    q.dd(ac, ar) += -I * c[e] * rot;
    q.dd(ai, ac) += c[e] * rot;
    q.dd(ac, ai) += c[e] * rot;
    q.dd(ac, ac) += -c[e] * u;
  }
  if (anchor < 0) {  // no anchor: w = Σ
    q.value = sum;
    return;
  }
  // The anchor's phase: w = e^{iχ_A} Σ, so ∂_a w = e^{iχ_A}(∂_a Σ + i δ_aA Σ)
  // and ∂_a∂_b w = e^{iχ_A}(∂_a∂_b Σ + i δ_aA ∂_b Σ + i δ_bA ∂_a Σ
  // − δ_aA δ_bA Σ).
  const int an = q.Slot(chi(anchor));
  const Complex phase = std::polar(1.0, chi_value(anchor));
  const int n = q.n;
  const auto dsum = q.d.head(n).eval();
  for (int a = 0; a < n; ++a) {
    q.dd(a, an) += I * dsum[a];
    q.dd(an, a) += I * dsum[a];
  }
  q.dd(an, an) += -sum;
  q.d[an] += I * sum;
  q.value = phase * sum;
  q.d.head(n) *= phase;
  q.dd.topLeftCorner(n, n) *= phase;
}

}  // namespace vivp::action
