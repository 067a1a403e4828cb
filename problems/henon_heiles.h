// The Hénon–Heiles system H = ½|p|² + ½|q|² + q₁²q₂ − q₂³/3 with
// q = p = (0.18, 0.18) (docs/steppers.md §5), energy ≈ 0.0718, regular orbit.
// No closed-form solution: references come from Gauss–Legendre (s = 3) at a
// much smaller step (stated where used).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace vivp::problems {

struct HenonHeiles {
  static constexpr int kDim = 2;
  static constexpr bool kConstantMass = true;  // L = ½ẋᵀMẋ − V(x)
  static constexpr bool kSeparable = true;
  std::array<double, 2> q0 = {0.18, 0.18};
  std::array<double, 2> p0 = {0.18, 0.18};

  // L = ½|ẋ|² − ½|x|² − x₁²x₂ + x₂³/3
  template <class T>
  T operator()(const T* x, const T* v) const {
    return T(0.5) * (v[0] * v[0] + v[1] * v[1]) - Potential(x);
  }

  // H = ½|p|² + ½|q|² + q₁²q₂ − q₂³/3
  template <class T>
  T Hamiltonian(const T* q, const T* p) const {
    return T(0.5) * (p[0] * p[0] + p[1] * p[1]) + Potential(q);
  }

  template <class T>
  T Potential(const T* q) const {
    return T(0.5) * (q[0] * q[0] + q[1] * q[1]) + q[0] * q[0] * q[1] -
           q[1] * q[1] * q[1] / T(3.0);
  }
};

}  // namespace vivp::problems
