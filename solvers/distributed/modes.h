// The space-diagonalized window solve (solvers/spacetime/mode_solver.h) with
// space spread over the ranks in slabs of whole planes of the slowest axis
// (docs/distributed.md §2b). Each axis' transform is the one-process one
// (spatial_modes.h); between the axes within a plane and the slowest axis
// the data are transposed once each way (FFTW's MPI transpose, comm.h), so
// that a rank then holds whole modes — every slowest-axis mode of a block of
// the others — and solves their banded time systems without communication.
// A rank factors only the distinct systems of the modes it holds.
//
// Every axis must be periodic (a bounded axis' dense eigenbasis is not
// split here).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/sbp/regularized.h"
#include "core/sbp/space_grid.h"
#include "solvers/distributed/comm.h"
#include "solvers/spacetime/grid_modes.h"
#include "solvers/spacetime/mode_solver.h"

namespace vivp::distributed {

class DistributedModes {
 public:
  // The window of dt's points on the whole grid, m components; this rank's
  // planes are those of Slab (window.h).
  DistributedModes(const Comm& comm, const sbp::RegularizedOperator<double>& dt,
                   const sbp::SpaceGrid<double>& grid, int m);

  // Builds and factors this rank's distinct time systems; false if one is
  // singular (message()). Collective: false on every rank if on one.
  bool Factor(const spacetime::DensityBlocks& blocks);
  // b ← J⁻¹ b for this rank's points, blocks of (W + 2)m values (the field
  // system's layout). Collective.
  void Solve(double* b) const;

  int time_points() const { return nt_; }
  long long factorizations() const { return solver_.factorizations(); }
  std::size_t factor_bytes() const { return solver_.factor_bytes(); }
  const std::string& message() const { return message_; }

 private:
  // Calls fn(first point) for every line along axis a < d − 1 within this
  // rank's planes (local flat index).
  template <class F>
  void Lines(int a, F&& fn) const;

  const Comm& comm_;
  const sbp::SpaceGrid<double>& grid_;
  int nt_, block_, dim_, slow_, rest_, planes_, rest_local_;
  std::shared_ptr<const spacetime::GridModes> modes_;
  spacetime::ModeSolver solver_;
  std::vector<char> needed_;
  std::vector<double> hx_;
  Transpose transpose_;
  mutable std::vector<double> buffer_;
  std::string message_;
};

}  // namespace vivp::distributed
