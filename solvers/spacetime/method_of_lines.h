// The method of lines on the same spatial operator: the reference for fields
// without a closed-form solution and the peer of the space-time solve in the
// work–precision comparison (docs/fields.md §9).
//
// Discretizing only space turns the action into that of Nx coupled
// oscillators, L_h(φ, φ̇) = Σ_j Hˣ_j ℒ(φ_j, φ̇_j, (D_x φ)_j). For a density
// ℒ = ½ φ_tᵀ M φ_t − U(φ, φ_x) with constant M its Euler–Lagrange equations
// are
//
//   M φ̈_j = ∂ℒ/∂φ(j) + (D_xᵀ Hˣ q)_j / Hˣ_j,   q = ∂ℒ/∂φ_x,
//
// with D_xᵀ Hˣ q formed through the SBP property (space.h), so on an interval
// the same natural boundary condition as the space-time solve. For the wave
// density this is φ̈ = D_x D_x φ on the periodic circle. Time integrators:
//
//   leapfrog   Störmer–Verlet (kick–drift–kick), order 2, stable for
//              h·ω_max < 2 (checked before the first step);
//   gauss4/6   the s = 2, 3 Gauss–Legendre collocation methods, orders 4, 6,
//              symplectic; the stage equations solved by fixed-point
//              iteration in the reduced Nyström form
//                Φ_i = φ + c_i h v + h² Σ_j (A²)_ij a(Φ_j),
//              which contracts like h²‖A²‖ω_max²: a step too long for it is
//              reported, not taken;
//   dopri5     Dormand–Prince 5(4) of Boost.Odeint, adaptive, absolute and
//              relative tolerance `tolerance`.
//
//   vivp::spacetime::MolOptions o{.method = "gauss6", .steps = 200,
//                              .output_every = 10};
//   auto s = vivp::spacetime::SolveFieldMol(density, dx, 2.0, phi0, pi0, o);
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <chrono>
#include <cmath>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/action/field_point.h"
#include "core/autodiff/pointwise.h"
#include "core/sbp/space.h"
#include "core/sbp/space_grid.h"
#include "solvers/spacetime/input.h"
#include "solvers/spacetime/resolution.h"
#include "solvers/steppers/tableau.h"
#include "solvers/variational/summary.h"

namespace vivp::spacetime {

struct MolOptions {
  std::string method = "gauss6";  // leapfrog | gauss4 | gauss6 | dopri5
  long long steps = 100;          // fixed-step methods: h = t_end / steps
  double tolerance = 1e-10;       // dopri5
  // Fixed-step methods keep every output_every-th step (0: only t_end);
  // dopri5 lands on the same times t_end·k/steps·output_every.
  long long output_every = 0;
};

struct MolSolution {
  // converged, reason, the wall time (a stepper has no Newton iterations).
  variational::Summary status;
  int nx = 0, components = 0;
  std::vector<double> t, phi, phi_t;  // kept slices, (s·Nx + j)·m + a
  long long steps = 0, evaluations = 0;
  double seconds = 0;
};

inline const std::vector<std::string>& MolMethods() {
  static const std::vector<std::string> names{"leapfrog", "gauss4", "gauss6",
                                              "dopri5"};
  return names;
}

// The acceleration φ̈ = M⁻¹[∂ℒ/∂φ + Hˣ⁻¹ D_xᵀ Hˣ ∂ℒ/∂φ_x] of the semi-discrete
// field. The constructor checks at the initial data that the density has the
// form above (∂²ℒ/∂φ_t² = M at every point, no φ_t × (φ, φ_x) coupling).
template <class Density>
class FieldAcceleration {
 public:
  static constexpr int m = Density::kDim;
  static constexpr int d = action::SpaceDimOf<Density>();
  static constexpr int K = (2 + d) * m;

