// Marching on the uniform grid of grid.points nodes (march.h): a window of
// W points covers W − 1 intervals, the last one takes the remainder (at
// least the operator's minimum); or the given windows
// (MarchOptions::given_windows), node i of window k being node
// first_[k] + i of the march. A spectral element (lobatto.h) marches in
// windows of its own size, whose ends are on the grid and whose inner
// nodes are its Gauss–Lobatto nodes. A window that fails is solved again
// with a fresh Jacobian, then split in halves (down to the operator's
// minimum); with `stabilize`, a window whose Δt·ω exceeds the stability
// limit is solved on a refined grid (and the requested grid's nodes
// returned).
#pragma once

#include <algorithm>
#include <vector>

#include "solvers/variational/march_core.h"

namespace vivp::variational::detail {

template <class WindowT>
class UniformMarch : public MarchCore<WindowT> {
 public:
  using Core = MarchCore<WindowT>;
  using Core::Core;
  using typename Core::Attempt;

  // The uniform grid of grid.points nodes.
  bool Run(InitialData& state) {
    if (!options_.given_windows.empty()) return RunGiven(state);
    Refine(state, false, Step());  // from the initial state, not a fallback
    const long long intervals = grid_.points - 1;
    const long long per_window = options_.window_points - 1;
    long long done = options_.start_node;
    while (done < intervals) {
      long long take = std::min(per_window, intervals - done);
      // Never leave a remainder shorter than the operator allows: absorb it.
      if (intervals - done - take > 0 &&
          intervals - done - take < min_points_ - 1)
        take = intervals - done;
      if (!Window(state, done, take + 1, 0, done + take == intervals))
        return false;
      done += take;
      if (options_.at_boundary && done < intervals)
        options_.at_boundary(done, state);
    }
    return true;
  }

 private:
  using Core::grid_;
  using Core::min_points_;
  using Core::options_;
  using Core::order_;
  using Core::out_;
  using Core::window_;

  // The predictor on a uniform grid: enough to tell a branch of the discrete
  // equations from another (they differ by the size of the solution), to
  // check a window's resolution to 1 %, and to start Newton within a few
  // chord steps of its solution. (Measured, SBP42, 2^18 points: at 1e-6 the
  // predictor took 3.2 steps per window of the damped oscillator and cost
  // 6 % of the throughput; the anharmonic marches did not change.)
  static constexpr Tolerance kPredictorTolerance = {1e-4, 1e-4};

  // The given windows, one after another (march.h has checked them).
  bool RunGiven(InitialData& state) {
    const std::vector<GivenWindow>& w = options_.given_windows;
    first_.assign(1, 0);
    for (const GivenWindow& g : w)
      first_.push_back(first_.back() + g.points - 1);
    Refine(state, false,
           (w[0].t_end - grid_.t_start) / double(w[0].points - 1));
    for (std::size_t k = 0; k < w.size(); ++k) {
      if (first_[k] < options_.start_node) continue;  // resumed after it
      if (!Window(state, first_[k], w[k].points, 0, k + 1 == w.size()))
        return false;
      if (options_.at_boundary && k + 1 < w.size())
        options_.at_boundary(first_[k + 1], state);
    }
    return true;
  }

  // Δt·ω of the requested step at a state, against the limit.
  double StepRatio(const InitialData& state, double dt) const {
    if (order_ != 2) return 0.0;
    return dt * window_.FastestFrequency(state.x.data(), state.v.data()) /
           StabilityLimit(grid_.op);
  }

  // With options.stabilize: refines the solve grid so that Δt·ω/refine is
  // half the stability limit at `state` (measured, stiff spring Δt·ω = 10,
  // SBP42, 159 periods: at 0.9 of the limit the marched path still grew to
  // max|x| = 1.42, at 0.5 it stays at 1.03), and at least doubles it when
  // `at_least_double` (a window came out under-resolved somewhere inside).
  // False when refinement is off or would exceed options.max_refinement.
  bool Refine(const InitialData& state, bool at_least_double, double dt) {
    // A spectral element is a window of its fixed size: not refinable.
    if (!options_.stabilize || sbp::IsElement(grid_.op)) return false;
    int needed = static_cast<int>(std::ceil(StepRatio(state, dt) / 0.5));
    if (at_least_double)
      needed = std::max(needed, std::min(2 * refine_, options_.max_refinement));
    if (needed <= refine_ || needed > options_.max_refinement) return false;
    refine_ = needed;
    out_.refinement = std::max(out_.refinement, refine_);
    return true;
  }

