// The full doubled discrete action of Rothkopf & Nordström (2023), eqs. 24,
// 33, 39, 43 in generic form (docs/method.md §4):
//
//   S = Σ_i H_ii f(x1_i, v1_i, x2_i, v2_i)
//       + λ1·(x1_0 − x_i) + λ2·((Dx1)_0 − ẋ_i)
//       + λ3·(x1_N − x2_N) + λ4·((Dx1)_N − (Dx2)_N),
//
// v_a = D̄x̄_a per path (each with its own affine shift), f = L1 − L2 + Λ.
// First-order systems carry λ1 and λ3 only. Unknowns are interleaved
//   (λ1, λ2, x1_0, x2_0, x1_1, x2_1, ..., x1_N, x2_N, λ3, λ4),
// each a d-vector, which makes the Hessian banded.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "core/action/density.h"
#include "core/action/local_map.h"
#include "core/sbp/regularized.h"

namespace vivp::action {

template <class P, class Real>
class FullSystem {
 public:
  static constexpr int d = P::kDim;
  using State = std::array<Real, d>;

  FullSystem(const P& problem, const sbp::RegularizedOperator<Real>& dbar,
             const State& x_init, const State& v_init, int order)
      : problem_(problem),
        dbar_(dbar),
        x_init_(x_init),
        v_init_(v_init),
        order_(order),
        n_(dbar.points()) {}

  int points() const { return n_; }
  int order() const { return order_; }
  int lead() const { return (order_ == 2 ? 2 : 1) * d; }
  int size() const { return 2 * lead() + 2 * n_ * d; }

  int Lambda1(int c) const { return c; }
  int Lambda2(int c) const { return d + c; }
  // Path a = 0 (forward, x1) or 1 (backward, x2).
  int X(int a, int node, int c) const {
    return lead() + (2 * node + a) * d + c;
  }
  int Lambda3(int c) const { return lead() + 2 * n_ * d + c; }
  int Lambda4(int c) const { return lead() + 2 * n_ * d + d + c; }

  void Paths(const Real* u, std::vector<Real> (*x)[d],
             std::vector<Real> (*v)[d]) const {
    for (int a = 0; a < 2; ++a)
      for (int c = 0; c < d; ++c) {
        x[a][c].resize(n_);
        v[a][c].resize(n_);
        for (int i = 0; i < n_; ++i) x[a][c][i] = u[X(a, i, c)];
        dbar_.Apply(std::span<const Real>(x[a][c]), x_init_[c],
                    std::span<Real>(v[a][c]));
      }
  }

  // The node values z = (x1, v1, x2, v2) at node i.
  void NodeValues(const std::vector<Real> (*x)[d],
                  const std::vector<Real> (*v)[d], int i, Real* z) const {
    for (int c = 0; c < d; ++c) {
      z[c] = x[0][c][i];
      z[d + c] = v[0][c][i];
      z[2 * d + c] = x[1][c][i];
      z[3 * d + c] = v[1][c][i];
    }
  }

  auto DensityOf() const {
    return [this](const auto* z) {
      return Density(problem_, z, z + d, z + 2 * d, z + 3 * d);
    };
  }

  Real Value(const Real* u) const {
    std::vector<Real> x[2][d], v[2][d];
    Paths(u, x, v);
    const auto& D = dbar_.base();
    Real s(0);
    for (int i = 0; i < n_; ++i) {
      Real z[4 * d];
      NodeValues(x, v, i, z);
      s += D.NormWeight(i) * DensityOf()(z);
    }
    for (int c = 0; c < d; ++c) {
      s += u[Lambda1(c)] * (x[0][c][0] - x_init_[c]);
      s += u[Lambda3(c)] * (x[0][c][n_ - 1] - x[1][c][n_ - 1]);
      if (order_ == 2) {
        s += u[Lambda2(c)] * (D.ApplyRow(0, x[0][c].data()) - v_init_[c]);
        s += u[Lambda4(c)] * (D.ApplyRow(n_ - 1, x[0][c].data()) -
                              D.ApplyRow(n_ - 1, x[1][c].data()));
      }
    }
    return s;
  }

