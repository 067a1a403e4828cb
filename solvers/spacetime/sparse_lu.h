// A sparse LU factorization of the space-time Jacobian, behind one small
// interface so that the solver can be chosen by measurement
// (docs/fields.md §3):
//
//   kUmfpack   UMFPACK (Davis 2004, SuiteSparse) with its default ordering,
//              AMD on A + Aᵀ for these nearly symmetric patterns;
//   kEigen     Eigen's supernodal SparseLU with COLAMD.
//
// (KLU, also in SuiteSparse, was measured and left out: without BLAS-level
// supernodes it took 13 s for the Klein–Gordon system on 64 × 64 points,
// where UMFPACK took 0.14 s.)
//
// Analyze fixes the ordering for a pattern; Factorize may be called again
// for new values on the same pattern (every Newton iteration, every window).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <string_view>

namespace vivp::spacetime {

enum class SparseSolver { kUmfpack, kEigen };

std::string_view SparseSolverName(SparseSolver s);
// "umfpack" or "eigen"; throws std::invalid_argument naming the valid
// names otherwise.
SparseSolver ParseSparseSolver(std::string_view name);

class SparseLu {
 public:
  explicit SparseLu(SparseSolver kind = SparseSolver::kUmfpack);
  ~SparseLu();
  SparseLu(SparseLu&&) noexcept;
  SparseLu& operator=(SparseLu&&) noexcept;

  SparseSolver kind() const { return kind_; }
  // The fill-reducing ordering and symbolic analysis of a's pattern.
  void Analyze(const Eigen::SparseMatrix<double>& a);
  // The numeric factorization; false if a is singular to working precision
  // (the reason in message()).
  bool Factorize(const Eigen::SparseMatrix<double>& a);
  // x = A⁻¹ b with the last factorization.
  void Solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  // Nonzeros of L + U (the fill), where the solver reports it, else −1.
  long long FactorNonzeros() const;
  const std::string& message() const { return message_; }

 private:
  struct Impl;
  SparseSolver kind_;
  std::unique_ptr<Impl> impl_;
  std::string message_;
};

}  // namespace vivp::spacetime
