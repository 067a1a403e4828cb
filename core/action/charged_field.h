// The reduced doubled action of a charged scalar field coupled to a U(1)
// gauge field on a periodic grid of d axes (docs/gauge.md §7), exactly
// invariant under discrete gauge transformations for every SBP operator in
// time. With D_μ = ∂_μ − iA_μ and A_μ → A_μ + ∂_μα, φ → e^{iα}φ:
//
//   ℒ = (1/(2e(t)²)) (Σ_b E_b² − Σ_{b<c} F_bc²) + |D_0φ|² − Σ_b |D_bφ|²
//       − V(|φ|²),     E_b = ∂_tA_b − ∂_bA₀,  F_bc = ∂_bA_c − ∂_cA_b,
//
// discretized as
//   - A_b on the links (j, j + ê_b), the forward difference D_b⁺ in space:
//     (D_bφ)_j = (e^{−ih_bA_b,j} φ_{j+ê_b} − φ_j)/h_b, E_b = D̄A_b − D_b⁺A₀,
//     F_bc = D_b⁺A_c − D_c⁺A_b;
//   - A₀ = D̄χ at the nodes (the temporal Wilson line): χ is the unknown,
//     and the time derivative of φ is transported along D̄'s stencil,
//     (D_0φ)_i = e^{iχ_i} Σ_k D̄_ik e^{−iχ_k} φ_k, its regularization datum
//     e^{−ic}φ₀ with c the datum of χ;
//   - the doubled action's data and end connection as for every field
//     (field_system.h), the velocity ones covariant: (D_0φ)(0) = π₀ and
//     Re(λ̄4 (D_0φ)(N)) with D's rows unregularized.
// Under α at every node (data moved with it: φ₀ → e^{iα₀}φ₀, π₀ →
// e^{iα₀}π₀, c → c + α₀, a_b → a_b + D_b⁺α₀, ȧ_b → ȧ_b + D_b⁺(Dα)₀, the
// multipliers rotated) every term is unchanged: the transport phases cancel
// e^{iα} node by node whatever the stencil's width, and D̄, D_b⁺ commute.
//
// Unknowns as field_system.h with m = 3 + d components per node, (Re φ,
// Im φ, A_0 … A_{d−1} of the links, χ): φ₊(i, j, a) at j·B + i·m + a, then
// λ3(j, ·) and λ4(j, ·), B = (Nt + 2)m; χ has no data and no end
// connection (its two rows read λ3 = λ4 = 0). The model supplies
// Potential(s), its derivatives in s = |φ|², and InverseCouplingSquared(t).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/action/local_terms.h"
#include "core/sbp/regularized.h"
#include "core/sbp/space_grid.h"

namespace vivp::action {

template <class Model, int d>
class ChargedFieldSystem {
 public:
  static constexpr int m = 3 + d;
  static constexpr int kRe = 0, kIm = 1, kChi = 2 + d;
  static constexpr int A(int b) { return 2 + b; }
  using Scalar = double;

  // phi0 and pi0 as field_system.h: per point j, (Re φ, Im φ, a_0 …, c) and
  // (Re π, Im π, ȧ_0 …, unused). Every axis of grid periodic.
  ChargedFieldSystem(const Model& model,
                     const sbp::RegularizedOperator<double>& dt,
                     sbp::SpaceGrid<double> grid, std::vector<double> phi0,
                     std::vector<double> pi0)
      : model_(model),
        dt_(dt),
        grid_(std::move(grid)),
        nt_(dt.points()),
        nx_(grid_.points()) {
    if (grid_.dim() != d)
      throw std::invalid_argument("a charged field of " + std::to_string(d) +
                                  " spatial dimensions on a grid of " +
                                  std::to_string(grid_.dim()) + " axes");
    for (int b = 0; b < d; ++b)
      if (!grid_.axis(b).periodic())
        throw std::invalid_argument(
            "a charged field needs periodic axes (links wrap around); axis " +
            std::to_string(b) + " is an interval");
    SetInitial(std::move(phi0), std::move(pi0));
  }