  // ∇S, matrix-free: H ∂f/∂x + D̄ᵀ H ∂f/∂v per path, plus multiplier terms.
  void Residual(const Real* u, Real* g) const {
    auto& x = scratch_.x;
    auto& v = scratch_.v;
    auto& w = scratch_.w;
    Paths(u, x, v);
    const auto& D = dbar_.base();
    for (int a = 0; a < 2; ++a)
      for (int c = 0; c < d; ++c) w[a][c].assign(n_, Real(0));
    for (int i = 0; i < n_; ++i) {
      Real z[4 * d];
      NodeValues(x, v, i, z);
      const auto grad = autodiff::Gradient<Real, 4 * d>(DensityOf(), z).second;
      const Real h = D.NormWeight(i);
      for (int a = 0; a < 2; ++a)
        for (int c = 0; c < d; ++c) {
          g[X(a, i, c)] = h * grad[2 * a * d + c];
          w[a][c][i] = grad[2 * a * d + d + c];
        }
    }
    // D̄ᵀ H w = B w − H D w + penalty·H_0 w_0 e_0 (SBP property; see
    // ReducedSystem::Residual for why D is applied to w rather than Dᵀ to Hw).
    auto& dw = scratch_.dtw;
    dw.resize(n_);
    for (int a = 0; a < 2; ++a)
      for (int c = 0; c < d; ++c) {
        D.Apply(std::span<const Real>(w[a][c]), std::span<Real>(dw));
        for (int j = 0; j < n_; ++j) g[X(a, j, c)] -= D.NormWeight(j) * dw[j];
        g[X(a, 0, c)] += (-dbar_.sigma0() - Real(1)) * w[a][c][0];
        g[X(a, n_ - 1, c)] += w[a][c][n_ - 1];
      }
    for (int c = 0; c < d; ++c) {
      g[Lambda1(c)] = x[0][c][0] - x_init_[c];
      g[X(0, 0, c)] += u[Lambda1(c)];
      g[Lambda3(c)] = x[0][c][n_ - 1] - x[1][c][n_ - 1];
      g[X(0, n_ - 1, c)] += u[Lambda3(c)];
      g[X(1, n_ - 1, c)] -= u[Lambda3(c)];
      if (order_ == 2) {
        g[Lambda2(c)] = D.ApplyRow(0, x[0][c].data()) - v_init_[c];
        g[Lambda4(c)] = D.ApplyRow(n_ - 1, x[0][c].data()) -
                        D.ApplyRow(n_ - 1, x[1][c].data());
        ForRow(0, [&](int k, Real dk) { g[X(0, k, c)] += u[Lambda2(c)] * dk; });
        ForRow(n_ - 1, [&](int k, Real dk) {
          g[X(0, k, c)] += u[Lambda4(c)] * dk;
          g[X(1, k, c)] -= u[Lambda4(c)] * dk;
        });
      }
    }
  }

  // ∇²S entry by entry into sink.Add(row, col, value).
  template <class Sink>
  void Jacobian(const Real* u, Sink& sink) const {
    Jacobian(u, sink, 0, n_);
  }

  // Only the node terms of nodes [node_begin, node_end) plus the multiplier
  // entries (see ReducedSystem::Jacobian).
  template <class Sink>
  void Jacobian(const Real* u, Sink& sink, int node_begin, int node_end) const {
    auto& x = scratch_.x;
    auto& v = scratch_.v;
    Paths(u, x, v);
    const auto& D = dbar_.base();
    for (int i = node_begin; i < node_end; ++i) {
      Real z[4 * d];
      NodeValues(x, v, i, z);
      const Eigen::Matrix<Real, 4 * d, 4 * d> hess =
          D.NormWeight(i) *
          autodiff::Hessian<Real, 4 * d>(DensityOf(), z).hessian;
      const LocalMap<Real> map = MakeLocalMap(dbar_, i);
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) {
          const int xa = 2 * a * d, va = xa + d, xb = 2 * b * d, vb = xb + d;
          for (int ea = 0; ea < map.size; ++ea) {
            const auto& ra = map.entries[ea];
            for (int eb = 0; eb < map.size; ++eb) {
              const auto& cb = map.entries[eb];
              const Eigen::Matrix<Real, d, d> block =
                  ra.wx * cb.wx * hess.template block<d, d>(xa, xb) +
                  ra.wx * cb.wv * hess.template block<d, d>(xa, vb) +
                  ra.wv * cb.wx * hess.template block<d, d>(va, xb) +
                  ra.wv * cb.wv * hess.template block<d, d>(va, vb);
              for (int r = 0; r < d; ++r)
                for (int s = 0; s < d; ++s)
                  if (block(r, s) != Real(0))
                    sink.Add(X(a, ra.node, r), X(b, cb.node, s), block(r, s));
            }
          }
        }
    }
    auto sym = [&](int i, int j, Real val) {
      sink.Add(i, j, val);
      sink.Add(j, i, val);
    };
    for (int c = 0; c < d; ++c) {
      sym(Lambda1(c), X(0, 0, c), Real(1));
      sym(Lambda3(c), X(0, n_ - 1, c), Real(1));
      sym(Lambda3(c), X(1, n_ - 1, c), Real(-1));
      if (order_ == 2) {
        ForRow(0, [&](int k, Real dk) { sym(Lambda2(c), X(0, k, c), dk); });
        ForRow(n_ - 1, [&](int k, Real dk) {
          sym(Lambda4(c), X(0, k, c), dk);
          sym(Lambda4(c), X(1, k, c), -dk);
        });
      }
    }
  }

 private:
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
  // Work arrays reused across evaluations (see ReducedSystem).
  struct Scratch {
    std::vector<Real> x[2][d], v[2][d], w[2][d], dtw;
  };
  mutable Scratch scratch_;
};

}  // namespace vivp::action
