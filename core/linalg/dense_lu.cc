#include "core/linalg/dense_lu.h"

namespace vivp::linalg {

DenseLu::DenseLu(const Eigen::MatrixXd& a) : lu_(a) {}

Eigen::VectorXd DenseLu::Solve(const Eigen::VectorXd& b) const {
  return lu_.solve(b);
}

}  // namespace vivp::linalg
