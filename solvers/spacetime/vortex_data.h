// Moving data from a static slice of a charged field on two periodic axes
// (core/action/charged_terms.h's layout): each region of the slice set in
// motion with its own velocity u(x), to first order in u.
//
// A static solution translated with velocity u, φ(x − ut) and A(x − ut), is
// with A₀ = −u·A (the boost's first order) a solution whose data are
//
//   D_0φ = −(u·D)φ,   E_b = −u_c F_cb,
//
// and Gauss's law holds: ∂_bE_b/e² = −u_c ∂_bF_cb/e² = −u_c j_c = ρ by the
// static Ampère law ∂_bF_bc/e² = −j_c, with j_c = 2 Im(φ̄ D_cφ) and ρ =
// 2 Im(φ̄ D_0φ). Both data are gauge covariant (D_0φ) or invariant (E), so
// they are the data of the gauge A₀ = 0 at t = 0 as well. On the lattice
// D_cφ at a node is the mean of the covariant forward and backward
// differences, and F on a link the mean of its two plaquettes: the data
// then hold Gauss's law to O(h²), and A₀, an unknown of every window, takes
// up the rest. Where u varies, the law is off by u's gradient times the
// fields, which is small where the regions of different u are far apart.
#pragma once

#include <array>
#include <cmath>
#include <complex>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "core/action/charged_terms.h"

