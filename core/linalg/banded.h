// A square banded matrix in LAPACK general-band storage (with room for the
// fill-in of LU with partial pivoting), assembled entry by entry in O(1).
//
// The Jacobians of the discrete action couple only time nodes within a few
// stencil widths, so every row has O(1) nonzeros near the diagonal: storing
// and factoring the band costs O(N), independent of how the unknowns are
// numbered inside the band.
#pragma once

#include <Eigen/Sparse>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace vivp::linalg {

template <class Real>
class BandedMatrix {
 public:
  BandedMatrix() = default;
  // n x n with kl sub- and ku super-diagonals.
  BandedMatrix(int n, int kl, int ku)
      : n_(n),
        kl_(kl),
        ku_(ku),
        ld_(2 * kl + ku + 1),
        data_(static_cast<std::size_t>(ld_) * n, Real(0)) {}

  int size() const { return n_; }
  int lower() const { return kl_; }
  int upper() const { return ku_; }
  int leading_dimension() const { return ld_; }
  Real* data() { return data_.data(); }
  const Real* data() const { return data_.data(); }

  void SetZero() { std::fill(data_.begin(), data_.end(), Real(0)); }

  // A = s·B and A += s·B for B of the same size and band: the whole storage
  // in one sweep, LU's fill-in rows included (zero in B), so A needs no
  // zeroing before the first.
  void AssignScaled(Real s, const BandedMatrix& b) {
    CheckSameBand(b);
    Real* __restrict a = data_.data();
    const Real* __restrict c = b.data_.data();
    const std::size_t size = data_.size();
    for (std::size_t i = 0; i < size; ++i) a[i] = s * c[i];
  }
  void AddScaled(Real s, const BandedMatrix& b) {
    CheckSameBand(b);
    Real* __restrict a = data_.data();
    const Real* __restrict c = b.data_.data();
    const std::size_t size = data_.size();
    // The product formed before it is added, as AddBlockAt does (no fused
    // multiply–add where the target has one).
    for (std::size_t i = 0; i < size; ++i) {
      const Real p = s * c[i];
      a[i] += p;
    }
  }

  // A(i, j) += v. Entries outside the declared band are a programming error.
  // Assembly calls this for every entry of every node (a fifth of a marched
  // window's instructions, callgrind), so the check is two unsigned
  // comparisons and the message is built out of line.
  void Add(int i, int j, Real v) {
    const unsigned band = unsigned(kl_ + ku_);
    if (unsigned(ku_ + i - j) > band || unsigned(i) >= unsigned(n_) ||
        unsigned(j) >= unsigned(n_)) [[unlikely]]
      OutsideBand(i, j);
    data_[Index(i, j)] += v;
  }
  // A(i0 + r, j0 + s) += block(r, s) for r, s < k when the k × k block lies
  // inside the band (one check for the block; a column's k entries are
  // adjacent in the storage); false, adding nothing, when it does not.
  template <int k, class Block>
  bool AddBlockInBand(int i0, int j0, const Block& block) {
    if (i0 < 0 || j0 < 0 || i0 + k > n_ || j0 + k > n_ ||
        i0 - j0 - (k - 1) < -ku_ || i0 + (k - 1) - j0 > kl_)
      return false;
    for (int s = 0; s < k; ++s) {
      Real* column = &data_[Index(i0, j0 + s)];
      for (int r = 0; r < k; ++r) column[r] += block(r, s);
    }
    return true;
  }
  // Where AddBlockInBand would put a k × k block at (i0, j0): its first
  // entry's index in the storage, or −1 when the block is not inside the
  // band. AddBlockAt then adds a block there without the check: a block
  // added at the same places every assembly (reduced_system.h, K ⊗ M)
  // locates them once.
  template <int k>
  std::ptrdiff_t BlockOffset(int i0, int j0) const {
    if (i0 < 0 || j0 < 0 || i0 + k > n_ || j0 + k > n_ ||
        i0 - j0 - (k - 1) < -ku_ || i0 + (k - 1) - j0 > kl_)
      return -1;
    return static_cast<std::ptrdiff_t>(Index(i0, j0));
  }
  // A(i0 + r, j0 + s) += scale · block(r, s) at an offset from BlockOffset
  // (along a row the storage steps by ld − 1). Each entry's product is
  // formed before it is added, as AddBlockInBand adds a block formed first:
  // the same bits.
  template <int k, class Block>
  void AddBlockAt(std::ptrdiff_t offset, Real scale, const Block& block) {
    for (int s = 0; s < k; ++s) {
      Real* column = &data_[std::size_t(offset) + std::size_t(s) * (ld_ - 1)];
      for (int r = 0; r < k; ++r) {
        const Real entry = scale * block(r, s);
        column[r] += entry;
      }
    }
  }
  Real operator()(int i, int j) const {
    if (i - j > kl_ || j - i > ku_) return Real(0);
    return data_[Index(i, j)];
  }

