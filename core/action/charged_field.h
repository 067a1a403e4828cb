// The reduced doubled action of a charged scalar field and its U(1) gauge
// field on a periodic grid of d axes, exactly invariant under discrete gauge
// transformations for every SBP operator in time (docs/gauge.md §7). With
// D_μ = ∂_μ − iA_μ, A_μ → A_μ + ∂_μα, φ → e^{iα}φ:
//
//   ℒ = (1/(2e(t)²)) (Σ_b E_b² − Σ_{b<c} F_bc²) + |D_0φ|² − Σ_b |D_bφ|²
//       − V(|φ|²),     E_b = ∂_tA_b − ∂_bA₀,  F_bc = ∂_bA_c − ∂_cA_b,
//
//   - A_b on the links (j, j + ê_b): (D_bφ)_j = (e^{−ih_bA_b,j} φ_{j+ê_b} −
//     φ_j)/h_b, E_b = D̄A_b − D_b⁺A₀, F_bc = D_b⁺A_c − D_c⁺A_b;
//   - A₀ = Dχ (the temporal Wilson line; D unregularized, χ has no datum):
//     the time difference of φ is transported along D̄'s stencil, (D_0φ)_i =
//     e^{iχ_i} Σ_k D̄_ik e^{−iχ_k} φ_k, with the shift p(φ_0 − φ₀);
//   - the data as for every field (field_system.h), φ's velocity covariant,
//     (D_0φ)(0) = π₀; the end connection λ3·x(N) + λ4·(Dx)(N) on ψ =
//     e^{−iχ}φ and Ã_b = A_b − D_b⁺χ (the fields in the gauge A₀ = 0), gauge
//     invariant term by term.
// Under α at every node, the data moved with it, every term is unchanged.
// Unknowns as field_system.h with m = 3 + d components (Re φ, Im φ, A_0 …
// A_{d−1}, χ); χ has no data and no end connection (λ3 = λ4 = 0). The model
// supplies Potential(s) and its derivatives in s = |φ|², and
// InverseCouplingSquared(t).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/action/charged_terms.h"
#include "core/action/local_terms.h"
#include "core/sbp/regularized.h"
#include "core/sbp/space_grid.h"

namespace vivp::action {

template <class Model, int d>
class ChargedFieldSystem : public ChargedLayout<d> {
 public:
  using Layout = ChargedLayout<d>;
  using Layout::A;
  using Layout::kChi;
  using Layout::kIm;
  using Layout::kRe;
  using Layout::m;
  using Scalar = double;
  static constexpr int kSpaceDim = d;

  // phi0 and pi0 as field_system.h: per point j, (Re φ, Im φ, a_0 …, unused)
  // and (Re π, Im π, ȧ_0 …, unused). Every axis of grid periodic.
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
  int Next(int j, int b) const { return NextOn(grid_, j, b); }
  int Previous(int j, int b) const { return PreviousOn(grid_, j, b); }
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
    CheckFinite("the initial data", phi0);
    CheckFinite("the initial velocities", pi0);
    phi0_ = std::move(phi0);
    pi0_ = std::move(pi0);
    inv_g2_.resize(nt_);
    for (int i = 0; i < nt_; ++i)
      inv_g2_[i] = CheckedInverseCouplingSquared(model_, dt_.base().t(i));
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
  // A₀ = Dχ at node (i, j).
  double A0(const double* y, int i, int j) const {
    return TimeRow(y, i, j, kChi, false);
  }

