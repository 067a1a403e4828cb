// The local pieces of the lattice action of a charged field
// (charged_field.h) that need no time direction: the layout of a node's
// components, the periodic neighbours, the covariant forward difference on a
// link, the field strength of a plaquette, the potential, and the potential
// energy of one slice with its gradient (the forces of the method of lines
// in the gauge A₀ = 0, charged_leapfrog.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/action/local_terms.h"
#include "core/sbp/space_grid.h"

namespace vivp::action {

// 1/e(t)², or std::invalid_argument naming t when e(t) is not finite or
// zero (the coupling is the user's function).
template <class Model>
double CheckedInverseCouplingSquared(const Model& model, double t) {
  const double v = model.InverseCouplingSquared(t);
  if (!std::isfinite(v) || !(v > 0))
    throw std::invalid_argument(
        "the coupling e(t) at t = " + std::to_string(t) + " gives 1/e² = " +
        std::to_string(v) + "; it must be finite and nonzero at every node");
  return v;
}
inline void CheckFinite(const std::string& what, const std::vector<double>& v) {
  for (std::size_t k = 0; k < v.size(); ++k)
    if (!std::isfinite(v[k]))
      throw std::invalid_argument(what + " hold a non-finite value at entry " +
                                  std::to_string(k));
}

// The charge density 2 Im(φ̄ v) of φ with (covariant) velocity v: the
// action's δ/δA₀ of |D_0φ|², with the sign of Gauss's law (D⁻·E)/e² = ρ.
inline double ChargeDensity(Complex phi, Complex v) {
  return 2 * (std::conj(phi) * v).imag();
}

// Per node: Re φ, Im φ, A_0 … A_{d−1} on the links, χ.
template <int d>
struct ChargedLayout {
  static constexpr int m = 3 + d;
  static constexpr int kRe = 0, kIm = 1, kChi = 2 + d;
  static constexpr int A(int b) { return 2 + b; }
};

// The point one link along axis b of a periodic grid, and one back.
inline int NextOn(const sbp::SpaceGrid<double>& grid, int j, int b) {
  const int c = grid.Coordinate(j, b);
  return c + 1 < grid.points(b) ? j + grid.stride(b) : j - c * grid.stride(b);
}
inline int PreviousOn(const sbp::SpaceGrid<double>& grid, int j, int b) {
  const int c = grid.Coordinate(j, b);
  return c > 0 ? j - grid.stride(b) : j + (grid.points(b) - 1) * grid.stride(b);
}

// (e^{−ih a} φ_next − φ_here)/h over the unknowns at the given positions
// of y.
inline void ForwardDifference(double hb, const double* y, int re0, int im0,
                              int re1, int im1, int link, LocalComplex& q) {
  const Complex I(0, 1), u = std::polar(1.0, -hb * y[link]);
  const Complex next(y[re1], y[im1]), here(y[re0], y[im0]);
  q.Reset(5);
  const int r0 = q.Slot(re0), i0 = q.Slot(im0);
  const int r1 = q.Slot(re1), i1 = q.Slot(im1), ab = q.Slot(link);
  q.value = (u * next - here) / hb;
  q.d[r0] = -1.0 / hb;
  q.d[i0] = -I / hb;
  q.d[r1] = u / hb;
  q.d[i1] = I * u / hb;
  q.d[ab] = -I * u * next;
  q.dd(r1, ab) = q.dd(ab, r1) = -I * u;
  q.dd(i1, ab) = q.dd(ab, i1) = u;
  q.dd(ab, ab) = -hb * u * next;
}

// The same over the positions at(j, component) of y.
template <int d, class At>
void MagneticAt(const sbp::SpaceGrid<double>& grid, const double* y, int j,
                int b, int c, At at, LocalReal& out) {
  const int kb = NextOn(grid, j, b), kc = NextOn(grid, j, c);
  const double hb = grid.axis(b).dx(), hc = grid.axis(c).dx();
  out.n = 4;
  out.index[0] = at(kb, ChargedLayout<d>::A(c));
  out.index[1] = at(j, ChargedLayout<d>::A(c));
  out.index[2] = at(kc, ChargedLayout<d>::A(b));
  out.index[3] = at(j, ChargedLayout<d>::A(b));
  out.g.resize(4);
  out.g << 1 / hb, -1 / hb, -1 / hc, 1 / hc;
  out.value = 0;
  for (int e = 0; e < 4; ++e) out.value += out.g[e] * y[out.index[e]];
}

// V(|φ|²) and its derivatives in (Re φ, Im φ) at positions r, im of y.
template <class Model>
void PotentialAt(const Model& model, const double* y, int r, int im,
                 LocalReal& t) {
  const double x[2] = {y[r], y[im]}, s = x[0] * x[0] + x[1] * x[1];
  const double v1 = model.PotentialSlope(s), v2 = model.PotentialCurvature(s);
  t.n = 2;
  t.index[0] = r;
  t.index[1] = im;
  t.value = model.Potential(s);
  t.g.resize(2);
  t.h.resize(2, 2);
  for (int a = 0; a < 2; ++a) {
    t.g[a] = 2 * x[a] * v1;
    for (int b = 0; b < 2; ++b)
      t.h(a, b) = 2 * v1 * (a == b) + 4 * x[a] * x[b] * v2;
  }
}

// A linear form ℓ (t.g its coefficients, t.value its value) → ℓ².
inline void Square(LocalReal& t) {
  t.h = 2.0 * t.g * t.g.transpose();
  t.g *= 2.0 * t.value;
  t.value *= t.value;
}

// Calls visit(term, weight) for every term of the potential energy of one
// slice x (values j·m + a, χ's unused),
//   U = Σ_j Hˣ_j [Σ_b |D_bφ|² + V(|φ|²) + (inv_g2/2) Σ_{b<c} F_bc²],
// each term with its gradient and Hessian in the slice's unknowns: the sum,
// the forces and the Hessian of U are sums over these.
template <int d, class Model, class Visit>
void ForEachSliceTerm(const Model& model, const sbp::SpaceGrid<double>& grid,
                      double inv_g2, const double* x, Visit&& visit) {
  using L = ChargedLayout<d>;
  constexpr int m = L::m;
  LocalComplex q;
  LocalReal t;
  for (int j = 0; j < grid.points(); ++j) {
    const double hx = grid.NormWeight(j);
    for (int b = 0; b < d; ++b) {
      const int k = NextOn(grid, j, b);
      ForwardDifference(grid.axis(b).dx(), x, j * m + L::kRe, j * m + L::kIm,
                        k * m + L::kRe, k * m + L::kIm, j * m + L::A(b), q);
      SquaredNorm(q, t);
      visit(t, hx);
      for (int c = b + 1; c < d; ++c) {
        MagneticAt<d>(
            grid, x, j, b, c, [&](int jj, int a) { return jj * m + a; }, t);
        Square(t);
        visit(t, 0.5 * hx * inv_g2);
      }
    }
    PotentialAt(model, x, j * m + L::kRe, j * m + L::kIm, t);
    visit(t, hx);
  }
}

// U and its gradient into grad (same layout, if not null): the forces of a
// method of lines in the gauge A₀ = 0 (charged_leapfrog.h), and what a
// static solution makes vanish (solvers/spacetime/charged_static.h).
template <int d, class Model>
double ChargedSlicePotential(const Model& model,
                             const sbp::SpaceGrid<double>& grid, double inv_g2,
                             const double* x, double* grad) {
  if (grad)
    std::fill(grad, grad + std::size_t(grid.points()) * ChargedLayout<d>::m,
              0.0);
  double u = 0;
  ForEachSliceTerm<d>(model, grid, inv_g2, x,
                      [&](const LocalReal& term, double w) {
                        u += w * term.value;
                        if (grad)
                          for (int a = 0; a < term.n; ++a)
                            grad[term.index[a]] += w * term.g[a];
                      });
  return u;
}

}  // namespace vivp::action