  int time_points() const { return nt_; }
  int space_points() const { return nx_; }
  int block() const { return (nt_ + 2) * m; }
  int size() const { return nx_ * block(); }
  int Phi(int i, int j, int a) const { return j * block() + i * m + a; }
  int Lambda3(int j, int a) const { return j * block() + nt_ * m + a; }
  int Lambda4(int j, int a) const { return j * block() + (nt_ + 1) * m + a; }
  // The point one link along axis b (periodic).
  int Next(int j, int b) const {
    const int c = grid_.Coordinate(j, b);
    return c + 1 < grid_.points(b) ? j + grid_.stride(b)
                                   : j - c * grid_.stride(b);
  }
  int Previous(int j, int b) const {
    const int c = grid_.Coordinate(j, b);
    return c > 0 ? j - grid_.stride(b)
                 : j + (grid_.points(b) - 1) * grid_.stride(b);
  }
  double h(int b) const { return grid_.axis(b).dx(); }
  const sbp::RegularizedOperator<double>& time_operator() const { return dt_; }
  const sbp::SpaceGrid<double>& space_grid() const { return grid_; }
  const Model& model() const { return model_; }
  const std::vector<double>& phi0() const { return phi0_; }
  const std::vector<double>& pi0() const { return pi0_; }

  void SetInitial(std::vector<double> phi0, std::vector<double> pi0) {
    const std::size_t n = std::size_t(nx_) * m;
    if (phi0.size() != n || pi0.size() != n)
      throw std::invalid_argument(
          "initial data: expected " + std::to_string(n) +
          " values of the data and of their velocities, got " +
          std::to_string(phi0.size()) + " and " + std::to_string(pi0.size()));
    phi0_ = std::move(phi0);
    pi0_ = std::move(pi0);
    inv_g2_.resize(nt_);
    for (int i = 0; i < nt_; ++i)
      inv_g2_[i] = model_.InverseCouplingSquared(dt_.base().t(i));
  }

  // (D x)_i of component a at point j, or (D̄ x)_i with the component's
  // datum when regularized.
  double TimeRow(const double* y, int i, int j, int a, bool regularized) const {
    const auto& D = dt_.base();
    const auto r = D.row(i);
    double s = 0;
    for (std::size_t e = 0; e < r.coeffs.size(); ++e)
      s += r.coeffs[e] * y[Phi(r.first + int(e), j, a)];
    s *= D.inv_dt();
    if (regularized && i == 0)
      s += dt_.penalty() * (y[Phi(0, j, a)] - phi0_[j * m + a]);
    return s;
  }
  // A₀ = D̄χ at node (i, j).
  double A0(const double* y, int i, int j) const {
    return TimeRow(y, i, j, kChi, true);
  }

  // The covariant time difference of φ along row `row` of D (D̄ when
  // regularized) at point j, anchored at node `row`: its value and
  // derivatives in q.
  void TimeDifference(const double* y, int row, int j, bool regularized,
                      LocalComplex& q) const {
    const auto& D = dt_.base();
    const auto r = D.row(row);
    double c[LocalComplex::kMax];
    const int count = int(r.coeffs.size());
    for (int e = 0; e < count; ++e) c[e] = r.coeffs[e] * D.inv_dt();
    Complex s = 0;
    if (regularized && row == 0) {
      // D̄ adds p(ψ_0 − ψ_init), ψ = e^{−iχ}φ, ψ_init = e^{−ic}φ₀.
      const double p = dt_.penalty();
      c[0 - r.first] += p;
      s = -p * std::polar(1.0, -phi0_[j * m + kChi]) *
          Complex(phi0_[j * m + kRe], phi0_[j * m + kIm]);
    }
    Transport(
        r.first, c, count, row, s, [&](int k) { return Phi(k, j, kRe); },
        [&](int k) { return Phi(k, j, kIm); },
        [&](int k) { return Phi(k, j, kChi); },
        [&](int k) { return Complex(y[Phi(k, j, kRe)], y[Phi(k, j, kIm)]); },
        [&](int k) { return y[Phi(k, j, kChi)]; }, q);
  }

