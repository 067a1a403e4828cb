// The anharmonic oscillator of Rothkopf & Nordström (2023), Sec. 4.2:
//   x'' + kappa x^3 = 0,  kappa = 20, x(0) = 1, x'(0) = 0.3.
// (The paper does not state x'(0); 0.3 reproduces its convergence orders,
// docs/method.md §11.)
#pragma once

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>

namespace vivp::problems {

struct Anharmonic {
  static constexpr int kDim = 1;
  static constexpr bool kConstantMass = true;  // L = ½ẋᵀMẋ − V(x)
  double kappa = 20.0;
  double x0 = 1.0;
  double v0 = 0.3;

  // L = ½ẋ² − ¼κx⁴
  template <class T>
  T operator()(const T* x, const T* v) const {
    return T(0.5) * v[0] * v[0] - T(0.25 * kappa) * x[0] * x[0] * x[0] * x[0];
  }

  // H = ½p² + ¼κq⁴
  template <class T>
  T Hamiltonian(const T* q, const T* p) const {
    return T(0.5) * p[0] * p[0] + T(0.25 * kappa) * q[0] * q[0] * q[0] * q[0];
  }

  double Energy() const {
    return 0.5 * v0 * v0 + 0.25 * kappa * std::pow(x0, 4);
  }

  // Exact solution x(t) = A cn(ω (t − t0) | k² = ½), A = (4E/κ)^¼, ω = A√κ
  // (x = A cn(ωt) solves x'' = −κx³ exactly when k² = ½). The phase u0 = −ω t0
  // satisfies cn(u0) = x0/A with sn(u0) of the sign opposite to v0.
  struct State {
    double x, v;
  };
  State Exact(double t) const {
    using boost::math::ellint_1;
    using boost::math::jacobi_elliptic;
    const double k = std::sqrt(0.5);
    const double amplitude = std::pow(4 * Energy() / kappa, 0.25);
    const double omega = amplitude * std::sqrt(kappa);
    const double ratio = std::fmin(1.0, std::fmax(-1.0, x0 / amplitude));
    double u0 = ellint_1(k, std::acos(ratio));
    if (v0 > 0) u0 = -u0;
    double sn, cn, dn;
    sn = jacobi_elliptic(k, u0 + omega * t, &cn, &dn);
    return {amplitude * cn, -amplitude * omega * sn * dn};
  }
};

}  // namespace vivp::problems
