#include "solvers/spacetime/grid_modes.h"

#include <stdexcept>
#include <string>

namespace vivp::spacetime {

namespace {

std::vector<int> AllFirst(const sbp::SpaceGrid<double>& g) {
  return std::vector<int>(g.dim(), 0);
}
std::vector<int> AllCount(const sbp::SpaceGrid<double>& g) {
  std::vector<int> c;
  for (int a = 0; a < g.dim(); ++a) c.push_back(g.points(a));
  return c;
}

}  // namespace

GridModes::GridModes(const sbp::SpaceGrid<double>& grid)
    : GridModes(grid, AllFirst(grid), AllCount(grid)) {}

GridModes::GridModes(const sbp::SpaceGrid<double>& grid,
                     std::span<const int> first, std::span<const int> count) {
  if (int(first.size()) != grid.dim() || int(count.size()) != grid.dim())
    throw std::invalid_argument(
        "grid modes: one first point and one count per axis (" +
        std::to_string(grid.dim()) + " axes)");
  for (int a = 0; a < grid.dim(); ++a) {
    axes_.emplace_back(grid.axis(a), first[a], count[a]);
    grid_strides_.push_back(grid.stride(a));
    mode_strides_.push_back(count_);
    system_strides_.push_back(distinct_);
    count_ *= axes_.back().count();
    distinct_ *= axes_.back().distinct();
  }
}

double GridModes::eigenvalue(int q) const {
  double s = 0;
  for (int a = 0; a < dim(); ++a)
    s += axes_[a].eigenvalue(mode_coordinate(q, a));
  return s;
}

int GridModes::system_of(int q) const {
  int k = 0;
  for (int a = 0; a < dim(); ++a)
    k += axes_[a].system_of(mode_coordinate(q, a)) * system_strides_[a];
  return k;
}

int GridModes::point_of(int q) const {
  int j = 0;
  for (int a = 0; a < dim(); ++a)
    j += (axes_[a].first() + mode_coordinate(q, a)) * grid_strides_[a];
  return j;
}

// Calls fn(j) for every line along axis a whose other coordinates lie in
// the kept box, j the flat index of the line's point of axis-a coordinate
// 0 (SpatialModes finds its kept points from there).
template <class F>
void GridModes::Lines(int a, F&& fn) const {
  int c[3] = {0, 0, 0};
  const int d = dim();
  for (int b = 0; b < d; ++b) c[b] = b == a ? 0 : axes_[b].first();
  while (true) {
    int j = 0;
    for (int b = 0; b < d; ++b) j += c[b] * grid_strides_[b];
    fn(j);
    int b = 0;
    for (; b < d; ++b) {
      if (b == a) continue;
      if (++c[b] < axes_[b].first() + axes_[b].count()) break;
      c[b] = axes_[b].first();
    }
    if (b == d) return;
  }
}

void GridModes::Forward(double* data, int stride, int rows) const {
  for (int a = 0; a < dim(); ++a)
    Lines(a, [&](int j) {
      axes_[a].Forward(data + std::size_t(j) * stride,
                       grid_strides_[a] * stride, rows);
    });
}

void GridModes::Inverse(double* data, int stride, int rows) const {
  for (int a = dim() - 1; a >= 0; --a)
    Lines(a, [&](int j) {
      axes_[a].Inverse(data + std::size_t(j) * stride,
                       grid_strides_[a] * stride, rows);
    });
}

}  // namespace vivp::spacetime
