#include "solvers/distributed/modes.h"

#include <array>
#include <stdexcept>

namespace vivp::distributed {

namespace {

std::shared_ptr<const spacetime::GridModes> PeriodicModes(
    const sbp::SpaceGrid<double>& grid) {
  for (int a = 0; a < grid.dim(); ++a)
    if (!grid.axis(a).periodic())
      throw std::invalid_argument(
          "the distributed mode solve needs periodic axes; axis " +
          std::to_string(a) +
          " is an interval (run it on one process, without mpirun)");
  return std::make_shared<const spacetime::GridModes>(grid);
}

}  // namespace

DistributedModes::DistributedModes(const Comm& comm,
                                   const sbp::RegularizedOperator<double>& dt,
                                   const sbp::SpaceGrid<double>& grid, int m)
    : comm_(comm),
      grid_(grid),
      nt_(dt.points()),
      block_((dt.points() + 2) * m),
      dim_(grid.dim()),
      slow_(grid.points(grid.dim() - 1)),
      rest_(grid.stride(grid.dim() - 1)),
      planes_(slow_ / comm.size()),
      rest_local_(rest_ / comm.size()),
      modes_(PeriodicModes(grid)),
      solver_(dt, grid, m, std::array<bool, 2>{false, false}.data(), modes_),
      transpose_(comm, slow_, rest_, block_) {
  if (slow_ % comm.size() != 0 || rest_ % comm.size() != 0)
    throw std::invalid_argument(
        "the distributed mode solve needs the grid's planes and the points "
        "of a plane to divide over the ranks");
  // The modes this rank holds after the transpose: (first + r) + rest·q.
  needed_.assign(modes_->distinct(), 0);
  const int first = comm.rank() * rest_local_;
  for (int r = 0; r < rest_local_; ++r)
    for (int q = 0; q < slow_; ++q)
      needed_[modes_->system_of(first + r + rest_ * q)] = 1;
  const int begin = comm.rank() * planes_ * rest_;
  hx_.resize(std::size_t(planes_) * rest_);
  for (std::size_t j = 0; j < hx_.size(); ++j)
    hx_[j] = grid.NormWeight(begin + int(j));
  buffer_.resize(hx_.size() * block_);
}

bool DistributedModes::Factor(const spacetime::DensityBlocks& blocks) {
  bool ok = solver_.Factor(blocks, &needed_);
  double failed[1] = {ok ? 0.0 : 1.0};
  comm_.Max(failed);
  message_ =
      ok ? (failed[0] != 0 ? "a time system is singular on another rank" : "")
         : solver_.message();
  return failed[0] == 0;
}

template <class F>
void DistributedModes::Lines(int a, F&& fn) const {
  const int stride = grid_.stride(a), n = grid_.points(a);
  for (int p = 0; p < planes_; ++p)
    for (int j = 0; j < rest_; ++j)
      if ((j / stride) % n == 0) fn(p * rest_ + j);
}

void DistributedModes::Solve(double* b) const {
  const int B = block_, nm = nt_ * (B / (nt_ + 2));
  // The initial-data rows carry Hˣ_j like the node rows (mode_solver.h).
  for (std::size_t j = 0; j < hx_.size(); ++j)
    for (int r = nm; r < B; ++r) b[j * B + r] *= hx_[j];
  for (int a = 0; a + 1 < dim_; ++a)
    Lines(a, [&](int j) {
      modes_->axis(a).Forward(b + std::size_t(j) * B, grid_.stride(a) * B, B);
    });
  transpose_.Forward(b, buffer_.data());
  const auto& slow = modes_->axis(dim_ - 1);
  const int first = comm_.rank() * rest_local_;
  for (int r = 0; r < rest_local_; ++r) {
    double* line = buffer_.data() + std::size_t(r) * slow_ * B;
    slow.Forward(line, B, B);
    for (int q = 0; q < slow_; ++q)
      solver_.SolveMode(first + r + rest_ * q, line + std::size_t(q) * B);
    slow.Inverse(line, B, B);
  }
  transpose_.Backward(buffer_.data(), b);
  for (int a = dim_ - 2; a >= 0; --a)
    Lines(a, [&](int j) {
      modes_->axis(a).Inverse(b + std::size_t(j) * B, grid_.stride(a) * B, B);
    });
}

}  // namespace vivp::distributed