  // The covariant time difference of φ along row `row` of D (D̄ when
  // regularized) at point j, anchored at node `row`, into q.
  void TimeDifference(const double* y, int row, int j, bool regularized,
                      LocalComplex& q, bool anchored = true) const {
    const auto& D = dt_.base();
    const auto r = D.row(row);
    double c[LocalComplex::kMax];
    const int count = int(r.coeffs.size());
    for (int e = 0; e < count; ++e) c[e] = r.coeffs[e] * D.inv_dt();
    Transport(
        r.first, c, count, anchored ? row : -1, Complex(0),
        [&](int k) { return Phi(k, j, kRe); },
        [&](int k) { return Phi(k, j, kIm); },
        [&](int k) { return Phi(k, j, kChi); },
        [&](int k) { return Complex(y[Phi(k, j, kRe)], y[Phi(k, j, kIm)]); },
        [&](int k) { return y[Phi(k, j, kChi)]; }, q);
    if (regularized && row == 0) {
      // D̄ adds p(ψ_0 − ψ_init) for ψ = e^{−iχ}φ. Its datum is the data
      // transported to the node's own χ_0, ψ_init = e^{−iχ_0}φ₀, so that the
      // shift, e^{iχ_0}p(ψ_0 − ψ_init) = p(φ_0 − φ₀), vanishes with the value
      // row as for every field. (A fixed datum e^{−ic}φ₀, with A₀ = D̄χ on
      // the same c, solved to round-off but left a shift p(1 − e^{i(χ_0 −
      // c)})φ₀ where the solution's χ_0 ≠ c: the energy drifted 1.6 % in
      // t = 1.5 whatever Δt, docs/gauge.md §8.)
      const double p = dt_.penalty();
      const int re = q.Slot(Phi(0, j, kRe)), im = q.Slot(Phi(0, j, kIm));
      q.value += p * (Complex(y[Phi(0, j, kRe)], y[Phi(0, j, kIm)]) -
                      Complex(phi0_[j * m + kRe], phi0_[j * m + kIm]));
      q.d[re] += p;
      q.d[im] += Complex(0, p);
    }
  }

  // The covariant forward difference (D_bφ)_j at node i over (Re φ_j,
  // Im φ_j, Re φ_{j+ê}, Im φ_{j+ê}, A_b).
  void SpaceDifference(const double* y, int i, int j, int b,
                       LocalComplex& q) const {
    const int k = Next(j, b);
    ForwardDifference(h(b), y, Phi(i, j, kRe), Phi(i, j, kIm), Phi(i, k, kRe),
                      Phi(i, k, kIm), Phi(i, j, A(b)), q);
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
      const double c = r.coeffs[e] * D.inv_dt();
      out.index[e] = Phi(r.first + e, j, A(b));
      out.index[count + e] = Phi(r.first + e, k, kChi);
      out.index[2 * count + e] = Phi(r.first + e, j, kChi);
      out.g[e] = c + (i == 0 && e == -r.first ? dt_.penalty() : 0.0);
      out.g[count + e] = -c / hb;
      out.g[2 * count + e] = c / hb;
    }
    out.value = TimeRow(y, i, j, A(b), true) - (A0(y, i, k) - A0(y, i, j)) / hb;
  }

  // F_bc at node (i, j), b < c, as a linear form.
  void Magnetic(const double* y, int i, int j, int b, int c,
                LocalReal& out) const {
    MagneticAt<d>(
        grid_, y, j, b, c, [&](int jj, int a) { return Phi(i, jj, a); }, out);
  }
  // Which terms a residual holds: the matter's (|D_0φ|², |D_bφ|², V and
  // φ's end connection) and the gauge field's (E², F² and A_b's).
  static constexpr unsigned kMatter = 1u, kGauge = 2u, kAllTerms = 3u;

