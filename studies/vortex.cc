#include "studies/vortex.h"

#include <Eigen/CholmodSupport>
#include <chrono>
#include <cmath>
#include <complex>

#include "core/action/vortex_tracks.h"
#include "core/linalg/fit.h"
#include "solvers/spacetime/charged_march.h"
#include "solvers/spacetime/charged_static.h"
#include "solvers/spacetime/vortex_data.h"

namespace vivp::studies {

namespace {

constexpr int kDim = 2;

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
  return spacetime::VortexAnsatz(grid, 1.0,  // v of CriticalHiggs
                                 {{length / 4, 0, 1}, {-length / 4, 0, -1}});
}

std::vector<int> PlaquetteWindings(const sbp::SpaceGrid<double>& grid,
                                   const std::vector<double>& x) {
  std::vector<int> w(grid.points());
  action::Complex corners[4];
  for (int j = 0; j < grid.points(); ++j)
    w[j] = action::PlaquetteWinding(grid, x.data(), j, corners);
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

linalg::PowerLawFit FitPower(const std::vector<double>& h,
                             const std::vector<double>& y) {
  std::vector<double> magnitude;
  for (double v : y) magnitude.push_back(std::abs(v));
  return linalg::FitPowerLaw(h, magnitude);
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
