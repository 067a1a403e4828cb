// Initial profiles with exact solutions beyond exact.h, written out with
// their time derivative (no automatic differentiation: the sums over images
// need the value of x − ct to choose the images):
//
//   MovingGaussian  a Gaussian pulse f(y) = A exp(−y²/(2σ²)) moving at v,
//                   φ(0, x) = f(x − ξ), φ_t(0, x) = −v f′(x − ξ). For the wave
//                   equation φ_tt = c²φ_xx d'Alembert's formula gives
//                     φ = ½(1 + v/c) f(x − ct − ξ) + ½(1 − v/c) f(x + ct − ξ),
//                   summed over the pulse's images: ξ + kL on a periodic
//                   domain of length L; ξ + 2kL and its mirror 2x₀ − ξ + 2kL
//                   (moving at −v) on [x₀, x₀ + L] with φ_x = 0 at both ends,
//                   the even extension that satisfies the natural boundary
//                   condition.
//   PlaneWave       φ = A cos(kx − ωt) and, for two components,
//                   φ₁ = A sin(kx − ωt): with ∂V/∂φ_a = w(|φ|²) φ_a the field
//                   equation holds when ω² = c²k² + w(A²) (the caller's ω).
#pragma once

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace vivp::fields {

struct MovingGaussian {
  double amplitude = 1.0, width = 1.0, center = 0.0, velocity = 0.0;
  double c = 1.0;  // the wave speed of the exact solution

  // Mirrored: even images about both ends (φ_x = 0 there); anti-mirrored:
  // odd ones (φ = 0 there).
  enum class Images { kNone, kPeriodic, kMirrored, kAntiMirrored };
  Images images = Images::kNone;
  double x0 = 0.0, length = 1.0;  // the domain, for the images

  // φ and φ_t at (t, x); at t = 0 without images: the profile itself.
  std::pair<double, double> operator()(double t, double x) const {
    double phi = 0, phi_t = 0;
    auto add = [&](double xi, double v, double sign) {
      const double a = 0.5 * (1 + v / c), b = 0.5 * (1 - v / c);
      const auto [fr, dfr] = Pulse(x - c * t - xi);
      const auto [fl, dfl] = Pulse(x + c * t - xi);
      phi += sign * (a * fr + b * fl);
      phi_t += sign * (-c * a * dfr + c * b * dfl);
    };
    if (images == Images::kNone) {
      add(center, velocity, 1);
      return {phi, phi_t};
    }
    const double period = images == Images::kPeriodic ? length : 2 * length;
    // Images beyond 40σ of both x − ct and x + ct contribute below 1e-300.
    const double reach = 40 * width + c * std::abs(t);
    auto family = [&](double xi, double v, double sign) {
      const double first = std::ceil((x - xi - reach) / period);
      const double last = std::floor((x - xi + reach) / period);
      // A pulse far wider than the domain, or a time far beyond it, would
      // take more images than is sensible: no value rather than a wrong one.
      if (!(last - first < 1e5)) {
        phi = phi_t = std::numeric_limits<double>::quiet_NaN();
        return;
      }
      for (double k = first; k <= last; ++k) add(xi + k * period, v, sign);
    };
    family(center, velocity, 1);
    if (images != Images::kPeriodic)
      family(2 * x0 - center, -velocity,
             images == Images::kMirrored ? 1.0 : -1.0);
    return {phi, phi_t};
  }

 private:
  // f(y) and f′(y).
  std::pair<double, double> Pulse(double y) const {
    const double f = amplitude * std::exp(-y * y / (2 * width * width));
    return {f, -y / (width * width) * f};
  }
};

struct PlaneWave {
  double amplitude = 1.0, k = 1.0, omega = 1.0;
  int components = 1;
  // φ_a and φ_t,a at (t, x), a < components.
  void operator()(double t, double x, double* phi, double* phi_t) const {
    const double theta = k * x - omega * t;
    phi[0] = amplitude * std::cos(theta);
    phi_t[0] = amplitude * omega * std::sin(theta);
    if (components == 2) {
      phi[1] = amplitude * std::sin(theta);
      phi_t[1] = -amplitude * omega * std::cos(theta);
    }
  }
};

}  // namespace vivp::fields
