// Error control for a spectral element (lobatto.h) by step doubling: the
// element of length h, then its two halves of h/2 each, started from the
// whole element's polynomial; the halves are kept, and the difference of
// the two hand-offs (over kDivisor, below) is their estimate.
//
// Why not an embedded estimate, as the finite-difference windows have: theirs
// (|M⁻¹λ4|, (Dx)_N + M⁻¹λ3) measure the end node's error, which for an
// element is of order about n in its length, while the state it hands on
// converges with order 2n − 2 (docs/method.md §13), set by elementary
// differentials of order 2n − 1 of the flow that nothing of degree n − 1 on
// one element observes. (ElementEstimate::kEmbedded controls by those
// estimates all the same, for a tolerance on every node rather than on the
// hand-off: march_types.h.) Tried and not kept: the same integrals of ∂L/∂x
// along the element's polynomial by the n-point Gauss rule against the
// Lobatto rule, with the collocation defect carried through the linearized
// flow — 2–30 times below the true local error on the anharmonic
// oscillator, the ratio not tending to 1 as the step shrank.
//
// Why halves and not thirds (four solves per three kept, not three per
// two): their marches took 25–45 % more nodes for end errors 10–100 times
// smaller, and neither the time at equal end error nor the price per node
// against the uniform march fell (docs/performance.md §9, "Step doubling's
// floor").
//
// The halves need no predictor: the whole element's polynomial at their
// nodes is a start within its own error, and the whole element was checked
// against the predictor (check 2, window_checks.h). Halves whose hand-off
// is within the tolerance of the whole element's are on its branch.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/sbp/lobatto.h"
#include "solvers/variational/ivp_types.h"
#include "solvers/variational/march_types.h"
#include "solvers/variational/window_checks.h"

namespace vivp::variational::detail {

template <class WindowT>
class ElementHalves {
 public:
  ElementHalves(WindowT& window, const std::string& op, HandOff hand_off)
      : window_(window), n_(sbp::Table(op).max_points), hand_off_(hand_off) {
    const auto& all = sbp::ElementOperators();
    for (std::size_t k = 0; k < all.size(); ++k)
      if (all[k]->name == op) element_ = int(k);
  }

  // The difference of the whole element's hand-off and the halves' over
  // this is the halves' estimate (Estimate below).
  static constexpr double kDivisor = 16.0;

  WindowAttempt& half(int k) { return half_[k]; }
  // What the march judges after Solve: the half that failed, or the second
  // half, which carries the pair's estimate.
  WindowAttempt& judged() { return half_[0].ok() ? half_[1] : half_[0]; }
  // The round-off level of the last pair's position estimate of component c
  // (the velocity's is the halves' roundoff_v).
  double PositionRoundOff(int c) const { return roundoff_x_[c]; }

  // Solves the halves of `whole` (solved from `start` at t0, its nodes
  // kept); if one fails, that half holds the failure and judged() names it.
  // `nodes`: keep the halves' nodes.
  void Solve(const WindowAttempt& whole, const InitialData& start, double t0,
             bool nodes) {
    const int d = whole.n;
    from_ = start;
    Slot(1);
    for (int k = 0; k < 2; ++k) {
      WindowAttempt& a = half_[k];
      a.Reset(d);
      a.points = n_;
      a.dt = 0.5 * whole.dt;
      Interpolate(k, whole);
      if (!window_.Solve(a, t0 + 0.5 * whole.dt * double(k * (n_ - 1)), from_,
                         px_, pv_, false, nodes)) {
        Slot(0);
        return;
      }
      if (std::string why = CheckFinite(a, window_.order()); !why.empty()) {
        a.failure = WindowFailure::kCheck;
        a.why = std::move(why);
        Slot(0);
        return;
      }
      const bool corrected = hand_off_ == HandOff::kCorrected;
      for (int c = 0; c < d; ++c) {
        from_.x[c] = corrected ? a.end.position[c] : a.x_end[c];
        if (window_.order() == 2)
          from_.v[c] = corrected ? a.end.velocity[c] : a.v_end[c];
      }
    }
    Slot(0);
    Estimate(whole);
  }

 private:
  // The halves on an engine of their own where the window keeps several
  // (point_window.h): the whole element's step and theirs differ by 2,
  // and each keeps its operators and factorization from pair to pair.
  void Slot(int k) {
    if constexpr (requires { window_.set_engine_slot(k); })
      window_.set_engine_slot(k);
  }

