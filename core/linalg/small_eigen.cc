#include "core/linalg/small_eigen.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>

namespace vivp::linalg {

double LargestGeneralizedEigenvalue(const Eigen::MatrixXd& k,
                                    const Eigen::MatrixXd& m) {
  const Eigen::MatrixXd a = m.fullPivLu().solve(k);
  const Eigen::VectorXcd ev = a.eigenvalues();
  double largest = 0;
  for (Eigen::Index i = 0; i < ev.size(); ++i)
    largest = std::max(largest, ev[i].real());
  return largest;
}

}  // namespace vivp::linalg
