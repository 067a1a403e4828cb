// The reduced critical-point equations of the doubled action
// (docs/method.md §5): in x₊ = (x1 + x2)/2, x₋ = x1 − x2 the solution has
// x₋ = λ1 = λ2 = 0 exactly, and what remains are the discrete Euler–Lagrange
// equations ∂S/∂x₋ = 0 at x₋ = 0 (obtained by differentiating S, never
// written by hand) plus the initial-data constraints.
//
// Unknowns y = (x₊ node-major: y[i*d + c], then λ3 (d), then λ4 (d)).
// Rows: initial position (d), initial velocity (d, second order only), then
// ∂S/∂x₋ at every node. λ4 and the velocity row are absent for first-order
// systems (multipliers λ1, λ3 only, docs/method.md §4).
//
//   ∂S/∂x₋_j = H_j ∂f_j/∂x₋ + (D̄ᵀ H ∂f/∂v₋)_j + λ3 δ_{j,N-1} + λ4 D_{N-1,j}
//
// with f the density in ± variables (density.h). The residual is evaluated
// matrix-free (apply D̄, weight with H, apply D̄ᵀ): an assembled DᵀHD has row
// sums that are not exactly zero, a spurious constant force that the Nt³
// conditioning amplifies (docs/method.md §6).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "core/action/density.h"
#include "core/action/gradient_sweep.h"
#include "core/action/local_map.h"
#include "core/action/mass_band.h"
#include "core/action/mass_fill.h"
#include "core/action/system_base.h"
#include "core/linalg/banded.h"
#include "core/sbp/regularized.h"

namespace vivp::action {

template <class P, class Real>
class ReducedSystem : public SystemBase<P, Real> {
  using Base = SystemBase<P, Real>;
  using Base::dbar_, Base::x_init_, Base::v_init_, Base::order_, Base::n_,
      Base::problem_, Base::ForRow;

 public:
  static constexpr int d = P::kDim;
  using Base::Base;
  using typename Base::State;

  int multiplier_blocks() const { return order_ == 2 ? 2 : 1; }
  int size() const { return (n_ + multiplier_blocks()) * d; }
  // New initial data for the same grid (time-slab marching reuses the
  // system, its scratch space and its Jacobian from window to window).
  void SetInitial(const State& x_init, const State& v_init) {
    x_init_ = x_init;
    v_init_ = v_init;
  }

  int X(int node, int c) const { return node * d + c; }
  int Lambda3(int c) const { return n_ * d + c; }
  int Lambda4(int c) const { return n_ * d + d + c; }
  int NodeRow(int node, int c) const {
    return multiplier_blocks() * d + node * d + c;
  }

  // Positions and regularized velocities v = D̄x̄ of the path, per component.
  void Paths(const Real* y, std::vector<Real>* x, std::vector<Real>* v) const {
    this->Path(
        y, [&](int i, int c) { return X(i, c); }, x, v);
  }

  // The density's arguments at node i on the diagonal x₋ = 0: p = (x₊, v₊).
  void NodePoint(const std::vector<Real>* x, const std::vector<Real>* v, int i,
                 Real* p) const {
    for (int c = 0; c < d; ++c) {
      p[c] = x[c][i];
      p[d + c] = v[c][i];
    }
  }

  void Residual(const Real* y, Real* f) const {
    auto& x = scratch_.x;
    auto& v = scratch_.v;
    auto& w = scratch_.w;
    Paths(y, x, v);
    // H·∂f/∂x₋ into the node rows and the momentum-like w = ∂f/∂v₋, one
    // sweep over the nodes (gradient_sweep.h).
    GradientSweep<Real, d> sweep;
    sweep.norm = &dbar_.base();
    sweep.n = n_;
    sweep.rows = f + NodeRow(0, 0);
    for (int c = 0; c < d; ++c) {
      w[c].resize(n_);
      sweep.x[c] = x[c].data();
      sweep.v[c] = v[c].data();
      sweep.w[c] = w[c].data();
    }
    SweepDiagonalGradient<Real>(problem_, sweep);
    FinishResidual(y, f);
  }

  // The residual and the Jacobian at the same y, from one evaluation of the
  // path and of the pointwise derivatives (∂f/∂m, the residual's, comes with
  // ∂²f/∂m∂p): Newton's start on a window it factors afresh.
  template <class Sink>
  void ResidualAndJacobian(const Real* y, Real* f, Sink& sink) const {
    Jacobian(y, sink, 0, n_, f);
    FinishResidual(y, f);
  }

