// One rank's slab of a periodic grid (docs/distributed.md §1): whole planes
// of the slowest axis, contiguous in the grid's flat point index, and the
// same slab widened by a halo of g planes on either side, g twice the reach
// of that axis' stencil, on which the one-process field system runs
// unchanged (window.h).
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/sbp/space_grid.h"
#include "solvers/distributed/comm.h"

namespace vivp::distributed {

class Slab {
 public:
  // Throws std::invalid_argument, naming the fix, for a grid this many ranks
  // cannot share.
  Slab(const Comm& comm, const sbp::SpaceGrid<double>& grid)
      : grid_(grid), wide_(Widened(comm, grid)) {}

  const sbp::SpaceGrid<double>& grid() const { return grid_; }
  const sbp::SpaceGrid<double>& wide() const { return wide_; }
  int planes() const { return planes_; }
  int halo_planes() const { return halo_; }
  int plane_points() const { return plane_; }
  int own_points() const { return planes_ * plane_; }
  int halo_points() const { return halo_ * plane_; }
  // The grid's flat index of this rank's first point.
  int first_point() const { return first_plane_ * plane_; }

  // The widened slab's values of a whole-grid slice (value j·m + a).
  std::vector<double> Widen(std::span<const double> slice, int m) const {
    const int n = grid_.points(grid_.dim() - 1);
    std::vector<double> out(std::size_t(planes_ + 2 * halo_) * plane_ * m);
    for (int p = 0; p < planes_ + 2 * halo_; ++p) {
      const int global = ((first_plane_ - halo_ + p) % n + n) % n;
      std::copy_n(slice.begin() + std::size_t(global) * plane_ * m,
                  std::size_t(plane_) * m,
                  out.begin() + std::size_t(p) * plane_ * m);
    }
    return out;
  }
  // Fills the halo of y on the widened slab (blocks of `block` values per
  // point) from the neighbouring ranks' slabs.
  void ExchangeHalo(const Comm& comm, double* y, std::size_t block) const {
    const std::size_t h = std::size_t(halo_points()) * block;
    const std::size_t own = std::size_t(own_points()) * block;
    comm.Exchange({y + own, h}, {y, h}, {y + h, h}, {y + h + own, h});
  }

 private:
  sbp::SpaceGrid<double> Widened(const Comm& comm,
                                 const sbp::SpaceGrid<double>& grid) {
    const int d = grid.dim(), P = comm.size();
    if (d < 2)
      throw std::invalid_argument(
          "a field on one axis runs on one process (without mpirun); "
          "spread a grid of 2 or 3 axes over ranks");
    for (int a = 0; a < d; ++a)
      if (!grid.axis(a).periodic())
        throw std::invalid_argument(
            "on several ranks every axis must be periodic; axis " +
            std::to_string(a) +
            " is an interval (run it on one process, without mpirun)");
    const auto& slow = grid.axis(d - 1);
    const int n = slow.points();
    plane_ = grid.stride(d - 1);
    if (n % P != 0 || plane_ % P != 0)
      throw std::invalid_argument(
          "the grid's last axis has " + std::to_string(n) +
          " points and a "
          "plane " +
          std::to_string(plane_) + ": both must divide by the " +
          std::to_string(P) + " ranks (use a rank count that divides them)");
    planes_ = n / P;
    halo_ = slow.order();  // twice the reach 2q/2 of periodic differences
    if (planes_ < halo_)
      throw std::invalid_argument(
          std::to_string(P) + " ranks leave " + std::to_string(planes_) +
          " planes each, fewer than the " + std::to_string(halo_) +
          " a rank's halo takes from one neighbour: use at most " +
          std::to_string(n / halo_) + " ranks");
    first_plane_ = comm.rank() * planes_;
    std::vector<sbp::SpaceDerivative<double>> axes;
    for (int a = 0; a + 1 < d; ++a) axes.push_back(grid.axis(a));
    const int wide = planes_ + 2 * halo_;
    axes.push_back(sbp::SpaceDerivative<double>::Periodic(
        slow.order(), wide, slow.x(first_plane_ - halo_), slow.dx() * wide));
    return sbp::SpaceGrid<double>(std::move(axes));
  }

  const sbp::SpaceGrid<double>& grid_;
  int plane_ = 0, planes_ = 0, halo_ = 0, first_plane_ = 0;
  sbp::SpaceGrid<double> wide_;
};

}  // namespace vivp::distributed
