// The variational IVP solver: the trajectory of an initial value problem as
// the critical point of the doubled SBP action (Rothkopf & Nordström 2023).
//
//   vivp::problems::Anharmonic anharmonic;                 // L = ½ẋ² − ¼κx⁴
//   auto sol = vivp::variational::SolveIvp(anharmonic, {.x = {1.0}, .v =
//   {0.3}},
//                             {.op = "sbp42", .points = 256, .t_end = 1.0});
//   if (!sol.status.converged) ... sol.status.reason ...
//   sol.x1(sol.points() - 1, 0);        // x(T)
//   sol.corrected.position[0];          // x_N + λ4/μ, one order better
//
// Two ways to the critical point, both from automatic differentiation of S:
//   Path::kReducedNewton (default)  Newton on ∂S/∂x₋ = 0 at x₋ = 0 plus the
//       initial-data rows (x₊, λ3, λ4; docs/method.md §5);
//   Path::kFullNewton  Newton on the full ∇S = 0 (x1, x2, λ1..λ4), for
//       cross-checking.
// (Levenberg–Marquardt through Ceres: solvers/variational/ceres_lm.h; every
// path, global or marched, behind one call: solvers/variational/solve.h.)
// Both are O(Nt) per iteration: pointwise AD through the stencil, a banded
// Jacobian, banded LU, matrix-free residuals for the refinement steps.
//
// Warnings:
//  1. A non-converged solve is returned, never thrown: check status.
//  2. The conditioning grows like Nt³; the reduced path with matrix-free
//     refinement (D on differences, DᵀH through the SBP property) holds free
//     fall (exact in exact arithmetic for SBP42) to 2.2e-16 up to Nt = 2^20
//     in plain double.
#pragma once

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "core/action/full_system.h"
#include "core/action/reduced_system.h"
#include "core/sbp/builder.h"
#include "solvers/variational/end_state.h"
#include "solvers/variational/ivp_types.h"
#include "solvers/variational/newton.h"
#include "solvers/variational/resolution.h"

