// Central differences on a periodic grid x_j = x_0 + jΔx, j = 0 … n−1,
// x_n ≡ x_0: the interior stencils of the SBP operators without a boundary,
// orders 2q = 2, 4, 6, 8 (Fornberg, "Generation of finite difference
// formulas on arbitrarily spaced grids", Math. Comp. 1988):
//
//   (Du)_j = (1/Δx) Σ_{k=1..q} c_k (u_{j+k} − u_{j−k}).
//
// With the norm H = Δx·I the matrix D is skew-symmetric, HD + (HD)ᵀ = 0: the
// summation-by-parts property with no boundary term. For a field φ on a
// periodic domain it makes Σ_j Δx φ_j (Dφ)_j vanish, so the discrete action
// in space has no boundary contribution.
//
// Stored as the q coefficients of the stencil, never as a matrix; the
// arguments of Apply may be any scalar (automatic differentiation passes
// Jets through the stencil).
#pragma once

#include <array>
#include <span>
#include <stdexcept>
#include <string>

namespace vivp::sbp {

template <class Real>
class PeriodicOperator {
 public:
  // Throws std::invalid_argument for an order other than 2, 4, 6, 8, for
  // fewer than 2q + 1 points (the stencil would meet itself around the
  // circle) and for a length that is not positive and finite.
  PeriodicOperator(int order, int points, Real length)
      : order_(order), n_(points) {
    if (order != 2 && order != 4 && order != 6 && order != 8)
      throw std::invalid_argument("periodic differences of order " +
                                  std::to_string(order) +
                                  " do not exist here; use 2, 4, 6 or 8");
    if (points < order + 1)
      throw std::invalid_argument(
          "periodic differences of order " + std::to_string(order) +
          " need at least " + std::to_string(order + 1) + " points; got " +
          std::to_string(points) + " (use more points or a lower order)");
    if (!(length > Real(0)) || !(length < Real(1) / Real(0)))
      throw std::invalid_argument(
          "the periodic domain needs a positive, finite length");
    dx_ = length / Real(points);
    inv_dx_ = Real(1) / dx_;
    const int q = order / 2;
    // c_k of order 2q (Fornberg 1988, Table 1, first derivative, centred).
    static constexpr long double kC[4][4] = {
        {0.5L, 0, 0, 0},
        {2.0L / 3, -1.0L / 12, 0, 0},
        {3.0L / 4, -3.0L / 20, 1.0L / 60, 0},
        {4.0L / 5, -1.0L / 5, 4.0L / 105, -1.0L / 280}};
    for (int k = 0; k < q; ++k) c_[k] = Real(kC[q - 1][k]);
  }

  int order() const { return order_; }
  int points() const { return n_; }
  int half_width() const { return order_ / 2; }
  Real dx() const { return dx_; }
  Real inv_dx() const { return inv_dx_; }
  // H_jj = Δx for every j.
  Real NormWeight() const { return dx_; }
  // c_k, k = 1 … q.
  Real coefficient(int k) const { return c_[k - 1]; }
  // An index within q of [0, n) wrapped into it (n ≥ 2q + 1, so one
  // shift suffices).
  int Wrap(int j) const { return j < 0 ? j + n_ : j >= n_ ? j - n_ : j; }

  // (Du)_j; u points at all n values.
  template <class T>
  T ApplyAt(const T* u, int j) const {
    T acc = T(0.0);
    for (int k = 1; k <= half_width(); ++k)
      acc += T(c_[k - 1]) * (u[Wrap(j + k)] - u[Wrap(j - k)]);
    return acc * T(inv_dx_);
  }

  template <class T>
  void Apply(std::span<const T> u, std::span<T> out) const {
    if (static_cast<int>(u.size()) != n_ || static_cast<int>(out.size()) != n_)
      throw std::invalid_argument("PeriodicOperator::Apply: expected " +
                                  std::to_string(n_) + " values");
    const int q = half_width();
    // Only the q points at either end reach across the seam; the interior
    // reads its neighbours directly.
    for (int j = 0; j < q; ++j) out[j] = ApplyAt(u.data(), j);
    for (int j = q; j < n_ - q; ++j) {
      T acc = T(0.0);
      for (int k = 1; k <= q; ++k) acc += T(c_[k - 1]) * (u[j + k] - u[j - k]);
      out[j] = acc * T(inv_dx_);
    }
    for (int j = n_ - q; j < n_; ++j) out[j] = ApplyAt(u.data(), j);
  }

 private:
  int order_, n_;
  Real dx_ = 0, inv_dx_ = 0;
  std::array<Real, 4> c_{};
};

}  // namespace vivp::sbp
