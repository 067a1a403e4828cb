#include "solvers/spacetime/sparse_lu.h"

#include <Eigen/SparseLU>
#include <Eigen/UmfPackSupport>
#include <stdexcept>

namespace vivp::spacetime {

using Matrix = Eigen::SparseMatrix<double>;

std::string_view SparseSolverName(SparseSolver s) {
  switch (s) {
    case SparseSolver::kUmfpack:
      return "umfpack";
    case SparseSolver::kEigen:
      return "eigen";
  }
  return "?";
}

SparseSolver ParseSparseSolver(std::string_view name) {
  if (name == "umfpack") return SparseSolver::kUmfpack;
  if (name == "eigen") return SparseSolver::kEigen;
  throw std::invalid_argument("unknown sparse solver '" + std::string(name) +
                              "'; valid: umfpack, eigen");
}

struct SparseLu::Impl {
  Impl() {
    // No iterative refinement inside UMFPACK's solve: Newton refines with
    // the exact, matrix-free residual itself (solvers/variational/
    // newton.h). With UMFPACK's default of up to two steps, each a sparse
    // product and another solve, the solves took 93 % of a sine-Gordon
    // march (bench/fields_bench --profile: 6.3 s of 6.8 s).
    umfpack.umfpackControl()(UMFPACK_IRSTEP) = 0;
  }
  Eigen::UmfPackLU<Matrix> umfpack;
  Eigen::SparseLU<Matrix, Eigen::COLAMDOrdering<int>> eigen;
};

SparseLu::SparseLu(SparseSolver kind)
    : kind_(kind), impl_(std::make_unique<Impl>()) {}
SparseLu::~SparseLu() = default;
SparseLu::SparseLu(SparseLu&&) noexcept = default;
SparseLu& SparseLu::operator=(SparseLu&&) noexcept = default;

void SparseLu::Analyze(const Matrix& a) {
  switch (kind_) {
    case SparseSolver::kUmfpack:
      impl_->umfpack.analyzePattern(a);
      break;
    case SparseSolver::kEigen:
      impl_->eigen.analyzePattern(a);
      break;
  }
}

bool SparseLu::Factorize(const Matrix& a) {
  Eigen::ComputationInfo info = Eigen::Success;
  switch (kind_) {
    case SparseSolver::kUmfpack:
      impl_->umfpack.factorize(a);
      info = impl_->umfpack.info();
      break;
    case SparseSolver::kEigen:
      impl_->eigen.factorize(a);
      info = impl_->eigen.info();
      if (info != Eigen::Success) message_ = impl_->eigen.lastErrorMessage();
      break;
  }
  if (info == Eigen::Success) {
    message_.clear();
    return true;
  }
  if (message_.empty())
    message_ = std::string(SparseSolverName(kind_)) +
               ": the Jacobian is singular to working precision";
  return false;
}

void SparseLu::Solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  switch (kind_) {
    case SparseSolver::kUmfpack:
      x = impl_->umfpack.solve(b);
      break;
    case SparseSolver::kEigen:
      x = impl_->eigen.solve(b);
      break;
  }
}

long long SparseLu::FactorNonzeros() const {
  switch (kind_) {
    case SparseSolver::kUmfpack:
      return impl_->umfpack.matrixL().nonZeros() +
             impl_->umfpack.matrixU().nonZeros();
    case SparseSolver::kEigen:
      return impl_->eigen.nnzL() + impl_->eigen.nnzU();
  }
  return -1;
}

}  // namespace vivp::spacetime
