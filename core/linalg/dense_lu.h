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

  // x with A x = b, into x (resized if needed). b a Ref and x the caller's,
  // so that neither a mapped b nor x is allocated per call: the
  // Runge–Kutta Newton step calls this with tiny systems, where an
  // allocation per call showed (implicit midpoint 6–10 % slower).
  void Solve(const Eigen::Ref<const Eigen::VectorXd>& b,
             Eigen::VectorXd& x) const;

 private:
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

}  // namespace vivp::linalg
