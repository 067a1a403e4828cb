// The window of a field's march as the generic window solver sees it
// (solvers/variational/window_solve.h): the predictor (predictor.h), the
// space-time window's equations (core/action/field_system.h) solved by the
// one Newton with the window's linear solver (window_solver.h), the
// multiplier-corrected end state and its embedded estimates per spatial
// point (end_state.h). Everything else — the hand-off, the a-posteriori
// checks, fallbacks, error control — is the point-mechanics march's
// (solvers/variational/march_core.h). The point-mechanics counterpart is
// solvers/variational/point_window.h.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/action/field_system.h"
#include "core/sbp/builder.h"
#include "core/sbp/regularized.h"
#include "solvers/spacetime/end_state.h"
#include "solvers/spacetime/predictor.h"
#include "solvers/spacetime/resolution.h"
#include "solvers/spacetime/window_solver.h"
#include "solvers/variational/newton.h"
#include "solvers/variational/resolution.h"
#include "solvers/variational/solve_ivp.h"
#include "solvers/variational/window_checks.h"

namespace vivp::spacetime {

// One end of an interval: the natural condition ∂L/∂φ_x = 0 of the discrete
// action, or Dirichlet / Neumann data imposed by multipliers
// (core/action/field_boundary.h); value(t, a) is g or h of component a
// (empty: 0).
struct FieldBoundarySide {
  action::BoundaryKind kind = action::BoundaryKind::kNatural;
  std::function<double(double t, int a)> value;
};
struct FieldBoundary {
  FieldBoundarySide left, right;  // the ends of one spatial axis
  std::vector<FieldFace> faces;   // Neumann faces in d > 1 (input.h)
};

// What carries from one field window to the next besides the hand-off
// state (FieldWindow::Save): the time operator's points and step (kept
// while the step stays within 64 ε), the predictor's first step, the mode
// solve's factorization.
struct FieldWindowCarry {
  int points = 0;
  double dt = 0, predictor_step = 0;
  ModesSnapshot modes;
};

// What a field window needs besides the density and the grids.
struct FieldWindowOptions {
  variational::NewtonOptions newton;
  WindowLinearSolver linear = WindowLinearSolver::kModes;
  SparseSolver sparse = SparseSolver::kUmfpack;
  FieldBoundary boundary;
  bool check_resolution = true;
  double t_end = 0;  // of the march (the points an under-resolved run needs)
};

// Where a field march's time goes (bench/fields_bench --profile).
struct FieldTimings {
  double residual = 0, assembly = 0, factorization = 0, solve = 0;
  double setup = 0, check = 0, handoff = 0, predictor = 0;
};

namespace detail {

// The window's boundary data at its nodes t0 + iΔt.
template <class System>
void SetBoundaryData(System& sys, const FieldBoundary& b, double t0,
                     double dt) {
  constexpr int m = System::m;
  const FieldBoundarySide* sides[2] = {&b.left, &b.right};
  for (int side = 0; side < 2; ++side) {
    if (sides[side]->kind == action::BoundaryKind::kNatural) continue;
    std::vector<double> values(std::size_t(sys.time_points()) * m, 0.0);
    if (sides[side]->value)
      for (int i = 0; i < sys.time_points(); ++i)
        for (int a = 0; a < m; ++a) {
          const double t = t0 + dt * i;
          values[i * m + a] = sides[side]->value(t, a);
          if (!std::isfinite(values[i * m + a]))
            throw std::invalid_argument(
                std::string(side == 0 ? "left" : "right") + " " +
                action::BoundaryName(sides[side]->kind) +
                " data: non-finite value at t = " + std::to_string(t));
        }
    sys.SetBoundary(side, sides[side]->kind, std::move(values));
  }
  const auto& g = sys.space_grid();
  for (const FieldFace& face : b.faces) {
    const auto points = action::detail::FacePoints(g, face.axis, face.side);
    std::vector<double> slopes(std::size_t(sys.time_points()) * points.size() *
                               m);
    double x[3];
    for (int i = 0; i < sys.time_points(); ++i)
      for (std::size_t k = 0; k < points.size(); ++k) {
        for (int a = 0; a < g.dim(); ++a) x[a] = g.x(points[k], a);
        for (int c = 0; c < m; ++c) {
          double& h = slopes[(i * points.size() + k) * m + c];
          h = face.slope ? face.slope(t0 + dt * i, x, c) : 0.0;
          if (!std::isfinite(h))
            throw std::invalid_argument(
                "Neumann data of face " + std::to_string(face.side) +
                " of axis " + std::to_string(face.axis) +
                ": non-finite slope at t = " + std::to_string(t0 + dt * i));
        }
      }
    sys.SetFace(face.axis, face.side, slopes);
  }
}

}  // namespace detail

template <class Density>
class FieldWindow {
 public:
  static constexpr int m = Density::kDim;
  using System = action::FieldSystem<Density>;
  using Clock = std::chrono::steady_clock;