  // The Jacobian written over `band` whatever it held (no zeroing first),
  // and with f the residual at the same y (ResidualAndJacobian): the band
  // starts as K ⊗ M, one sweep over its storage (mass_fill.h), and the node
  // terms are added to it. Zeroing it and adding K ⊗ M after the node terms
  // swept the storage twice (4 % of a uniform SBP84 march of the anharmonic
  // oscillator, perf). An entry with one node term gets the same bits either
  // way (a + b = b + a); one that sums several could differ in its last bit
  // (none does in the five problems of tests/reduced_jacobian_test).
  void OverwriteJacobian(const Real* y, linalg::BandedMatrix<Real>& band,
                         Real* f = nullptr) const {
    Jacobian(y, band, 0, n_, f, true);
    if (f) FinishResidual(y, f);
  }

  // Feeds every Jacobian entry to sink.Add(row, col, value); entries at the
  // same position are summed by the sink.
  template <class Sink>
  void Jacobian(const Real* y, Sink& sink) const {
    Jacobian(y, sink, 0, n_);
  }

  // Only the node terms of nodes [node_begin, node_end) (plus the multiplier
  // and constraint entries): the interior pattern repeats, so the ends and one
  // interior stretch reveal the band without the cost of a full assembly.
  // With `rows` (all nodes), the residual's node terms too, as Residual's
  // sweep writes them, for FinishResidual.
  // `overwrite` (a banded sink only): the sink's contents are replaced, not
  // added to (OverwriteJacobian).
  template <class Sink>
  void Jacobian(const Real* y, Sink& sink, int node_begin, int node_end,
                Real* rows = nullptr, bool overwrite = false) const {
    auto& x = scratch_.x;
    auto& v = scratch_.v;
    Paths(y, x, v);
    auto& w = scratch_.w;
    if (rows)
      for (int c = 0; c < d; ++c) w[c].resize(n_);
    const auto& D = dbar_.base();
    // The pointwise derivatives a block of nodes at a time (density.h).
    auto& points = scratch_.points;
    auto& derivatives = scratch_.derivatives;
    points.resize(2 * d * kBlock);
    derivatives.resize(kBlock);
    // A whole assembly of a constant-mass density takes its vv blocks from
    // K = D̄ᵀHD̄ (mass_band.h), with M the first node's vv block; a node whose
    // vv block differs adds the difference itself. After one assembly with
    // such a node the system stops trying (a varying mass would pay for K
    // on top of every block).
    const bool kron = mass_constant_ && node_begin == 0 && node_end == n_ &&
                      scratch_.mass_band.Prepare(dbar_);
    Block mass = Block::Zero();
    bool same_mass = true;
    // Overwriting: the band starts as K ⊗ M (decided at the first node,
    // whose vv block is M) or as zeros.
    bool mass_added = false;
    if constexpr (std::is_same_v<Sink, linalg::BandedMatrix<Real>>) {
      if (overwrite && !kron) sink.SetZero();
    }
    for (int begin = node_begin; begin < node_end; begin += kBlock) {
      const int end = std::min(node_end, begin + kBlock);
      for (int i = begin; i < end; ++i)
        NodePoint(x, v, i, &points[2 * d * (i - begin)]);
      DiagonalDerivativesAt<Real>(problem_, points.data(), end - begin,
                                  derivatives.data());
      if (declared_mass_) CheckConstantMass(derivatives.data(), begin, end);
      if (kron && begin == 0) {
        mass = derivatives[0].dmp.template bottomRightCorner<d, d>();
        if constexpr (std::is_same_v<Sink, linalg::BandedMatrix<Real>>) {
          if (overwrite) {
            mass_added = (mass.array() != Real(0)).any();
            if (mass_added)
              AddMassBand(mass, sink, true);
            else
              sink.SetZero();
          }
        }
      }
      for (int i = begin; i < end; ++i) {
        const auto& di = derivatives[i - begin];
        same_mass &= AddNodeJacobian(i, di.dmp, kron ? &mass : nullptr, sink);
        if (rows) {
          const Real h = D.NormWeight(i);
          for (int c = 0; c < d; ++c) {
            rows[NodeRow(i, c)] = h * di.dm[c];
            w[c][i] = di.dm[d + c];
          }
        }
      }
    }
    // (A first-order density is linear in v: M = 0 and K adds nothing.)
    if (kron && !mass_added && (mass.array() != Real(0)).any())
      AddMassBand(mass, sink);
    if (kron) mass_constant_ = same_mass;
    for (int c = 0; c < d; ++c) {
      sink.Add(NodeRow(n_ - 1, c), Lambda3(c), Real(1));
      sink.Add(c, X(0, c), Real(1));
      if (order_ == 2) {
        ForRow(n_ - 1, [&](int k, Real dk) {
          sink.Add(NodeRow(k, c), Lambda4(c), dk);
        });
        ForRow(0, [&](int k, Real dk) { sink.Add(d + c, X(k, c), dk); });
      }
    }
  }

