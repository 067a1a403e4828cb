// The velocity–velocity part of the reduced Jacobian (reduced_system.h) for
// a density whose vv block is one constant matrix M at every node — every
// Lagrangian ½ vᵀMv + (terms linear in v) + (terms in x), which is most of
// mechanics. Node i contributes H_ii (∂v_i/∂x_a)(∂v_i/∂x_b) M to the block
// (a, b) of the node rows; summed over the nodes this is K_ab M with
//
//   K = D̄ᵀ H D̄,
//
// a scalar band that depends on the operator only. The per-node assembly
// then adds only the blocks a node's position reaches (about 2·12 for SBP84
// against 12² through its velocity; one, its own, for a separable density):
// an SBP84 window of 48 points assembled in 7.4 µs instead of 15.7 (Kepler,
// bench/window_algebra_bench).
//
// K = K̃/Δt with K̃ free of Δt (H ∝ Δt, D̄ ∝ 1/Δt, the SAT penalty −σ0/H_00
// too), so a march under error control, whose step changes from window to
// window, computes K̃ once per window length and operator.
#pragma once

#include <cstddef>
#include <vector>

#include "core/action/local_map.h"
#include "core/sbp/regularized.h"

namespace vivp::action {

template <class Real>
class MassBand {
 public:
  // Beyond this many nodes the band is not kept (a global solve of 2^20
  // nodes assembles once per Newton iteration and would hold 17 entries per
  // node): Prepare returns false and the assembly adds every block itself.
  static constexpr int kMaxPoints = 8192;

  // K̃ for `dbar`, computed when its table, points or σ0 changed; false when
  // there are too many points to keep it.
  bool Prepare(const sbp::RegularizedOperator<Real>& dbar) {
    const auto& D = dbar.base();
    const int n = D.points();
    if (n > kMaxPoints) return false;
    if (&D.table() == table_ && n == n_ && dbar.sigma0() == sigma0_)
      return true;
    table_ = &D.table();
    n_ = n;
    sigma0_ = dbar.sigma0();
    // Accumulated in a dense band of half-width 2·kMaxLocal (two map
    // entries of one node are at most that far apart), then compressed.
    constexpr int kHalf = 2 * kMaxLocal;
    constexpr int kWidth = 2 * kHalf + 1;
    std::vector<Real> band(std::size_t(n) * kWidth, Real(0));
    const Real inv_dt = D.inv_dt();
    for (int i = 0; i < n; ++i) {
      const LocalMap<Real> map = MakeLocalMap(dbar, i);
      const Real h = D.NormWeight(i) * inv_dt;  // H_ii / Δt
      for (int ea = 0; ea < map.size; ++ea) {
        const Real wa = map.entries[ea].wv / inv_dt;  // Δt ∂v_i/∂x_a
        if (wa == Real(0)) continue;
        for (int eb = 0; eb < map.size; ++eb) {
          const Real wb = map.entries[eb].wv / inv_dt;
          const int a = map.entries[ea].node, b = map.entries[eb].node;
          band[std::size_t(a) * kWidth + (b - a + kHalf)] += h * wa * wb;
        }
      }
    }
    entries_.clear();
    ++version_;
    for (int a = 0; a < n; ++a)
      for (int k = 0; k < kWidth; ++k)
        if (const Real v = band[std::size_t(a) * kWidth + k]; v != Real(0))
          entries_.push_back({a, a + k - kHalf, v});
    return true;
  }

  // The nonzeros of K̃ of the prepared operator (K = K̃/Δt).
  struct Entry {
    int row, column;
    Real value;
  };
  const std::vector<Entry>& Entries() const { return entries_; }
  // Changes whenever Entries() does: what a caller that indexes the entries
  // keys its cache on.
  long long version() const { return version_; }

 private:
  const void* table_ = nullptr;
  int n_ = -1;
  Real sigma0_ = Real(0);
  std::vector<Entry> entries_;
  long long version_ = 0;
};

}  // namespace vivp::action