namespace vivp::variational {

namespace detail {

inline void CheckFinite(const std::vector<double>& v, const char* what) {
  for (double x : v)
    if (!std::isfinite(x))
      throw std::invalid_argument(std::string(what) +
                                  " contains a non-finite value; all initial "
                                  "data must be finite");
}

template <class P, class Real>
IvpSolution<Real> Finish(const P& problem,
                         const sbp::RegularizedOperator<Real>& dbar,
                         const action::FullSystem<P, Real>& full,
                         const std::vector<Real>& u,
                         const variational::NewtonReport& report, Path path) {
  constexpr int d = P::kDim;
  const auto& D = dbar.base();
  const int n = D.points();
  IvpSolution<Real> s;
  s.path = path;
  s.order = full.order();
  s.t = D.Grid();
  s.x1.resize(n, d);
  s.x2.resize(n, d);
  s.velocity.resize(n, d);
  s.velocity_regularized.resize(n, d);
  std::vector<Real> x[2][d], v[2][d];
  full.Paths(u.data(), x, v);
  Real max_diff(0);
  for (int c = 0; c < d; ++c) {
    const auto dx = D.Apply(x[0][c]);
    for (int i = 0; i < n; ++i) {
      s.x1(i, c) = x[0][c][i];
      s.x2(i, c) = x[1][c][i];
      s.velocity(i, c) = dx[i];
      s.velocity_regularized(i, c) = v[0][c][i];
      max_diff = std::max(max_diff, std::abs(x[0][c][i] - x[1][c][i]));
    }
  }
  s.max_path_difference = double(max_diff);
  for (int c = 0; c < d; ++c) {
    s.lambda1.push_back(u[full.Lambda1(c)]);
    s.lambda3.push_back(u[full.Lambda3(c)]);
    if (s.order == 2) {
      s.lambda2.push_back(u[full.Lambda2(c)]);
      s.lambda4.push_back(u[full.Lambda4(c)]);
    }
  }
  // ‖∇S‖∞ of the full doubled action at the returned point, for every path.
  std::vector<Real> g(full.size());
  full.Residual(u.data(), g.data());
  s.gradient_norm = double(variational::detail::MaxAbs(g));

  Real xn[d], vn[d];
  for (int c = 0; c < d; ++c) {
    xn[c] = s.x1(n - 1, c);
    vn[c] = s.velocity(n - 1, c);
  }
  s.corrected = CorrectEnd<Real>(problem, s.order, xn, vn, s.lambda3.data(),
                                 s.order == 2 ? s.lambda4.data() : nullptr);
  s.status.converged = report.converged;
  s.status.reason = report.reason;
  s.status.iterations = report.iterations;
  s.status.last_residual = report.last_residual;
  s.status.seconds = report.phases.total;
  s.iterations = int(report.iterations);
  s.residual_norm = report.last_residual;
  s.seconds = report.phases;
  return s;
}

// Why the grid is too coarse for the problem, or "" if it is not: Δt·ω at
// the two given states (x, v per DOF; a window's or the solve's first and
// last node) must stay below the operator's stability limit (resolution.h).
// The advice is based on ω at the first state: at the last one ω may come
// from a solution that has already grown without bound, and the point count
// it implies is meaningless (a quartic potential's ω grows with |x|).
// This form takes ω at the two states (FastestFrequency) when the caller has
// them already.
inline std::string UnderResolution(const Grid& grid, double omega_a,
                                   double omega_b) {
  const double dt = (grid.t_end - grid.t_start) / double(grid.points - 1);
  const double limit = StabilityLimit(grid.op);
  const double worst = dt * std::max(omega_a, omega_b);
  if (!(worst > limit)) return "";
  auto number = [](double v) {
    std::ostringstream o;
    o << std::setprecision(3) << v;
    return o.str();
  };
  std::string why = "under-resolved: dt*omega = " + number(worst) +
                    " exceeds the stability limit " + number(limit) + " of " +
                    grid.op + " (the discrete solution grows without bound); ";
  if (dt * omega_a > limit) {
    const double needed =
        std::ceil((grid.t_end - grid.t_start) * omega_a / limit) + 1;
    return why + "use at least " +
           (needed < 1e15 ? std::to_string(static_cast<long long>(needed))
                          : number(needed)) +
           " points";
  }
  return why + "dt*omega is " + number(dt * omega_a) +
         " at the start, so the solution grew on the way; use more points "
         "(at least " +
         std::to_string(2 * (grid.points - 1) + 1) +
         ") and check that the end state stays bounded";
}

template <class P>
std::string UnderResolution(const P& problem, const Grid& grid,
                            const double* xa, const double* va,
                            const double* xb, const double* vb) {
  return UnderResolution(grid, FastestFrequency(problem, xa, va),
                         FastestFrequency(problem, xb, vb));
}

// Marks a converged solve as not converged when the grid is under-resolved.
template <class P, class Real>
void CheckResolution(const P& problem, const Grid& grid, IvpSolution<Real>& s) {
  if (!s.status.converged || s.order != 2) return;
  constexpr int d = P::kDim;
  double x[2][d], v[2][d];
  for (int k = 0; k < 2; ++k) {
    const int i = k == 0 ? 0 : s.points() - 1;
    for (int c = 0; c < d; ++c) {
      x[k][c] = double(s.x1(i, c));
      v[k][c] = double(s.velocity(i, c));
    }
  }
  std::string why = UnderResolution(problem, grid, x[0], v[0], x[1], v[1]);
  if (!why.empty()) {
    s.status.converged = false;
    s.status.reason = std::move(why);
  }
}

// Checks the initial data against the problem (one value per DOF, finite, a
// velocity exactly when the problem is second order) and returns the order.
template <class P>
int CheckInitialData(const P& problem, const InitialData& initial) {
  constexpr int d = P::kDim;
  if (static_cast<int>(initial.x.size()) != d)
    throw std::invalid_argument("initial position has " +
                                std::to_string(initial.x.size()) +
                                " components; the problem has " +
                                std::to_string(d) + " degrees of freedom");
  CheckFinite(initial.x, "initial position");
  CheckFinite(initial.v, "initial velocity");
  const bool has_v = !initial.v.empty();
  if (has_v && static_cast<int>(initial.v.size()) != d)
    throw std::invalid_argument("initial velocity has " +
                                std::to_string(initial.v.size()) +
                                " components; the problem has " +
                                std::to_string(d) + " degrees of freedom");
  double x0[d], v0[d];
  for (int c = 0; c < d; ++c) {
    x0[c] = initial.x[c];
    v0[c] = has_v ? initial.v[c] : 0.0;
  }
  const int order = action::SystemOrder<double>(problem, x0, v0);
  if (order == 2 && !has_v)
    throw std::invalid_argument(
        "the problem is second order (∂²L/∂v² ≠ 0) and needs an initial "
        "velocity");
  if (order == 1 && has_v)
    throw std::invalid_argument(
        "the problem is first order (∂²L/∂v² = 0): give no initial "
        "velocity");
  return order;
}

// Everything a solve needs before the critical-point search: the checked
// grid and operators, initial data, the detected order and the initial guess.
template <class P, class Real>
struct Prepared {
  static constexpr int d = P::kDim;
  using State = std::array<Real, d>;
  sbp::Operator<Real> D;
  sbp::RegularizedOperator<Real> dbar;
  State x0{}, v0{};
  int order = 2;
  std::vector<Real> guess;  // node-major, points x dof

