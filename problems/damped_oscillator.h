// The damped harmonic oscillator of Rothkopf & Nordström (2023), eqs. 40-43:
//   L = ½μẋ² − ½κx²,  Λ = −ξẋ₊x₋;  μ = 0.5, κ = 1, ξ = 0.00071,
//   x(0) = 1, ẋ(0) = 0.
// Eq. (43) as printed solves μẍ + ξẋ + κx = 0 (x(1) ≈ 0.156); eqs. (41)-(42)
// suggest 2κ. We follow eq. (43); the convergence orders are the same either
// way (docs/method.md §11).
#pragma once

#include <cmath>

namespace vivp::problems {

struct DampedOscillator {
  static constexpr int kDim = 1;
  double mu = 0.5;
  double kappa = 1.0;
  double xi = 0.00071;
  double x0 = 1.0;
  double v0 = 0.0;

  // L = ½μẋ² − ½κx²
  template <class T>
  T operator()(const T* x, const T* v) const {
    return T(0.5 * mu) * v[0] * v[0] - T(0.5 * kappa) * x[0] * x[0];
  }

  // Λ = −ξẋ₊x₋ (Galley's non-conservative term for linear damping)
  template <class T>
  T Lambda(const T* x1, const T* v1, const T* x2, const T* v2) const {
    return T(-0.5 * xi) * (v1[0] + v2[0]) * (x1[0] - x2[0]);
  }

  double Energy(double x, double v) const {
    return 0.5 * mu * v * v + 0.5 * kappa * x * x;
  }

  // x = e^{−γt}(A cos ωt + B sin ωt), γ = ξ/(2μ), ω = √(κ/μ − γ²).
  struct State {
    double x, v;
  };
  State Exact(double t) const {
    const double gamma = xi / (2 * mu);
    const double omega = std::sqrt(kappa / mu - gamma * gamma);
    const double a = x0, b = (v0 + gamma * x0) / omega;
    const double e = std::exp(-gamma * t), c = std::cos(omega * t),
                 s = std::sin(omega * t);
    return {e * (a * c + b * s),
            e * ((-gamma * a + omega * b) * c + (-gamma * b - omega * a) * s)};
  }
};

}  // namespace vivp::problems