  // The whole element's polynomial (positions and their derivatives) at
  // half k's nodes: the start of its Newton iteration.
  void Interpolate(int k, const WindowAttempt& whole) {
    using Rows =
        Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    const int d = whole.n;
    const Eigen::Map<const Rows> e(Interpolation(k).data(), n_, n_);
    px_.resize(std::size_t(n_) * d);
    pv_.resize(std::size_t(n_) * d);
    // Nodes are rows (node-major storage). A lazy product: the hand-written
    // triple loop over std::vector took 9 % of an lgl8 march's instructions;
    // with it the march takes 5 % fewer (callgrind, Kepler e = 0.9 over
    // three orbits at 1e-10 and 1e-12; lgl12 4 %).
    Eigen::Map<Rows>(px_.data(), n_, d).noalias() =
        e.lazyProduct(Eigen::Map<const Rows>(whole.x.data(), n_, d));
    Eigen::Map<Rows>(pv_.data(), n_, d).noalias() =
        e.lazyProduct(Eigen::Map<const Rows>(whole.v.data(), n_, d));
  }

  // Half k's node i lies at k·(n − 1)/2 + offset_i/2 steps of the whole
  // element: the interpolation there, computed once per element for the
  // process (a march's own copy cost 8 % of a march of 1000 nodes).
  const std::vector<double>& Interpolation(int k) const {
    static const auto tables = [] {
      std::vector<std::array<std::vector<double>, 2>> out;
      for (const sbp::Coefficients* t : sbp::ElementOperators()) {
        out.emplace_back();
        for (int h = 0; h < 2; ++h) {
          std::vector<double> at;
          const int n = t->max_points;
          for (int i = 0; i < n; ++i)
            at.push_back(0.5 * double(h * (n - 1)) +
                         0.5 * t->Offset<double>(i));
          out.back()[h] = sbp::ElementInterpolation(t->name, at);
        }
      }
      return out;
    }();
    return tables[element_][k];
  }

  // The halves' error from the difference of the two hand-offs at the
  // element's end: the whole element's local error is C·h^(2n − 1), the
  // halves' 2·C·(h/2)^(2n − 1), so in the asymptotic range the difference
  // is 2^(2n − 2) − 1 times the halves' error (Richardson; 16383 for lgl8).
  // Error control takes elements far from that range (Δt·ω up to half the
  // stability limit, an element spanning up to half a period), and kDivisor
  // is what measured there: the largest true local error of a half over
  // difference/16 was 0.95 (lgl8 on Kepler e = 0.6 at 1e-4), and at most
  // 0.37 from 1e-6 on, over four problems, three elements and tolerances
  // 1e-4 … 1e-10 (bench/window_estimates_bench; docs/error_control.md,
  // "Spectral elements"); with /100 it was up to 5.1. Both halves carry the
  // pair's estimate.
  void Estimate(const WindowAttempt& whole) {
    const int d = whole.n;
    const WindowAttempt& last = half_[1];
    roundoff_x_.resize(std::size_t(d));
    constexpr double eps = std::numeric_limits<double>::epsilon();
    for (int c = 0; c < d; ++c) {
      const double ex = std::abs(whole.end.position[c] - last.end.position[c]);
      const double ev =
          window_.order() == 2
              ? std::abs(whole.end.velocity[c] - last.end.velocity[c])
              : 0.0;
      const double scale = window_.order() == 2
                               ? std::max(std::abs(whole.end.velocity[c]),
                                          std::abs(last.end.velocity[c]))
                               : 0.0;
      const double size = std::max(std::abs(whole.end.position[c]),
                                   std::abs(last.end.position[c]));
      // The differences' round-off, as check 2 allows it.
      roundoff_x_[c] = 64.0 * n_ * eps * size / kDivisor;
      for (WindowAttempt& a : half_) {
        a.est_x[c] = ex / kDivisor;
        a.est_v[c] = ev / kDivisor;
        a.roundoff_v[c] = 64.0 * n_ * eps * scale / kDivisor;
      }
    }
  }

  WindowT& window_;
  int n_;
  HandOff hand_off_;
  int element_ = 0;  // its index in sbp::ElementOperators()
  std::array<WindowAttempt, 2> half_;
  std::vector<double> px_, pv_;
  InitialData from_;
  std::vector<double> roundoff_x_;
};

}  // namespace vivp::variational::detail