namespace vivp::spacetime {

// A vortex of the ansatz: its centre and winding.
struct VortexSeed {
  double x = 0, y = 0;
  int winding = 1;
};

namespace detail {

// Jacobi's ϑ₁(u | τ = i) = 2 Σ_{k≥0} (−1)^k q^{(k+½)²} sin((2k+1)u), q =
// e^{−π}: simple zeros at u = π(a + ib), ϑ₁(u + π) = −ϑ₁(u), ϑ₁(u + πτ) =
// −q⁻¹ e^{−2iu} ϑ₁(u) (Whittaker & Watson, A Course of Modern Analysis
// 1927, ch. 21). For |Im u| ≤ π the terms fall as e^{−π k²}.
inline std::complex<double> Theta1(std::complex<double> u) {
  std::complex<double> s = 0;
  for (int k = 0; k < 8; ++k)
    s += (k % 2 ? -2.0 : 2.0) *
         std::exp(-std::numbers::pi * (k + 0.5) * (k + 0.5)) *
         std::sin(double(2 * k + 1) * u);
  return s;
}

// The displacement d on a circle of length L, minimum image.
inline double Wrap(double d, double length) {
  return d - length * std::round(d / length);
}

}  // namespace detail

// The ansatz of vortices on the periodic square [x0, x0 + L)² (windings
// summing to zero, as the torus demands), in charged_terms.h's layout with
// χ = 0: φ = v Π_k f(r_k)^{|n_k|} e^{iΘ}, f = tanh, and
//
//   A = ∇Θ − Σ_k n_k (1 − a(r_k)) ∇θ_k,   a = tanh²,
//
// each link the line integral of A along it over h (8-point Gauss–Legendre
// for the cores, arg of the ratio for ∇Θ): far from the cores D_bφ → 0.
// Θ is the phase of F(z) = Π_k ϑ₁(π(z − z_k)/L)^{n_k} e^{icy}: a zero or
// pole of order |n_k| at each centre, periodic in x, and in y once c
// cancels the phase e^{2πi Re Σ n_k z_k / L} that a period iL adds. So φ
// and A are exactly periodic, and the winding around each centre is n_k.
inline std::vector<double> VortexAnsatz(const sbp::SpaceGrid<double>& grid,
                                        double v,
                                        const std::vector<VortexSeed>& seeds) {
  using L = action::ChargedLayout<2>;
  using C = std::complex<double>;
  constexpr int m = L::m;
  constexpr double pi = std::numbers::pi;
  const double length = grid.axis(0).dx() * grid.points(0);
  if (grid.dim() != 2 || grid.points(1) != grid.points(0) ||
      std::abs(grid.axis(1).dx() - grid.axis(0).dx()) > 1e-12 * length)
    throw std::invalid_argument(
        "the vortex ansatz is built on a square torus: equal periods and "
        "points on both axes");
  int total = 0;
  C w = 0;
  for (const auto& s : seeds) {
    total += s.winding;
    w += double(s.winding) * C(s.x, s.y);
  }
  if (total != 0)
    throw std::invalid_argument(
        "the windings of the vortices sum to " + std::to_string(total) +
        "; on a torus they must sum to 0 (add antivortices)");
  // e^{icL} e^{2πi Re w/L} = 1, c reduced to (−π/L, π/L].
  double c = -2 * pi * w.real() / (length * length);
  c -= 2 * pi / length * std::round(c * length / (2 * pi));
  auto phase = [&](double x, double y) {
    C f = std::polar(1.0, c * y);
    for (const auto& s : seeds)
      f *= std::pow(detail::Theta1(pi * (C(x, y) - C(s.x, s.y)) / length),
                    s.winding);
    return f;
  };
  // ∫ n(1 − a(r)) dθ along the link from (px, py), length h along axis b.
  auto twist = [&](double px, double py, int b, double h, const VortexSeed& s) {
    static const double node[4] = {0.1834346424956498, 0.5255324099163290,
                                   0.7966664774136267, 0.9602898564975363};
    static const double weight[4] = {0.3626837833783620, 0.3137066458778873,
                                     0.2223810344533745, 0.1012285362903763};
    double sum = 0;
    for (int k = 0; k < 8; ++k) {
      const double t = 0.5 * h * (1 + (k < 4 ? -node[k] : node[k - 4]));
      const double dx = detail::Wrap(px + (b == 0 ? t : 0) - s.x, length);
      const double dy = detail::Wrap(py + (b == 1 ? t : 0) - s.y, length);
      const double r2 = dx * dx + dy * dy, th = std::tanh(std::sqrt(r2));
      sum += 0.5 * h * weight[k % 4] * (1 - th * th) * (b == 0 ? -dy : dx) / r2;
    }
    return s.winding * sum;
  };
  std::vector<double> x(std::size_t(grid.points()) * m, 0.0);
  for (int j = 0; j < grid.points(); ++j) {
    const double px = grid.x(j, 0), py = grid.x(j, 1);
    const C f = phase(px, py);
    double modulus = v;
    for (const auto& s : seeds)
      modulus *= std::pow(std::tanh(std::hypot(detail::Wrap(px - s.x, length),
                                               detail::Wrap(py - s.y, length))),
                          std::abs(s.winding));
    const C phi = modulus * f / std::abs(f);
    x[j * m + L::kRe] = phi.real();
    x[j * m + L::kIm] = phi.imag();
    for (int b = 0; b < 2; ++b) {
      const double h = grid.axis(b).dx();
      double line =
          std::arg(phase(px + (b == 0 ? h : 0), py + (b == 1 ? h : 0)) / f);
      for (const auto& s : seeds) line -= twist(px, py, b, h, s);
      x[j * m + L::A(b)] = line / h;
    }
  }
  return x;
}

// π (Re, Im of D_0φ; ∂_tA_b = E_b; 0 for χ) of the static slice x moving
// with velocity u(x, y) (two components).
inline std::vector<double> MovingSliceVelocities(
    const sbp::SpaceGrid<double>& grid, const std::vector<double>& x,
    const std::function<std::array<double, 2>(double, double)>& u) {
  using L = action::ChargedLayout<2>;
  constexpr int m = L::m;
  std::vector<double> pi(x.size(), 0.0);
  auto phi = [&](int k) {
    return action::Complex(x[k * m + L::kRe], x[k * m + L::kIm]);
  };
  auto plaquette = [&](int k) {
    action::LocalReal f;
    action::MagneticAt<2>(
        grid, x.data(), k, 0, 1, [](int p, int a) { return p * m + a; }, f);
    return f.value;
  };
  for (int j = 0; j < grid.points(); ++j) {
    // The node's covariant derivative along each axis, forward and back.
    action::Complex d_phi[2];
    for (int b = 0; b < 2; ++b) {
      const double h = grid.axis(b).dx();
      const int next = action::NextOn(grid, j, b),
                back = action::PreviousOn(grid, j, b);
      const action::Complex forward =
          (std::polar(1.0, -h * x[j * m + L::A(b)]) * phi(next) - phi(j)) / h;
      const action::Complex backward =
          (phi(j) - std::polar(1.0, h * x[back * m + L::A(b)]) * phi(back)) / h;
      d_phi[b] = 0.5 * (forward + backward);
    }
    const auto un = u(grid.x(j, 0), grid.x(j, 1));
    const action::Complex v = -(un[0] * d_phi[0] + un[1] * d_phi[1]);
    pi[j * m + L::kRe] = v.real();
    pi[j * m + L::kIm] = v.imag();
    // E on the links: E_x = u_y F_xy on (j, j + x̂), F the mean of the
    // plaquettes below and above it; E_y = −u_x F_xy on (j, j + ŷ), F the
    // mean of the plaquettes left and right of it; u at the link's middle.
    const double hx = grid.axis(0).dx(), hy = grid.axis(1).dx();
    const double fx =
        0.5 * (plaquette(j) + plaquette(action::PreviousOn(grid, j, 1)));
    const double fy =
        0.5 * (plaquette(j) + plaquette(action::PreviousOn(grid, j, 0)));
    const auto ux = u(grid.x(j, 0) + 0.5 * hx, grid.x(j, 1));
    const auto uy = u(grid.x(j, 0), grid.x(j, 1) + 0.5 * hy);
    pi[j * m + L::A(0)] = ux[1] * fx;
    pi[j * m + L::A(1)] = -uy[0] * fy;
  }
  return pi;
}

}  // namespace vivp::spacetime