  Prepared(const P& problem, const InitialData& initial, const Grid& grid,
           const SolveOptions& options)
      : D(sbp::MakeOperator<Real>(grid.op, grid.points, Real(grid.t_start),
                                  Real(grid.t_end))),
        dbar(D, Real(grid.sigma0)) {
    order = CheckInitialData(problem, initial);
    for (int c = 0; c < d; ++c) {
      x0[c] = Real(initial.x[c]);
      v0[c] = initial.v.empty() ? Real(0) : Real(initial.v[c]);
    }
    const int n = D.points();
    if (!options.guess.empty() && options.guess.size() != std::size_t(n) * d)
      throw std::invalid_argument(
          "initial guess has " + std::to_string(options.guess.size()) +
          " values; need points x dof = " + std::to_string(n * d));
    for (double g : options.guess)
      if (!std::isfinite(g))
        throw std::invalid_argument(
            "initial guess contains a non-finite value");
    // Default guess: the initial data continued linearly.
    guess.resize(std::size_t(n) * d);
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < d; ++c)
        guess[i * d + c] = options.guess.empty()
                               ? x0[c] + v0[c] * (D.t(i) - D.t(0))
                               : Real(options.guess[i * d + c]);
  }

  // The full doubled unknowns with both paths at the guess, multipliers 0.
  std::vector<Real> FullGuess(const action::FullSystem<P, Real>& full) const {
    std::vector<Real> u(full.size(), Real(0));
    for (int i = 0; i < D.points(); ++i)
      for (int c = 0; c < d; ++c)
        u[full.X(0, i, c)] = u[full.X(1, i, c)] = guess[i * d + c];
    return u;
  }
};

}  // namespace detail

template <class Real = double, action::LagrangianProblem P>
IvpSolution<Real> SolveIvp(const P& problem, const InitialData& initial,
                           const Grid& grid, const SolveOptions& options = {}) {
  constexpr int d = P::kDim;
  const detail::Prepared<P, Real> prep(problem, initial, grid, options);
  const int n = prep.D.points();
  const action::FullSystem<P, Real> full(problem, prep.dbar, prep.x0, prep.v0,
                                         prep.order);
  std::vector<Real> u;
  variational::NewtonReport report;
  if (options.path == Path::kReducedNewton) {
    const action::ReducedSystem<P, Real> reduced(problem, prep.dbar, prep.x0,
                                                 prep.v0, prep.order);
    std::vector<Real> y(reduced.size(), Real(0));
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < d; ++c) y[reduced.X(i, c)] = prep.guess[i * d + c];
    if (options.extended_residual && std::is_same_v<Real, double>) {
      // The same reduced system in long double, used only for residuals.
      const auto d_ext = sbp::MakeOperator<long double>(
          grid.op, grid.points, grid.t_start, grid.t_end);
      const sbp::RegularizedOperator<long double> dbar_ext(d_ext, grid.sigma0);
      std::array<long double, d> x0e, v0e;
      for (int c = 0; c < d; ++c) {
        x0e[c] = initial.x[c];
        v0e[c] = initial.v.empty() ? 0.0L : initial.v[c];
      }
      const action::ReducedSystem<P, long double> ext(problem, dbar_ext, x0e,
                                                      v0e, prep.order);
      std::vector<long double> ye(reduced.size()), fe(reduced.size());
      report = variational::Newton<Real>(
          reduced, y, options.newton, [&](const Real* yy, Real* ff) {
            for (int k = 0; k < reduced.size(); ++k) ye[k] = yy[k];
            ext.Residual(ye.data(), fe.data());
            for (int k = 0; k < reduced.size(); ++k) ff[k] = Real(fe[k]);
          });
    } else {
      report = variational::Newton(reduced, y, options.newton);
    }
    u.assign(full.size(), Real(0));
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < d; ++c)
        u[full.X(0, i, c)] = u[full.X(1, i, c)] = y[reduced.X(i, c)];
    for (int c = 0; c < d; ++c) {
      u[full.Lambda3(c)] = y[reduced.Lambda3(c)];
      if (prep.order == 2) u[full.Lambda4(c)] = y[reduced.Lambda4(c)];
    }
  } else if (options.path == Path::kFullNewton) {
    u = prep.FullGuess(full);
    report = variational::Newton(full, u, options.newton);
  } else {
    throw std::invalid_argument(
        "SolveIvp runs the Newton paths; vivp::variational::Solve "
        "(solvers/variational/solve.h) runs Levenberg-Marquardt too");
  }
  IvpSolution<Real> s =
      detail::Finish(problem, prep.dbar, full, u, report, options.path);
  detail::CheckResolution(problem, grid, s);
  return s;
}

}  // namespace vivp::variational
