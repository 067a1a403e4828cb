// The window system of a linear field with constant coefficients on a
// periodic grid, solved one wave vector at a time (docs/gauge.md §4): the
// solve for densities the space-diagonalized solve of mode_solver.h does
// not cover — φ_t coupled with ∇φ, axes coupled (electromagnetism's
// E_b = −∂_bA₀ − ∂_tA_b and F_bc) — and for Jacobians that are singular
// along gauge directions.
//
// Every spatial operator of a periodic grid is circulant: with the discrete
// Fourier basis e_k(x_j) = exp(i k·x_j), D_b e_k = s_b(k) e_k and
// D_bᵀ e_k = conj(s_b(k)) e_k, and Hˣ is a multiple w of the identity. The
// window's equations (core/action/field_system.h), transformed point by
// point with the same DFT for unknowns and rows, split into one system per
// wave vector of (W + 2)m complex unknowns:
//
//   node rows   w Pᴴ (Hᵗ ⊗ h) P,   P φ̂ = (φ̂(i), (D̄ φ̂)(i), s_0 φ̂(i), …)_i,
//   λ3, λ4      w e_N and w (row N of D) in the node rows of each component,
//   data rows   e_0ᵀ and row 0 of D, or λ3 = λ4 = 0 for a component without
//               a time derivative,
//
// h the density's constant K × K Hessian over (φ, φ_t, ∂_0φ, …). Each system
// is factored by a complete orthogonal decomposition (rows equilibrated,
// pivots below `rank_threshold` of the largest treated as zero), whose
// solve is the minimum-norm one: a consistent right-hand side gets the
// solution with no component along the null space, and since the DFT is a
// multiple of a unitary map, the whole window's solution is the
// minimum-norm one. That choice of gauge is the solve's; nothing in the
// equations fixes one.
//
// The data are real, so the systems of k and −k are complex conjugates
// (the stencils are real): only the half spectrum of a real-to-complex
// transform is factored and solved.
//
// Cost: each system is dense (W + 2)m square, built from four W × W time
// matrices and factored once per window operator: O(N (Wm)³ / 2) to
// factor, O(N (Wm)² / 2 + N log N · Wm) per solve, and N (Wm)² / 2 complex
// numbers held. Linear in the points, cubic in the window: a solve for
// windows, not for a global one.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/action/field_point.h"
#include "core/autodiff/pointwise.h"
#include "core/sbp/regularized.h"
#include "core/sbp/space_grid.h"

namespace vivp::spacetime {

class FourierWindowSolver {
 public:
  // The window of dt's points on `grid` (every axis periodic), m
  // components, the density's Hessian (K × K, K = (2 + d)m), `constraints`
  // a bit per component without a time derivative. Throws
  // std::invalid_argument for a bounded axis or a Hessian of the wrong size.
  FourierWindowSolver(const sbp::RegularizedOperator<double>& dt,
                      const sbp::SpaceGrid<double>& grid, int m,
                      const Eigen::MatrixXd& hessian, unsigned constraints,
                      double rank_threshold = 1e-10);
  ~FourierWindowSolver();
  FourierWindowSolver(const FourierWindowSolver&) = delete;
  FourierWindowSolver& operator=(const FourierWindowSolver&) = delete;

  // b ← the minimum-norm x with J x = b (the least-squares one where b is
  // not in J's range), in the field system's layout.
  void Solve(double* b) const;
  // The dimension treated as null, summed over the wave vectors.
  int nullity() const;
  int size() const;
  int time_points() const;
  double dt() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The density's Hessian over (φ, φ_t, ∂_0φ, …), the same at zero and at
// generic points (AtGenericPoints); else std::invalid_argument: the
// Fourier solve is exact for a linear field only.
template <class Density>
Eigen::MatrixXd ConstantHessian(const Density& density) {
  constexpr int m = Density::kDim, K = (2 + action::SpaceDimOf<Density>()) * m;
  auto call = [&](const auto* z) { return density(z, z + m, z + 2 * m); };
  const double zero[K] = {};
  const auto h = autodiff::Hessian<double, K>(call, zero).hessian;
  if (!action::AtGenericPoints<double, K>(call, [&](const auto& g) {
        return (g.hessian - h).cwiseAbs().maxCoeff() <=
               1e-14 * (1 + h.cwiseAbs().maxCoeff());
      }))
    throw std::invalid_argument(
        "the Fourier window solve needs a linear field (a density whose "
        "Hessian is constant); this one's varies");
  return h;
}

// newton.h's LinearSolver for a window of action::FieldSystem<Density> on a
// periodic grid with the FourierWindowSolver above: exact, built again when
// the window's operator changes.
template <class Density>
class FourierSolver {
 public:
  explicit FourierSolver(const Density& density)
      : hessian_(ConstantHessian(density)) {}
  bool valid = false;
  void Invalidate() { valid = false; }
  bool exact() const { return true; }
  std::string message() const { return {}; }
  template <class System>
  void Prepare(const System& sys, const double*) {
    const auto& D = sys.time_operator().base();
    if (solver_ && solver_->time_points() == D.points() &&
        solver_->dt() == D.dt())
      return;
    solver_ = std::make_unique<FourierWindowSolver>(
        sys.time_operator(), sys.space_grid(), Density::kDim, hessian_,
        action::ConstraintMaskOf<Density>());
    ++factorizations_;
    valid = false;
  }
  template <class System>
  void Assemble(const System&, const double*) {}
  bool Factorize() { return solver_ != nullptr; }
  void Solve(double* b) const { solver_->Solve(b); }
  const FourierWindowSolver& solver() const { return *solver_; }
  // Window systems built (each factors the half spectrum's wave vectors).
  long long factorizations() const { return factorizations_; }

 private:
  Eigen::MatrixXd hessian_;
  std::unique_ptr<FourierWindowSolver> solver_;
  long long factorizations_ = 0;
};

}  // namespace vivp::spacetime
