// The spatial modes that diagonalize the space part of a field's window
// Jacobian (docs/fields.md §3).
//
// The discrete action couples the spatial points of a time slice only
// through S = D_xᵀ H_x D_x, the variation of Σ_j Hˣ_j ½(D_x φ)_j² (the
// gradient term), and through the weights Hˣ_j elsewhere. A basis V with
//
//   S V = H_x V Λ,   Vᵀ H_x V = I                                   (1)
//
// turns the window's Jacobian into one independent banded time system per
// column of V (mode_solver.h). Two such bases:
//
//   periodic   S = Δx D_xᵀD_x is circulant: V is the real Fourier basis,
//              applied with FFTW's real-to-halfcomplex transform (Frigo &
//              Johnson, "The design and implementation of FFTW3", Proc. IEEE
//              2005). Mode k and −k share s_k = σ(θ_k)²/Δx², σ the symbol
//              Σ_l 2c_l sin(lθ) of the central differences.
//   interval   the generalized symmetric eigenproblem (1) solved once per
//              grid (Eigen's SelfAdjointEigenSolver on H^{-1/2} S H^{-1/2}),
//              applied as a dense product, O(Nx²) per time row.
//
// On an interval, points whose value is Dirichlet data are not unknowns of
// the spatial system: the basis is that of S and H restricted to the other
// points (`first`, `count`), and mode_solver.h eliminates the boundary
// columns around it.
//
// Data are in the layout of the field system's unknowns
// (core/action/field_system.h): spatial point j's block of `stride` values
// at j·stride; a "row" r < rows is the spatial signal x_j = data[r +
// j·stride]. Forward replaces the kept points' signals by their mode
// coefficients (X ← X V), Inverse by the point values (X ← X Vᵀ); a mode's
// coefficients are then contiguous, in the block of point first + q.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "core/sbp/space.h"

namespace vivp::spacetime {

class SpatialModes {
 public:
  // The modes of dx over the points [first, first + count) (an interval
  // only; the periodic circle keeps every point).
  SpatialModes(const sbp::SpaceDerivative<double>& dx, int first, int count);
  ~SpatialModes();
  SpatialModes(SpatialModes&&) noexcept;
  SpatialModes& operator=(SpatialModes&&) noexcept;

  int first() const { return first_; }
  int count() const { return count_; }
  // s_q of (1) for mode q < count().
  double eigenvalue(int q) const { return eigenvalues_[q]; }
  // Modes with the same s_q share one time system: its index, < distinct().
  int system_of(int q) const { return system_of_[q]; }
  int distinct() const { return distinct_; }
  // S restricted to the kept points... and beyond: S(j, l) over the whole
  // grid, dense (an interval only; it couples Dirichlet columns to the rest).
  const Eigen::MatrixXd& stiffness() const { return stiffness_; }

  // X ← X V and X ← X Vᵀ for the `rows` signals of data (see above).
  void Forward(double* data, int stride, int rows) const;
  void Inverse(double* data, int stride, int rows) const;

 private:
  struct Fft;
  int first_ = 0, count_ = 0, distinct_ = 0;
  std::vector<double> eigenvalues_;
  std::vector<int> system_of_;
  Eigen::MatrixXd stiffness_;  // interval: S over all points
  Eigen::MatrixXd basis_;      // interval: V over the kept points
  // periodic: c_q, the column scale of (1) for the unnormalized transform,
  // and c_q/w_q for its inverse (w: 1 at k = 0 and n/2, else 2)
  std::vector<double> forward_scale_, inverse_scale_;
  std::unique_ptr<Fft> fft_;
  mutable Eigen::MatrixXd work_;
};

}  // namespace vivp::spacetime
