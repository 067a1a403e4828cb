// One process: the build without MPI (comm.h). Every collective is the
// identity or a local copy, so the distributed march runs here on one rank
// exactly as it does on one MPI rank.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "solvers/distributed/comm.h"

namespace vivp::distributed {

const Comm& Comm::World() {
  static const Comm world;
  return world;
}

void Comm::Max(std::span<double> v) const {
  // As the MPI build: a NaN reads as +∞, so non-finite values stay visible.
  for (double& x : v)
    if (std::isnan(x)) x = INFINITY;
}
void Comm::Sum(std::span<double>) const {}
void Comm::Allgather(std::span<const double> local,
                     std::span<double> all) const {
  if (all.size() != local.size())
    throw std::invalid_argument("Allgather: one rank's values, sized wrong");
  std::copy(local.begin(), local.end(), all.begin());
}
void Comm::Exchange(std::span<const double> up, std::span<double> from_below,
                    std::span<const double> down,
                    std::span<double> from_above) const {
  std::copy(up.begin(), up.end(), from_below.begin());
  std::copy(down.begin(), down.end(), from_above.begin());
}

bool Launched() { return false; }
void Init(int*, char***) {}
void Finalize() {}
bool Built() { return false; }

struct Transpose::Plans {};

Transpose::Transpose(const Comm& comm, std::ptrdiff_t n0, std::ptrdiff_t n1,
                     std::ptrdiff_t howmany)
    : n0_(n0), n1_(n1), howmany_(howmany), size_(comm.size()) {}
Transpose::~Transpose() = default;

void Transpose::Forward(double* in, double* out) const {
  detail::LocalTranspose(in, out, n0_, n1_, howmany_);
}
void Transpose::Backward(double* in, double* out) const {
  detail::LocalTranspose(in, out, n1_, n0_, howmany_);
}

}  // namespace vivp::distributed
