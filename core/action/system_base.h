// What the full doubled system (full_system.h) and the reduced system
// (reduced_system.h) share: the problem, the regularized operator D̄ with its
// affine shift, the initial data, and the two pieces of SBP arithmetic both
// residuals and Jacobians are made of — the paths' velocities v = D̄x̄ and the
// transpose D̄ᵀ H w evaluated through the SBP property (docs/method.md §4, §6).
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "core/sbp/regularized.h"

namespace vivp::action {

template <class P, class Real>
class SystemBase {
 public:
  static constexpr int d = P::kDim;
  using State = std::array<Real, d>;

  SystemBase(const P& problem, const sbp::RegularizedOperator<Real>& dbar,
             const State& x_init, const State& v_init, int order)
      : problem_(problem),
        dbar_(dbar),
        x_init_(x_init),
        v_init_(v_init),
        order_(order),
        n_(dbar.points()) {}

  int points() const { return n_; }
  int order() const { return order_; }
  const sbp::RegularizedOperator<Real>& dbar() const { return dbar_; }
  const State& x_init() const { return x_init_; }

 protected:
  // One path: x[c][i] = u[index(i, c)] and its regularized velocity
  // v[c] = D̄x̄[c], the affine shift being the initial position.
  template <class Index>
  void Path(const Real* u, Index index, std::vector<Real>* x,
            std::vector<Real>* v) const {
    for (int c = 0; c < d; ++c) {
      x[c].resize(n_);
      v[c].resize(n_);
      for (int i = 0; i < n_; ++i) x[c][i] = u[index(i, c)];
      dbar_.Apply(std::span<const Real>(x[c]), x_init_[c],
                  std::span<Real>(v[c]));
    }
  }

  // out[j] += (D̄ᵀ H w)_j for one component (regularized.h).
  template <class Out>
  void AddDbarTransposeHw(const std::vector<Real>& w, std::vector<Real>& dw,
                          Out&& out) const {
    sbp::AddDbarTransposeHw(dbar_, w, dw, out);
  }

  // Calls fn(column, D[i][column]) for the nonzeros of row i of plain D.
  template <class F>
  void ForRow(int i, F&& fn) const {
    const auto& D = dbar_.base();
    const auto row = D.row(i);
    for (std::size_t k = 0; k < row.coeffs.size(); ++k)
      if (row.coeffs[k] != Real(0))
        fn(row.first + static_cast<int>(k), row.coeffs[k] * D.inv_dt());
  }

  const P& problem_;
  const sbp::RegularizedOperator<Real>& dbar_;
  State x_init_, v_init_;
  int order_;
  int n_;
};

}  // namespace vivp::action
