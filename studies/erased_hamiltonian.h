// A Hamiltonian of d degrees of freedom behind function objects (value,
// gradient, Hessian; SuppliesDerivatives in hamiltonian_system.h), so that
// the stepper templates are compiled once per (d, separable) for every
// registered Lagrangian (bench_lagrangian_impl.h) and a registration compiles
// only its own H. `Of` builds one from a Lagrangian's Legendre form
// (legendre.h), differentiated pointwise (core/autodiff/pointwise.h) like
// the action.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "core/autodiff/pointwise.h"
#include "studies/legendre.h"

namespace vivp::studies {

template <int d, bool Separable>
struct ErasedHamiltonian {
  static constexpr int kDim = d;
  static constexpr bool kSeparable = Separable;
  using Vector = Eigen::Matrix<double, 2 * d, 1>;
  using Matrix = Eigen::Matrix<double, 2 * d, 2 * d>;

  std::function<double(const double*)> value;
  std::function<Vector(const double*)> gradient;
  std::function<Matrix(const double*)> hessian;
  std::vector<double> initial;  // (q0, p0)

  double Value(const double* y) const { return value(y); }
  Vector Gradient(const double* y) const { return gradient(y); }
  Matrix Hessian(const double* y) const { return hessian(y); }
  std::vector<double> Initial() const { return initial; }

  // H of L's Legendre form, starting at the registered initial data with
  // p0 = Mẋ0 + b(q0).
  template <class L>
  static ErasedHamiltonian Of(const L& l, const LegendreForm<d>& form,
                              const variational::InitialData& init) {
    auto h = [l, form](const auto* y) {
      return LegendreHamiltonian<Separable>(l, form, y, y + d);
    };
    ErasedHamiltonian e;
    e.value = [h](const double* y) { return double(h(y)); };
    e.gradient = [h](const double* y) {
      return Vector(autodiff::Gradient<double, 2 * d>(h, y).second);
    };
    e.hessian = [h](const double* y) {
      return Matrix(autodiff::Hessian<double, 2 * d>(h, y).hessian);
    };
    double b[d];
    VectorPotential(l, init.x.data(), b);
    for (int c = 0; c < d; ++c) e.initial.push_back(init.x[c]);
    for (int c = 0; c < d; ++c) {
      double p = b[c];
      for (int j = 0; j < d; ++j)
        p += form.mass(c, j) * (init.v.empty() ? 0.0 : init.v[j]);
      e.initial.push_back(p);
    }
    return e;
  }
};

}  // namespace vivp::studies