  // phi0, pi0: the march's initial data (the predictor checks the density's
  // form there).
  FieldWindow(const Density& density, const sbp::SpaceGrid<double>& grid,
              const std::string& op, const FieldWindowOptions& options,
              std::span<const double> phi0, std::span<const double> pi0)
      : density_(density),
        grid_(grid),
        op_(op),
        options_(options),
        n_(grid.points() * m),
        rho_(SpectralRadius(grid)),
        modes_(density, options.sparse),
        sparse_(options.sparse) {
    const typename FieldPredictor<Density>::End ends[2] = {
        {options.boundary.left.kind, options.boundary.left.value},
        {options.boundary.right.kind, options.boundary.right.value}};
    try {
      predictor_.emplace(density, grid, phi0, pi0, ends);
      predictor_->SetFaces(options.boundary.faces);
    } catch (const std::invalid_argument& e) {
      no_predictor_ = e.what();
    }
  }

  int dim() const { return n_; }
  int order() const { return 2; }
  const std::string& op() const { return op_; }
  double FastestFrequency(const double* x, const double* v) const {
    return FastestFieldFrequency(density_, grid_, rho_,
                                 std::span<const double>(x, n_),
                                 std::span<const double>(v, n_));
  }
  // Why the windows are not checked against an independent integration
  // (empty: they are).
  const std::string& unchecked() const { return no_predictor_; }

  variational::PredictorReport Predict(double t0, const double* x0,
                                       const double* v0, const double* tau,
                                       int points, double tol_abs,
                                       double tol_rel, double* px, double* pv) {
    const auto start = Clock::now();
    variational::PredictorReport r;
    if (predictor_) {
      r = predictor_->Run(t0, x0, v0, tau, points, tol_abs, tol_rel, px, pv);
    } else {
      // No independent integration: the Newton start φ₀ + τπ₀, and no
      // bound (the checks then pass; FieldSolution says so).
      for (int i = 0; i < points; ++i)
        for (int k = 0; k < n_; ++k) {
          px[std::size_t(i) * n_ + k] = x0[k] + tau[i] * v0[k];
          pv[std::size_t(i) * n_ + k] = v0[k];
        }
      r.error_x = r.error_v = std::numeric_limits<double>::infinity();
    }
    timings_.predictor += Since(start);
    return r;
  }

