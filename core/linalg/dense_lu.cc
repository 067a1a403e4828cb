#include "core/linalg/dense_lu.h"

namespace vivp::linalg {

DenseLu::DenseLu(const Eigen::MatrixXd& a) : lu_(a) {}

void DenseLu::Solve(const Eigen::Ref<const Eigen::VectorXd>& b,
                    Eigen::VectorXd& x) const {
  x = lu_.solve(b);
}

}  // namespace vivp::linalg
