#include "core/linalg/spectrum.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vivp::linalg {
namespace {

// Safety factor over the n * eps * |A| size of round-off in a computed zero
// singular value; the gap to the smallest genuine singular value of the
// operators analysed here is many orders of magnitude larger.
constexpr double kToleranceFactor = 100.0;

Eigen::VectorXd SignFixed(Eigen::VectorXd v) {
  Eigen::Index k;
  v.cwiseAbs().maxCoeff(&k);
  if (v[k] < 0) v = -v;
  return v;
}

}  // namespace

double ZeroTolerance(const Eigen::MatrixXd& a) {
  const double norm = Eigen::JacobiSVD<Eigen::MatrixXd>(a).singularValues()(0);
  return kToleranceFactor * static_cast<double>(a.rows()) *
         std::numeric_limits<double>::epsilon() * norm;
}

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
  Eigen::EigenSolver<Eigen::MatrixXd> eig(a, /*computeEigenvectors=*/false);
  const Eigen::VectorXcd ev = eig.eigenvalues();
  out.eigenvalues.assign(ev.data(), ev.data() + ev.size());
  std::sort(out.eigenvalues.begin(), out.eigenvalues.end(),
            [](const auto& x, const auto& y) {
              if (std::abs(x) != std::abs(y)) return std::abs(x) < std::abs(y);
              return std::arg(x) < std::arg(y);
            });

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