  bool Solve(variational::detail::WindowAttempt& a, double t0,
             const variational::InitialData& initial,
             const std::vector<double>& px, const std::vector<double>& pv,
             bool fresh, bool nodes) {
    using variational::detail::WindowFailure;
    auto lap = Clock::now();
    const int points = a.points, nx = grid_.points();
    // The system is kept while the window's operator is (its work arrays
    // are a window's size: allocating them per window cost page faults).
    if (Operators(points, a.dt) || !system_)
      system_ = std::make_unique<System>(density_, *dbar_, grid_, initial.x,
                                         initial.v);
    else
      system_->SetInitial(initial.x, initial.v);
    detail::SetBoundaryData(*system_, options_.boundary, t0, a.dt);
    System& sys = *system_;
    // Newton from the predictor's path, λ3 at its end momentum.
    y_.assign(sys.size(), 0.0);
    for (int i = 0; i < points; ++i)
      for (int j = 0; j < nx; ++j)
        for (int c = 0; c < m; ++c)
          y_[sys.Phi(i, j, c)] = px[std::size_t(i) * n_ + j * m + c];
    if (predictor_) {
      momentum_.resize(n_);
      const std::size_t end = std::size_t(points - 1) * n_;
      predictor_->Momentum(&px[end], &pv[end], momentum_.data());
      for (int j = 0; j < nx; ++j)
        for (int c = 0; c < m; ++c)
          y_[sys.Lambda3(j, c)] = sys.Fixed(j) ? 0.0 : -momentum_[j * m + c];
    }
    // A Dirichlet point's column is data: the checks skip it.
    a.data.assign(n_, 0);
    for (int j = 0; j < nx; ++j)
      if (sys.Fixed(j))
        for (int c = 0; c < m; ++c) a.data[j * m + c] = 1;
    timings_.setup += Since(lap);
    variational::NewtonOptions newton = options_.newton;
    if (fresh) {
      modes_.Invalidate();
      sparse_.Invalidate();
    }
    if (options_.linear == WindowLinearSolver::kSparseLu &&
        sparse_points_ != points) {
      sparse_retired_ += sparse_.factorizations;
      sparse_ = SparseLuSolver(options_.sparse);
      sparse_points_ = points;
    }
    const auto r = options_.linear == WindowLinearSolver::kModes
                       ? variational::Newton<double>(sys, y_, newton, modes_)
                       : variational::Newton<double>(sys, y_, newton, sparse_);
    a.iterations = r.iterations;
    a.corrections = r.corrections;
    timings_.residual += r.phases.residual;
    timings_.assembly += r.phases.assembly;
    timings_.factorization += r.phases.factorization;
    timings_.solve += r.phases.solve;
    residual_ = std::max(residual_, r.last_residual);
    if (!r.converged) {
      a.residual = r.last_residual;
      a.failure = WindowFailure::kNewton;
      a.why = r.reason;
      return false;
    }
    lap = Clock::now();
    sys.Fields(y_.data(), values_);
    const auto& D = dbar_->base();
    const int last = points - 1;
    // x_N and (D φ)_N with the plain operator, as the connection rows.
    column_.resize(points);
    for (int j = 0; j < nx; ++j)
      for (int c = 0; c < m; ++c) {
        const int k = j * m + c;
        double xmax = 0;
        for (int i = 0; i < points; ++i) {
          column_[i] = y_[sys.Phi(i, j, c)];
          xmax = std::max(xmax, std::abs(column_[i]));
        }
        a.x_end[k] = column_[last];
        a.v_end[k] = D.ApplyRow(last, column_.data());
        a.roundoff_v[k] = std::numeric_limits<double>::epsilon() * row_sum_ *
                          D.inv_dt() * xmax;
      }
    if (options_.check_resolution) {
      const auto t_check = Clock::now();
      // ω at the start: the last window's at its end when this window
      // continues from its hand-off (the same state up to the correction).
      const bool continues =
          omega_end_ >= 0 && initial.x == handed_x_ && initial.v == handed_v_;
      const double omega_start =
          continues ? omega_end_
                    : FastestFrequency(initial.x.data(), initial.v.data());
      omega_end_ = FastestFrequency(a.x_end.data(), a.v_end.data());
      omega_dt_ = std::max(omega_dt_, a.dt * std::max(omega_start, omega_end_));
      // The rule of SolveField's check before the march (resolution.h), at
      // either end of the window.
      const double limit = variational::StabilityLimit(op_);
      std::string why =
          UnderResolved(op_, limit, a.dt, omega_start, t0, options_.t_end);
      if (why.empty())
        why = UnderResolved(op_, limit, a.dt, omega_end_,
                            t0 + a.dt * double(last), options_.t_end);
      timings_.check += Since(t_check);
      if (!why.empty()) {
        omega_end_ = -1;
        a.failure = WindowFailure::kUnderResolved;
        a.why = std::move(why);
        return false;
      }
    }
    const FieldEnd e = CorrectFieldEnd(sys, y_.data(), values_);
    a.end.position = e.phi;
    a.end.velocity = e.phi_t;
    a.end.momentum.assign(n_, 0.0);
    for (int j = 0; j < nx; ++j)
      for (int c = 0; c < m; ++c)
        a.end.momentum[j * m + c] = sys.Fixed(j) ? 0.0 : -y_[sys.Lambda3(j, c)];
    a.end.position_error_estimate = e.phi_estimate;
    a.end.velocity_error_estimate = e.phi_t_estimate;
    for (int k = 0; k < n_; ++k) {
      a.est_x[k] = std::abs(a.end.position[k] - a.x_end[k]);
      a.est_v[k] = std::abs(a.v_end[k] - a.end.velocity[k]);
    }
    for (int i = 0; i < points; ++i)
      for (int k = 0; k < n_; ++k)
        if (!a.IsData(k))
          a.deviation = std::max(a.deviation,
                                 std::abs(values_.phi[std::size_t(i) * n_ + k] -
                                          px[std::size_t(i) * n_ + k]));
    if (nodes) {
      a.x = values_.phi;
      a.v = values_.phi_t;
    }
    handed_x_ = a.end.position;
    handed_v_ = a.end.velocity;
    last_phi_ = a.x_end;
    last_estimates_ = {e.phi_estimate, e.phi_t_estimate};
    timings_.handoff += Since(lap);
    return true;
  }

