// The window of a field's march with space spread over the ranks
// (docs/distributed.md): the Window of solvers/variational/window_solve.h,
// as solvers/spacetime/field_window.h is for one process, so that the march,
// its hand-off, its a-posteriori checks and its fallbacks are the same code.
//
// Each rank owns a slab of whole planes of the slowest axis, for every node
// of the window, with each point's λ3 and λ4: the unknowns of the field
// system (core/action/field_system.h) at those points, contiguous in its
// layout. Its residual is the one-process residual on the slab widened by g
// planes on either side, g = 2r for a stencil of reach r: ∇φ is right on
// the r planes next to the slab and D_bᵀH of the fluxes on the slab itself
// (one exchange of width 2r per residual, docs/distributed.md §2a). Newton
// is the one Newton (newton.h) with the distributed mode solve (modes.h)
// and its decisions read maxima over the ranks (ReduceMax). The state the
// march hands from window to window, one slice, is gathered on every rank,
// as are the nodes the march keeps.
//
// No independent integration starts and checks the windows here (the
// predictor runs on one process): Newton starts from the Taylor path
// φ₀ + τφ_t0 + ½τ²φ̈₀ and λ3 at its end momentum, and
// FieldSolution::unchecked says so. The resolution limit is checked at
// every window's ends as on one process.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/action/field_system.h"
#include "core/sbp/builder.h"
#include "core/sbp/regularized.h"
#include "solvers/distributed/comm.h"
#include "solvers/distributed/modes.h"
#include "solvers/distributed/slab.h"
#include "solvers/spacetime/density_blocks.h"
#include "solvers/spacetime/end_state.h"
#include "solvers/spacetime/method_of_lines.h"
#include "solvers/spacetime/resolution.h"
#include "solvers/spacetime/window_data.h"
#include "solvers/spacetime/window_parts.h"
#include "solvers/variational/newton.h"
#include "solvers/variational/resolution.h"
#include "solvers/variational/window_checks.h"

namespace vivp::distributed {

// This rank's part of the window's system for the one Newton: y and F at
// the slab's points; the halo is filled before each residual.
template <class Density>
class SlabSystem {
 public:
  using Full = action::FieldSystem<Density>;
  static constexpr int m = Density::kDim;
  SlabSystem(const Comm& comm, const Slab& slab, Full& wide)
      : comm_(comm), slab_(slab), wide_(wide) {}
  int size() const { return slab_.own_points() * wide_.block(); }
  // y on the widened slab: this rank's values, then the halo's.
  const double* Widen(const double* y) const {
    const std::size_t B = wide_.block();
    y_.resize(std::size_t(wide_.size()));
    std::copy(y, y + size(), y_.begin() + slab_.halo_points() * B);
    slab_.ExchangeHalo(comm_, y_.data(), B);
    return y_.data();
  }
  void Residual(const double* y, double* f) const {
    f_.resize(std::size_t(wide_.size()));
    wide_.Residual(Widen(y), f_.data());
    const std::size_t first = slab_.halo_points() * std::size_t(wide_.block());
    std::copy(f_.begin() + first, f_.begin() + first + size(), f);
  }
  void ReduceMax(std::span<double> v) const { comm_.Max(v); }
  const Full& wide() const { return wide_; }
  const Slab& slab() const { return slab_; }
  const Comm& comm() const { return comm_; }

 private:
  const Comm& comm_;
  const Slab& slab_;
  Full& wide_;
  mutable std::vector<double> y_, f_;
};

// The linear solver (newton.h's concept) of a SlabSystem: the distributed
// mode solve with the density's Hessian blocks averaged over the whole grid
// (the sums of the ranks added in rank order), first over the window's
// initial slice, then over the whole window at the iterate; a third round
// fails the window (there is no sparse LU across ranks), and the march
// solves it again afresh or in halves.
template <class Density>
class SlabModesSolver {
 public:
  static constexpr int kRounds = 2;
  explicit SlabModesSolver(const Density& density)
      : constant_(spacetime::HasConstantBlocks(density)) {
    if (constant_) {
      const double z[action::FieldSystem<Density>::K] = {};
      blocks_ = spacetime::BlocksAt(density, z);
    }
  }
  bool valid = false;
  void Invalidate() { valid = false; }
  bool exact() const { return constant_; }
  std::string message() const { return message_; }
  // The modes of the window's operator (rebuilt when it changes).
  void Prepare(const SlabSystem<Density>& s, const double*) {
    const auto& D = s.wide().time_operator().base();
    if (!modes_ || modes_->time_points() != D.points() || dt_ != D.dt()) {
      if (modes_) retired_ += modes_->factorizations();
      modes_ = std::make_unique<DistributedModes>(
          s.comm(), s.wide().time_operator(), s.slab().grid(), Density::kDim);
      dt_ = D.dt();
      factored_ = valid = false;
    }
    rounds_ = 0;
  }
  void Assemble(const SlabSystem<Density>& s, const double* y) {
    if (++rounds_ > kRounds || constant_) return;
    const auto& sys = s.wide();
    sys.Fields(s.Widen(y), values_);
    const auto& D = sys.time_operator().base();
    const int slices = rounds_ == 1 ? 1 : sys.time_points();
    constexpr int K = action::FieldSystem<Density>::K;
    Eigen::Matrix<double, K, K> sum;
    sum.setZero();
    double weight = 0;
    const int first = s.slab().halo_points();
    for (int i = 0; i < slices; ++i)
      for (int j = first; j < first + s.slab().own_points(); ++j) {
        const double w = D.NormWeight(i) * sys.space_grid().NormWeight(j);
        sum += w * sys.PointHessian(values_, i, j);
        weight += w;
      }
    std::vector<double> all(sum.data(), sum.data() + K * K);
    all.push_back(weight);
    s.comm().Sum(all);
    for (int k = 0; k < K * K; ++k) sum.data()[k] = all[k] / all[K * K];
    sum = (0.5 * (sum + sum.transpose())).eval();
    blocks_ = spacetime::detail::BlocksOf<Density::kDim,
                                          action::FieldSystem<Density>::d>(sum);
    factored_ = false;
  }
  bool Factorize() {
    if (rounds_ > kRounds) {
      message_ =
          "the spectral solve stopped contracting twice (there is no "
          "sparse LU across ranks)";
      return false;
    }
    if (factored_) return true;
    factored_ = modes_->Factor(blocks_);
    message_ = modes_->message();
    return factored_;
  }
  void Solve(double* b) const { modes_->Solve(b); }
  long long factorizations() const {
    return retired_ + (modes_ ? modes_->factorizations() : 0);
  }
  std::size_t factor_bytes() const {
    return modes_ ? modes_->factor_bytes() : 0;
  }

 private:
  bool constant_;
  spacetime::DensityBlocks blocks_;
  std::unique_ptr<DistributedModes> modes_;
  double dt_ = 0;
  bool factored_ = false;
  int rounds_ = 0;
  long long retired_ = 0;
  std::string message_;
  action::FieldValues<double> values_;
};

}  // namespace vivp::distributed

#include "solvers/distributed/window_impl.h"
