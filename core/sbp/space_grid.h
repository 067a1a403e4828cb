// Space in d = 1, 2 or 3 dimensions as the tensor product of one-dimensional
// derivatives (space.h), one per axis: periodic differences or an SBP
// operator on an interval, chosen per axis. Point (j_0, …, j_{d−1}) has the
// flat index j = Σ_a j_a s_a with s_0 = 1, s_a = s_{a−1} N_{a−1}: axis 0
// runs fastest. The norm is the product of the axes' norms,
//
//   H_j = Π_a Hᵃ_{j_a},
//
// and the derivative along axis a acts on every line of points parallel to
// that axis, D_a = I ⊗ … ⊗ Dᵃ ⊗ … ⊗ I. Each satisfies the SBP property of
// its axis with the other axes' weights as a factor, so the variation of
// Σ_j H_j q_j (D_a u)_j in u is D_aᵀ H q, line by line
//
//   (D_aᵀ H q)_j = H^{⊥a}_j (Dᵃᵀ Hᵃ q_line)_{j_a},   H^{⊥a}_j = Π_{b≠a}
//   Hᵇ_{j_b},
//
// with the boundary term of axis a (its faces' natural condition) inside
// the line's transpose (space.h). A field's gradient at a point is then
// (D_0 φ, …, D_{d−1} φ) there, and the one-dimensional field is the case
// d = 1, where every formula is that of space.h.
//
//   auto g = vivp::sbp::SpaceGrid<double>({
//       SpaceDerivative<double>::Periodic(8, 64, 0.0, 2 * pi),
//       SpaceDerivative<double>::Bounded("sbp42", 41, -1.0, 1.0)});
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/sbp/space.h"

namespace vivp::sbp {

template <class Real>
class SpaceGrid {
 public:
  static constexpr int kMaxDim = 3;

  // Throws std::invalid_argument for no axis or more than three.
  explicit SpaceGrid(std::vector<SpaceDerivative<Real>> axes)
      : axes_(std::move(axes)) {
    if (axes_.empty() || int(axes_.size()) > kMaxDim)
      throw std::invalid_argument("a spatial grid has 1, 2 or 3 axes; got " +
                                  std::to_string(axes_.size()));
    std::size_t n = 1;
    for (std::size_t a = 0; a < axes_.size(); ++a) {
      strides_[a] = n;
      n *= std::size_t(axes_[a].points());
    }
    if (n > std::size_t(1) << 31)
      throw std::invalid_argument(
          "a spatial grid of " + std::to_string(n) +
          " points is more than one process indexes (2^31)");
    points_ = int(n);
  }
  // The one-dimensional grid.
  explicit SpaceGrid(SpaceDerivative<Real> axis)
      : SpaceGrid(std::vector<SpaceDerivative<Real>>{std::move(axis)}) {}

  int dim() const { return int(axes_.size()); }
  int points() const { return points_; }
  const SpaceDerivative<Real>& axis(int a) const { return axes_[a]; }
  int points(int a) const { return axes_[a].points(); }
  // s_a: the flat-index distance of neighbours along axis a.
  int stride(int a) const { return int(strides_[a]); }

  // j_a of the flat index j.
  int Coordinate(int j, int a) const {
    return int((std::size_t(j) / strides_[a]) % std::size_t(points(a)));
  }
  std::array<int, kMaxDim> Coordinates(int j) const {
    std::array<int, kMaxDim> c{};
    for (int a = 0; a < dim(); ++a) c[a] = Coordinate(j, a);
    return c;
  }
  int Index(std::span<const int> c) const {
    std::size_t j = 0;
    for (int a = 0; a < dim(); ++a) j += std::size_t(c[a]) * strides_[a];
    return int(j);
  }
  // The position of point j along axis a.
  Real x(int j, int a) const { return axes_[a].x(Coordinate(j, a)); }

  // H_j = Π_a Hᵃ_{j_a}, and the product without axis a.
  Real NormWeight(int j) const {
    Real w(1);
    for (int a = 0; a < dim(); ++a) w *= axes_[a].NormWeight(Coordinate(j, a));
    return w;
  }
  Real NormWeightAcross(int j, int a) const {
    Real w(1);
    for (int b = 0; b < dim(); ++b)
      if (b != a) w *= axes_[b].NormWeight(Coordinate(j, b));
    return w;
  }

