// The harmonic oscillator H = ½p² + ½ω²q². Linear, so it cannot reveal
// nonlinear defects (orders are fitted on the pendulum and Kepler instead);
// with large ω it is a stiff spring: an explicit method is unstable once hω
// exceeds its stability interval (RK4: 2√2).
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace vivp::problems {

struct HarmonicOscillator {
  static constexpr int kDim = 1;
  static constexpr bool kConstantMass = true;  // L = ½ẋᵀMẋ − V(x)
  static constexpr bool kSeparable = true;
  double omega = 1.0;
  std::array<double, 1> q0 = {1.0};
  std::array<double, 1> p0 = {0.0};

  // L = ½ẋ² − ½ω²x²
  template <class T>
  T operator()(const T* x, const T* v) const {
    return T(0.5) * v[0] * v[0] - T(0.5 * omega * omega) * x[0] * x[0];
  }

  // H = ½p² + ½ω²q²
  template <class T>
  T Hamiltonian(const T* q, const T* p) const {
    return T(0.5) * p[0] * p[0] + T(0.5 * omega * omega) * q[0] * q[0];
  }

  // No invariants besides H.

  // q = q0 cos ωt + (p0/ω) sin ωt, p = −ω q0 sin ωt + p0 cos ωt.
  std::vector<double> Exact(double t) const {
    const double c = std::cos(omega * t), s = std::sin(omega * t);
    return {q0[0] * c + p0[0] / omega * s, -omega * q0[0] * s + p0[0] * c};
  }
};

}  // namespace vivp::problems
