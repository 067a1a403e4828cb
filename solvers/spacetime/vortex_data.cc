#include "solvers/spacetime/vortex_data.h"

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/action/charged_terms.h"
#include "core/action/vortex_tracks.h"

namespace vivp::spacetime {

namespace detail {

// Jacobi's ϑ₁(u | τ = i) = 2 Σ_{k≥0} (−1)^k q^{(k+½)²} sin((2k+1)u), q =
// e^{−π}: simple zeros at u = π(a + ib), ϑ₁(u + π) = −ϑ₁(u), ϑ₁(u + πτ) =
// −q⁻¹ e^{−2iu} ϑ₁(u) (Whittaker & Watson, A Course of Modern Analysis
// 1927, ch. 21). For |Im u| ≤ π the terms fall as e^{−π k²}.
std::complex<double> Theta1(std::complex<double> u) {
  std::complex<double> s = 0;
  for (int k = 0; k < 8; ++k)
    s += (k % 2 ? -2.0 : 2.0) *
         std::exp(-std::numbers::pi * (k + 0.5) * (k + 0.5)) *
         std::sin(double(2 * k + 1) * u);
  return s;
}

// The displacement d on a circle of length L, minimum image.
double Wrap(double d, double length) {
  return d - length * std::round(d / length);
}

}  // namespace detail

std::vector<double> VortexAnsatz(const sbp::SpaceGrid<double>& grid, double v,
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

std::vector<double> MovingSliceVelocities(
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

namespace {

// The plaquette centre nearest p on axis b of the grid.
double PlaquetteCentre(const sbp::SpaceGrid<double>& grid, int b, double p) {
  const double x0 = grid.axis(b).x(0), h = grid.axis(b).dx();
  return x0 + (std::floor((p - x0) / h) + 0.5) * h;
}

VortexData Relaxed(const fields::ScalarQed& model,
                   const sbp::SpaceGrid<double>& grid,
                   std::vector<VortexSeed> seeds, const StaticOptions& o) {
  for (auto& s : seeds) {
    s.x = PlaquetteCentre(grid, 0, s.x);
    s.y = PlaquetteCentre(grid, 1, s.y);
  }
  VortexData d;
  d.x = VortexAnsatz(grid, std::sqrt(model.v2), seeds);
  d.relax = RelaxChargedSlice2(model, grid, 0.0, d.x, o);
  d.seeds = std::move(seeds);
  d.pi.assign(d.x.size(), 0.0);
  // A posteriori: every vortex still where it was placed.
  const auto zeros = action::FindVortices(grid, d.x.data());
  const double length = grid.axis(0).dx() * grid.points(0);
  d.found = int(zeros.size());
  for (const auto& s : d.seeds) {
    double nearest = INFINITY;
    for (const auto& z : zeros)
      if (z.winding == s.winding)
        nearest =
            std::min(nearest, std::hypot(detail::Wrap(z.x - s.x, length),
                                         detail::Wrap(z.y - s.y, length)));
    d.moved = std::max(d.moved, nearest);
  }
  return d;
}

std::array<double, 2> Centre(const sbp::SpaceGrid<double>& grid) {
  std::array<double, 2> c;
  for (int b = 0; b < 2; ++b)
    c[b] = grid.axis(b).x(0) + (grid.points(b) / 2 + 0.5) * grid.axis(b).dx();
  return c;
}

}  // namespace

VortexData VortexPairData(const fields::ScalarQed& model,
                          const sbp::SpaceGrid<double>& grid, double separation,
                          double residual) {
  const auto c = Centre(grid);
  StaticOptions o;
  o.residual = residual;
  return Relaxed(
      model, grid,
      {{c[0] + separation / 2, c[1], 1}, {c[0] - separation / 2, c[1], -1}}, o);
}

VortexData VortexCollisionData(const fields::ScalarQed& model,
                               const sbp::SpaceGrid<double>& grid,
                               double offset, double speed, double transition) {
  const auto c = Centre(grid);
  const double l = grid.axis(0).dx() * grid.points(0);
  StaticOptions o;
  o.residual = 1e-3;
  o.max_iterations = 30;
  o.newton_steps = 0;
  VortexData d = Relaxed(model, grid,
                         {{c[0] + offset, c[1], 1},
                          {c[0] - offset, c[1], 1},
                          {c[0] + l / 2, c[1] + 3 * l / 8, -1},
                          {c[0] + l / 2, c[1] - 3 * l / 8, -1}},
                         o);
  const double u = speed, w = transition;
  d.pi = MovingSliceVelocities(grid, d.x, [&](double px, double py) {
    const double dx = px - c[0], dy = py - c[1];
    const double r2 = (dx * dx + dy * dy) / (5.5 * 5.5);
    return std::array<double, 2>{
        -u * std::tanh(dx / w) * std::exp(-std::pow(r2, 4)), 0.0};
  });
  return d;
}

}  // namespace vivp::spacetime