 private:
  using Block = Eigen::Matrix<Real, d, d>;

  // The residual after its node terms (H·∂f/∂x₋ in the node rows, w =
  // ∂f/∂v₋ in scratch, the path in scratch): D̄ᵀH w, the multipliers and
  // the initial-data rows.
  void FinishResidual(const Real* y, Real* f) const {
    const auto& x = scratch_.x;
    const auto& w = scratch_.w;
    const auto& D = dbar_.base();
    auto& dw = scratch_.dtw;
    for (int c = 0; c < d; ++c) {
      this->AddDbarTransposeHw(
          w[c], dw, [&](int j) -> Real& { return f[NodeRow(j, c)]; });
      f[NodeRow(n_ - 1, c)] += y[Lambda3(c)];
      f[c] = x[c][0] - x_init_[c];
      if (order_ == 2) {
        // λ4·(last row of D) by hand rather than ForRow: ForRow's
        // λ4·(c·(1/Δt)) rounds differently from (λ4·c)·(1/Δt) and would
        // move last digits of every marched result.
        const auto row = D.row(n_ - 1);
        for (std::size_t k = 0; k < row.coeffs.size(); ++k)
          f[NodeRow(row.first + static_cast<int>(k), c)] +=
              y[Lambda4(c)] * row.coeffs[k] * D.inv_dt();
        f[d + c] = D.ApplyRow(0, x[c].data()) - v_init_[c];
      }
    }
  }

  // Node i's terms: rows (x₋, v₋) of node i, columns (x₊, v₊), both mapped
  // to path values through the same local map (v± = D̄x±, linear part);
  // dmp is the density's mixed block there. With `mass` given, the vv
  // block's part M is left to the caller (K ⊗ M) and the node adds its vv
  // block minus M. When that is zero — true is returned — the block (a, b)
  // is wx_a wx_b A_xx + wx_a wv_b A_xv + wv_a wx_b A_vx, nonzero only where
  // a or b is node i itself (wx = 1 there, 0 elsewhere), and only at (i, i)
  // when A_xv and A_vx vanish too (a separable density): one block instead
  // of (1 + the row's width)².
  template <class Sink>
  bool AddNodeJacobian(int i, const Eigen::Matrix<Real, 2 * d, 2 * d>& dmp,
                       const Block* mass, Sink& sink) const {
    Eigen::Matrix<Real, 2 * d, 2 * d> a = dbar_.base().NormWeight(i) * dmp;
    bool same = false, xv_zero = false, vx_zero = false;
    if (mass) {
      const Block rest = dmp.template bottomRightCorner<d, d>() - *mass;
      same = (rest.array() == Real(0)).all();
      a.template bottomRightCorner<d, d>() = dbar_.base().NormWeight(i) * rest;
      xv_zero = (a.template topRightCorner<d, d>().array() == Real(0)).all();
      vx_zero = (a.template bottomLeftCorner<d, d>().array() == Real(0)).all();
      // A separable density: the one block (i, i) is H_ii A_xx (wx = 1 at
      // node i, 0 elsewhere; the loops below add the same bits), without
      // building and walking the local map: 31 % of the assembly of a
      // uniform SBP84 march of the anharmonic oscillator (callgrind).
      if (same && xv_zero && vx_zero) {
        AddBlock(i, i, Block(a.template topLeftCorner<d, d>()), sink);
        return true;
      }
    }
    const LocalMap<Real> map = MakeLocalMap(dbar_, i);
    for (int ea = 0; ea < map.size; ++ea) {
      const auto& ra = map.entries[ea];
      if (same && ra.wx == Real(0) && vx_zero) continue;  // a zero row
      // Row entry a's weights applied once: (wx_a, wv_a)·A, d × 2d.
      const Eigen::Matrix<Real, d, 2 * d> row =
          ra.wx * a.template topRows<d>() + ra.wv * a.template bottomRows<d>();
      for (int eb = 0; eb < map.size; ++eb) {
        const auto& cb = map.entries[eb];
        if (same && cb.wx == Real(0) && (ra.wx == Real(0) || xv_zero))
          continue;  // a zero block
        AddBlock(ra.node, cb.node,
                 Block(cb.wx * row.template leftCols<d>() +
                       cb.wv * row.template rightCols<d>()),
                 sink);
      }
    }
    return same;
  }

