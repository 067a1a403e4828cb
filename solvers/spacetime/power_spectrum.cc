#include "solvers/spacetime/power_spectrum.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace vivp::spacetime {

std::vector<SpectrumBin> PowerSpectrum(const sbp::SpaceGrid<double>& grid,
                                       std::span<const double> phi, int m,
                                       int a) {
  const int d = grid.dim();
  const std::size_t n = std::size_t(grid.points());
  if (m < 1 || a < 0 || a >= m || phi.size() != n * std::size_t(m))
    throw std::invalid_argument(
        "power spectrum: expected " + std::to_string(n) + " × " +
        std::to_string(m) + " values and a component below " +
        std::to_string(m) + ", got " + std::to_string(phi.size()) +
        " values and component " + std::to_string(a));
  double longest = 0;
  std::vector<double> length(d);
  for (int b = 0; b < d; ++b) {
    if (!grid.axis(b).periodic())
      throw std::invalid_argument("power spectrum: axis " + std::to_string(b) +
                                  " is not periodic (the spectrum is that of "
                                  "a periodic grid)");
    length[b] = grid.axis(b).dx() * grid.points(b);
    longest = std::max(longest, length[b]);
  }
  // FFTW's arrays are row-major (last index fastest): dimensions reversed.
  std::vector<int> dims(d);
  for (int b = 0; b < d; ++b) dims[d - 1 - b] = grid.points(b);
  const int n0 = grid.points(0), half = n0 / 2 + 1;
  const std::size_t out = n / std::size_t(n0) * std::size_t(half);
  double* in = fftw_alloc_real(n);
  fftw_complex* hat = fftw_alloc_complex(out);
  const fftw_plan plan =
      fftw_plan_dft_r2c(d, dims.data(), in, hat, FFTW_ESTIMATE);
  for (std::size_t j = 0; j < n; ++j) in[j] = phi[j * m + a];
  fftw_execute(plan);
  const double dk = 2 * std::numbers::pi / longest;
  std::vector<SpectrumBin> bins;
  const double norm = 1.0 / (double(n) * double(n));
  for (std::size_t r = 0; r < out; ++r) {
    // Output index r: axis 0 over [0, half), then the other axes in full.
    std::size_t rest = r / std::size_t(half);
    const int i0 = int(r % std::size_t(half));
    double k2 = std::pow(2 * std::numbers::pi * i0 / length[0], 2);
    for (int b = 1; b < d; ++b) {
      const int nb = grid.points(b);
      int ib = int(rest % std::size_t(nb));
      rest /= std::size_t(nb);
      if (ib > nb / 2) ib -= nb;
      k2 += std::pow(2 * std::numbers::pi * ib / length[b], 2);
    }
    // The modes of axis 0 left out by the real transform are the complex
    // conjugates of those inside (0 < i0 < n0/2 stands for two).
    const int weight = i0 == 0 || 2 * i0 == n0 ? 1 : 2;
    const std::size_t bin = std::size_t(std::floor(std::sqrt(k2) / dk + 0.5));
    if (bin >= bins.size()) bins.resize(bin + 1);
    bins[bin].power +=
        weight * norm * (hat[r][0] * hat[r][0] + hat[r][1] * hat[r][1]);
    bins[bin].modes += weight;
  }
  for (std::size_t b = 0; b < bins.size(); ++b) bins[b].k = dk * double(b);
  fftw_destroy_plan(plan);
  fftw_free(hat);
  fftw_free(in);
  return bins;
}

}  // namespace vivp::spacetime