  Eigen::SparseMatrix<Real> ToSparse() const {
    std::vector<Eigen::Triplet<Real>> t;
    t.reserve(static_cast<std::size_t>(n_) * (kl_ + ku_ + 1));
    for (int j = 0; j < n_; ++j)
      for (int i = std::max(0, j - ku_); i <= std::min(n_ - 1, j + kl_); ++i)
        if (const Real v = (*this)(i, j); v != Real(0)) t.emplace_back(i, j, v);
    Eigen::SparseMatrix<Real> s(n_, n_);
    s.setFromTriplets(t.begin(), t.end());
    return s;
  }

  // y = A x.
  void Multiply(const Real* x, Real* y) const {
    for (int i = 0; i < n_; ++i) {
      Real acc(0);
      for (int j = std::max(0, i - kl_); j <= std::min(n_ - 1, i + ku_); ++j)
        acc += (*this)(i, j) * x[j];
      y[i] = acc;
    }
  }

 private:
  // LAPACK ?gbtrf layout: AB(kl + ku + i - j, j), column-major, ld = 2kl+ku+1.
  std::size_t Index(int i, int j) const {
    return static_cast<std::size_t>(j) * ld_ + (kl_ + ku_ + i - j);
  }

  void CheckSameBand(const BandedMatrix& b) const {
    if (b.n_ != n_ || b.kl_ != kl_ || b.ku_ != ku_)
      throw std::logic_error("banded matrices of different sizes or bands");
  }
  [[noreturn, gnu::noinline, gnu::cold]] void OutsideBand(int i, int j) const {
    throw std::logic_error("banded entry (" + std::to_string(i) + ", " +
                           std::to_string(j) + ") outside band kl=" +
                           std::to_string(kl_) + " ku=" + std::to_string(ku_));
  }

  int n_ = 0, kl_ = 0, ku_ = 0, ld_ = 1;
  std::vector<Real> data_;
};

// Records the band of a pattern: feed every (i, j) an assembly would touch.
struct BandwidthProbe {
  int kl = 0, ku = 0;
  template <class Real>
  void Add(int i, int j, Real) {
    kl = std::max(kl, i - j);
    ku = std::max(ku, j - i);
  }
};

// The band of a System's Jacobian whose per-node pattern repeats away from
// the ends (true of every SBP action): probing the first and last `margin`
// nodes and one interior node is enough.
template <class System, class Real>
BandwidthProbe ProbeBand(const System& system, const Real* y, int points,
                         int margin) {
  BandwidthProbe probe;
  if (points <= 2 * margin + 1) {
    system.Jacobian(y, probe, 0, points);
  } else {
    system.Jacobian(y, probe, 0, margin);
    system.Jacobian(y, probe, points / 2, points / 2 + 1);
    system.Jacobian(y, probe, points - margin, points);
  }
  return probe;
}

}  // namespace vivp::linalg
