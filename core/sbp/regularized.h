// The regularized operator D̄ of Rothkopf & Nordström (2023), Sec. 3.2.
//
// The SAT penalty sigma0 H^{-1} E0 (x - g) of eq. (28) is absorbed into the
// derivative in affine coordinates x̄ = (x, 1):
//   D̄ x̄ = (D - sigma0 H^{-1} E0) x + sigma0 H^{-1} E0 g,
// so only row 0 changes:
//   (D̄ x̄)_0 = (D x)_0 - sigma0 (x_0 - x_i) / H_00,
// with x_i the initial value and H_00 the first norm weight (dt/2 for SBP21).
// sigma0 = -1 is the only value that reproduces the paper (docs/method.md §3);
// the printed top-left entry of eq. (29) is a typo, the correct one is
// -1/dt - 2 sigma0/dt = +1/dt for SBP21.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/sbp/operator.h"

namespace vivp::sbp {

template <class Real>
class RegularizedOperator {
 public:
  explicit RegularizedOperator(Operator<Real> d, Real sigma0 = Real(-1))
      : d_(std::move(d)),
        sigma0_(sigma0),
        penalty_(-sigma0 / d_.NormWeight(0)) {
    if (!std::isfinite(static_cast<long double>(sigma0)))
      throw std::invalid_argument("sigma0 must be finite, got " +
                                  std::to_string(static_cast<double>(sigma0)));
  }

  const Operator<Real>& base() const { return d_; }
  // The same operator on [t_start, t_end] (Operator::Retime), its penalty
  // recomputed as the constructor computes it.
  void Retime(Real t_start, Real t_end) {
    d_.Retime(t_start, t_end);
    penalty_ = -sigma0_ / d_.NormWeight(0);
  }
  Real sigma0() const { return sigma0_; }
  int points() const { return d_.points(); }
  // -sigma0 / H_00: the coefficient of (x_0 - x_i) added to row 0.
  Real penalty() const { return penalty_; }

  // (D̄ x̄)_i for the path x with initial value x_initial.
  template <class T>
  T ApplyRow(int i, const T* x, const T& x_initial) const {
    T out = d_.ApplyRow(i, x);
    if (i == 0) autodiff::AddScaled(out, penalty_, T(x[0] - x_initial));
    return out;
  }

  template <class T>
  void Apply(std::span<const T> x, const T& x_initial, std::span<T> out) const {
    d_.Apply(x, out);
    autodiff::AddScaled(out[0], penalty_, T(x[0] - x_initial));
  }

  // The (N+1)x(N+1) affine matrix [[D - sigma0 H^{-1}E0, b], [0, 1]] with
  // shift b = sigma0 H^{-1} E0 g, g = (x_i, 0, ..., 0).
  Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic> AffineMatrix(
      Real x_initial) const {
    const int n = d_.points();
    Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic> m =
        Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>::Zero(n + 1, n + 1);
    m.topLeftCorner(n, n) = d_.DenseD();
    m(0, 0) += penalty_;
    m(0, n) = -penalty_ * x_initial;
    m(n, n) = Real(1);
    return m;
  }

 private:
  Operator<Real> d_;
  Real sigma0_;
  Real penalty_;
};

// out(j) += (D̄ᵀ H w)_j for j = 0 … N−1, through HD + DᵀH = B:
// DᵀHw = Bw − H D w, so the only stencil work is D applied (in its
// exact-on-constants difference form) to w, and D̄ᵀ = Dᵀ + penalty·E0 adds
// penalty·H_0 w_0 = −σ0 w_0. An assembled DᵀHD would have row sums that are
// not exactly zero, a spurious constant force (docs/method.md §6). `dw` is
// scratch of any size.
template <class Real, class Out>
void AddDbarTransposeHw(const RegularizedOperator<Real>& dbar,
                        const std::vector<Real>& w, std::vector<Real>& dw,
                        Out&& out) {
  const auto& D = dbar.base();
  const int n = D.points();
  dw.resize(n);
  D.Apply(std::span<const Real>(w), std::span<Real>(dw));
  for (int j = 0; j < n; ++j) out(j) -= D.NormWeight(j) * dw[j];
  out(0) += (-dbar.sigma0() - Real(1)) * w[0];
  out(n - 1) += w[n - 1];
}

}  // namespace vivp::sbp
