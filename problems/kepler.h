// The Kepler problem H = ½|p|² − 1/|q| (docs/steppers.md §5): eccentricity e,
// q(0) = (1−e, 0), p(0) = (0, √((1+e)/(1−e))), H = −½, period 2π. e = 0.6 is
// the standard benchmark, e = 0.9 the hard case (speed √19 at pericentre).
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace vivp::problems {

struct Kepler {
  static constexpr int kDim = 2;
  static constexpr bool kConstantMass = true;  // L = ½ẋᵀMẋ − V(x)
  static constexpr bool kSeparable = true;
  double e = 0.6;

  // (q, p) of the initial data: pericentre.
  std::vector<double> Initial() const {
    return {1 - e, 0.0, 0.0, std::sqrt((1 + e) / (1 - e))};
  }

  // L = ½|ẋ|² + 1/|x|
  template <class T>
  T operator()(const T* x, const T* v) const {
    using std::sqrt;
    return T(0.5) * (v[0] * v[0] + v[1] * v[1]) +
           T(1.0) / sqrt(x[0] * x[0] + x[1] * x[1]);
  }

  // H = ½|p|² − 1/|q|
  template <class T>
  T Hamiltonian(const T* q, const T* p) const {
    using std::sqrt;
    return T(0.5) * (p[0] * p[0] + p[1] * p[1]) -
           T(1.0) / sqrt(q[0] * q[0] + q[1] * q[1]);
  }

  // Through quadratic invariants (LeMesurier 2012, §5.2): ŷ = (|p|², |q|²),
  // Ĥ = ½ŷ₀ − ŷ₁^{−½}. Both are rotation invariant, so the discrete gradient
  // keeps the angular momentum as well.
  static constexpr int kInvariantCount = 2;
  template <class T>
  void QuadraticInvariants(const T* q, const T* p, T* y) const {
    y[0] = p[0] * p[0] + p[1] * p[1];
    y[1] = q[0] * q[0] + q[1] * q[1];
  }
  template <class T>
  T HamiltonianOfInvariants(const T* y) const {
    using std::sqrt;
    return T(0.5) * y[0] - T(1.0) / sqrt(y[1]);
  }

  // Angular momentum ℓ = q × p and the Runge–Lenz vector A = p × ℓẑ − q/|q|.
  static std::vector<std::string> InvariantNames() {
    return {"angular_momentum", "runge_lenz_x", "runge_lenz_y"};
  }
  std::vector<double> Invariants(const double* q, const double* p) const {
    const double l = q[0] * p[1] - q[1] * p[0];
    const double r = std::hypot(q[0], q[1]);
    return {l, p[1] * l - q[0] / r, -p[0] * l - q[1] / r};
  }

  // Exact solution from Kepler's equation E − e sin E = t (semi-major axis
  // 1, so mean motion 1), solved by Newton to round-off:
  // q = (cos E − e, √(1−e²) sin E), p = (−sin E, √(1−e²) cos E)/(1 − e cos E).
  std::vector<double> Exact(double t) const {
    const double m = std::remainder(t, 2 * M_PI);
    double ecc_anomaly = e < 0.8 ? m : (m >= 0 ? M_PI : -M_PI);
    for (int k = 0; k < 100; ++k) {
      const double step = (ecc_anomaly - e * std::sin(ecc_anomaly) - m) /
                          (1 - e * std::cos(ecc_anomaly));
      ecc_anomaly -= step;
      if (std::fabs(step) <= 1e-16 * (1 + std::fabs(ecc_anomaly))) break;
    }
    const double c = std::cos(ecc_anomaly), s = std::sin(ecc_anomaly);
    const double b = std::sqrt(1 - e * e), d = 1 - e * c;
    return {c - e, b * s, -s / d, b * c / d};
  }
};

}  // namespace vivp::problems
