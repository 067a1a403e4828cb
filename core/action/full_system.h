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
#include "core/action/system_base.h"
#include "core/sbp/regularized.h"

namespace vivp::action {

template <class P, class Real>
class FullSystem : public SystemBase<P, Real> {
  using Base = SystemBase<P, Real>;
  using Base::dbar_, Base::x_init_, Base::v_init_, Base::order_, Base::n_,
      Base::problem_, Base::ForRow;

 public:
  static constexpr int d = P::kDim;
  using Base::Base;
  using typename Base::State;

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
      this->Path(
          u, [&](int i, int c) { return X(a, i, c); }, x[a], v[a]);
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

  Real Value(const Real* u) const {
    std::vector<Real> x[2][d], v[2][d];
    Paths(u, x, v);
    const auto& D = dbar_.base();
    Real s(0);
    for (int i = 0; i < n_; ++i) {
      Real z[4 * d];
      NodeValues(x, v, i, z);
      // The value part of the AD is f itself (a precompiled problem offers
      // no plain f(z) with Λ); only the tests' finite differences call this.
      s += D.NormWeight(i) * DensityGradient<Real>(problem_, z).first;
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
      const auto grad = DensityGradient<Real>(problem_, z).second;
      const Real h = D.NormWeight(i);
      for (int a = 0; a < 2; ++a)
        for (int c = 0; c < d; ++c) {
          g[X(a, i, c)] = h * grad[2 * a * d + c];
          w[a][c][i] = grad[2 * a * d + d + c];
        }
    }
    auto& dw = scratch_.dtw;
    for (int a = 0; a < 2; ++a)
      for (int c = 0; c < d; ++c)
        this->AddDbarTransposeHw(w[a][c], dw,
                                 [&](int j) -> Real& { return g[X(a, j, c)]; });
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
          D.NormWeight(i) * DensityDerivatives<Real>(problem_, z).hessian;
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
  // Work arrays reused across evaluations (see ReducedSystem).
  struct Scratch {
    std::vector<Real> x[2][d], v[2][d], w[2][d], dtw;
  };
  mutable Scratch scratch_;
};

}  // namespace vivp::action
