// The SVD parts of the analysis (spectrum.h). The eigenvalues and the zero
// tolerance are in spectrum_eigenvalues.cc, so that the dense Eigen
// decompositions compile in two halves in parallel: 14 s in one translation
// unit, 10 s and 5.5 s apart (Clang 14, -O3).
#include "core/linalg/spectrum.h"

#include <algorithm>
#include <cmath>
#include <limits>

// BDCSVD runs JacobiSVD<MatrixXd> on small blocks; it is compiled once, in
// spectrum_eigenvalues.cc.
extern template class Eigen::JacobiSVD<Eigen::MatrixXd>;

namespace vivp::linalg {
namespace {

Eigen::VectorXd SignFixed(Eigen::VectorXd v) {
  Eigen::Index k;
  v.cwiseAbs().maxCoeff(&k);
  if (v[k] < 0) v = -v;
  return v;
}

}  // namespace

ZeroEigenvalueStructure AnalyzeZeroEigenvalue(const Eigen::MatrixXd& a) {
  const Eigen::Index n = a.rows();
  ZeroEigenvalueStructure out;
  out.tolerance = ZeroTolerance(a);
  // Orthonormal basis of ker(A^k), grown one power at a time.
  Eigen::MatrixXd kernel(n, 0);
  for (Eigen::Index k = 1; k <= n; ++k) {
    Eigen::MatrixXd projected = a;
    if (kernel.cols() > 0) projected -= kernel * (kernel.transpose() * a);
    Eigen::BDCSVD<Eigen::MatrixXd> svd(projected, Eigen::ComputeFullV);
    const Eigen::VectorXd s = svd.singularValues();
    Eigen::Index zeros = 0;
    for (Eigen::Index i = 0; i < s.size(); ++i)
      if (s[i] <= out.tolerance) ++zeros;
    // P A x = 0 iff A x lies in ker(A^{k-1}), i.e. ker(P A) = ker(A^k); the
    // right singular vectors of the zero singular values are an orthonormal
    // basis of it.
    out.kernel_dimensions.push_back(static_cast<int>(zeros));
    if (zeros == kernel.cols()) break;
    kernel = svd.matrixV().rightCols(zeros);
  }
  out.geometric_multiplicity =
      out.kernel_dimensions.empty() ? 0 : out.kernel_dimensions.front();
  out.algebraic_multiplicity =
      out.kernel_dimensions.empty() ? 0 : out.kernel_dimensions.back();
  if (out.kernel_dimensions.size() >= 2 &&
      out.kernel_dimensions.back() ==
          out.kernel_dimensions[out.kernel_dimensions.size() - 2])
    out.kernel_dimensions.pop_back();
  return out;
}

Spectrum AnalyzeSpectrum(const Eigen::MatrixXd& a) {
  Spectrum out;
  out.eigenvalues = SortedEigenvalues(a);

  Eigen::BDCSVD<Eigen::MatrixXd> svd(a,
                                     Eigen::ComputeFullU | Eigen::ComputeFullV);
  out.singular_values = svd.singularValues();
  out.zero = AnalyzeZeroEigenvalue(a);
  const Eigen::Index n = a.rows();
  if (out.zero.geometric_multiplicity > 0) {
    out.right_null_vector = SignFixed(svd.matrixV().col(n - 1));
    out.left_null_vector = SignFixed(svd.matrixU().col(n - 1));
  }

  out.min_abs_eigenvalue = std::numeric_limits<double>::infinity();
  out.min_real_part = std::numeric_limits<double>::infinity();
  for (const auto& z : out.eigenvalues) {
    out.min_abs_eigenvalue = std::min(out.min_abs_eigenvalue, std::abs(z));
    out.min_real_part = std::min(out.min_real_part, z.real());
    if (std::abs(z.imag()) <= out.zero.tolerance)
      out.real_eigenvalues.push_back(z.real());
  }
  return out;
}

}  // namespace vivp::linalg