  // K ⊗ M, K = K̃/Δt (mass_band.h): into a banded matrix from MassFill's
  // K̃ ⊗ M scaled by 1/Δt (mass_fill.h; `overwrite`: written over the
  // band), into any other sink block by block through AddBlock.
  template <class Sink>
  void AddMassBand(const Block& mass, Sink& sink,
                   bool overwrite = false) const {
    const Real inv_dt = dbar_.base().inv_dt();
    if constexpr (std::is_same_v<Sink, linalg::BandedMatrix<Real>>) {
      auto& fill = scratch_.mass_fill;
      fill.Prepare(scratch_.mass_band, mass, sink, [&](int a, int b) {
        return sink.template BlockOffset<d>(NodeRow(a, 0), X(b, 0));
      });
      fill.Scaled(inv_dt, sink, overwrite,
                  [&](int a, int b, const Block& block) {
                    AddBlock(a, b, block, sink);
                  });
    } else {
      for (const auto& [a, b, k] : scratch_.mass_band.Entries())
        AddBlock(a, b, Block(inv_dt * k * mass), sink);
    }
  }

  // The block of node row a and node column b.
  template <class Sink>
  void AddBlock(int a, int b, const Block& block, Sink& sink) const {
    // A banded matrix takes the block whole inside its band: entry by
    // entry, each checked, the assembly took a fifth longer (0.28 against
    // 0.23 µs per node, Kepler e = 0.9, SBP84 under error control,
    // bench/march_phases_bench). The band's edges, and any other sink,
    // entry by entry with zeros skipped (the band was probed on the
    // nonzero pattern).
    if constexpr (requires { sink.template AddBlockInBand<d>(0, 0, block); }) {
      if (sink.template AddBlockInBand<d>(NodeRow(a, 0), X(b, 0), block))
        return;
    }
    for (int r = 0; r < d; ++r)
      for (int s = 0; s < d; ++s)
        if (block(r, s) != Real(0))
          sink.Add(NodeRow(a, r), X(b, s), block(r, s));
  }

  // Nodes per call of the pointwise derivatives: one call (a virtual one
  // for a precompiled problem) per block, and a block's points and
  // derivatives stay in cache (whole sweeps at once were 8 % slower at
  // Nt = 2^20 than node by node).
  static constexpr int kBlock = 128;

  // Work arrays reused across evaluations: at Nt = 2^20 fresh allocations
  // cost more in page faults than the stencil work. (Not thread-safe: one
  // system per thread.)
  struct Scratch {
    std::vector<Real> x[d], v[d], w[d], dtw;
    std::vector<Real> points;  // 2d per node
    std::vector<Diagonal<Real, d>> derivatives;
    MassBand<Real> mass_band;
    MassFill<Real, d> mass_fill;  // K̃ ⊗ M in a banded Jacobian's storage
  };
  mutable Scratch scratch_;
  // Whether the last whole assembly found one vv block at every node.
  mutable bool mass_constant_ = true;

  // A Lagrangian that declares kConstantMass (density.h) has ∂²L/∂ẋ² = M and
  // ∂²L/∂x∂ẋ = 0 at every node, M the block of the first node this system
  // evaluated: checked here, where ∇²L is evaluated anyway, so that a wrong
  // declaration fails with its name instead of steering the predictor
  // (euler_lagrange.h, Accelerator).
  const bool declared_mass_ = ConstantMass(problem_);
  mutable bool have_declared_mass_ = false;
  mutable Block declared_mass_block_ = Block::Zero();
  void CheckConstantMass(const Diagonal<Real, d>* derivatives, int begin,
                         int end) const {
    if (!have_declared_mass_) {
      declared_mass_block_ =
          derivatives[0].dmp.template bottomRightCorner<d, d>();
      have_declared_mass_ = true;
    }
    for (int i = begin; i < end; ++i) {
      const auto& h = derivatives[i - begin].dmp;
      if ((h.template bottomRightCorner<d, d>().array() ==
           declared_mass_block_.array())
              .all() &&
          (h.template topRightCorner<d, d>().array() == Real(0)).all() &&
          (h.template bottomLeftCorner<d, d>().array() == Real(0)).all())
        continue;
      throw std::invalid_argument(
          "the Lagrangian declares kConstantMass, but ∂²L/∂ẋ² is not the "
          "same at every node or ∂²L/∂x∂ẋ ≠ 0: it is not ½ẋᵀMẋ + c·ẋ − V(x); "
          "remove kConstantMass");
    }
  }
};

}  // namespace vivp::action
