// Newton's linear solver (solvers/variational/newton.h, its LinearSolver
// concept) for a window whose Jacobian is singular along the gauge and not
// constant: charged matter (core/action/charged_field.h). Each step is a
// Levenberg–Marquardt step with a fixed, tiny damping on the equilibrated
// Jacobian,
//
//   δ = C⁻¹ (ĴᵀĴ + μI)⁻¹ Ĵᵀ b,   Ĵ = J C⁻¹,  C = diag(‖J e_k‖),
//
// factored by a sparse Cholesky (Eigen's simplicial LDLᵀ). For a consistent
// right-hand side (the gauge's Noether identity makes Newton's residual
// one) the step tends, as μ → 0, to the minimum-norm solution in the
// equilibrated unknowns: it has no component along the null space, so the
// gauge of the solution is the gauge of Newton's start, as in the Fourier
// solve (fourier_solver.h). μ = 1e-12 (the columns have unit norm) biases
// each step by at most μ/σ² along the smallest nonzero singular value σ,
// which Newton's next correction removes. No gauge condition is imposed.
//
// Cost: the pattern of ĴᵀĴ couples what J's columns share; its ordering is
// analysed once per pattern, and each factorization is of that banded-like
// matrix (one per Newton iteration, none for refinement steps). The
// factorization is a parameter: Eigen's simplicial LDLᵀ by default, or a
// supernodal Cholesky (Eigen's CholmodSupernodalLLT, SuiteSparse's CHOLMOD)
// where the fill is large, as in windows of 2 + 1 D grids
// (studies/vortex.cc).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>
#include <string>
#include <vector>

#include "solvers/spacetime/assembly.h"

namespace vivp::spacetime {

template <class Factorization>
class NormalEquationsSolverOf {
 public:
  explicit NormalEquationsSolverOf(double damping = 1e-12) : mu_(damping) {}

  bool valid = false;
  long long factorizations = 0;

  void Invalidate() { valid = false; }
  bool exact() const { return true; }
  std::string message() const { return message_; }
  template <class System>
  void Prepare(const System& system, const double*) {
    if (valid && jacobian_.matrix().rows() != system.size()) valid = false;
  }
  template <class System>
  void Assemble(const System& system, const double* y) {
    jacobian_.Assemble(system.size(),
                       [&](auto& sink) { system.Jacobian(y, sink); });
    held_.assign(system.size(), false);
    if constexpr (requires { system.Held(0); })
      for (int k = 0; k < system.size(); ++k) held_[k] = system.Held(k);
  }
  bool Factorize() {
    // A held unknown's column and row leave the system; its step is 0.
    Eigen::SparseMatrix<double> j = jacobian_.matrix();
    for (int c = 0; c < j.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(j, c); it; ++it)
        if (held_[it.row()] || held_[it.col()])
          it.valueRef() = it.row() == it.col() ? 1.0 : 0.0;
    scale_.resize(j.cols());
    for (int k = 0; k < j.cols(); ++k) {
      const double c = j.col(k).norm();
      scale_[k] = c > 0 ? 1.0 / c : 1.0;
    }
    scaled_ = j * scale_.asDiagonal();
    normal_ = scaled_.transpose() * scaled_;
    for (int k = 0; k < normal_.cols(); ++k) normal_.coeffRef(k, k) += mu_;
    if (analyzed_ != jacobian_.patterns()) {
      ldlt_.analyzePattern(normal_);
      analyzed_ = jacobian_.patterns();
    }
    ldlt_.factorize(normal_);
    ++factorizations;
    if (ldlt_.info() != Eigen::Success) {
      message_ =
          "the damped normal equations of the window are not positive "
          "definite (a non-finite Jacobian?)";
      return false;
    }
    return true;
  }
  void Solve(double* b) const {
    const Eigen::Index n = scaled_.rows();
    Eigen::Map<Eigen::VectorXd> rhs(b, n);
    for (Eigen::Index k = 0; k < n; ++k)
      if (held_[k]) rhs[k] = 0;
    Eigen::VectorXd z = ldlt_.solve(scaled_.transpose() * rhs);
    // One refinement on the unsquared system: the normal equations square
    // the condition number.
    const Eigen::VectorXd r = rhs - scaled_ * z;
    z += ldlt_.solve(scaled_.transpose() * r);
    Eigen::Map<Eigen::VectorXd>(b, n) = scale_.cwiseProduct(z);
  }
  long long nonzeros() const { return normal_.nonZeros(); }

 private:
  double mu_;
  PatternedMatrix jacobian_;
  Eigen::SparseMatrix<double> scaled_, normal_;
  Eigen::VectorXd scale_;
  std::vector<bool> held_;
  Factorization ldlt_;
  int analyzed_ = 0;
  std::string message_;
};

using NormalEquationsSolver =
    NormalEquationsSolverOf<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>;

}  // namespace vivp::spacetime
