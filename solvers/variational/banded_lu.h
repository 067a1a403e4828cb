// LU factorization with partial pivoting of a banded matrix, O(n kl (kl+ku)).
// double goes to LAPACK's dgbtrf/dgbtrs; any other scalar (long double) to
// Eigen's SparseLU on the same band.
#pragma once

#include <Eigen/SparseLU>
#include <stdexcept>
#include <string>
#include <type_traits>
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

namespace vivp::solvers {

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
      return info == 0;
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
      int kl = a_->lower(), ku = a_->upper(), ld = a_->leading_dimension();
      int nrhs = 1, info = 0;
      const char trans = 'N';
      dgbtrs_(&trans, &n_, &kl, &ku, &nrhs, a_->data(), &ld, pivots_.data(), b,
              &n_, &info, 1);
      if (info != 0)
        throw std::runtime_error("dgbtrs failed with info " +
                                 std::to_string(info));
    } else {
      Eigen::Map<Eigen::Matrix<Real, Eigen::Dynamic, 1>> v(b, n_);
      v = lu_.solve(Eigen::Matrix<Real, Eigen::Dynamic, 1>(v));
    }
  }

 private:
  int n_ = 0;
  linalg::BandedMatrix<Real>* a_ = nullptr;
  std::vector<int> pivots_;
  Eigen::SparseMatrix<Real> sparse_;
  Eigen::SparseLU<Eigen::SparseMatrix<Real>, Eigen::COLAMDOrdering<int>> lu_;
};

}  // namespace vivp::solvers
