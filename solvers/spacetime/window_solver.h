// The linear solvers of a field window for the one Newton
// (solvers/variational/newton.h, its LinearSolver concept):
//
//   SparseLuSolver   the exact sparse Jacobian (assembly.h) and a sparse LU
//                    (sparse_lu.h): the reference;
//   ModesSolver      the space-diagonalized solve (mode_solver.h) with the
//                    density's Hessian blocks — exact for a linear field with
//                    constant coefficients (one factorization per spatial
//                    mode for the whole march), otherwise averaged over the
//                    window's initial slice (then, if that stops
//                    contracting, over the whole window at the current
//                    iterate): a preconditioner whose chord steps Newton
//                    takes on the exact residual.
//                    When those stop contracting twice in one solve, the
//                    window falls back to the sparse LU; every fallback is
//                    counted (FieldSolution::fallbacks), never silent.
//
// Both keep their factorization from window to window of the same size
// (Newton starts a window with chord steps on it).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/action/field_system.h"
#include "solvers/spacetime/assembly.h"
#include "solvers/spacetime/density_blocks.h"
#include "solvers/spacetime/grid_modes.h"
#include "solvers/spacetime/mode_solver.h"
#include "solvers/spacetime/sparse_lu.h"

namespace vivp::spacetime {

// Which linear solver a field window uses.
// kFourier: fourier_solver.h, for linear fields on periodic grids and
// the only one for gauge fields (a Jacobian singular along the gauge).
enum class WindowLinearSolver { kModes, kSparseLu, kFourier };

// By name ("modes", "sparse-lu", "fourier"); anything else is kModes.
inline WindowLinearSolver WindowLinearSolverNamed(std::string_view name) {
  return name == "sparse-lu" ? WindowLinearSolver::kSparseLu
         : name == "fourier" ? WindowLinearSolver::kFourier
                             : WindowLinearSolver::kModes;
}

// The factors a Fourier window solve may hold (2 GiB; a scene over it is
// refused before solving).
inline constexpr double kFourierBytes = 2.0 * (1 << 30);

inline std::string_view WindowLinearSolverName(WindowLinearSolver s) {
  return s == WindowLinearSolver::kModes      ? "modes"
         : s == WindowLinearSolver::kSparseLu ? "sparse-lu"
                                              : "fourier";
}

class SparseLuSolver {
 public:
  explicit SparseLuSolver(SparseSolver kind = SparseSolver::kUmfpack)
      : lu_(kind) {}

  bool valid = false;
  long long factorizations = 0;

  void Invalidate() { valid = false; }
  bool exact() const { return true; }
  std::string message() const { return lu_.message(); }
  template <class System>
  void Prepare(const System& system, const double*) {
    if (valid && jacobian_.matrix().rows() != system.size()) valid = false;
  }
  template <class System>
  void Assemble(const System& system, const double* y) {
    jacobian_.Assemble(system.size(),
                       [&](auto& sink) { system.Jacobian(y, sink); });
  }
  bool Factorize() {
    if (analyzed_pattern_ != jacobian_.patterns()) {
      lu_.Analyze(jacobian_.matrix());
      analyzed_pattern_ = jacobian_.patterns();
    }
    ++factorizations;
    return lu_.Factorize(jacobian_.matrix());
  }
  void Solve(double* b) const {
    const Eigen::Index n = jacobian_.matrix().rows();
    rhs_ = Eigen::Map<const Eigen::VectorXd>(b, n);
    lu_.Solve(rhs_, x_);
    Eigen::Map<Eigen::VectorXd>(b, n) = x_;
  }
  long long nonzeros() const { return jacobian_.matrix().nonZeros(); }

 private:
  PatternedMatrix jacobian_;
  SparseLu lu_;
  int analyzed_pattern_ = 0;
  mutable Eigen::VectorXd rhs_, x_;
};

// What a ModesSolver hands from one window to the next: the blocks of the
// held factorization, whether it is factored, and whether Newton may start
// on it (part of a checkpoint, checkpoint.h).
struct ModesSnapshot {
  DensityBlocks blocks;
  bool factored = false, valid = false;
};

template <class Density>
class ModesSolver {
 public:
  using System = action::FieldSystem<Density>;
  static constexpr int m = Density::kDim;
  // Spectral rounds (factorizations) per solve before the sparse LU.
  static constexpr int kRounds = 2;

  explicit ModesSolver(const Density& density,
                       SparseSolver fallback = SparseSolver::kUmfpack)
      : constant_(HasConstantBlocks(density)), lu_(fallback) {
    if (constant_) {
      const double z[System::K] = {};
      blocks_ = BlocksAt(density, z);
    }
  }