  FieldAcceleration(const Density& density, const sbp::SpaceGrid<double>& grid,
                    std::span<const double> phi0, std::span<const double> pi0)
      : density_(density), grid_(grid), n_(grid.points()) {
    std::vector<double> phi_x(phi0.size() * d);
    grid.Gradient<double>(m, phi0, phi_x, gradient_work_);
    Eigen::Matrix<double, m, m> mass;
    for (int j = 0; j < n_; ++j) {
      double z[K];
      for (int a = 0; a < m; ++a) {
        z[a] = phi0[j * m + a];
        z[m + a] = pi0[j * m + a];
      }
      for (int k = 0; k < d * m; ++k) z[2 * m + k] = phi_x[j * d * m + k];
      const auto h = autodiff::Hessian<double, K>(
          [&](const auto* w) { return density_(w, w + m, w + 2 * m); }, z);
      const auto mj = h.hessian.template block<m, m>(m, m);
      if (j == 0) mass = mj;
      const double scale = 1 + mass.cwiseAbs().maxCoeff();
      if ((mj - mass).cwiseAbs().maxCoeff() > 1e-12 * scale ||
          h.hessian.template block<m, m>(m, 0).cwiseAbs().maxCoeff() >
              1e-12 * scale ||
          h.hessian.template block<m, d * m>(m, 2 * m).cwiseAbs().maxCoeff() >
              1e-12 * scale)
        throw std::invalid_argument(
            "method of lines: the density must be ½ φ_tᵀ M φ_t − U(φ, ∇φ) "
            "with constant M; it is not at " +
            PointName(grid_, j));
    }
    Eigen::FullPivLU<Eigen::Matrix<double, m, m>> lu(mass);
    if (!lu.isInvertible())
      throw std::invalid_argument(
          "method of lines: ∂²ℒ/∂φ_t² is singular (no kinetic term)");
    inverse_mass_ = lu.inverse();
    phi_x_.resize(std::size_t(n_) * m * d);
    q_.resize(n_);
    out_.resize(n_);
    flux_.resize(std::size_t(n_) * m * d);
    drive_.resize(std::size_t(n_) * m);
  }

  long long evaluations() const { return evaluations_; }
  // M⁻¹ (the same at every point).
  const Eigen::Matrix<double, m, m>& inverse_mass() const {
    return inverse_mass_;
  }

  void operator()(std::span<const double> phi, std::span<double> acc) const {
    ++evaluations_;
    grid_.Gradient<double>(m, phi, phi_x_, gradient_work_);
    for (int j = 0; j < n_; ++j) {
      double z[K];
      for (int a = 0; a < m; ++a) {
        z[a] = phi[j * m + a];
        z[m + a] = 0;  // ∂ℒ/∂φ and ∂ℒ/∂φ_x do not depend on φ_t here
      }
      for (int k = 0; k < d * m; ++k) z[2 * m + k] = phi_x_[j * d * m + k];
      const auto g =
          autodiff::Gradient<double, K>(
              [&](const auto* w) { return density_(w, w + m, w + 2 * m); }, z)
              .second;
      for (int a = 0; a < m; ++a) drive_[j * m + a] = g[a];
      for (int k = 0; k < d * m; ++k) flux_[j * d * m + k] = g[2 * m + k];
    }
    // + Σ_b H⁻¹ D_bᵀ H q_b, q_b = ∂ℒ/∂(∂_bφ), per component.
    for (int a = 0; a < m; ++a) {
      std::fill(out_.begin(), out_.end(), 0.0);
      for (int b = 0; b < d; ++b) {
        for (int j = 0; j < n_; ++j) q_[j] = flux_[(j * d + b) * m + a];
        grid_.AddTransposeH<double>(b, q_, out_, line_);
      }
      for (int j = 0; j < n_; ++j)
        drive_[j * m + a] += out_[j] / grid_.NormWeight(j);
    }
    for (int j = 0; j < n_; ++j) {
      const Eigen::Map<const Eigen::Matrix<double, m, 1>> f(&drive_[j * m]);
      Eigen::Map<Eigen::Matrix<double, m, 1>> out(&acc[j * m]);
      out = inverse_mass_ * f;
    }
  }

