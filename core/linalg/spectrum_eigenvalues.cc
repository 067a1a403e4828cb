// The eigenvalues and the zero tolerance of the analysis (spectrum.h), apart
// from its SVD parts in spectrum.cc so that the two compile in parallel.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include "core/linalg/spectrum.h"

// Also the JacobiSVD that spectrum.cc's BDCSVD runs on small blocks.
template class Eigen::JacobiSVD<Eigen::MatrixXd>;

namespace vivp::linalg {
namespace {

// Safety factor over the n * eps * |A| size of round-off in a computed zero
// singular value; the gap to the smallest genuine singular value of the
// operators analysed here is many orders of magnitude larger.
constexpr double kToleranceFactor = 100.0;

}  // namespace

double ZeroTolerance(const Eigen::MatrixXd& a) {
  const double norm = Eigen::JacobiSVD<Eigen::MatrixXd>(a).singularValues()(0);
  return kToleranceFactor * static_cast<double>(a.rows()) *
         std::numeric_limits<double>::epsilon() * norm;
}

std::vector<std::complex<double>> SortedEigenvalues(const Eigen::MatrixXd& a) {
  Eigen::EigenSolver<Eigen::MatrixXd> eig(a, /*computeEigenvectors=*/false);
  const Eigen::VectorXcd ev = eig.eigenvalues();
  std::vector<std::complex<double>> out(ev.data(), ev.data() + ev.size());
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) {
    if (std::abs(x) != std::abs(y)) return std::abs(x) < std::abs(y);
    return std::arg(x) < std::arg(y);
  });
  return out;
}

}  // namespace vivp::linalg
