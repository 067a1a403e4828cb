// LU with partial pivoting of a dynamic-size square matrix, compiled once
// (dense_lu.cc): Eigen's PartialPivLU<MatrixXd> factorization and solve cost
// about 1 s of compilation (Clang 14, -O3) in every translation unit that
// instantiates them, and the Runge–Kutta stepper's Newton matrix has the same
// dynamic type for every problem. Same Eigen calls, so the same numbers.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>

namespace vivp::linalg {

class DenseLu {
 public:
  explicit DenseLu(const Eigen::MatrixXd& a);

  // x with A x = b.
  Eigen::VectorXd Solve(const Eigen::VectorXd& b) const;

 private:
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

}  // namespace vivp::linalg