 private:
  const Density& density_;
  const sbp::SpaceGrid<double>& grid_;
  int n_;
  Eigen::Matrix<double, m, m> inverse_mass_;
  mutable std::vector<double> phi_x_, q_, out_, flux_, drive_, line_;
  mutable sbp::SpaceGrid<double>::GradientWork<double> gradient_work_;
  mutable long long evaluations_ = 0;
};

namespace detail {

// One Gauss–Legendre step of (φ, v) in the Nyström form of the header.
// Returns false when the stage iteration does not contract.
// The Nyström coefficients of a Gauss tableau: A² for the stages and
// bᵀA for the new φ.
struct NystromCoefficients {
  Eigen::MatrixXd a2;
  Eigen::VectorXd ba;
  explicit NystromCoefficients(const steppers::Tableau& tab)
      : a2(tab.a * tab.a), ba(tab.a.transpose() * tab.b) {}
};

template <class Accel>
bool GaussStep(const Accel& accel, const steppers::Tableau& tab,
               const NystromCoefficients& ny, double h, Eigen::VectorXd& phi,
               Eigen::VectorXd& v, std::vector<Eigen::VectorXd>& stage,
               std::vector<Eigen::VectorXd>& acc) {
  const int s = tab.stages();
  const Eigen::MatrixXd& a2 = ny.a2;
  const Eigen::VectorXd& ba = ny.ba;
  for (int i = 0; i < s; ++i) stage[i] = phi + tab.c[i] * h * v;
  const double scale = 1 + phi.lpNorm<Eigen::Infinity>();
  double last = INFINITY;
  for (int it = 0; it < 100; ++it) {
    for (int j = 0; j < s; ++j) accel(stage[j], acc[j]);
    double change = 0;
    for (int i = 0; i < s; ++i) {
      Eigen::VectorXd next = phi + tab.c[i] * h * v;
      for (int j = 0; j < s; ++j) next += h * h * a2(i, j) * acc[j];
      change = std::max(change, (next - stage[i]).lpNorm<Eigen::Infinity>());
      stage[i] = std::move(next);
    }
    if (!std::isfinite(change) || (it > 2 && change > 0.9 * last)) return false;
    last = change;
    if (change <= 1e-15 * scale) break;
  }
  for (int j = 0; j < s; ++j) accel(stage[j], acc[j]);
  // φ₁ = φ + h v + h² Σ_j (bᵀA)_j a(Φ_j),  v₁ = v + h Σ_j b_j a(Φ_j).
  phi += h * v;
  for (int j = 0; j < s; ++j) {
    phi += h * h * ba[j] * acc[j];
    v += h * tab.b[j] * acc[j];
  }
  return true;
}

}  // namespace detail

template <class Density>
MolSolution SolveFieldMol(const Density& density,
                          const sbp::SpaceGrid<double>& grid, double t_end,
                          const std::vector<double>& phi0,
                          const std::vector<double>& pi0,
                          const MolOptions& options = {}) {
  constexpr int m = Density::kDim;
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  MolSolution s;
  s.nx = grid.points();
  s.components = m;
  const std::size_t n = std::size_t(s.nx) * m;
  CheckFieldInput(t_end, grid, m, phi0, pi0);
  if (options.steps < 1)
    throw std::invalid_argument("method of lines: steps must be ≥ 1");
  const auto& names = MolMethods();
  if (std::find(names.begin(), names.end(), options.method) == names.end())
    throw std::invalid_argument("method of lines: unknown method '" +
                                options.method +
                                "' (leapfrog, gauss4, gauss6, dopri5)");
  FieldAcceleration<Density> accel(density, grid, phi0, pi0);
  const double h = t_end / double(options.steps);
  const long long every =
      options.output_every > 0 ? options.output_every : options.steps;
  Eigen::VectorXd phi = Eigen::Map<const Eigen::VectorXd>(phi0.data(), n);
  Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd>(pi0.data(), n);
  auto keep = [&](double t) {
    s.t.push_back(t);
    s.phi.insert(s.phi.end(), phi.data(), phi.data() + n);
    s.phi_t.insert(s.phi_t.end(), v.data(), v.data() + n);
  };
  auto finish = [&](bool ok, std::string message) {
    if (options.method != "dopri5") s.steps = options.steps;
    s.status.converged = ok;
    s.status.reason = std::move(message);
    s.evaluations = accel.evaluations();
    s.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    s.status.seconds = s.seconds;
    return s;
  };
  keep(0);
  if (options.method == "dopri5") {
    namespace odeint = boost::numeric::odeint;
    using State = std::vector<double>;
    State y(2 * n);
    std::copy(phi0.begin(), phi0.end(), y.begin());
    std::copy(pi0.begin(), pi0.end(), y.begin() + long(n));
    std::vector<double> times;
    for (long long k = 0; k <= options.steps; k += every)
      times.push_back(h * double(k));
    if (times.back() < t_end) times.push_back(t_end);
    auto rhs = [&](const State& x, State& d, double) {
      std::copy(x.begin() + long(n), x.end(), d.begin());
      accel(std::span<const double>(x.data(), n),
            std::span<double>(d.data() + n, n));
    };
    auto observe = [&](const State& x, double t) {
      if (t == 0) return;
      phi = Eigen::Map<const Eigen::VectorXd>(x.data(), n);
      v = Eigen::Map<const Eigen::VectorXd>(x.data() + n, n);
      keep(t);
    };
    s.steps = static_cast<long long>(odeint::integrate_times(
        odeint::make_controlled(options.tolerance, options.tolerance,
                                odeint::runge_kutta_dopri5<State>()),
        rhs, y, times.begin(), times.end(), h, observe));
    if (!phi.allFinite()) return finish(false, "dopri5: non-finite field");
    return finish(true, "converged");
  }
  const double rho = SpectralRadius(grid);
  const double omega = FastestFieldFrequency(density, grid, rho, phi0, pi0);
  auto a_of = [&](const Eigen::VectorXd& x, Eigen::VectorXd& out) {
    out.resize(long(n));
    accel(std::span<const double>(x.data(), n),
          std::span<double>(out.data(), n));
  };
  if (options.method == "leapfrog") {
    if (h * omega >= 2) {
      std::ostringstream msg;
      msg << "leapfrog: h·ω_max = " << h * omega
          << " ≥ 2, the method is unstable; use at least "
          << static_cast<long long>(std::ceil(t_end * omega / 2)) + 1
          << " steps";
      return finish(false, msg.str());
    }
    Eigen::VectorXd a;
    a_of(phi, a);
    for (long long k = 1; k <= options.steps; ++k) {
      v += 0.5 * h * a;
      phi += h * v;
      a_of(phi, a);
      v += 0.5 * h * a;
      if (k % every == 0 || k == options.steps) keep(h * double(k));
    }
  } else {
    const auto tab =
        options.method == "gauss4" ? steppers::Gauss2() : steppers::Gauss3();
    const detail::NystromCoefficients ny(tab);
    std::vector<Eigen::VectorXd> stage(tab.stages()), acc(tab.stages());
    for (long long k = 1; k <= options.steps; ++k) {
      if (!detail::GaussStep(a_of, tab, ny, h, phi, v, stage, acc)) {
        std::ostringstream msg;
        msg << options.method << ": the stage iteration does not contract at "
            << "t = " << h * double(k - 1) << " (h·ω_max = " << h * omega
            << "); use more steps";
        return finish(false, msg.str());
      }
      if (k % every == 0 || k == options.steps) keep(h * double(k));
    }
  }
  if (!phi.allFinite() || !v.allFinite())
    return finish(false, options.method + ": non-finite field");
  return finish(true, "converged");
}

// The one-dimensional field.
template <class Density>
MolSolution SolveFieldMol(const Density& density,
                          const sbp::SpaceDerivative<double>& dx, double t_end,
                          const std::vector<double>& phi0,
                          const std::vector<double>& pi0,
                          const MolOptions& options = {}) {
  return SolveFieldMol(density, sbp::SpaceGrid<double>(dx), t_end, phi0, pi0,
                       options);
}

}  // namespace vivp::spacetime
