// The space-diagonalized solve of a field window's linear system
// (docs/fields.md §3): one banded time system per spatial mode instead of a
// sparse LU of the whole space-time window.
//
// For a density whose Hessian blocks are constant — L_tt = ∂²L/∂φ_t²,
// L_xx = ∂²L/∂φ_x², L_φφ = ∂²L/∂φ², with no mixed blocks — the window
// Jacobian of core/action/field_system.h, with its initial-data rows scaled
// by Hˣ_j, is the generalized Sylvester operator
//
//   J Y = A Y H_x + B L_xx Y S,                                     (1)
//
// Y the (W + 2)m × Nx matrix of the unknowns (column j: point j's φ(0…W−1),
// λ3, λ4), S = D_xᵀH_xD_x, B = diag(Hᵗ) on the node rows, and A the time
// operator of point mechanics: K_t ⊗ L_tt + Hᵗ ⊗ L_φφ on the node rows
// (K_t = D̄ᵀHᵗD̄), the columns of λ3 and λ4 (e_N, row N of D) and the rows of
// the initial data (e_0ᵀ, row 0 of D). With the spatial modes S V = H_x V Λ,
// VᵀH_xV = I (spatial_modes.h), Z = Y H_x V gives, column by column,
//
//   (A + s_q B ⊗ L_xx) z_q = (J Y · V)_q,   Y = Z Vᵀ:                 (2)
//
// Nx independent banded systems of (W + 2)m unknowns, identical for modes
// of equal s_q, each factored once. (The time factor A⁻¹B is never
// diagonalized: it has Jordan blocks at infinity for every operator.)
//
// In d dimensions Y has one column per grid point, H_x is the grid's norm
// and S = Σ_b D_bᵀ H D_b, whose modes are the products of the axes' modes
// (grid_modes.h) with the eigenvalue Σ_b s_{q_b}; (2) holds as it stands for
// an isotropic density (L_xx the same for every axis).
//
// Dirichlet ends of a one-dimensional field (field_boundary.h) are
// eliminated around (2): the boundary
// column is the data's row of the right-hand side, its coupling S(j, j_b)
// moves to the right-hand side of the other points, and the multipliers μ_i
// follow from the boundary point's own rows afterwards. Neumann data change
// the residual only, not J.
//
// For a density that is not of that form (a potential with curvature that
// varies, or mixed blocks), the same solve with the blocks at a reference
// state is a preconditioner: the field Newton (newton.h) iterates with it
// on the exact residual.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "core/linalg/banded.h"
#include "core/sbp/regularized.h"
#include "core/sbp/space_grid.h"
#include "solvers/spacetime/grid_modes.h"
#include "solvers/variational/banded_lu.h"

namespace vivp::spacetime {

// The Hessian blocks a mode solve is built from, each m × m.
struct DensityBlocks {
  Eigen::MatrixXd ltt, lxx, lpp;
};

class ModeSolver {
 public:
  // The window of dt's points on the grid, m components; a side of a
  // one-dimensional grid with Dirichlet data is eliminated. `modes` must be
  // the grid's over the points that are not Dirichlet data.
  ModeSolver(const sbp::RegularizedOperator<double>& dt,
             const sbp::SpaceGrid<double>& grid, int m, const bool dirichlet[2],
             std::shared_ptr<const GridModes> modes);

  // Builds and factors the time system of every distinct mode (with
  // `needed`, only the systems k with needed[k]: the modes one rank of a
  // distributed solve holds); false if one is singular (its mode in
  // message()).
  bool Factor(const DensityBlocks& blocks,
              const std::vector<char>* needed = nullptr);
  // b ← J⁻¹ b in the field system's layout (Nx blocks of (W + 2)m, then the
  // Dirichlet multipliers).
  void Solve(double* b) const;
  // One mode's block of (2) in the point layout (φ(i, a), λ3, λ4), already
  // transformed: the banded solve of its system alone.
  void SolveMode(int q, double* block) const;

  int size() const;
  int time_points() const { return nt_; }
  int distinct_systems() const { return modes_->distinct(); }
  long long factorizations() const { return factorizations_; }
  // Bytes held by the factors.
  std::size_t factor_bytes() const;
  const std::string& message() const { return message_; }

 private:
  // Position in a point's block: φ(i, a), then λ3(a), λ4(a).
  int Phi(int i, int a) const { return i * m_ + a; }
  int Block() const { return (nt_ + 2) * m_; }
  void EliminatedRhs(double* b) const;
  void Multipliers(double* b) const;

  int nt_, nx_, m_;
  bool dirichlet_[2];
  std::shared_ptr<const GridModes> modes_;
  std::vector<double> ht_;                // Hᵗ_i
  std::vector<double> hx_;                // Hˣ_j
  std::vector<double> d_first_, d_last_;  // rows 0 and N of D, with 1/Δt
  int last_first_ = 0;                    // first column of row N
  struct Entry {
    int i, k;
    double v;
  };
  std::vector<Entry> kt_;     // K_t = D̄ᵀHᵗD̄, summed per (i, k)
  std::vector<int> partner_;  // the mode sharing q's time system, or −1
  DensityBlocks blocks_;
  int kl_ = 0, ku_ = 0;
  std::vector<linalg::BandedMatrix<double>> matrices_;
  // One per matrix, which it refers to (the vector is sized once).
  std::vector<std::unique_ptr<variational::BandedLu<double>>> lu_;
  long long factorizations_ = 0;
  std::string message_;
  mutable std::vector<double> work_, saved_;
};

}  // namespace vivp::spacetime