  // The covariant forward difference (D_bφ)_j at node i over (Re φ_j,
  // Im φ_j, Re φ_{j+ê}, Im φ_{j+ê}, A_b).
  void SpaceDifference(const double* y, int i, int j, int b,
                       LocalComplex& q) const {
    const int k = Next(j, b);
    const double hb = h(b), a = y[Phi(i, j, A(b))];
    const Complex I(0, 1), u = std::polar(1.0, -hb * a);
    const Complex next(y[Phi(i, k, kRe)], y[Phi(i, k, kIm)]);
    const Complex here(y[Phi(i, j, kRe)], y[Phi(i, j, kIm)]);
    q.Reset(5);
    const int r0 = q.Slot(Phi(i, j, kRe)), i0 = q.Slot(Phi(i, j, kIm));
    const int r1 = q.Slot(Phi(i, k, kRe)), i1 = q.Slot(Phi(i, k, kIm));
    const int ab = q.Slot(Phi(i, j, A(b)));
    q.value = (u * next - here) / hb;
    q.d[r0] = -1.0 / hb;
    q.d[i0] = -I / hb;
    q.d[r1] = u / hb;
    q.d[i1] = I * u / hb;
    q.d[ab] = -I * u * next;
    q.dd(r1, ab) = q.dd(ab, r1) = -I * u;
    q.dd(i1, ab) = q.dd(ab, i1) = u;
    q.dd(ab, ab) = -hb * u * next;
  }

  // E_b at node (i, j) as a linear form: coefficients over the unknowns in
  // out (value at y), E = D̄A_b − D_b⁺A₀.
  void Electric(const double* y, int i, int j, int b, LocalReal& out) const {
    const auto& D = dt_.base();
    const auto r = D.row(i);
    const int count = int(r.coeffs.size()), k = Next(j, b);
    out.n = 3 * count;
    out.g.setZero(out.n);
    const double hb = h(b);
    for (int e = 0; e < count; ++e) {
      const double c = r.coeffs[e] * D.inv_dt() +
                       (i == 0 && e == -r.first ? dt_.penalty() : 0.0);
      out.index[e] = Phi(r.first + e, j, A(b));
      out.index[count + e] = Phi(r.first + e, k, kChi);
      out.index[2 * count + e] = Phi(r.first + e, j, kChi);
      out.g[e] = c;
      out.g[count + e] = -c / hb;
      out.g[2 * count + e] = c / hb;
    }
    out.value = TimeRow(y, i, j, A(b), true) - (A0(y, i, k) - A0(y, i, j)) / hb;
  }

  // F_bc at node (i, j), b < c, as a linear form.
  void Magnetic(const double* y, int i, int j, int b, int c,
                LocalReal& out) const {
    const int kb = Next(j, b), kc = Next(j, c);
    out.n = 4;
    out.index[0] = Phi(i, kb, A(c));
    out.index[1] = Phi(i, j, A(c));
    out.index[2] = Phi(i, kc, A(b));
    out.index[3] = Phi(i, j, A(b));
    out.g.resize(4);
    out.g << 1 / h(b), -1 / h(b), -1 / h(c), 1 / h(c);
    out.value = 0;
    for (int e = 0; e < 4; ++e) out.value += out.g[e] * y[out.index[e]];
  }

  // Which terms a residual holds: the matter's (|D_0φ|², |D_bφ|², V and
  // φ's end connection) and the gauge field's (E², F² and A_b's).
  static constexpr unsigned kMatter = 1u, kGauge = 2u, kAllTerms = 3u;

