// The processes a field march is spread over (docs/distributed.md), behind
// an interface without MPI's types: comm_mpi.cc implements it with MPI and
// FFTW's MPI transposes when the distributed build is configured
// (VIVP_DISTRIBUTED), comm_serial.cc as one process otherwise. The march
// (window.h) is the same code either way, so one process runs exactly what
// each of N ranks runs.
//
// Every call is collective: all ranks make it, in the same order.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace vivp::distributed {

class Comm {
 public:
  // The world of the program: every rank when launched by mpirun (and
  // Init was called), else one process.
  static const Comm& World();

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }

  // The largest of v over the ranks, element by element (the same on every
  // rank).
  void Max(std::span<double> v) const;
  // The sums of v over the ranks, added in rank order on every rank, so
  // that every rank holds the same bits and a run at fixed size repeats.
  void Sum(std::span<double> v) const;
  // Every rank's `local` (the same count on each), concatenated in rank
  // order, on every rank.
  void Allgather(std::span<const double> local, std::span<double> all) const;
  // The ring of ranks along the slowest axis: sends `up` to rank + 1 and
  // receives into `from_below` from rank − 1, then sends `down` to rank − 1
  // and receives `from_above` from rank + 1 (periodically; one rank sends to
  // itself).
  void Exchange(std::span<const double> up, std::span<double> from_below,
                std::span<const double> down,
                std::span<double> from_above) const;

 private:
  int rank_ = 0, size_ = 1;
  friend struct CommAccess;
};

// Whether this process was started by mpirun (its environment says so);
// only then does Init start MPI, so that `vivp run` alone never needs it.
bool Launched();
// Starts MPI (and FFTW's MPI interface) when Launched() and the build is
// distributed; a no-op otherwise. Finalize ends them; a Session does both.
void Init(int* argc, char*** argv);
void Finalize();
// Whether this build can run on more than one rank.
bool Built();

struct Session {
  Session(int* argc, char*** argv) { Init(argc, argv); }
  ~Session() { Finalize(); }
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

namespace detail {
// out = inᵀ for an n0 × n1 array of tuples of h doubles on one process.
inline void LocalTranspose(const double* in, double* out, std::ptrdiff_t n0,
                           std::ptrdiff_t n1, std::ptrdiff_t h) {
  for (std::ptrdiff_t i0 = 0; i0 < n0; ++i0)
    for (std::ptrdiff_t i1 = 0; i1 < n1; ++i1)
      for (std::ptrdiff_t k = 0; k < h; ++k)
        out[(i1 * n0 + i0) * h + k] = in[(i0 * n1 + i1) * h + k];
}
}  // namespace detail

// The transpose of an n0 × n1 array of tuples of `howmany` doubles,
// distributed over the ranks in blocks of n0/size rows, into the n1 × n0
// array distributed in blocks of n1/size rows (FFTW's
// fftw_mpi_plan_many_transpose). Both counts must divide by the size.
class Transpose {
 public:
  Transpose(const Comm& comm, std::ptrdiff_t n0, std::ptrdiff_t n1,
            std::ptrdiff_t howmany);
  ~Transpose();
  Transpose(const Transpose&) = delete;
  Transpose& operator=(const Transpose&) = delete;
  // in: this rank's n0/size rows; out: its n1/size rows (in is overwritten).
  void Forward(double* in, double* out) const;
  // The inverse: in holds n1/size rows of the transposed array.
  void Backward(double* in, double* out) const;

 private:
  struct Plans;
  std::unique_ptr<Plans> plans_;
  std::ptrdiff_t n0_, n1_, howmany_;
  int size_;
};

}  // namespace vivp::distributed
