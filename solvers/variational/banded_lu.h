// LU factorization with partial pivoting of a banded matrix, O(n kl (kl+ku)).
// double goes to LAPACK's dgbtrf, and the substitutions of dgbtrs on its
// factors (Substitute); any other scalar (long double) to Eigen's SparseLU on
// the same band.
#pragma once

#include <Eigen/SparseLU>
#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/linalg/banded.h"

extern "C" {
void dgbtrf_(const int* m, const int* n, const int* kl, const int* ku,
             double* ab, const int* ldab, int* ipiv, int* info);
void dgbtrs_(const char* trans, const int* n, const int* kl, const int* ku,
             const int* nrhs, const double* ab, const int* ldab,
             const int* ipiv, double* b, const int* ldb, int* info,
             std::size_t trans_len);
}

namespace vivp::variational {

template <class Real>
class BandedLu {
 public:
  // Factors a (which it may overwrite). Returns false if a is singular.
  bool Factor(linalg::BandedMatrix<Real>& a) {
    n_ = a.size();
    if constexpr (std::is_same_v<Real, double>) {
      a_ = &a;
      pivots_.resize(n_);
      int kl = a.lower(), ku = a.upper(), ld = a.leading_dimension(), info = 0;
      dgbtrf_(&n_, &n_, &kl, &ku, a.data(), &ld, pivots_.data(), &info);
      if (info != 0) return false;
      // U's diagonal inverted once per factorization instead of once per
      // substitution: a window takes 4–5 substitutions per factorization,
      // and the divisions were a tenth of its time.
      inverse_diagonal_.resize(n_);
      const int kd = kl + ku;
      for (int j = 0; j < n_; ++j)
        inverse_diagonal_[j] = 1.0 / a.data()[std::size_t(j) * ld + kd];
      return true;
    } else {
      sparse_ = a.ToSparse();
      lu_.analyzePattern(sparse_);
      lu_.factorize(sparse_);
      return lu_.info() == Eigen::Success;
    }
  }

  // b <- A^{-1} b.
  void Solve(Real* b) const {
    if constexpr (std::is_same_v<Real, double>) {
      Substitute(*a_, pivots_.data(), b, inverse_diagonal_.data());
    } else {
      Eigen::Map<Eigen::Matrix<Real, Eigen::Dynamic, 1>> v(b, n_);
      v = lu_.solve(Eigen::Matrix<Real, Eigen::Dynamic, 1>(v));
    }
  }

  // b0 <- A^{-1} b0 and b1 <- A^{-1} b1 (double only): the substitutions of
  // Substitute for two right-hand sides at once, in the same order of
  // operations for each (the two halves of a Fourier mode share a matrix;
  // solutions equal Solve's to the bit).
  void SolvePair(double* b0,
                 double* b1) const requires std::is_same_v<Real, double> {
    const auto& lu = *a_;
    const int n = lu.size(), kl = lu.lower(), ld = lu.leading_dimension();
    const int kd = kl + lu.upper();
    const double* ab = lu.data();
    const int* pivots = pivots_.data();
    for (int j = 0; j + 1 < n; ++j) {
      const int l = pivots[j] - 1;
      if (l != j) {
        std::swap(b0[l], b0[j]);
        std::swap(b1[l], b1[j]);
      }
      const int lm = std::min(kl, n - 1 - j);
      const double* m = ab + std::size_t(j) * ld + kd + 1;
      const double c0 = b0[j], c1 = b1[j];
      for (int i = 0; i < lm; ++i) {
        b0[j + 1 + i] -= m[i] * c0;
        b1[j + 1 + i] -= m[i] * c1;
      }
    }
    for (int j = n - 1; j >= 0; --j) {
      const double* u = ab + std::size_t(j) * ld;
      const double inv = inverse_diagonal_[j];
      // Substitute skips a zero entry; the products below are then zero too
      // (a finite factor times 0), so skipping or not gives the same bits.
      b0[j] *= inv;
      b1[j] *= inv;
      const double t0 = b0[j], t1 = b1[j];
      for (int i = std::max(0, j - kd); i < j; ++i) {
        b0[i] -= t0 * u[kd + i - j];
        b1[i] -= t1 * u[kd + i - j];
      }
    }
  }

  // b <- A^{-1} b from dgbtrf's factors of A (in `lu`, pivots 1-based): the
  // two substitutions of LAPACK's dgbtrs (trans = 'N', one right-hand side),
  // in the same order of operations, with U's diagonal divided or, when
  // `inverse_diagonal` is given, multiplied by its inverse. dgbtrs itself
  // makes two BLAS calls per row (dswap, dger) and solves U with dtbsv; on
  // the narrow band of a marched window (about 50 rows, kl + ku about 10)
  // that call overhead was 45% of the run time of bench/march_bench (perf),
  // for a few hundred flops.
  static void Substitute(const linalg::BandedMatrix<double>& lu,
                         const int* pivots, double* b,
                         const double* inverse_diagonal = nullptr) {
    const int n = lu.size(), kl = lu.lower(), ld = lu.leading_dimension();
    const int kd = kl + lu.upper();  // row of the diagonal in the band
    const double* ab = lu.data();
    // L: the row interchanges and multipliers of each column in turn.
    for (int j = 0; j + 1 < n; ++j) {
      const int l = pivots[j] - 1;
      if (l != j) std::swap(b[l], b[j]);
      const int lm = std::min(kl, n - 1 - j);
      const double* m = ab + std::size_t(j) * ld + kd + 1;
      const double bj = b[j];
      for (int i = 0; i < lm; ++i) b[j + 1 + i] -= m[i] * bj;
    }
    // U: upper triangular with kl + ku superdiagonals (dtbsv's column sweep).
    for (int j = n - 1; j >= 0; --j) {
      if (b[j] == 0.0) continue;
      const double* u = ab + std::size_t(j) * ld;
      if (inverse_diagonal)
        b[j] *= inverse_diagonal[j];
      else
        b[j] /= u[kd];
      const double t = b[j];
      for (int i = std::max(0, j - kd); i < j; ++i) b[i] -= t * u[kd + i - j];
    }
  }

 private:
  int n_ = 0;
  linalg::BandedMatrix<Real>* a_ = nullptr;
  std::vector<int> pivots_;
  std::vector<double> inverse_diagonal_;
  Eigen::SparseMatrix<Real> sparse_;
  Eigen::SparseLU<Eigen::SparseMatrix<Real>, Eigen::COLAMDOrdering<int>> lu_;
};

}  // namespace vivp::variational
