// The spatial modes of a grid of d axes (core/sbp/space_grid.h): the tensor
// product of each axis' modes (spatial_modes.h). With S = Σ_a D_aᵀ H D_a the
// grid's stiffness and H = ⊗_b Hᵇ its norm, D_aᵀ H D_a = (⊗_{b≠a} Hᵇ) ⊗ Sᵃ,
// and the product basis V = ⊗_b Vᵇ of the axes' bases (Sᵇ Vᵇ = Hᵇ Vᵇ Λᵇ,
// Vᵇᵀ Hᵇ Vᵇ = I) satisfies
//
//   S V = H V (Σ_a Λᵃ),   Vᵀ H V = I,
//
// so mode (q_0, …, q_{d−1}) has the eigenvalue Σ_a sᵃ_{q_a}: one banded time
// system per distinct sum, as in one dimension. The transforms are the
// axes' own, applied along every line of each axis in turn (a real FFT on a
// periodic axis, the dense eigenbasis on an interval).
//
// Points whose values are data (Dirichlet faces) are left out per axis: the
// modes are those of the box of kept points [firstₐ, firstₐ + countₐ) on
// every axis, and a transform touches only lines inside that box.
//
// Data layout as in spatial_modes.h, over the grid's flat point index:
// point j's block of `stride` values at j·stride, a "row" r < rows the
// signal data[r + j·stride]. After Forward, mode q's coefficients are in
// the block of point point_of(q).
#pragma once

#include <span>
#include <vector>

#include "core/sbp/space_grid.h"
#include "solvers/spacetime/spatial_modes.h"

namespace vivp::spacetime {

class GridModes {
 public:
  // The modes of the box [first[a], first[a] + count[a]) of grid's points;
  // a periodic axis keeps every point. Throws std::invalid_argument for a
  // box outside the grid.
  GridModes(const sbp::SpaceGrid<double>& grid, std::span<const int> first,
            std::span<const int> count);
  // Every point kept.
  explicit GridModes(const sbp::SpaceGrid<double>& grid);

  int dim() const { return int(axes_.size()); }
  const SpatialModes& axis(int a) const { return axes_[a]; }
  int count() const { return count_; }
  // Mode q's (q_0, …) with axis 0 fastest, its eigenvalue Σ_a sᵃ_{q_a}, the
  // time system it shares with the modes of equal per-axis systems, and the
  // point whose block holds its coefficients.
  int mode_coordinate(int q, int a) const {
    return (q / mode_strides_[a]) % axes_[a].count();
  }
  double eigenvalue(int q) const;
  int system_of(int q) const;
  int distinct() const { return distinct_; }
  int point_of(int q) const;

  // X ← X V and X ← X Vᵀ over the kept box (see above).
  void Forward(double* data, int stride, int rows) const;
  void Inverse(double* data, int stride, int rows) const;

 private:
  template <class F>
  void Lines(int a, F&& fn) const;

  std::vector<SpatialModes> axes_;
  std::vector<int> grid_strides_, mode_strides_, system_strides_;
  int count_ = 1, distinct_ = 1;
};

}  // namespace vivp::spacetime