  void RecordResidual(variational::detail::WindowAttempt& a) const {
    if (!system_) return;
    std::vector<double> f(system_->size());
    system_->Residual(y_.data(), f.data());
    double worst = 0;
    for (double v : f)
      worst = std::isfinite(v) ? std::max(worst, std::abs(v)) : NAN;
    a.residual = worst;
  }

  // What carries from one window to the next besides the hand-off state —
  // the time operator's step, the predictor's first step, the mode solve's
  // factorization — so that a march resumed from a checkpoint repeats the
  // uninterrupted one bit for bit.
  using Carry = FieldWindowCarry;
  Carry Save() const {
    return {dbar_ ? dbar_->points() : 0, dt_,
            predictor_ ? predictor_->first_step() : 0.0, modes_.Save()};
  }
  void Restore(const Carry& c) {
    if (c.points > 0) Operators(c.points, c.dt);
    if (predictor_) predictor_->set_first_step(c.predictor_step);
    modes_.Restore(c.modes);
  }

  bool ReusesFactorizations() const { return true; }
  long long factorizations() const {
    return modes_.mode_factorizations() + lu_factorizations();
  }

  // What a FieldSolution reports.
  long long mode_factorizations() const { return modes_.mode_factorizations(); }
  long long lu_factorizations() const {
    return sparse_retired_ + sparse_.factorizations +
           modes_.lu_factorizations();
  }
  int fallbacks() const { return int(modes_.fallbacks); }
  std::size_t factor_bytes() const { return modes_.factor_bytes(); }
  long long jacobian_nonzeros() const { return sparse_.nonzeros(); }
  double omega_dt() const { return omega_dt_; }
  double residual_norm() const { return residual_; }
  const FieldTimings& timings() const { return timings_; }
  // φ at the last node of the last solved window (uncorrected), and that
  // window's largest estimates of the errors of φ_N and of the end velocity.
  const std::vector<double>& last_node() const { return last_phi_; }
  std::pair<double, double> last_estimates() const { return last_estimates_; }

 private:
  static double Since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  }

  // The time operator of a window of `points` nodes spaced dt, kept while
  // they stay (a step within 64 ε of the last is the same step: the windows
  // of a uniform march differ in the last bits); true if it was rebuilt.
  bool Operators(int points, double dt) {
    if (dbar_ && dbar_->points() == points &&
        std::abs(dt - dt_) <= 64 * std::numeric_limits<double>::epsilon() * dt_)
      return false;
    dt_ = dt;
    dbar_ = std::make_unique<sbp::RegularizedOperator<double>>(
        sbp::MakeOperator<double>(op_, points, 0.0, dt * double(points - 1)));
    row_sum_ = 0;
    for (double w : dbar_->base().row(points - 1).coeffs)
      row_sum_ += std::abs(w);
    return true;
  }

  const Density& density_;
  const sbp::SpaceGrid<double>& grid_;
  std::string op_;
  const FieldWindowOptions& options_;
  int n_;
  double rho_;
  std::optional<FieldPredictor<Density>> predictor_;
  std::string no_predictor_;
  ModesSolver<Density> modes_;
  SparseLuSolver sparse_;
  int sparse_points_ = -1;
  long long sparse_retired_ = 0;
  std::unique_ptr<sbp::RegularizedOperator<double>> dbar_;
  double dt_ = 0, row_sum_ = 0;
  std::unique_ptr<System> system_;  // of the last solve (refers to dbar_)
  std::vector<double> y_, momentum_, column_, last_phi_;
  action::FieldValues<double> values_;
  std::vector<double> handed_x_, handed_v_;
  double omega_end_ = -1, omega_dt_ = 0, residual_ = 0;
  std::pair<double, double> last_estimates_{0, 0};
  FieldTimings timings_;
};

}  // namespace vivp::spacetime