  void Residual(const double* y, double* f) const {
    std::fill(f, f + size(), 0.0);
    Accumulate<NoSink>(y, f, nullptr);
  }
  // The node rows of the chosen terms alone (the data rows left 0): the
  // parts that cancel in Gauss's law (charged_observables.h).
  void PartialResidual(const double* y, double* f, unsigned parts) const {
    std::fill(f, f + size(), 0.0);
    Visit(y, [&](const LocalReal& t, double w, unsigned part) {
      if (part & parts) AddTerm<NoSink>(t, w, f, nullptr);
    });
    EndConnection<NoSink>(y, f, nullptr, nullptr, parts);
  }
  template <class Sink>
  void Jacobian(const double* y, Sink& sink) const {
    Accumulate(y, nullptr, &sink);
  }

  // The single path's action Σ Hᵗ Hˣ ℒ at y. (The end connection is
  // invariant only as the doubled action's difference of two paths; the
  // rows, its derivatives, are invariant, or rotate with φ.)
  double Action(const double* y) const {
    double s = 0;
    Visit(y, [&](const LocalReal& t, double w, unsigned) { s += w * t.value; });
    return s;
  }

 private:
  struct NoSink {
    void Add(int, int, double) {}
  };

  template <class Sink>
  void Accumulate(const double* y, double* f, Sink* sink) const {
    Visit(y, [&](const LocalReal& t, double w, unsigned) {
      AddTerm(t, w, f, sink);
    });
    EndConnection(y, f, sink, nullptr, kAllTerms);
    DataRows(y, f, sink);
  }

  // Calls term(t, weight, part) for each real term of the single path's
  // action, part kMatter or kGauge.
  template <class Term>
  void Visit(const double* y, Term&& term) const {
    const auto& D = dt_.base();
    LocalComplex q;
    LocalReal t;
    for (int j = 0; j < nx_; ++j) {
      const double hx = grid_.NormWeight(j);
      for (int i = 0; i < nt_; ++i) {
        const double w = D.NormWeight(i) * hx;
        TimeDifference(y, i, j, true, q);  // |D_0φ|²
        SquaredNorm(q, t);
        term(t, w, kMatter);
        for (int b = 0; b < d; ++b) {  // −|D_bφ|²
          SpaceDifference(y, i, j, b, q);
          SquaredNorm(q, t);
          term(t, -w, kMatter);
        }
        Potential(y, i, j, t);
        term(t, -w, kMatter);
        for (int b = 0; b < d; ++b) {  // E_b²/(2e²)
          Electric(y, i, j, b, t);
          Square(t);
          term(t, 0.5 * w * inv_g2_[i], kGauge);
          for (int c = b + 1; c < d; ++c) {  // −F_bc²/(2e²)
            Magnetic(y, i, j, b, c, t);
            Square(t);
            term(t, -0.5 * w * inv_g2_[i], kGauge);
          }
        }
      }
    }
  }

  // The end connection Σ_j Hˣ_j [λ3·x(N) + λ4·(Dx)(N)], covariant for φ:
  // its derivatives in the node unknowns into f, the columns of the
  // multipliers (and for φ the second derivatives) into the sink; value
  // (if not null) gets the term itself. The rows at the multipliers'
  // positions are the data (DataRows), not the derivatives in λ.
  template <class Sink>
  void EndConnection(const double* y, double* f, Sink* sink, double* value,
                     unsigned parts) const {
    const auto& D = dt_.base();
    const int last = nt_ - 1;
    const auto r = D.row(last);
    LocalComplex q;
    for (int j = 0; j < nx_; ++j) {
      const double hx = grid_.NormWeight(j);
      for (int a = 0; a < kChi; ++a) {
        if (!(parts & (a < A(0) ? kMatter : kGauge))) continue;
        const int x = Phi(last, j, a), l = Lambda3(j, a);
        if (f) f[x] += hx * y[l];
        if (sink) sink->Add(x, l, hx);
        if (value) *value += hx * y[l] * y[x];
      }
      for (int b = 0; b < d && (parts & kGauge); ++b) {
        const int l = Lambda4(j, A(b));
        for (std::size_t e = 0; e < r.coeffs.size(); ++e) {
          const int x = Phi(r.first + int(e), j, A(b));
          const double c = hx * r.coeffs[e] * D.inv_dt();
          if (f) f[x] += c * y[l];
          if (sink) sink->Add(x, l, c);
          if (value) *value += c * y[l] * y[x];
        }
      }
      if (!(parts & kMatter)) continue;
      TimeDifference(y, last, j, false, q);
      const int lr = Lambda4(j, kRe), li = Lambda4(j, kIm);
      AddProjection(q, lr, li, y, hx, f, sink);
      if (value)
        *value += hx * (std::conj(Complex(y[lr], y[li])) * q.value).real();
    }
  }