  // The unknowns Newton holds at their start: χ at the nodes 2 … N − 1.
  // Every solution has a gauge-equivalent one with any chosen values there
  // (α_k = chosen − χ_k at those nodes, α_1 from (Dα)(0) = 0, α_0 = 0: the
  // data do not move), so holding them picks the representative and loses
  // no solution; their rows follow from the others by the Noether identity
  // of those directions (the end connection is invariant term by term), and
  // are checked afterwards with all the others (charged_observables.h).
  bool Held(int k) const {
    const int i = (k % block()) / m, a = (k % block()) % m;
    return a == kChi && i >= 2 && i < nt_;
  }

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
    EndConnection<NoSink>(y, f, nullptr, parts);
  }
  template <class Sink>
  void Jacobian(const double* y, Sink& sink) const {
    Accumulate(y, nullptr, &sink);
  }

  // The single path's action Σ Hᵗ Hˣ ℒ at y (without the end connection,
  // whose multipliers are not the data's).
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
    EndConnection(y, f, sink, kAllTerms);
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

  // The end connection Σ_j Hˣ_j [λ3·x(N) + λ4·(Dx)(N)] on ψ and Ã: its
  // derivatives in the node unknowns into f, the columns of the
  // multipliers (and for φ the second derivatives) into the sink. The rows
  // at the multipliers' positions are the data (DataRows), not the
  // derivatives in λ.
  template <class Sink>
  void EndConnection(const double* y, double* f, Sink* sink,
                     unsigned parts) const {
    const auto& D = dt_.base();
    const int last = nt_ - 1;
    const auto r = D.row(last);
    LocalComplex q;
    for (int j = 0; j < nx_; ++j) {
      const double hx = grid_.NormWeight(j);
      // A_b's connection on Ã_b = A_b − D_b⁺χ, the potential in the frame
      // of the Wilson line (the gauge A₀ = 0): λ3·Ã(N) + λ4·(DÃ)(N), with
      // (DÃ)(N) = (DA)(N) − D_b⁺A₀(N) = E_b(N). Gauge invariant term by term.
      for (int b = 0; b < d && (parts & kGauge); ++b) {
        const int k = Next(j, b);
        const double hb = h(b);
        auto link = [&](int l, int node, double c) {  // c·(A_b − D_b⁺χ)(node)
          const int xs[3] = {Phi(node, j, A(b)), Phi(node, k, kChi),
                             Phi(node, j, kChi)};
          const double cs[3] = {c, -c / hb, c / hb};
          for (int e = 0; e < 3; ++e) {
            if (f) f[xs[e]] += hx * cs[e] * y[l];
            if (sink) sink->Add(xs[e], l, hx * cs[e]);
          }
        };
        link(Lambda3(j, A(b)), last, 1.0);
        for (std::size_t e = 0; e < r.coeffs.size(); ++e)
          link(Lambda4(j, A(b)), r.first + int(e), r.coeffs[e] * D.inv_dt());
      }
      if (!(parts & kMatter)) continue;
      // φ's connection in the frame of the Wilson line, on ψ = e^{−iχ}φ:
      // λ3·ψ(N) + λ4·(Dψ)(N), invariant without rotating the multipliers.
      const double one = 1.0;
      for (int which = 0; which < 2; ++which) {
        if (which == 0)
          Transport(
              last, &one, 1, -1, Complex(0),
              [&](int k) { return Phi(k, j, kRe); },
              [&](int k) { return Phi(k, j, kIm); },
              [&](int k) { return Phi(k, j, kChi); },
              [&](int k) {
                return Complex(y[Phi(k, j, kRe)], y[Phi(k, j, kIm)]);
              },
              [&](int k) { return y[Phi(k, j, kChi)]; }, q);
        else
          TimeDifference(y, last, j, false, q, false);
        const int lr = which == 0 ? Lambda3(j, kRe) : Lambda4(j, kRe);
        const int li = which == 0 ? Lambda3(j, kIm) : Lambda4(j, kIm);
        AddProjection(q, lr, li, y, hx, f, sink);
      }
    }
  }

  // V(|φ|²) and its derivatives in (Re φ, Im φ) at positions r, im of y
  // (the caller gives the sign).
  void Potential(const double* y, int i, int j, LocalReal& t) const {
    PotentialAt(model_, y, Phi(i, j, kRe), Phi(i, j, kIm), t);
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