  // Uniform grid: the window of `points` nodes from global node `first`.
  // Emits its nodes except the last (the next window starts there) and
  // updates `state` to the hand-off state.
  bool Window(InitialData& state, long long first, long long points, int depth,
              bool last_of_march) {
    const double t0 = T(first), t1 = T(first + points - 1);
    const double dt = (t1 - t0) / double((points - 1) * refine_);
    // attempt_ is free again once this window is accepted or failed: the
    // fallbacks below solve into it only after their last use of `a`.
    const Attempt& a =
        this->Solve(attempt_, state, t0, int((points - 1) * refine_ + 1), dt,
                    false, kPredictorTolerance, true);
    if (a.ok()) {
      // A spectral element's nodes sit at its Gauss–Lobatto offsets between
      // the window's ends (lobatto.h); a finite-difference window's on the
      // grid.
      const sbp::Coefficients& table = sbp::Table(grid_.op);
      const bool element = table.max_points > 0;
      this->Accept(a, state, t0, refine_, last_of_march ? points : points - 1,
                   depth, 0.0, [&](long long i) {
                     if (!element || i == 0 || i == points - 1)
                       return T(first + i);
                     return t0 + dt * table.Offset<double>(int(i));
                   });
      return true;
    }
    // Δt·ω above the limit: a shorter window has the same Δt, a finer grid
    // does not. Refine (counted as a fallback) or report. Once the requested
    // grid is known to be beyond the stability limit, the march chooses the
    // solve grid, and then one that passes the a-posteriori checks too; a
    // grid within the limit that fails them is the user's, reported.
    const bool refinable =
        a.failure == WindowFailure::kUnderResolved ||
        (refine_ > 1 && (a.failure == WindowFailure::kCoarse ||
                         a.failure == WindowFailure::kCheck));
    if (refinable && Refine(state, true, (t1 - t0) / double(points - 1))) {
      ++out_.fallbacks;
      return Window(state, first, points, depth, last_of_march);
    }
    if (!a.split_helps()) {
      this->FailAt(t0, t1, a);
      return false;
    }
    const long long half = (points + 1) / 2;
    if (depth >= options_.max_split_depth || half < min_points_) {
      this->FailAt(t0, t1, a);
      return false;
    }
    ++out_.fallbacks;
    return Window(state, first, half, depth + 1, false) &&
           Window(state, first + half - 1, points - half + 1, depth + 1,
                  last_of_march);
  }

  // The time of node `index` of the march.
  double T(long long index) const {
    if (!first_.empty()) {  // given windows: window k holds node index
      const std::vector<GivenWindow>& w = options_.given_windows;
      const std::size_t k =
          std::upper_bound(first_.begin(), first_.end(), index) -
          first_.begin() - 1;
      if (k + 1 >= first_.size()) return grid_.t_end;  // the last node
      const double t0 = k == 0 ? grid_.t_start : w[k - 1].t_end;
      const long long i = index - first_[k];
      return i == 0
                 ? t0
                 : t0 + (w[k].t_end - t0) * double(i) / double(w[k].points - 1);
    }
    return index == grid_.points - 1 ? grid_.t_end
                                     : grid_.t_start + Step() * double(index);
  }

  double Step() const {
    return (grid_.t_end - grid_.t_start) / double(grid_.points - 1);
  }

  std::vector<long long> first_;  // given windows: each one's first node
  int refine_ = 1;   // solve grid = requested grid refined this many times
  Attempt attempt_;  // every window's, its storage kept
};

}  // namespace vivp::variational::detail
