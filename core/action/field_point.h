// What the density of a field sees at one grid point of the space-time
// window (field_system.h): its number of spatial dimensions, the values φ,
// φ_t and ∇φ on the grid, and the unknowns a point's arguments depend on —
// the node itself, its time neighbours (a row of D̄_t) and its space
// neighbours (a row of each D_b) — with the weights ∂(φ, φ_t, ∂_0 φ, …)/∂φ₊
// by which the point's Hessian is chained into the Jacobian.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "core/action/local_map.h"
#include "core/autodiff/pointwise.h"
#include "core/sbp/regularized.h"
#include "core/sbp/space_grid.h"

namespace vivp::action {

// A density's number of spatial dimensions: its kSpaceDim, 1 if it declares
// none. Its third argument then holds the gradient, d·m values: ∂_0 φ (m
// components), then ∂_1 φ, …
template <class Density>
constexpr int SpaceDimOf() {
  if constexpr (requires { Density::kSpaceDim; })
    return Density::kSpaceDim;
  else
    return 1;
}

// Whether test(h) holds for the value, gradient and Hessian h of call (a
// density of K arguments) at four generic points: a density that depends
// on an argument, or couples two, does so at almost every point.
template <class Real, int K, class F, class Test>
bool AtGenericPoints(const F& call, Test&& test) {
  for (int s = 0; s < 4; ++s) {
    Real z[K];
    for (int k = 0; k < K; ++k)
      z[k] = Real(0.3) + Real(0.17) * Real(s) + Real(0.11) * Real(k * k % 7);
    if (!test(autodiff::Hessian<Real, K>(call, z))) return false;
  }
  return true;
}

// The density's arguments at point j of a slice, (φ, φ_t, ∇φ) as one
// vector z of (2 + d)m: phi and phi_t at j·m + a, ∇φ at (j·d + b)·m + a
// (SpaceGrid::Gradient's layout). A null phi_t gives φ_t = 0.
template <int m, int d>
void SliceArguments(int j, const double* phi, const double* phi_t,
                    const double* phi_x, double* z) {
  for (int a = 0; a < m; ++a) {
    z[a] = phi[j * m + a];
    z[m + a] = phi_t ? phi_t[j * m + a] : 0.0;
  }
  for (int k = 0; k < d * m; ++k) z[2 * m + k] = phi_x[j * d * m + k];
}

// The components whose time derivative the density does not take, as a bit
// per component in `static constexpr unsigned kWithoutTimeDerivative` (0,
// none, without it): the scalar potential A₀ of a gauge field, whose
// equation is a constraint (Gauss's law) at every node. Such a component
// has no initial data and no end connection in the doubled action
// (docs/gauge.md §2).
template <class Density>
constexpr unsigned ConstraintMaskOf() {
  if constexpr (requires { Density::kWithoutTimeDerivative; })
    return Density::kWithoutTimeDerivative;
  else
    return 0u;
}

// φ, φ_t and the gradient on the grid, time-major: φ and φ_t at
// (i·Nx + j)·m + a, ∂_b φ at ((i·Nx + j)·d + b)·m + a (d = 1: as φ).
template <class Real>
struct FieldValues {
  std::vector<Real> phi, phi_t, phi_x;
};

// One unknown node (i, j) the density at a grid point depends on, with
// ∂(φ, φ_t, ∂_0 φ, …)/∂φ₊(i, j); kind 0 = the point itself, 1 = a time
// neighbour, 2 = a space neighbour.
template <class Real, int d>
struct FieldLocal {
  // 1 + the widest row of D̄_t (SBP84: 12) + the widest row of each D_b.
  static constexpr int kMax = 20 + 12 * d;
  int i, j, kind;
  Real w[2 + d];

  // Σ_s w_s · (rows s·m … s·m + m − 1 of h), and the same over the columns
  // of such a row block: one expression, summed left to right.
  template <int m, class Matrix>
  Eigen::Matrix<Real, m, (2 + d) * m> Rows(const Matrix& h) const {
    return RowsOf<m>(h, std::make_integer_sequence<int, 2 + d>());
  }
  template <int m, class Matrix>
  Eigen::Matrix<Real, m, m> Cols(const Matrix& row) const {
    return ColsOf<m>(row, std::make_integer_sequence<int, 2 + d>());
  }

 private:
  template <int m, class Matrix, int... S>
  Eigen::Matrix<Real, m, (2 + d) * m> RowsOf(
      const Matrix& h, std::integer_sequence<int, S...>) const {
    return (... + (w[S] * h.template middleRows<m>(S * m)));
  }
  template <int m, class Matrix, int... S>
  Eigen::Matrix<Real, m, m> ColsOf(const Matrix& row,
                                   std::integer_sequence<int, S...>) const {
    return (... + (w[S] * row.template middleCols<m>(S * m)));
  }
};

// The unknowns grid point (i, j) depends on, into out (at most
// FieldLocal::kMax); returns their number. The time neighbours are those of
// point mechanics (local_map.h: row i of D̄ including the penalty, the node
// itself first or among them).
template <class Real, int d>
int FieldLocalEntries(const sbp::RegularizedOperator<Real>& dt,
                      const sbp::SpaceGrid<Real>& grid, int i, int j,
                      FieldLocal<Real, d>* out) {
  int count = 1;
  out[0] = {i, j, 0, {}};
  out[0].w[0] = Real(1);
  const LocalMap<Real> time = MakeLocalMap(dt, i);
  for (int e = 0; e < time.size; ++e) {
    const auto& t = time.entries[e];
    if (t.node == i) {
      out[0].w[1] = t.wv;
    } else {
      out[count] = {t.node, j, 1, {}};
      out[count++].w[1] = t.wv;
    }
  }
  for (int b = 0; b < d; ++b)
    grid.ForRow(b, j, [&](int l, Real w) {
      if (l == j) {
        out[0].w[2 + b] += w;
      } else {
        out[count] = {i, l, 2, {}};
        out[count++].w[2 + b] = w;
      }
    });
  return count;
}

}  // namespace vivp::action
