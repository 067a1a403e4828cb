// The power spectrum of a field slice on a periodic grid of d axes: the
// diagnostic of lattice field codes (the occupation of modes as energy
// moves between scales). With the discrete Fourier transform φ̂(k) over the
// N = Π_a N_a points (FFTW's multi-dimensional real transform, Frigo &
// Johnson, "The design and implementation of FFTW3", Proc. IEEE 2005),
//
//   P(k) = Σ_{|k⃗| in the bin of k} |φ̂(k⃗)|² / N²,
//
// k⃗ = (2π k_a / L_a)_a with integer k_a in (−N_a/2, N_a/2], binned by |k⃗|
// in bins of Δk = 2π / max_a L_a. By Parseval, Σ_bins P = (1/N) Σ_j φ_j²,
// the mean square of the slice.
#pragma once

#include <span>
#include <vector>

#include "core/sbp/space_grid.h"

namespace vivp::spacetime {

struct SpectrumBin {
  double k = 0;      // the bin's centre, |k⃗| in [k − Δk/2, k + Δk/2)
  double power = 0;  // P(k)
  long long modes = 0;
};

// The spectrum of component a of the slice phi (value j·m + a). Throws
// std::invalid_argument unless every axis is periodic and phi has m values
// per point.
std::vector<SpectrumBin> PowerSpectrum(const sbp::SpaceGrid<double>& grid,
                                       std::span<const double> phi, int m = 1,
                                       int a = 0);

}  // namespace vivp::spacetime
