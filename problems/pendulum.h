// The mathematical pendulum H = ½p² − cos q (docs/steppers.md §5), q(0) = 0,
// p(0) = 1: a libration with energy −½, turning points ±π/3.
// Reference (docs/steppers.md §5): q(2π) = −0.443944662290259,
//                                  p(2π) =  0.897846803312944.
#pragma once

#include <array>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>
#include <string>
#include <vector>

namespace vivp::problems {

struct Pendulum {
  static constexpr int kDim = 1;
  static constexpr bool kConstantMass = true;  // L = ½ẋᵀMẋ − V(x)
  static constexpr bool kSeparable = true;
  std::array<double, 1> q0 = {0.0};
  std::array<double, 1> p0 = {1.0};

  // L = ½ẋ² + cos x
  template <class T>
  T operator()(const T* x, const T* v) const {
    using std::cos;
    return T(0.5) * v[0] * v[0] + cos(x[0]);
  }

  // H = ½p² − cos q
  template <class T>
  T Hamiltonian(const T* q, const T* p) const {
    using std::cos;
    return T(0.5) * p[0] * p[0] - cos(q[0]);
  }

  // Through invariants for the discrete gradient (LeMesurier 2012, §5.2):
  // ŷ = (p², q) (the second is affine, which the engine allows),
  // Ĥ = ½ŷ₀ − cos ŷ₁.
  static constexpr int kInvariantCount = 2;
  template <class T>
  void QuadraticInvariants(const T* q, const T* p, T* y) const {
    y[0] = p[0] * p[0];
    y[1] = q[0];
  }
  template <class T>
  T HamiltonianOfInvariants(const T* y) const {
    using std::cos;
    return T(0.5) * y[0] - cos(y[1]);
  }

  // Exact solution for q(0) = 0, p(0) = p0 < 2 (libration):
  // q = 2 arcsin(k sn(t, k)), p = 2k cn(t, k), k = p0/2.
  std::vector<double> Exact(double t) const {
    const double k = 0.5 * p0[0];
    double cn = 0, dn = 0;
    const double sn = boost::math::jacobi_elliptic(k, t, &cn, &dn);
    return {2 * std::asin(k * sn), 2 * k * cn};
  }
};

}  // namespace vivp::problems
