// How the values at one time node depend on the unknowns of one path.
//
// At node i the density sees x_i and v_i = (D̄x̄)_i. Both are linear in the
// path: x_i has weight 1 on node i, v_i has the weights of row i of D̄ (row 0
// includes the SAT penalty −sigma0/H_00). The chain rule of the action's
// gradient and Hessian runs over exactly these few nodes (docs/method.md §4:
// ∇S = H ∂_xL + D̄ᵀ H ∂_vL per path).
#pragma once

#include <array>

#include "core/sbp/regularized.h"

namespace vivp::action {

template <class Real>
struct LocalEntry {
  int node;
  Real wx;  // ∂x_i / ∂(path value at node)
  Real wv;  // ∂v_i / ∂(path value at node)
};

// At most 1 + the widest row of D (SBP84: 12 columns).
inline constexpr int kMaxLocal = 16;

template <class Real>
struct LocalMap {
  std::array<LocalEntry<Real>, kMaxLocal> entries;
  int size = 0;
};

template <class Real>
LocalMap<Real> MakeLocalMap(const sbp::RegularizedOperator<Real>& dbar, int i) {
  const auto& d = dbar.base();
  const auto row = d.row(i);
  LocalMap<Real> map;
  bool has_i = false;
  for (std::size_t k = 0; k < row.coeffs.size(); ++k) {
    const int node = row.first + static_cast<int>(k);
    Real wv = row.coeffs[k] * d.inv_dt();
    if (i == 0 && node == 0) wv += dbar.penalty();
    const Real wx = node == i ? Real(1) : Real(0);
    has_i = has_i || node == i;
    if (wv != Real(0) || wx != Real(0))
      map.entries[map.size++] = {node, wx, wv};
  }
  if (!has_i) map.entries[map.size++] = {i, Real(1), Real(0)};
  return map;
}

}  // namespace vivp::action