  // out = D_a u for a scalar field u of points() values; work is scratch
  // (resized to two lines).
  template <class T>
  void Apply(int a, std::span<const T> u, std::span<T> out,
             std::vector<T>& work) const {
    const int n = points(a), s = stride(a);
    work.resize(2 * std::size_t(n));
    const std::span<T> line(work.data(), n), d(work.data() + n, n);
    ForEachLine(a, [&](int base) {
      if (s == 1) {  // a line of axis 0 is contiguous: no copies
        axes_[a].template Apply<T>(
            u.subspan(std::size_t(base), std::size_t(n)),
            out.subspan(std::size_t(base), std::size_t(n)));
        return;
      }
      for (int k = 0; k < n; ++k) line[k] = u[base + k * s];
      axes_[a].template Apply<T>(line, d);
      for (int k = 0; k < n; ++k) out[base + k * s] = d[k];
    });
  }
  template <class T>
  void Apply(int a, std::span<const T> u, std::span<T> out) const {
    std::vector<T> work;
    Apply(a, u, out, work);
  }

  // out += D_aᵀ H q, the variation of Σ_j H_j q_j (D_a u)_j in u; work is
  // scratch (resized to three lines).
  template <class T>
  void AddTransposeH(int a, std::span<const T> q, std::span<T> out,
                     std::vector<T>& work) const {
    const int n = points(a), s = stride(a);
    work.resize(3 * std::size_t(n));
    const std::span<T> line(work.data(), n), dq(work.data() + n, n),
        acc(work.data() + 2 * n, n);
    ForEachLine(a, [&](int base) {
      for (int k = 0; k < n; ++k) line[k] = q[base + k * s];
      std::fill(acc.begin(), acc.end(), T(0));
      axes_[a].template AddTransposeH<T>(line, dq, acc);
      // The other axes' weights are those of the line's first point all
      // along it.
      const T across(NormWeightAcross(base, a));
      for (int k = 0; k < n; ++k) out[base + k * s] += across * acc[k];
    });
  }
  template <class T>
  void AddTransposeH(int a, std::span<const T> q, std::span<T> out) const {
    std::vector<T> work;
    AddTransposeH(a, q, out, work);
  }

  // Scratch of Gradient, kept by a caller that differentiates often.
  template <class T>
  struct GradientWork {
    std::vector<T> comp, du, line;
  };
  // out = ∇u for a field of m components (value j·m + a): ∂_b u_a at
  // (j·d + b)·m + a, so that d = 1 is the axis' ApplyComponents.
  template <class T>
  void Gradient(int m, std::span<const T> u, std::span<T> out,
                GradientWork<T>& w) const {
    const std::size_t n = std::size_t(points_);
    const int d = dim();
    w.comp.resize(n);
    w.du.resize(n);
    for (int a = 0; a < m; ++a) {
      for (std::size_t j = 0; j < n; ++j) w.comp[j] = u[j * m + a];
      for (int b = 0; b < d; ++b) {
        Apply<T>(b, w.comp, w.du, w.line);
        for (std::size_t j = 0; j < n; ++j) out[(j * d + b) * m + a] = w.du[j];
      }
    }
  }

  // Calls fn(l, (D_a)_{jl}) for the nonzero entries of row j of D_a (flat
  // indices, 1/Δx_a included).
  template <class F>
  void ForRow(int a, int j, F&& fn) const {
    const int ja = Coordinate(j, a);
    const int base = j - ja * stride(a);
    axes_[a].ForRow(ja, [&](int l, Real c) { fn(base + l * stride(a), c); });
  }

  // Calls fn(base) for the first point of every line along axis a.
  template <class F>
  void ForEachLine(int a, F&& fn) const {
    const int n = points(a), s = stride(a);
    const int outer = points_ / (n * s);
    for (int o = 0; o < outer; ++o)
      for (int i = 0; i < s; ++i) fn(o * n * s + i);
  }

 private:
  std::vector<SpaceDerivative<Real>> axes_;
  std::array<std::size_t, kMaxDim> strides_{};
  int points_ = 0;
};

}  // namespace vivp::sbp