  bool valid = false;
  long long fallbacks = 0;  // windows that needed the sparse LU

  // What the next window's Newton starts from (ModesSnapshot). Restore
  // refactors the same blocks when the next window's modes are built, so a
  // resumed march is bit-identical.
  using Snapshot = ModesSnapshot;
  Snapshot Save() const {
    return {blocks_, factored_, use_lu_ ? factored_ : valid};
  }
  void Restore(const Snapshot& s) {
    blocks_ = s.blocks;
    restored_ = s;
    restore_ = true;
  }

  void Invalidate() {
    valid = false;
    if (use_lu_) lu_.Invalidate();
  }
  bool exact() const { return use_lu_ || constant_; }
  std::string message() const {
    return use_lu_ ? lu_.message() : modes_ ? modes_->message() : "";
  }
  // Per solve: the modes of this window's grid (rebuilt when the window
  // length, step or boundary changes), and the spectral solve again.
  void Prepare(const System& system, const double*) {
    const auto& D = system.time_operator().base();
    const bool dirichlet[2] = {IsDirichlet(system, 0), IsDirichlet(system, 1)};
    if (!modes_ || modes_->time_points() != D.points() || dt_ != D.dt() ||
        dirichlet[0] != dirichlet_[0] || dirichlet[1] != dirichlet_[1]) {
      if (!spatial_ || dirichlet[0] != dirichlet_[0] ||
          dirichlet[1] != dirichlet_[1]) {
        const auto& grid = system.space_grid();
        if (grid.dim() == 1) {
          // Dirichlet ends are not unknowns of the spatial system.
          const int first = dirichlet[0] ? 1 : 0;
          const int count =
              grid.points() - int(dirichlet[0]) - int(dirichlet[1]);
          spatial_ = std::make_shared<const GridModes>(
              grid, std::span<const int>(&first, 1),
              std::span<const int>(&count, 1));
        } else {
          spatial_ = std::make_shared<const GridModes>(grid);
        }
      }
      dirichlet_[0] = dirichlet[0];
      dirichlet_[1] = dirichlet[1];
      dt_ = D.dt();
      if (modes_) retired_ += modes_->factorizations();
      modes_ = std::make_unique<ModeSolver>(
          system.time_operator(), system.space_grid(), m, dirichlet_, spatial_);
      factored_ = false;
      valid = false;
      if (restore_) {
        factored_ = restored_.factored && modes_->Factor(blocks_);
        valid = factored_ && restored_.valid;
        restore_ = false;
      }
    }
    if (use_lu_) {
      // Back to the spectral solve after a window that fell back.
      use_lu_ = false;
      valid = factored_;
    }
    rounds_ = 0;
  }
  void Assemble(const System& system, const double* y) {
    if (++rounds_ > kRounds) {
      if (!use_lu_) ++fallbacks;
      use_lu_ = true;
      lu_.Prepare(system, y);
      lu_.Assemble(system, y);
      return;
    }
    if (constant_) return;
    // The first linearization of a solve at the window's initial slice
    // (Nx Hessians; the iterate's first slice is the initial data), a second
    // one averaged over the whole window at the current iterate.
    system.Fields(y, values_);
    blocks_ =
        MeanBlocks(system, values_, rounds_ == 1 ? 1 : system.time_points());
    factored_ = false;
  }
  bool Factorize() {
    if (use_lu_) return lu_.Factorize();
    if (factored_) return true;
    factored_ = modes_->Factor(blocks_);
    return factored_;
  }
  void Solve(double* b) const {
    if (use_lu_)
      lu_.Solve(b);
    else
      modes_->Solve(b);
  }

  // Time systems factored (one per distinct spatial mode and factorization).
  long long mode_factorizations() const {
    return retired_ + (modes_ ? modes_->factorizations() : 0);
  }
  long long lu_factorizations() const { return lu_.factorizations; }
  std::size_t factor_bytes() const {
    return modes_ ? modes_->factor_bytes() : 0;
  }
  int distinct_systems() const {
    return modes_ ? modes_->distinct_systems() : 0;
  }

 private:
  static bool IsDirichlet(const System& s, int side) {
    return s.boundary(side).kind == action::BoundaryKind::kDirichlet;
  }

  bool constant_;
  DensityBlocks blocks_;
  Snapshot restored_;
  bool restore_ = false;
  std::shared_ptr<const GridModes> spatial_;
  std::unique_ptr<ModeSolver> modes_;
  bool dirichlet_[2] = {false, false};
  double dt_ = 0;
  bool factored_ = false;
  bool use_lu_ = false;
  int rounds_ = 0;
  long long retired_ = 0;
  SparseLuSolver lu_;
  action::FieldValues<double> values_;
};

}  // namespace vivp::spacetime
