#include "studies/vortex.h"

#include <Eigen/CholmodSupport>
#include <chrono>
#include <cmath>
#include <complex>

#include "solvers/spacetime/charged_march.h"
#include "solvers/spacetime/charged_static.h"

namespace vivp::studies {

namespace {

constexpr int kDim = 2;
using Layout = action::ChargedLayout<kDim>;
using Complex = std::complex<double>;

// Jacobi's ϑ₁(u | τ = i) = 2 Σ_{k≥0} (−1)^k q^{(k+½)²} sin((2k+1)u), q =
// e^{−π}: zeros at u = π(a + ib) for integers a, b, simple, and ϑ₁(u + π) =
// −ϑ₁(u), ϑ₁(u + πτ) = −q⁻¹ e^{−2iu} ϑ₁(u) (Whittaker & Watson, A Course of
// Modern Analysis 1927, ch. 21). For |Im u| ≤ π/2 (|y| ≤ L/2) the terms fall
// as e^{−π k²}.
Complex Theta1(Complex u) {
  Complex s = 0;
  for (int k = 0; k < 8; ++k)
    s += (k % 2 ? -2.0 : 2.0) * std::exp(-M_PI * (k + 0.5) * (k + 0.5)) *
         std::sin(double(2 * k + 1) * u);
  return s;
}

// The pair's periodic phase function on the torus of side L: a zero at z₁
// = L/4, a pole at z₂ = −L/4. The ratio of ϑ₁'s is periodic in x; shifted
// by iL it gains e^{−2iπ(z₂ − z₁)/L} = −1, which e^{iπy/L} undoes.
Complex PairPhase(double x, double y, double length) {
  const Complex z(x, y), z1(length / 4, 0), z2(-length / 4, 0);
  return Theta1(M_PI * (z - z1) / length) / Theta1(M_PI * (z - z2) / length) *
         std::polar(1.0, M_PI * y / length);
}

// The displacement from c to p on the torus, minimum image.
double Wrap(double d, double length) {
  return d - length * std::round(d / length);
}

double Profile(double r) { return std::tanh(r); }             // f
double Gauge(double r) { return std::pow(std::tanh(r), 2); }  // a

// ∫ (1 − a(r)) dθ along the link from p, length h along axis b, about the
// centre c (minimum image): 8-point Gauss–Legendre.
double CoreTwist(double px, double py, int b, double h, double cx, double cy,
                 double length) {
  static const double node[4] = {0.1834346424956498, 0.5255324099163290,
                                 0.7966664774136267, 0.9602898564975363};
  static const double weight[4] = {0.3626837833783620, 0.3137066458778873,
                                   0.2223810344533745, 0.1012285362903763};
  double s = 0;
  for (int k = 0; k < 8; ++k) {
    const double t = 0.5 * h * (1 + (k < 4 ? -node[k] : node[k - 4]));
    const double w = 0.5 * h * weight[k % 4];
    const double dx = Wrap(px + (b == 0 ? t : 0) - cx, length);
    const double dy = Wrap(py + (b == 1 ? t : 0) - cy, length);
    const double r2 = dx * dx + dy * dy, r = std::sqrt(r2);
    s += w * (1 - Gauge(r)) * (b == 0 ? -dy : dx) / r2;
  }
  return s;
}

}  // namespace

namespace {

struct Radial {
  double f, a;
};
Radial Bogomolny(int n, double r, Radial s) {
  return {n / r * s.f * (1 - s.a), r / n * (1 - s.f * s.f)};
}
// The energy density times r (e = v = λ = 1).
double RadialDensity(int n, double r, Radial s) {
  const Radial d = Bogomolny(n, r, s);
  return r * (d.f * d.f + n * n * s.f * s.f * (1 - s.a) * (1 - s.a) / (r * r) +
              n * n * d.a * d.a / (2 * r * r) +
              0.5 * (1 - s.f * s.f) * (1 - s.f * s.f));
}
// +1: f passed 1; −1: f turned down; 0: reached r_max. The energy and the
// radius reached into out.
int Shoot(int n, double c, RadialVortex& out) {
  const double dr = 1e-4, r_max = 30;
  double r = 1e-4;
  Radial s{c * std::pow(r, n), r * r / (2 * n)};
  auto at = [&](Radial base, Radial k, double w) {
    return Radial{base.f + w * k.f, base.a + w * k.a};
  };
  out.energy = 0;
  for (; r < r_max; r += dr) {
    const Radial k1 = Bogomolny(n, r, s),
                 k2 = Bogomolny(n, r + dr / 2, at(s, k1, dr / 2)),
                 k3 = Bogomolny(n, r + dr / 2, at(s, k2, dr / 2)),
                 k4 = Bogomolny(n, r + dr, at(s, k3, dr));
    const Radial next{s.f + dr / 6 * (k1.f + 2 * k2.f + 2 * k3.f + k4.f),
                      s.a + dr / 6 * (k1.a + 2 * k2.a + 2 * k3.a + k4.a)};
    const Radial mid{(s.f + next.f) / 2, (s.a + next.a) / 2};
    out.energy +=
        2 * M_PI * dr / 6 *
        (RadialDensity(n, r, s) + 4 * RadialDensity(n, r + dr / 2, mid) +
         RadialDensity(n, r + dr, next));
    s = next;
    out.radius = r + dr;
    if (s.f > 1) return 1;
    if (k1.f < 0) return -1;
  }
  return 0;
}

}  // namespace

RadialVortex ShootRadialVortex(int n) {
  double lo = 0.01, hi = 10;
  RadialVortex out;
  for (int k = 0; k < 60; ++k) {
    const double c = 0.5 * (lo + hi);
    (Shoot(n, c, out) > 0 ? hi : lo) = c;
  }
  Shoot(n, lo, out);
  out.slope = lo;
  return out;
}

fields::ScalarQed CriticalHiggs() {
  fields::ScalarQed model;
  model.lambda = 1.0;
  model.v2 = 1.0;
  return model;
}

sbp::SpaceGrid<double> VortexSquare(int n, double length) {
  const double h = length / n;
  auto axis = [&] {
    return sbp::SpaceDerivative<double>::Periodic(2, n, -length / 2 + h / 2,
                                                  length);
  };
  return sbp::SpaceGrid<double>({axis(), axis()});
}

std::vector<double> VortexPairAnsatz(const sbp::SpaceGrid<double>& grid,
                                     double length) {
  constexpr int m = Layout::m;
  const double v = 1.0, c = length / 4;  // v of CriticalHiggs
  std::vector<double> x(std::size_t(grid.points()) * m, 0.0);
  for (int j = 0; j < grid.points(); ++j) {
    const double px = grid.x(j, 0), py = grid.x(j, 1);
    const double r1 = std::hypot(Wrap(px - c, length), py);
    const double r2 = std::hypot(Wrap(px + c, length), py);
    const Complex f = PairPhase(px, py, length);
    const Complex phi = v * Profile(r1) * Profile(r2) * f / std::abs(f);
    x[j * m + Layout::kRe] = phi.real();
    x[j * m + Layout::kIm] = phi.imag();
    for (int b = 0; b < kDim; ++b) {
      const double h = grid.axis(b).dx();
      const Complex next =
          PairPhase(px + (b == 0 ? h : 0), py + (b == 1 ? h : 0), length);
      // ∫ ∇Θ · dl = arg F(end)/F(start), minus the cores' (1 − a)∇θ.
      const double line = std::arg(next / f) -
                          CoreTwist(px, py, b, h, c, 0, length) +
                          CoreTwist(px, py, b, h, -c, 0, length);
      x[j * m + Layout::A(b)] = line / h;
    }
  }
  return x;
}

std::vector<int> PlaquetteWindings(const sbp::SpaceGrid<double>& grid,
                                   const std::vector<double>& x) {
  constexpr int m = Layout::m;
  auto phi = [&](int j) {
    return Complex(x[j * m + Layout::kRe], x[j * m + Layout::kIm]);
  };
  // arg(φ̄_j e^{−ihA_b} φ_k) along the link (j, b), and h A_b.
  auto link = [&](int j, int b) {
    const double ha = grid.axis(b).dx() * x[j * m + Layout::A(b)];
    return std::arg(std::conj(phi(j)) * std::polar(1.0, -ha) *
                    phi(action::NextOn(grid, j, b))) +
           ha;
  };
  std::vector<int> w(grid.points());
  for (int j = 0; j < grid.points(); ++j) {
    const int right = action::NextOn(grid, j, 0),
              up = action::NextOn(grid, j, 1);
    // Counter-clockwise: the links' (arg + hA) sum to Σ arg + h²F.
    const double total = link(j, 0) + link(right, 1) - link(up, 0) - link(j, 1);
    w[j] = int(std::lround(total / (2 * M_PI)));
  }
  return w;
}

VortexStatic RelaxVortexPair(int n, double length, double residual) {
  VortexStatic out{.n = n, .length = length, .h = length / n};
  const auto grid = VortexSquare(n, length);
  out.x = VortexPairAnsatz(grid, length);
  spacetime::StaticOptions o;
  o.residual = residual;
  const auto r =
      spacetime::RelaxChargedSlice2(CriticalHiggs(), grid, 0.0, out.x, o);
  out.energy = r.energy;
  out.deficit = r.energy / (2 * M_PI * 1.0 * 2) - 1;  // v² = 1, Σ|n| = 2
  out.start_residual = r.start_residual;
  out.lbfgs_residual = r.lbfgs_residual;
  out.residual = r.residual;
  out.iterations = r.iterations;
  out.newton = r.newton;
  out.lbfgs_seconds = r.lbfgs_seconds;
  out.seconds = r.seconds;
  out.message = r.message;
  return out;
}

PowerFit FitPower(const std::vector<double>& h, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double k = double(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double a = std::log(h[i]), b = std::log(std::abs(y[i]));
    sx += a;
    sy += b;
    sxx += a * a;
    sxy += a * b;
  }
  const double p = (k * sxy - sx * sy) / (k * sxx - sx * sx);
  return {p, std::exp((sy - p * sx) / k)};
}

namespace {

template <class Solver>
VortexMarchRun MarchWith(const VortexStatic& pair, const std::string& op,
                         int window, double dt, int windows) {
  using System = action::ChargedFieldSystem<fields::ScalarQed, kDim>;
  VortexMarchRun run;
  const auto grid = VortexSquare(pair.n, pair.length);
  const std::vector<double> pi(pair.x.size(), 0.0);
  spacetime::ChargedMarchOptions o;
  o.time_operator = op;
  o.window = window;
  o.dt = dt;
  o.windows = windows;
  // The pair's E and ρ vanish: the law is measured against the charge
  // density 2v²·m of a field of amplitude v at the mass m = √2 e v.
  o.gauss_scale_floor = 2 * std::sqrt(2.0);
  std::vector<double> modulus0, density0;
  auto clock = std::chrono::steady_clock::now();
  const auto march = spacetime::MarchCharged<fields::ScalarQed, kDim, Solver>(
      CriticalHiggs(), grid, pair.x, pi, o,
      [&](const System& s, const std::vector<double>&,
          const action::ChargedNodes& nodes,
          const spacetime::ChargedSliceState&) {
        const auto now = std::chrono::steady_clock::now();
        run.window_seconds.push_back(
            std::chrono::duration<double>(now - clock).count());
        clock = now;
        const int nx = s.space_points();
        if (modulus0.empty()) {  // the first node of the first window: data
          modulus0.assign(nodes.modulus.begin(), nodes.modulus.begin() + nx);
          density0.assign(nodes.energy_density.begin(),
                          nodes.energy_density.begin() + nx);
          for (double e : density0)
            run.energy_scale = std::max(run.energy_scale, e);
        }
        for (std::size_t k = 0; k < nodes.modulus.size(); ++k) {
          run.modulus = std::max(run.modulus,
                                 std::abs(nodes.modulus[k] - modulus0[k % nx]));
          run.energy_density =
              std::max(run.energy_density,
                       std::abs(nodes.energy_density[k] - density0[k % nx]));
          run.gauss = std::max(run.gauss, nodes.gauss_action[k]);
        }
      });
  run.ok = march.ok;
  run.reason = march.reason;
  run.windows = int(march.windows.size());
  run.t_end = dt * (window - 1) * run.windows;
  for (const auto& w : march.windows) run.newton += w.iterations;
  return run;
}

}  // namespace

VortexMarchRun MarchVortexPair(const VortexStatic& pair, const std::string& op,
                               int window, double dt, int windows,
                               bool cholmod) {
  using Matrix = Eigen::SparseMatrix<double>;
  if (cholmod)
    return MarchWith<spacetime::NormalEquationsSolverOf<
        Eigen::CholmodSupernodalLLT<Matrix>>>(pair, op, window, dt, windows);
  return MarchWith<spacetime::NormalEquationsSolver>(pair, op, window, dt,
                                                     windows);
}

}  // namespace vivp::studies
