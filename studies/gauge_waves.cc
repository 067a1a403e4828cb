#include "studies/gauge_waves.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/action/field_constraints.h"
#include "core/action/field_system.h"
#include "core/sbp/builder.h"
#include "core/sbp/regularized.h"
#include "problems/fields/gauge.h"
#include "solvers/spacetime/ceres_window.h"
#include "solvers/spacetime/fourier_solver.h"
#include "solvers/spacetime/resolution.h"
#include "solvers/variational/newton.h"
#include "solvers/variational/resolution.h"

namespace vivp::studies {

using Grid = sbp::SpaceGrid<double>;
constexpr double kPi = std::numbers::pi;

MaxwellFields FieldsOf(const Grid& g, std::span<const double> phi,
                       std::span<const double> phi_t) {
  const int n = g.points();
  std::vector<double> grad(std::size_t(n) * 6);
  Grid::GradientWork<double> w;
  g.Gradient<double>(3, phi, grad, w);
  auto d = [&](int j, int b, int a) { return grad[(j * 2 + b) * 3 + a]; };
  MaxwellFields f{std::vector<double>(std::size_t(n) * 2),
                  std::vector<double>(n)};
  for (int j = 0; j < n; ++j) {
    for (int b = 0; b < 2; ++b)
      f.e[j * 2 + b] = -d(j, b, 0) - phi_t[j * 3 + 1 + b];
    f.b[j] = d(j, 0, 2) - d(j, 1, 1);
  }
  return f;
}

MaxwellPlaneWave::MaxwellPlaneWave(const Grid& g, int kx, int ky)
    : grid_(g), k_{double(kx), double(ky)} {
  for (int b = 0; b < 2; ++b) {
    const auto& axis = g.axis(b);
    std::vector<double> u(axis.points()), du(axis.points());
    for (int j = 0; j < axis.points(); ++j) u[j] = std::sin(k_[b] * axis.x(j));
    axis.Apply<double>(u, du);
    sigma_[b] = du[0] / std::cos(k_[b] * axis.x(0));
  }
  omega_ = std::hypot(sigma_[0], sigma_[1]);
  eps_[0] = -sigma_[1] / omega_;
  eps_[1] = sigma_[0] / omega_;
}

double MaxwellPlaneWave::Phase(int j, double t) const {
  return k_[0] * grid_.x(j, 0) + k_[1] * grid_.x(j, 1) - omega_ * t;
}

MaxwellSlice MaxwellPlaneWave::At(double t) const {
  const std::size_t n = grid_.points();
  MaxwellSlice s{std::vector<double>(n * 3, 0.0),
                 std::vector<double>(n * 3, 0.0)};
  for (std::size_t j = 0; j < n; ++j)
    for (int b = 0; b < 2; ++b) {
      s.phi[j * 3 + 1 + b] = eps_[b] * std::sin(Phase(int(j), t));
      s.phi_t[j * 3 + 1 + b] = -omega_ * eps_[b] * std::cos(Phase(int(j), t));
    }
  return s;
}

MaxwellPlaneWave::Error MaxwellPlaneWave::Errors(std::span<const double> phi,
                                                 std::span<const double> phi_t,
                                                 double t) const {
  const MaxwellFields f = FieldsOf(grid_, phi, phi_t);
  const double bamp = sigma_[0] * eps_[1] - sigma_[1] * eps_[0];
  Error r;
  for (int j = 0; j < grid_.points(); ++j) {
    const double c = std::cos(Phase(j, t));
    for (int b = 0; b < 2; ++b)
      r.e = std::max(r.e, std::abs(f.e[j * 2 + b] - omega_ * eps_[b] * c));
    r.b = std::max(r.b, std::abs(f.b[j] - bamp * c));
  }
  r.e /= omega_;
  r.b /= std::abs(bamp);
  return r;
}

double TextbookGauss(const Grid& g, std::span<const double> phi,
                     std::span<const double> phi_t) {
  return action::TextbookConstraintsOfSlice(fields::MaxwellIn<2>{}, g, phi,
                                            phi_t)
      .relative();
}

GaussRun RunGauss(const std::string& op, int window, double fraction, int n,
                  int space_order, double t_end) {
  GaussRun r{.op = op,
             .window = window,
             .n = n,
             .space_order = space_order,
             .fraction = fraction};
  const Grid g(
      {sbp::SpaceDerivative<double>::Periodic(space_order, n, 0.0, 2 * kPi),
       sbp::SpaceDerivative<double>::Periodic(space_order, n, 0.0, 2 * kPi)});
  const MaxwellPlaneWave wave(g, 1, 2);
  const auto data = wave.At(0);
  const double limit = variational::StabilityLimit(op);
  const double dt = fraction * limit / spacetime::SpectralRadius(g);
  const long long points = (long long)std::ceil(t_end / dt) + 1;
  r.dt = t_end / double(points - 1);
  spacetime::FieldSolveOptions o;
  o.linear = spacetime::WindowLinearSolver::kFourier;
  const spacetime::FieldGrid grid{
      .op = op, .points = points, .t_end = t_end, .window_points = window};
  const auto start = std::chrono::steady_clock::now();
  const fields::MaxwellIn<2> density;
  spacetime::FieldSolution s;
  try {
    s = spacetime::SolveField(density, g, grid, data.phi, data.phi_t, o);
  } catch (const std::invalid_argument& e) {
    r.failure = e.what();  // a window below the operator's minimum, say
    return r;
  }
  r.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  r.windows = s.windows;
  r.newton = s.status.iterations;
  if (!s.status.converged) {
    r.failure = s.status.reason;
    return r;
  }
  const std::size_t size = std::size_t(g.points()) * 3;
  for (std::size_t k = 0; k < s.t.size(); ++k) {
    const std::span<const double> phi(&s.phi[k * size], size),
        phi_t(&s.phi_t[k * size], size);
    r.gauss = std::max(
        r.gauss, action::ConstraintsOfSlice(density, g, phi, phi_t).relative());
    r.textbook = std::max(r.textbook, TextbookGauss(g, phi, phi_t));
  }
  r.handoff =
      action::ConstraintsOfSlice(density, g, std::span<const double>(s.end.phi),
                                 std::span<const double>(s.end.phi_t))
          .relative();
  r.error_e = wave.Errors(s.end.phi, s.end.phi_t, t_end).e;
  return r;
}

std::vector<GaugeDriftRow> GaugeDrift(const std::string& op, int window,
                                      const std::vector<double>& times) {
  const int n = 16;
  const Grid g({sbp::SpaceDerivative<double>::Periodic(8, n, 0.0, 2 * kPi),
                sbp::SpaceDerivative<double>::Periodic(8, n, 0.0, 2 * kPi)});
  const MaxwellPlaneWave wave(g, 1, 2);
  const auto data = wave.At(0);
  const double t_end = times.back();
  const double dt =
      0.25 * variational::StabilityLimit(op) / spacetime::SpectralRadius(g);
  spacetime::FieldSolveOptions o;
  o.linear = spacetime::WindowLinearSolver::kFourier;
  const spacetime::FieldGrid grid{
      .op = op,
      .points = (long long)std::ceil(t_end / dt) + 1,
      .t_end = t_end,
      .window_points = window};
  const fields::MaxwellIn<2> density;
  const auto s =
      spacetime::SolveField(density, g, grid, data.phi, data.phi_t, o);
  std::vector<GaugeDriftRow> rows;
  if (!s.status.converged) return rows;
  const std::size_t size = std::size_t(g.points()) * 3;
  std::vector<double> grad(size * 2);
  Grid::GradientWork<double> w;
  GaugeDriftRow r;
  std::size_t next = 0;
  for (std::size_t k = 0; k < s.t.size() && next < times.size(); ++k) {
    const std::span<const double> phi(&s.phi[k * size], size),
        phi_t(&s.phi_t[k * size], size);
    g.Gradient<double>(3, phi, grad, w);
    for (int j = 0; j < g.points(); ++j) {
      r.a0 = std::max(r.a0, std::abs(phi[j * 3]));
      r.divergence =
          std::max(r.divergence,
                   std::abs(grad[(j * 2) * 3 + 1] + grad[(j * 2 + 1) * 3 + 2]));
    }
    r.gauss = std::max(
        r.gauss, action::ConstraintsOfSlice(density, g, phi, phi_t).relative());
    if (s.t[k] >= times[next] - 1e-12 || k + 1 == s.t.size()) {
      r.t = s.t[k];
      rows.push_back(r);
      ++next;
    }
  }
  return rows;
}

namespace {

// max over the window's nodes of the action's Gauss law, relative, and E.
struct WindowFields {
  double gauss = 0;
  std::vector<double> e, a0;
};
template <class System>
WindowFields FieldsOfWindow(const System& sys, const Grid& g,
                            const std::vector<double>& y) {
  action::FieldValues<double> v;
  sys.Fields(y.data(), v);
  WindowFields w;
  const std::size_t size = std::size_t(g.points()) * 3;
  for (int i = 0; i < sys.time_points(); ++i) {
    const std::span<const double> phi(&v.phi[i * size], size),
        phi_t(&v.phi_t[i * size], size);
    w.gauss = std::max(w.gauss, action::ConstraintsOfSlice(
                                    fields::MaxwellIn<2>{}, g, phi, phi_t)
                                    .relative());
    const auto f = FieldsOf(g, phi, phi_t);
    w.e.insert(w.e.end(), f.e.begin(), f.e.end());
    for (std::size_t j = 0; j < size; j += 3) w.a0.push_back(phi[j]);
  }
  return w;
}

double MaxAbsDifference(const std::vector<double>& a,
                        const std::vector<double>& b) {
  double d = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    d = std::max(d, std::abs(a[k] - b[k]));
  return d;
}

}  // namespace

WindowSolveComparison CompareWindowSolves(const std::string& op, int window,
                                          int n) {
  using Density = fields::MaxwellIn<2>;
  const Grid g({sbp::SpaceDerivative<double>::Periodic(2, n, 0.0, 2 * kPi),
                sbp::SpaceDerivative<double>::Periodic(2, n, 0.0, 2 * kPi)});
  const MaxwellPlaneWave wave(g, 1, 2);
  const auto data = wave.At(0);
  const double t_end = 0.2 * (window - 1) / 15.0;
  const sbp::RegularizedOperator<double> dbar(
      sbp::MakeOperator<double>(op, window, 0.0, t_end));
  const Density density;
  const action::FieldSystem<Density> sys(density, dbar, g, data.phi,
                                         data.phi_t);
  WindowSolveComparison c;
  c.unknowns = sys.size();
  std::vector<double> start(sys.size(), 0.0);
  for (int i = 0; i < window; ++i)
    for (int j = 0; j < g.points(); ++j)
      for (int a = 1; a < 3; ++a)
        start[sys.Phi(i, j, a)] =
            data.phi[j * 3 + a] + dbar.base().t(i) * data.phi_t[j * 3 + a];
  auto finish = [&](WindowSolveComparison::Side& side,
                    const variational::NewtonReport& r,
                    const std::vector<double>& y, double seconds) {
    side.iterations = r.corrections;
    side.seconds = seconds;
    side.converged = r.converged;
    side.message = r.reason;
    std::vector<double> f(sys.size());
    sys.Residual(y.data(), f.data());
    for (double v : f) side.residual = std::max(side.residual, std::abs(v));
    side.correction = MaxAbsDifference(y, start);
  };
  using Clock = std::chrono::steady_clock;
  std::vector<double> yf = start, yl = start;
  auto t0 = Clock::now();
  spacetime::FourierSolver<Density> fourier(density);
  const auto rf = variational::Newton<double>(sys, yf, {}, fourier);
  finish(c.fourier, rf, yf,
         std::chrono::duration<double>(Clock::now() - t0).count());
  t0 = Clock::now();
  const auto rl = spacetime::SolveWindowCeres(sys, yl);
  finish(c.lm, rl, yl,
         std::chrono::duration<double>(Clock::now() - t0).count());
  const auto wf = FieldsOfWindow(sys, g, yf), wl = FieldsOfWindow(sys, g, yl);
  c.fourier.gauss = wf.gauss;
  c.lm.gauss = wl.gauss;
  double emax = 0, amax = 0;
  for (double e : wf.e) emax = std::max(emax, std::abs(e));
  for (double a : data.phi) amax = std::max(amax, std::abs(a));
  c.e_difference = MaxAbsDifference(wf.e, wl.e) / emax;
  c.a0_difference = MaxAbsDifference(wf.a0, wl.a0) / amax;
  return c;
}

}  // namespace vivp::studies
