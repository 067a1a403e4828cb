// A field window solved by Ceres Levenberg–Marquardt (the design's
// reference path, solvers/variational/ceres_lm.h) instead of Newton: the
// window's equations as rows of residual blocks, one parameter block per
// spatial point (its column, λ3 and λ4), the Jacobian through its band.
// LM's damping makes each step well defined where the Jacobian is singular
// (the gauge directions of docs/gauge.md): a measurement to compare the
// Fourier window solve with, on small windows (the band of a periodic grid
// wraps around, so the stored band is nearly the whole matrix).
#pragma once

#include <vector>

#include "core/linalg/banded.h"
#include "solvers/variational/ceres_lm.h"

namespace vivp::spacetime {

template <class System>
variational::NewtonReport SolveWindowCeres(
    const System& sys, std::vector<double>& y,
    const variational::CeresOptions& options = {}) {
  variational::detail::LmSystem s;
  s.size = sys.size();
  sys.Jacobian(y.data(), s.band);
  const int block = sys.Phi(0, 1, 0);  // a point's unknowns
  for (int j = 0; j < sys.space_points(); ++j) {
    s.block_offsets.push_back(j * block);
    s.block_sizes.push_back(block);
  }
  s.gradient = [&sys](const double* x, double* g) { sys.Residual(x, g); };
  s.hessian = [&sys](const double* x, linalg::BandedMatrix<double>& h) {
    sys.Jacobian(x, h);
  };
  return variational::detail::RunCeresLm(s, y, options);
}

}  // namespace vivp::spacetime