  // −V(|φ|²) enters with the caller's sign; here V and its derivatives.
  void Potential(const double* y, int i, int j, LocalReal& t) const {
    const int r = Phi(i, j, kRe), im = Phi(i, j, kIm);
    const double x[2] = {y[r], y[im]}, s = x[0] * x[0] + x[1] * x[1];
    const double v1 = model_.PotentialSlope(s),
                 v2 = model_.PotentialCurvature(s);
    t.n = 2;
    t.index[0] = r;
    t.index[1] = im;
    t.value = model_.Potential(s);
    t.g.resize(2);
    t.h.resize(2, 2);
    for (int a = 0; a < 2; ++a) {
      t.g[a] = 2 * x[a] * v1;
      for (int b = 0; b < 2; ++b)
        t.h(a, b) = 2 * v1 * (a == b) + 4 * x[a] * x[b] * v2;
    }
  }

  // A linear form ℓ (t.g its coefficients, t.value its value) → ℓ².
  static void Square(LocalReal& t) {
    t.h = 2.0 * t.g * t.g.transpose();
    t.g *= 2.0 * t.value;
    t.value *= t.value;
  }

  // The rows at the multipliers' positions: the initial data, covariant for
  // the velocity of φ; λ3 = λ4 = 0 for χ.
  template <class Sink>
  void DataRows(const double* y, double* f, Sink* sink) const {
    const auto& D = dt_.base();
    const auto first = D.row(0);
    LocalComplex q;
    for (int j = 0; j < nx_; ++j) {
      for (int a = 0; a < kChi; ++a) {
        const int row = Lambda3(j, a);
        if (f) f[row] = y[Phi(0, j, a)] - phi0_[j * m + a];
        if (sink) sink->Add(row, Phi(0, j, a), 1.0);
      }
      for (int b = 0; b < d; ++b) {
        const int row = Lambda4(j, A(b));
        if (f) f[row] = TimeRow(y, 0, j, A(b), false) - pi0_[j * m + A(b)];
        if (sink)
          for (std::size_t e = 0; e < first.coeffs.size(); ++e)
            sink->Add(row, Phi(first.first + int(e), j, A(b)),
                      first.coeffs[e] * D.inv_dt());
      }
      TimeDifference(y, 0, j, false, q);
      const int rr = Lambda4(j, kRe), ri = Lambda4(j, kIm);
      if (f) {
        f[rr] = q.value.real() - pi0_[j * m + kRe];
        f[ri] = q.value.imag() - pi0_[j * m + kIm];
      }
      if (sink)
        for (int a = 0; a < q.n; ++a) {
          sink->Add(rr, q.index[a], q.d[a].real());
          sink->Add(ri, q.index[a], q.d[a].imag());
        }
      if (f) {
        f[Lambda3(j, kChi)] = y[Lambda3(j, kChi)];
        f[Lambda4(j, kChi)] = y[Lambda4(j, kChi)];
      }
      if (sink) {
        sink->Add(Lambda3(j, kChi), Lambda3(j, kChi), 1.0);
        sink->Add(Lambda4(j, kChi), Lambda4(j, kChi), 1.0);
      }
    }
  }

  const Model& model_;
  const sbp::RegularizedOperator<double>& dt_;
  sbp::SpaceGrid<double> grid_;
  int nt_, nx_;
  std::vector<double> phi0_, pi0_, inv_g2_;
};

}  // namespace vivp::action
