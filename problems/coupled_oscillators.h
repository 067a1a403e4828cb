// Two unit masses on springs to the wall (k) and to each other (c):
//   L = ½(ẋ1² + ẋ2²) − ½k(x1² + x2²) − ½c(x1 − x2)²,
// a d = 2 system with the exact solution of its normal modes
//   y± = x1 ± x2,  ÿ+ = −k y+,  ÿ− = −(k + 2c) y−.
#pragma once

#include <array>
#include <cmath>

namespace vivp::problems {

struct CoupledOscillators {
  static constexpr int kDim = 2;
  static constexpr bool kConstantMass = true;  // L = ½ẋᵀMẋ − V(x)
  double k = 1.0;
  double c = 0.5;
  std::array<double, 2> x0 = {1.0, 0.0};
  std::array<double, 2> v0 = {0.0, 0.3};

  // L = ½|ẋ|² − ½k|x|² − ½c(x1 − x2)²
  template <class T>
  T operator()(const T* x, const T* v) const {
    const T dx = x[0] - x[1];
    return T(0.5) * (v[0] * v[0] + v[1] * v[1]) -
           T(0.5 * k) * (x[0] * x[0] + x[1] * x[1]) - T(0.5 * c) * dx * dx;
  }

  struct State {
    std::array<double, 2> x, v;
  };
  State Exact(double t) const {
    auto mode = [t](double omega, double y0, double w0, double& y, double& w) {
      y = y0 * std::cos(omega * t) + w0 / omega * std::sin(omega * t);
      w = -y0 * omega * std::sin(omega * t) + w0 * std::cos(omega * t);
    };
    double yp, wp, ym, wm;
    mode(std::sqrt(k), x0[0] + x0[1], v0[0] + v0[1], yp, wp);
    mode(std::sqrt(k + 2 * c), x0[0] - x0[1], v0[0] - v0[1], ym, wm);
    return {{0.5 * (yp + ym), 0.5 * (yp - ym)},
            {0.5 * (wp + wm), 0.5 * (wp - wm)}};
  }
};

}  // namespace vivp::problems
