// Exact solutions of the densities in densities.h, the references of the
// field solver's convergence tests. Each is φ(t, x) templated on the scalar,
// so that φ_t, φ_x (initial data) and φ_tt, φ_xx (the field equation, in the
// tests) come from automatic differentiation of the same formula.
//
// Sine-Gordon φ_tt − φ_xx + sin φ = 0 (Rajaraman, "Solitons and
// Instantons", 1982, ch. 2; Perring & Skyrme 1962 for the kink–antikink
// pair): with γ = 1/√(1 − v²),
//   kink          φ = 4 atan(exp(γ(x − x₀ − vt)))          (charge +1)
//   breather      φ = 4 atan(√(1 − ω²) sin(ωt) / (ω cosh(√(1 − ω²) x)))
//   kink–antikink φ = 4 atan(v⁻¹ sinh(γvt) / cosh(γx))     (charge 0)
// φ⁴ with V = ¼λ(φ² − v²)²: φ = v tanh(v√(λ/2) γ(x − x₀ − ut)).
// Klein–Gordon: φ = A cos(kx − ωt), ω² = c²k² + m².
// Wave equation (d'Alembert): φ = ½[f(x − ct) + f(x + ct)] for φ(0, x) = f,
// φ_t(0, x) = 0, with the Gaussian f = exp(−x²/(2σ²)).
#pragma once

#include <ceres/jet.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/sbp/space.h"
#include "problems/fields/densities.h"

namespace vivp::fields {

namespace detail {
// γ = 1/√(1 − v²); a speed at or above that of light (1 here) has no
// solution, so it is refused rather than turned into NaN.
inline double LorentzFactor(double v) {
  if (!(std::abs(v) < 1.0))
    throw std::invalid_argument(
        "a soliton's velocity must satisfy |v| < 1 (got " + std::to_string(v) +
        ")");
  return 1.0 / std::sqrt(1.0 - v * v);
}

// atan(y) as atan2(y, 1): Eigen's AutoDiffScalar has atan2, not atan.
template <class T>
T Atan(const T& y) {  // called with a concrete T, not an expression
  using std::atan2;
  return atan2(y, T(1.0));
}
}  // namespace detail

struct KleinGordonPlaneWave {
  KleinGordon density;
  double amplitude = 1.0, k = 1.0;
  double omega() const {
    return std::sqrt(density.c * density.c * k * k +
                     density.mass * density.mass);
  }
  template <class T>
  T operator()(const T& t, const T& x) const {
    using std::cos;
    return T(amplitude) * cos(T(k) * x - T(omega()) * t);
  }
};

struct SineGordonKink {
  double velocity = 0.0, x0 = 0.0;
  template <class T>
  T operator()(const T& t, const T& x) const {
    using std::exp;
    const double gamma = detail::LorentzFactor(velocity);
    const T y = exp(T(gamma) * (x - T(x0) - T(velocity) * t));
    return T(4.0) * detail::Atan<T>(y);
  }
};

struct SineGordonBreather {
  double omega = 0.5;
  template <class T>
  T operator()(const T& t, const T& x) const {
    using std::cosh;
    using std::sin;
    if (!(omega > 0.0 && omega < 1.0))
      throw std::invalid_argument(
          "the sine-Gordon breather needs 0 < ω < 1 (got " +
          std::to_string(omega) + ")");
    const double s = std::sqrt(1.0 - omega * omega);
    const T y = T(s / omega) * sin(T(omega) * t) / cosh(T(s) * x);
    return T(4.0) * detail::Atan<T>(y);
  }
};

struct SineGordonKinkAntikink {
  double velocity = 0.5;
  template <class T>
  T operator()(const T& t, const T& x) const {
    using std::cosh;
    using std::sinh;
    if (velocity == 0.0)
      throw std::invalid_argument(
          "the kink–antikink pair needs a velocity 0 < |v| < 1 (at v = 0 "
          "there is no pair solution of this form)");
    const double gamma = detail::LorentzFactor(velocity);
    const T y =
        sinh(T(gamma * velocity) * t) / (T(velocity) * cosh(T(gamma) * x));
    return T(4.0) * detail::Atan<T>(y);
  }
};

struct Phi4Kink {
  Phi4 density;
  double velocity = 0.0, x0 = 0.0;
  template <class T>
  T operator()(const T& t, const T& x) const {
    using std::tanh;
    const double gamma = detail::LorentzFactor(velocity);
    const double a = density.v * std::sqrt(0.5 * density.lambda) * gamma;
    return T(density.v) * tanh(T(a) * (x - T(x0) - T(velocity) * t));
  }
};

struct WaveGaussian {
  Wave density;
  double sigma = 1.0;
  template <class T>
  T operator()(const T& t, const T& x) const {
    using std::exp;
    const T a = x - T(density.c) * t, b = x + T(density.c) * t;
    const double s = 1.0 / (2.0 * sigma * sigma);
    return T(0.5) * (exp(-T(s) * a * a) + exp(-T(s) * b * b));
  }
};

// φ(0, x_j) and φ_t(0, x_j) of an exact solution u(t, x) on the grid of dx
// (one component), φ_t by a Jet in t: the initial data of a solve.
template <class U>
std::pair<std::vector<double>, std::vector<double>> InitialData(
    const U& u, const sbp::SpaceDerivative<double>& dx) {
  using J = ceres::Jet<double, 1>;
  std::vector<double> phi(dx.points()), pi(dx.points());
  for (int j = 0; j < dx.points(); ++j) {
    const J v = u(J(0.0, 0), J(dx.x(j)));
    phi[j] = v.a;
    pi[j] = v.v[0];
  }
  return {phi, pi};
}

}  // namespace vivp::fields
