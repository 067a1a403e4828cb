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

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

#include "core/action/local_map.h"
#include "core/sbp/builder.h"
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
    ++version_;
    // A window's K̃, computed by an earlier system of this thread (every
    // march builds its systems anew, one per window length). Only for the
    // library's operators, whose tables live as long as the program, so
    // that an address names one table; and only at the same step to the
    // bit: K̃ is computed through H and D̄ at the step, which leaves their
    // rounding in it, and one computed at another step made a march's
    // result depend, at round-off, on the marches run before it.
    const bool shared = n <= kMaxRecentPoints && Registered(table_);
    const Real inv_dt = D.inv_dt();
    auto& recent = Recent();
    if (shared)
      for (const Computed& c : recent)
        if (c.table == table_ && c.n == n && c.sigma0 == sigma0_ &&
            c.inv_dt == inv_dt) {
          entries_ = c.entries;
          return true;
        }
    // Accumulated in a dense band of half-width 2·kMaxLocal (two map
    // entries of one node are at most that far apart), then compressed.
    constexpr int kHalf = 2 * kMaxLocal;
    constexpr int kWidth = 2 * kHalf + 1;
    std::vector<Real> band(std::size_t(n) * kWidth, Real(0));
    std::vector<int> first(n, kWidth), last(n, -1);
    // Each weight Δt ∂v_i/∂x_a divided once per node, not once per pair
    // (the same bits; with the compression below reading only the columns a
    // node reached, 74 k → 55 k instructions for a window of 48 points under
    // SBP84, a fixed cost of every march, callgrind).
    Real w[kMaxLocal];
    for (int i = 0; i < n; ++i) {
      const LocalMap<Real> map = MakeLocalMap(dbar, i);
      const Real h = D.NormWeight(i) * inv_dt;  // H_ii / Δt
      int lo = n, hi = -1;
      for (int e = 0; e < map.size; ++e) {
        w[e] = map.entries[e].wv / inv_dt;
        lo = std::min(lo, map.entries[e].node);
        hi = std::max(hi, map.entries[e].node);
      }
      for (int ea = 0; ea < map.size; ++ea) {
        const Real wa = w[ea];  // Δt ∂v_i/∂x_a
        if (wa == Real(0)) continue;
        const Real hwa = h * wa;
        const int a = map.entries[ea].node;
        Real* row = &band[std::size_t(a) * kWidth + kHalf - a];
        for (int eb = 0; eb < map.size; ++eb)
          row[map.entries[eb].node] += hwa * w[eb];
        // The columns reached, so that the compression below reads only
        // those.
        first[a] = std::min(first[a], lo - a + kHalf);
        last[a] = std::max(last[a], hi - a + kHalf);
      }
    }
    auto entries = std::make_shared<std::vector<Entry>>();
    for (int a = 0; a < n; ++a)
      for (int k = first[a]; k <= last[a]; ++k)
        if (const Real v = band[std::size_t(a) * kWidth + k]; v != Real(0))
          entries->push_back({a, a + k - kHalf, v});
    entries_ = std::move(entries);
    if (shared) {
      if (recent.size() == kRecent) recent.erase(recent.begin());
      recent.push_back({table_, n, sigma0_, inv_dt, entries_});
    }
    return true;
  }

  // The nonzeros of K̃ of the prepared operator (K = K̃/Δt).
  struct Entry {
    int row, column;
    Real value;
  };
  const std::vector<Entry>& Entries() const { return *entries_; }
  // Changes whenever Entries() does: what a caller that indexes the entries
  // keys its cache on.
  long long version() const { return version_; }

 private:
  const void* table_ = nullptr;
  int n_ = -1;
  Real sigma0_ = Real(0);
  std::shared_ptr<const std::vector<Entry>> entries_ =
      std::make_shared<const std::vector<Entry>>();
  long long version_ = 0;

  // The last few K̃ of windows (up to kMaxRecentPoints nodes) this thread
  // computed: a march of the anharmonic oscillator in 25 windows built two
  // systems (its window and its last, longer one) and computed K̃ for each,
  // 2 % of its time (perf).
  static constexpr std::size_t kRecent = 8;
  static constexpr int kMaxRecentPoints = 512;
  struct Computed {
    const void* table;
    int n;
    Real sigma0, inv_dt;
    std::shared_ptr<const std::vector<Entry>> entries;
  };
  static bool Registered(const void* table) {
    for (const sbp::Coefficients* c : sbp::Operators())
      if (c == table) return true;
    return false;
  }
  static std::vector<Computed>& Recent() {
    thread_local std::vector<Computed> recent;
    return recent;
  }
};

}  // namespace vivp::action
