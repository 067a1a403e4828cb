// Free fall, Rothkopf & Nordström (2023) Sec. 3 (eqs. 23-24):
//   L = ½mẋ² − mgx,  ẍ = −g;  m = g = 1, x(0) = 1, ẋ(0) = 0.3, x(1) = 0.8.
// The exact path is a parabola, which SBP42 differentiates exactly: any error
// of an SBP42 solve is round-off.
#pragma once

namespace vivp::problems {

struct FreeFall {
  static constexpr int kDim = 1;
  static constexpr bool kConstantMass = true;  // L = ½ẋᵀMẋ − V(x)
  double m = 1.0;
  double g = 1.0;
  double x0 = 1.0;
  double v0 = 0.3;

  // L = ½mẋ² − mgx
  template <class T>
  T operator()(const T* x, const T* v) const {
    return T(0.5 * m) * v[0] * v[0] - T(m * g) * x[0];
  }

  struct State {
    double x, v;
  };
  State Exact(double t) const {
    return {x0 + v0 * t - 0.5 * g * t * t, v0 - g * t};
  }
};

}  // namespace vivp::problems
