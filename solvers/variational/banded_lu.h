// LU factorization with partial pivoting of a banded matrix, O(n kl (kl+ku)).
// double: LAPACK's unblocked algorithm dgbtf2 (which dgbtrf calls for bands
// narrower than its block) in the same order of operations, written out
// (FactorBand), and the substitutions of dgbtrs on its factors (Substitute);
// any other scalar (long double) to Eigen's SparseLU on the same band.
#pragma once

#include <Eigen/SparseLU>
#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/linalg/banded.h"

namespace vivp::variational {

namespace detail {
// y[i] −= a[i]·c for i < length: the inner loop of the factorization and
// the substitutions. A window's columns are short (SBP84: at most 26
// multipliers and 44 entries of U), and clang vectorizes such a loop with
// four vectors per iteration, leaving up to seven entries to a scalar
// tail; with one vector per iteration the vector body takes them. Each
// entry's operations are the same either way, so are the bits.
template <class T>
inline void SubtractScaled(T* __restrict y, const T* __restrict a, T c,
                           int length) {
#if defined(__clang__)
#pragma clang loop vectorize(enable) interleave_count(1)
#endif
  for (int i = 0; i < length; ++i) y[i] -= a[i] * c;
}
}  // namespace detail

template <class Real>
class BandedLu {
 public:
  // Factors a (which it may overwrite). Returns false if a is singular.
  bool Factor(linalg::BandedMatrix<Real>& a) {
    n_ = a.size();
    if constexpr (std::is_same_v<Real, double>) {
      a_ = &a;
      pivots_.resize(n_);
      extent_.resize(n_);
      top_.resize(n_);
      if (!FactorBand(a, pivots_.data(), extent_.data(), top_.data()))
        return false;
      const int kl = a.lower(), ku = a.upper(), ld = a.leading_dimension();
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
      Substitute(*a_, pivots_.data(), b, inverse_diagonal_.data(),
                 extent_.data(), top_.data());
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
      const int lm = extent_[j];
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
      for (int i = std::max({0, j - kd, top_[j]}); i < j; ++i) {
        b0[i] -= t0 * u[kd + i - j];
        b1[i] -= t1 * u[kd + i - j];
      }
    }
  }

  // A = P L U in place, pivots 1-based, as LAPACK's dgbtf2: column by
  // column, the pivot the largest |entry| (the first of equals), the
  // multipliers scaled by the pivot's inverse, and the rank-one update of
  // the columns the pivot row reaches. False at the first zero pivot
  // (singular). dgbtrf makes five BLAS calls per column (idamax, dswap,
  // dscal, dger and the fill-in's zeroing); on a marched window's band
  // (about 100 rows, kl + ku about 20) their overhead was most of the
  // factorization, a fifth of a march under error control (perf).
  //
  // extent[j] (n values) receives the number of multipliers of column j
  // that can be nonzero, and top[j] U's first row that can be nonzero in
  // column j (the first pivot row that reaches it). A window's band is as wide
  // as its closure rows and multipliers make it (SBP84: kl = 26 where the
  // interior needs 17): each column is swept only down to its last row that can
  // be nonzero — at first its last nonzero entry, then as far as the pivot
  // rows' updates reach. The rows skipped hold zeros, which dgbtf2 would
  // multiply and subtract to no effect: the same factors.
  static bool FactorBand(linalg::BandedMatrix<double>& a, int* pivots,
                         int* extent, int* top) {
    const int n = a.size(), kl = a.lower(), ku = a.upper();
    const int ld = a.leading_dimension(), kv = kl + ku;
    double* ab = a.data();
    const auto at = [&](int row, int col) -> double& {
      return ab[std::size_t(col) * ld + row];
    };
    for (int j = 0; j < n; ++j) {
      int e = std::min(kl, n - 1 - j);
      while (e > 0 && at(kv + e, j) == 0.0) --e;
      extent[j] = e;
    }
    // The fill-in rows of the columns ku + 1 … kv − 1 start zeroed; later
    // columns are zeroed as the sweep reaches them.
    for (int j = ku + 1; j < std::min(kv, n); ++j)
      for (int i = kv - j; i < kl; ++i) at(i, j) = 0.0;
    int ju = 0;  // the last column the pivot rows so far reach
    if (n > 0) top[0] = 0;
    for (int j = 0; j < n; ++j) {
      if (j + kv < n)
        for (int i = 0; i < kl; ++i) at(i, j + kv) = 0.0;
      const int km = extent[j];
      int jp = 0;
      double largest = std::abs(at(kv, j));
      for (int i = 1; i <= km; ++i)
        if (std::abs(at(kv + i, j)) > largest) {
          largest = std::abs(at(kv + i, j));
          jp = i;
        }
      pivots[j] = j + jp + 1;
      if (at(kv + jp, j) == 0.0) return false;
      // Columns first reached by this pivot row: U's top row there is j.
      for (int c = ju + 1; c <= std::min(j + ku + jp, n - 1); ++c) top[c] = j;
      ju = std::max(ju, std::min(j + ku + jp, n - 1));
      // Rows j and j + jp over columns j … ju: along a row, band storage
      // steps by ld − 1.
      if (jp != 0)
        for (int c = 0; c <= ju - j; ++c)
          std::swap(ab[std::size_t(j) * ld + kv + jp + c * (ld - 1)],
                    ab[std::size_t(j) * ld + kv + c * (ld - 1)]);
      if (km == 0) continue;
      const double inv = 1.0 / at(kv, j);
      double* l = &at(kv + 1, j);
      for (int i = 0; i < km; ++i) l[i] *= inv;
      for (int c = j + 1; c <= ju; ++c) {
        // The swap and the update reach row j + km of column c.
        extent[c] = std::max(extent[c], j + km - c);
        double* col = &at(kv - (c - j), c);  // U(j, c), then rows below
        const double u = col[0];
        if (u == 0.0) continue;  // dger skips a zero y entry too
        detail::SubtractScaled(col + 1, l, u, km);
      }
    }
    return true;
  }

