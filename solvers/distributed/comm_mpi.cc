// The ranks of an MPI run (comm.h): MPI for reductions, gathers and the
// halo exchange, FFTW's MPI interface for the distributed transpose of the
// mode solve (fftw_mpi_plan_many_transpose).
#include <fftw3-mpi.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include "solvers/distributed/comm.h"

namespace vivp::distributed {

struct CommAccess {
  static Comm& Mutable() {
    static Comm world;
    return world;
  }
  static void Set(int rank, int size) {
    Mutable().rank_ = rank;
    Mutable().size_ = size;
  }
};

namespace {

bool Running() {
  int on = 0, off = 0;
  MPI_Initialized(&on);
  MPI_Finalized(&off);
  return on && !off;
}

int Count(std::size_t n) {
  if (n > std::size_t(1) << 30)
    throw std::invalid_argument(
        "one message of " + std::to_string(n) +
        " values is beyond MPI's int count: use more ranks");
  return int(n);
}

}  // namespace

const Comm& Comm::World() { return CommAccess::Mutable(); }

void Comm::Max(std::span<double> v) const {
  for (double& x : v)
    if (std::isnan(x)) x = INFINITY;
  if (size_ > 1)
    MPI_Allreduce(MPI_IN_PLACE, v.data(), Count(v.size()), MPI_DOUBLE, MPI_MAX,
                  MPI_COMM_WORLD);
}

void Comm::Sum(std::span<double> v) const {
  if (size_ == 1) return;
  std::vector<double> all(v.size() * std::size_t(size_));
  MPI_Allgather(v.data(), Count(v.size()), MPI_DOUBLE, all.data(),
                Count(v.size()), MPI_DOUBLE, MPI_COMM_WORLD);
  for (std::size_t k = 0; k < v.size(); ++k) {
    double s = all[k];
    for (int r = 1; r < size_; ++r) s += all[std::size_t(r) * v.size() + k];
    v[k] = s;
  }
}

void Comm::Allgather(std::span<const double> local,
                     std::span<double> all) const {
  if (all.size() != local.size() * std::size_t(size_))
    throw std::invalid_argument("Allgather: the ranks' values, sized wrong");
  if (size_ == 1) {
    std::copy(local.begin(), local.end(), all.begin());
    return;
  }
  MPI_Allgather(local.data(), Count(local.size()), MPI_DOUBLE, all.data(),
                Count(local.size()), MPI_DOUBLE, MPI_COMM_WORLD);
}

void Comm::Exchange(std::span<const double> up, std::span<double> from_below,
                    std::span<const double> down,
                    std::span<double> from_above) const {
  if (size_ == 1) {
    std::copy(up.begin(), up.end(), from_below.begin());
    std::copy(down.begin(), down.end(), from_above.begin());
    return;
  }
  const int above = (rank_ + 1) % size_, below = (rank_ + size_ - 1) % size_;
  MPI_Sendrecv(up.data(), Count(up.size()), MPI_DOUBLE, above, 1,
               from_below.data(), Count(from_below.size()), MPI_DOUBLE, below,
               1, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  MPI_Sendrecv(down.data(), Count(down.size()), MPI_DOUBLE, below, 2,
               from_above.data(), Count(from_above.size()), MPI_DOUBLE, above,
               2, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
}

bool Launched() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") ||
         std::getenv("PMI_RANK");
}

void Init(int* argc, char*** argv) {
  if (!Launched() || Running()) return;
  MPI_Init(argc, argv);
  fftw_mpi_init();
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  CommAccess::Set(rank, size);
}

void Finalize() {
  if (!Running()) return;
  fftw_mpi_cleanup();
  MPI_Finalize();
}

bool Built() { return true; }

// FFTW plans on buffers of its own (a plan fixes its arrays' alignment); the
// data are copied in and out, O(local values) beside the banded solves.
struct Transpose::Plans {
  fftw_plan forward = nullptr, backward = nullptr;
  double *a = nullptr, *b = nullptr;
  std::size_t count = 0;
  ~Plans() {
    if (forward) fftw_destroy_plan(forward);
    if (backward) fftw_destroy_plan(backward);
    fftw_free(a);
    fftw_free(b);
  }
};

Transpose::Transpose(const Comm& comm, std::ptrdiff_t n0, std::ptrdiff_t n1,
                     std::ptrdiff_t howmany)
    : plans_(std::make_unique<Plans>()),
      n0_(n0),
      n1_(n1),
      howmany_(howmany),
      size_(comm.size()) {
  if (n0 % size_ != 0 || n1 % size_ != 0)
    throw std::invalid_argument("transpose: " + std::to_string(n0) + " × " +
                                std::to_string(n1) + " does not divide over " +
                                std::to_string(size_) + " ranks");
  if (size_ == 1) return;
  const std::ptrdiff_t b0 = n0 / size_, b1 = n1 / size_;
  plans_->count = std::size_t(b0 * n1 * howmany);
  plans_->a = fftw_alloc_real(plans_->count);
  plans_->b = fftw_alloc_real(plans_->count);
  plans_->forward =
      fftw_mpi_plan_many_transpose(n0, n1, howmany, b0, b1, plans_->a,
                                   plans_->b, MPI_COMM_WORLD, FFTW_ESTIMATE);
  plans_->backward =
      fftw_mpi_plan_many_transpose(n1, n0, howmany, b1, b0, plans_->a,
                                   plans_->b, MPI_COMM_WORLD, FFTW_ESTIMATE);
  if (!plans_->forward || !plans_->backward)
    throw std::runtime_error("FFTW could not plan the distributed transpose");
}

Transpose::~Transpose() = default;

void Transpose::Forward(double* in, double* out) const {
  if (size_ == 1) {
    detail::LocalTranspose(in, out, n0_, n1_, howmany_);
    return;
  }
  std::memcpy(plans_->a, in, plans_->count * sizeof(double));
  fftw_execute(plans_->forward);
  std::memcpy(out, plans_->b, plans_->count * sizeof(double));
}

void Transpose::Backward(double* in, double* out) const {
  if (size_ == 1) {
    detail::LocalTranspose(in, out, n1_, n0_, howmany_);
    return;
  }
  std::memcpy(plans_->a, in, plans_->count * sizeof(double));
  fftw_execute(plans_->backward);
  std::memcpy(out, plans_->b, plans_->count * sizeof(double));
}

}  // namespace vivp::distributed
