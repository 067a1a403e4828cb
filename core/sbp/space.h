// The derivative in space of a 1+1-dimensional field: either the periodic
// central differences of periodic.h or an SBP operator of operator.h on a
// bounded interval. Both satisfy H D + (H D)ᵀ = B with H diagonal (B = 0 on
// the periodic circle, diag(−1, 0, …, 0, 1) on the interval), which is all
// the discrete action needs:
//
//   Σ_j H_j q_j (D u)_j = qᵀ H D u,   its variation in u is Dᵀ H q = B q − H D
//   q,
//
// so the transpose is never stored. On the interval the boundary term B q
// is the natural boundary condition of the discrete action: with
// L = … − ½c²φ_x², q = −c²φ_x and the action is stationary only if φ_x = 0 at
// both ends, imposed weakly (docs/fields.md §2).
//
//   auto dx = vivp::sbp::SpaceDerivative<double>::Periodic(8, 64, 0.0, 2 * pi);
//   auto dx = vivp::sbp::SpaceDerivative<double>::Bounded("sbp42", 81, -20,
//   20);
#pragma once

#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/sbp/builder.h"
#include "core/sbp/periodic.h"

namespace vivp::sbp {

template <class Real>
class SpaceDerivative {
 public:
  // n points x_j = x0 + jΔx, Δx = length/n, x_n ≡ x_0.
  static SpaceDerivative Periodic(int order, int points, Real x0, Real length) {
    SpaceDerivative s;
    s.periodic_.emplace(order, points, length);
    s.x0_ = x0;
    return s;
  }
  // n points on [x0, x1] including both ends, Δx = (x1 − x0)/(n − 1).
  static SpaceDerivative Bounded(std::string_view name, int points, Real x0,
                                 Real x1) {
    // Space is a uniform grid of any size: the finite-difference operators
    // only, not the spectral elements (lobatto.h).
    if (IsElement(name))
      throw std::invalid_argument(
          std::string(name) +
          " is a spectral element in time; a space axis takes " +
          OperatorNameList());
    SpaceDerivative s;
    s.bounded_.emplace(MakeOperator<Real>(name, points, x0, x1));
    s.x0_ = x0;
    return s;
  }

  bool periodic() const { return periodic_.has_value(); }
  int points() const {
    return periodic_ ? periodic_->points() : bounded_->points();
  }
  // The interior order: 2q for periodic differences, 2p for SBP(2p, p).
  int order() const {
    return periodic_ ? periodic_->order() : bounded_->interior_order();
  }
  std::string name() const {
    return periodic_ ? "periodic" + std::to_string(periodic_->order())
                     : std::string(bounded_->name());
  }
  Real x0() const { return x0_; }
  Real dx() const { return periodic_ ? periodic_->dx() : bounded_->dt(); }
  Real x(int j) const { return x0_ + dx() * static_cast<Real>(j); }
  Real NormWeight(int j) const {
    return periodic_ ? periodic_->NormWeight() : bounded_->NormWeight(j);
  }
  const PeriodicOperator<Real>* periodic_operator() const {
    return periodic_ ? &*periodic_ : nullptr;
  }

  // out = D u.
  template <class T>
  void Apply(std::span<const T> u, std::span<T> out) const {
    if (periodic_)
      periodic_->Apply(u, out);
    else
      bounded_->Apply(u, out);
  }

  // The derivative of a slice of m interleaved components (value j·m + a),
  // each on its own.
  void ApplyComponents(int m, std::span<const Real> u,
                       std::span<Real> out) const {
    const int n = points();
    std::vector<Real> comp(n), dcomp(n);
    for (int a = 0; a < m; ++a) {
      for (int j = 0; j < n; ++j) comp[j] = u[j * m + a];
      Apply<Real>(comp, dcomp);
      for (int j = 0; j < n; ++j) out[j * m + a] = dcomp[j];
    }
  }

  // out_j += (Dᵀ H q)_j = (B q)_j − H_j (D q)_j, the variation of Σ H q D u;
  // dq is scratch of n values.
  template <class T>
  void AddTransposeH(std::span<const T> q, std::span<T> dq,
                     std::span<T> out) const {
    Apply(q, dq);
    const int n = points();
    for (int j = 0; j < n; ++j) out[j] -= T(NormWeight(j)) * dq[j];
    if (!periodic_) {
      out[0] -= q[0];
      out[n - 1] += q[n - 1];
    }
  }

  // Calls fn(l, D_jl) for the nonzero entries of row j, 1/Δx included.
  template <class F>
  void ForRow(int j, F&& fn) const {
    if (periodic_) {
      const auto& p = *periodic_;
      for (int k = 1; k <= p.half_width(); ++k) {
        const Real c = p.coefficient(k) * p.inv_dx();
        fn(p.Wrap(j + k), c);
        fn(p.Wrap(j - k), -c);
      }
      return;
    }
    const auto& d = *bounded_;
    const auto row = d.row(j);
    for (std::size_t k = 0; k < row.coeffs.size(); ++k)
      if (row.coeffs[k] != Real(0))
        fn(row.first + static_cast<int>(k), row.coeffs[k] * d.inv_dt());
  }

 private:
  SpaceDerivative() = default;
  std::optional<PeriodicOperator<Real>> periodic_;
  std::optional<Operator<Real>> bounded_;
  Real x0_ = 0;
};

}  // namespace vivp::sbp
