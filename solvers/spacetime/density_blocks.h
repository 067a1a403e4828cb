// The Hessian blocks of a density that the space-diagonalized solve is
// built from (mode_solver.h): L_tt = ∂²L/∂φ_t², L_xx = ∂²L/∂φ_x² and
// L_φφ = ∂²L/∂φ². In d dimensions L_xx is the mean of the axes' blocks
// ∂²L/∂(∂_bφ)².
//
// A density whose Hessian is the same at every point, has no mixed blocks
// and is isotropic (every axis' block the same: a linear field equation
// with constant coefficients, the wave and Klein–Gordon fields) is solved
// exactly by the mode solve; for any other the blocks averaged over a state
// are its preconditioner.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "core/action/field_system.h"
#include "core/autodiff/pointwise.h"
#include "solvers/spacetime/mode_solver.h"

namespace vivp::spacetime {

namespace detail {

template <int m, int d, class H>
DensityBlocks BlocksOf(const H& h) {
  DensityBlocks b;
  b.lpp = h.template block<m, m>(0, 0);
  b.ltt = h.template block<m, m>(m, m);
  b.lxx = h.template block<m, m>(2 * m, 2 * m);
  for (int a = 1; a < d; ++a)
    b.lxx += h.template block<m, m>((2 + a) * m, (2 + a) * m);
  if (d > 1) b.lxx /= double(d);
  return b;
}

}  // namespace detail

// Whether the density's Hessian is constant and isotropic with no mixed
// blocks, sampled at a few generic points (a density that varies does so
// almost everywhere).
template <class Density>
bool HasConstantBlocks(const Density& density) {
  constexpr int m = Density::kDim, d = action::SpaceDimOf<Density>();
  constexpr int K = (2 + d) * m;
  auto call = [&](const auto* z) { return density(z, z + m, z + 2 * m); };
  Eigen::Matrix<double, K, K> first;
  for (int s = 0; s < 4; ++s) {
    double z[K];
    for (int k = 0; k < K; ++k)
      z[k] = 0.3 + 0.37 * s * std::cos(1.3 * k + s) + 0.11 * (k * k % 7);
    const auto h = autodiff::Hessian<double, K>(call, z).hessian;
    for (int a = 0; a < 2 + d; ++a)
      for (int c = 0; c < 2 + d; ++c)
        if (a != c && h.block(a * m, c * m, m, m).cwiseAbs().maxCoeff() != 0)
          return false;
    for (int a = 3; a < 2 + d; ++a)
      if (h.block(a * m, a * m, m, m) != h.block(2 * m, 2 * m, m, m))
        return false;
    if (s == 0)
      first = h;
    else if (h != first)
      return false;
  }
  return true;
}

// The blocks averaged with the weights Hᵗ_i Hˣ_j at the fields v
// (FieldSystem::Fields), over the time slices [0, slices); symmetrized.
template <class System>
DensityBlocks MeanBlocks(const System& sys,
                         const action::FieldValues<double>& v, int slices) {
  constexpr int m = System::m;
  const auto& D = sys.time_operator().base();
  const auto& grid = sys.space_grid();
  Eigen::Matrix<double, System::K, System::K> sum;
  sum.setZero();
  double weight = 0;
  for (int i = 0; i < slices; ++i)
    for (int j = 0; j < sys.space_points(); ++j) {
      const double w = D.NormWeight(i) * grid.NormWeight(j);
      sum += w * sys.PointHessian(v, i, j);
      weight += w;
    }
  sum /= weight;
  sum = (0.5 * (sum + sum.transpose())).eval();
  return detail::BlocksOf<m, System::d>(sum);
}

// The blocks at one point z = (φ, φ_t, ∇φ) (a constant density's).
template <class Density>
DensityBlocks BlocksAt(const Density& density, const double* z) {
  constexpr int m = Density::kDim, d = action::SpaceDimOf<Density>();
  auto call = [&](const auto* w) { return density(w, w + m, w + 2 * m); };
  return detail::BlocksOf<m, d>(
      autodiff::Hessian<double, (2 + d) * m>(call, z).hessian);
}

}  // namespace vivp::spacetime