  // b <- A^{-1} b from FactorBand's (dgbtrf's) factors of A (in `lu`, pivots
  // 1-based): the two substitutions of LAPACK's dgbtrs (trans = 'N', one
  // right-hand side), in the same order of operations, with U's diagonal
  // divided or, when `inverse_diagonal` is given, multiplied by its inverse.
  // dgbtrs itself makes two BLAS calls per row (dswap, dger) and solves U with
  // dtbsv; on the narrow band of a marched window (about 50 rows, kl + ku about
  // 10) that call overhead was 45% of the run time of bench/march_bench (perf),
  // for a few hundred flops.
  // `extent` and `top`, when given, are FactorBand's: the multipliers of
  // each column and the rows of U that can be nonzero (the entries skipped
  // are zeros).
  static void Substitute(const linalg::BandedMatrix<double>& lu,
                         const int* pivots, double* b,
                         const double* inverse_diagonal = nullptr,
                         const int* extent = nullptr,
                         const int* top = nullptr) {
    const int n = lu.size(), kl = lu.lower(), ld = lu.leading_dimension();
    const int kd = kl + lu.upper();  // row of the diagonal in the band
    const double* ab = lu.data();
    // L: the row interchanges and multipliers of each column in turn.
    for (int j = 0; j + 1 < n; ++j) {
      const int l = pivots[j] - 1;
      if (l != j) std::swap(b[l], b[j]);
      const int lm = extent ? extent[j] : std::min(kl, n - 1 - j);
      const double* m = ab + std::size_t(j) * ld + kd + 1;
      const double bj = b[j];
      detail::SubtractScaled(b + j + 1, m, bj, lm);
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
      const int first = std::max(j - kd, top ? top[j] : 0);
      const int from = std::max(0, first);
      detail::SubtractScaled(b + from, u + kd + from - j, t, j - from);
    }
  }

 private:
  int n_ = 0;
  linalg::BandedMatrix<Real>* a_ = nullptr;
  std::vector<int> pivots_, extent_, top_;
  std::vector<double> inverse_diagonal_;
  Eigen::SparseMatrix<Real> sparse_;
  Eigen::SparseLU<Eigen::SparseMatrix<Real>, Eigen::COLAMDOrdering<int>> lu_;
};

}  // namespace vivp::variational
