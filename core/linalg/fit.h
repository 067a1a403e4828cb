// Fitted convergence orders: least-squares slope of log(error) against
// log(step), with a round-off cut-off so that errors at the floor of the
// arithmetic do not bend the fit.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

namespace vivp::linalg {

struct PowerLawFit {
  double order = std::numeric_limits<double>::quiet_NaN();      // slope p
  double prefactor = std::numeric_limits<double>::quiet_NaN();  // C in C·h^p
  int points_used = 0;
};

// Fits error ≈ C h^p over the pairs with error > floor (and both finite and
// positive). Fewer than two usable pairs give NaN.
inline PowerLawFit FitPowerLaw(std::span<const double> h,
                               std::span<const double> error,
                               double floor = 0.0) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (std::size_t i = 0; i < h.size() && i < error.size(); ++i) {
    if (!(error[i] > floor) || !std::isfinite(error[i]) || !(h[i] > 0))
      continue;
    const double x = std::log(h[i]), y = std::log(error[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    ++n;
  }
  PowerLawFit fit;
  fit.points_used = n;
  const double det = n * sxx - sx * sx;
  if (n < 2 || det == 0) return fit;
  fit.order = (n * sxy - sx * sy) / det;
  fit.prefactor = std::exp((sy - fit.order * sx) / n);
  return fit;
}

}  // namespace vivp::linalg
