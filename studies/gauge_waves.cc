#include "studies/gauge_waves.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/action/field_constraints.h"
#include "problems/fields/gauge.h"
#include "solvers/spacetime/resolution.h"
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

}  // namespace vivp::studies
