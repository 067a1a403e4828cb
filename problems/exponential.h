// Exponential growth, a first-order system: Rothkopf & Nordström (2023),
// eqs. 36-39:
//   ẋ = κx,  L = −½κx²,  Λ = ẋ₊x₋ with ẋ₊ = (ẋ1 + ẋ2)/2, x₋ = x1 − x2;
//   κ = 5/2, x(0) = 1.
// Λ with ẋ₊ built from both regularized paths equals the paper's
// ½ D̄(x̄1 + x̄2) with affine entry 2 (docs/method.md §3).
#pragma once

#include <cmath>

namespace vivp::problems {

struct Exponential {
  static constexpr int kDim = 1;
  double kappa = 2.5;
  double x0 = 1.0;

  // L = −½κx²
  template <class T>
  T operator()(const T* x, const T* /*v*/) const {
    return T(-0.5 * kappa) * x[0] * x[0];
  }

  // Λ = ẋ₊x₋
  template <class T>
  T Lambda(const T* x1, const T* v1, const T* x2, const T* v2) const {
    return T(0.5) * (v1[0] + v2[0]) * (x1[0] - x2[0]);
  }

  struct State {
    double x, v;
  };
  State Exact(double t) const {
    const double x = x0 * std::exp(kappa * t);
    return {x, kappa * x};
  }
};

}  // namespace vivp::problems
