// Spectrum analysis of SBP operators D and of the regularized D̄ (Rothkopf &
// Nordström 2023, Figs. 3-4; docs/method.md §2).
//
// The zero eigenvalue of D sits in a single Jordan block, so a floating-point
// eigensolver returns a ring of m eigenvalues of radius ~(eps |D|)^(1/m)
// instead of m zeros. Multiplicities are therefore never read off eigenvalues:
// they are counted through nested null spaces,
//   dim ker(D^k) = dim ker(D^{k-1}) + dim ker(P_{k-1} D),
// with P_{k-1} the orthogonal projector onto ker(D^{k-1})^⊥, each rank decided
// by singular values against a tolerance scaled to |D|. This never forms D^k,
// whose conditioning would grow like |D|^k.
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <vector>

namespace vivp::linalg {

struct ZeroEigenvalueStructure {
  int geometric_multiplicity = 0;      // dim ker(A)
  int algebraic_multiplicity = 0;      // dim ker(A^k) once it stops growing
  std::vector<int> kernel_dimensions;  // dim ker(A^k), k = 1, 2, ...
  double tolerance = 0;  // singular values <= tolerance count as zero
};

// Tolerance c * n * eps * sigma_max(A): the size round-off gives to an exact
// zero singular value of an n x n matrix with entries of size sigma_max.
double ZeroTolerance(const Eigen::MatrixXd& a);

ZeroEigenvalueStructure AnalyzeZeroEigenvalue(const Eigen::MatrixXd& a);

// The eigenvalues of A (EigenSolver), sorted by |.|, then arg.
std::vector<std::complex<double>> SortedEigenvalues(const Eigen::MatrixXd& a);

struct Spectrum {
  std::vector<std::complex<double>> eigenvalues;  // sorted by |.|, then arg
  Eigen::VectorXd singular_values;                // descending
  ZeroEigenvalueStructure zero;
  // Unit vectors spanning ker(A) and ker(A^T) (the last singular vectors),
  // sign fixed so the first entry of largest magnitude is positive; empty
  // when A has no zero singular value.
  Eigen::VectorXd right_null_vector;
  Eigen::VectorXd left_null_vector;
  double min_abs_eigenvalue = 0;
  double min_real_part = 0;
  // Eigenvalues with |Im| below the zero tolerance.
  std::vector<double> real_eigenvalues;
};

Spectrum AnalyzeSpectrum(const Eigen::MatrixXd& a);

}  // namespace vivp::linalg
