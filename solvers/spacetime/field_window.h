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

#include "core/action/field_constraints.h"
#include "core/action/field_system.h"
#include "core/sbp/builder.h"
#include "core/sbp/regularized.h"
#include "solvers/spacetime/end_state.h"
#include "solvers/spacetime/fourier_solver.h"
#include "solvers/spacetime/predictor.h"
#include "solvers/spacetime/resolution.h"
#include "solvers/spacetime/window_data.h"
#include "solvers/spacetime/window_parts.h"
#include "solvers/spacetime/window_solver.h"
#include "solvers/variational/newton.h"
#include "solvers/variational/resolution.h"
#include "solvers/variational/solve_ivp.h"
#include "solvers/variational/window_checks.h"

namespace vivp::spacetime {

// Whether the window's linear solver suits the field: the Fourier window
// solve needs a periodic grid (and so no boundary data), and a field with
// a component without a time derivative needs it, its Jacobian being
// singular along the gauge. Else std::invalid_argument, naming the fix.
template <class Density>
void CheckLinearSolver(const sbp::SpaceGrid<double>& grid,
                       WindowLinearSolver linear,
                       const FieldBoundary& boundary) {
  if (linear != WindowLinearSolver::kFourier) {
    if (action::ConstraintMaskOf<Density>() != 0u)
      throw std::invalid_argument(
          "a field with a component without a time derivative (a gauge "
          "field's A₀) has a window Jacobian singular along the gauge: solve "
          "it with the Fourier window solve");
    return;
  }
  for (int b = 0; b < grid.dim(); ++b)
    if (!grid.axis(b).periodic())
      throw std::invalid_argument(
          "the Fourier window solve needs a periodic grid; axis " +
          std::to_string(b) + " is an interval" +
          (action::ConstraintMaskOf<Density>() != 0u
               ? std::string(", and gauge fields are built on periodic grids "
                             "only (make every axis periodic)")
               : std::string(" (use the sparse LU or the mode solve "
                             "there)")));
  if (boundary.left.kind != action::BoundaryKind::kNatural ||
      boundary.right.kind != action::BoundaryKind::kNatural ||
      !boundary.faces.empty())
    throw std::invalid_argument(
        "the Fourier window solve has no boundary data on a periodic grid");
}

template <class Density>
class FieldWindow {
 public:
  static constexpr int m = Density::kDim;
  static constexpr unsigned kConstraints = action::ConstraintMaskOf<Density>();
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
    // (SolveField checked the linear solver against the field and grid.)
    if (options.linear == WindowLinearSolver::kFourier)
      fourier_.emplace(density);
    if (kConstraints != 0u) {
      no_predictor_ =
          "a component without a time derivative (a constraint such as A₀) "
          "has no explicit integration to check the windows against";
      return;
    }
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
  // The factor on the predictor's tolerance a uniform march carries from
  // window to window (window_solve.h).
  double predictor_factor() const { return predictor_factor_; }
  void set_predictor_factor(double f) { predictor_factor_ = f; }

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
      // bound (the checks then pass; FieldSolution says so). A gauge
      // field's start is in the gauge A₀ = 0 (end_state.h).
      if constexpr (kConstraints != 0u) {
        gauge_x_.assign(x0, x0 + n_);
        gauge_v_.assign(v0, v0 + n_);
        ToTemporalGauge(density_, grid_, std::span<double>(gauge_x_),
                        std::span<double>(gauge_v_));
        x0 = gauge_x_.data();
        v0 = gauge_v_.data();
      }
      detail::TaylorStart(x0, v0, nullptr, tau, points, n_, px, pv);
      r.error_x = r.error_v = std::numeric_limits<double>::infinity();
    }
    timings_.predictor += Since(start);
    return r;
  }

  bool Solve(variational::detail::WindowAttempt& a, double t0,
             const variational::InitialData& initial,
             const std::vector<double>& px, const std::vector<double>& pv,
             bool fresh, bool nodes) {
    auto lap = Clock::now();
    const int points = a.points, nx = grid_.points();
    // The system is kept while the window's operator is (its work arrays
    // are a window's size: allocating them per window cost page faults).
    if (time_.Set(op_, points, a.dt) || !system_)
      system_ = std::make_unique<System>(density_, *time_.dbar, grid_,
                                         initial.x, initial.v);
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
      if (fourier_) fourier_->Invalidate();
    }
    if (options_.linear == WindowLinearSolver::kSparseLu &&
        sparse_points_ != points) {
      sparse_retired_ += sparse_.factorizations;
      sparse_ = SparseLuSolver(options_.sparse);
      sparse_points_ = points;
    }
    const auto r = options_.linear == WindowLinearSolver::kModes
                       ? variational::Newton<double>(sys, y_, newton, modes_)
                   : fourier_
                       ? variational::Newton<double>(sys, y_, newton, *fourier_)
                       : variational::Newton<double>(sys, y_, newton, sparse_);
    if (!detail::AccountNewton(r, a, timings_, residual_)) return false;
    lap = Clock::now();
    sys.Fields(y_.data(), values_);
    if constexpr (kConstraints != 0u)
      if (!ConstraintsHold(a, points)) return false;
    const auto& D = time_.dbar->base();
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
        a.roundoff_v[k] = std::numeric_limits<double>::epsilon() *
                          time_.row_sum * D.inv_dt() * xmax;
      }
    if (options_.check_resolution &&
        !resolution_.Check(
            [this](const double* x, const double* v) {
              return FastestFrequency(x, v);
            },
            a, t0, initial, op_, options_.t_end, timings_.check))
      return false;
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
    resolution_.Handed(a.end.position, a.end.velocity);
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
    return {time_.dbar ? time_.dbar->points() : 0, time_.dt,
            predictor_ ? predictor_->first_step() : 0.0, modes_.Save(),
            predictor_factor_};
  }
  void Restore(const Carry& c) {
    if (c.points > 0) time_.Set(op_, c.points, c.dt);
    if (predictor_) predictor_->set_first_step(c.predictor_step);
    predictor_factor_ = c.predictor_factor;
    modes_.Restore(c.modes);
  }

  bool ReusesFactorizations() const { return true; }
  long long factorizations() const {
    return modes_.mode_factorizations() + lu_factorizations() +
           (fourier_ ? fourier_->factorizations() : 0);
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
  double omega_dt() const { return resolution_.omega_dt(); }
  double residual_norm() const { return residual_; }
  const FieldTimings& timings() const { return timings_; }
  // φ at the last node of the last solved window (uncorrected), and that
  // window's largest estimates of the errors of φ_N and of the end velocity.
  const std::vector<double>& last_node() const { return last_phi_; }
  std::pair<double, double> last_estimates() const { return last_estimates_; }

 private:
  // The a-posteriori check of a field with constraint components: their
  // equations (Gauss's law of the action) at every node of the solved
  // window, relative to their terms (core/action/field_constraints.h).
  // Measured at round-off (≤ 6e-15, docs/gauge.md §6); a solve whose
  // potentials grew until round-off swamped E fails here, though Newton's
  // residual, relative to the potentials, looked converged.
  static constexpr double kConstraintTolerance = 1e-10;
  bool ConstraintsHold(variational::detail::WindowAttempt& a, int points) {
    double worst = 0;
    for (int i = 0; i < points; ++i) {
      const std::span<const double> phi(&values_.phi[std::size_t(i) * n_],
                                        std::size_t(n_)),
          phi_t(&values_.phi_t[std::size_t(i) * n_], std::size_t(n_));
      const double r =
          action::ConstraintsOfSlice(density_, grid_, phi, phi_t).relative();
      worst = std::isnan(r) ? r : std::max(worst, r);
      if (std::isnan(worst)) break;
    }
    if (worst <= kConstraintTolerance) return true;
    a.failure = variational::detail::WindowFailure::kCheck;
    a.why =
        "the constraint of a component without a time derivative "
        "(Gauss's law of the action) holds only to " +
        variational::detail::ShortNumber(worst) +
        " relative in the window: the solve lost it to round-off";
    return false;
  }

  static double Since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  }

  const Density& density_;
  const sbp::SpaceGrid<double>& grid_;
  std::string op_;
  const FieldWindowOptions& options_;
  int n_;
  double rho_;
  std::optional<FieldPredictor<Density>> predictor_;
  std::string no_predictor_;
  double predictor_factor_ = 1.0;
  ModesSolver<Density> modes_;
  SparseLuSolver sparse_;
  std::optional<FourierSolver<Density>> fourier_;
  int sparse_points_ = -1;
  long long sparse_retired_ = 0;
  detail::WindowOperator time_;
  std::unique_ptr<System> system_;  // of the last solve (refers to time_)
  std::vector<double> y_, momentum_, column_, last_phi_;
  std::vector<double> gauge_x_, gauge_v_;  // a gauge field's start
  action::FieldValues<double> values_;
  detail::WindowResolution resolution_;
  double residual_ = 0;
  std::pair<double, double> last_estimates_{0, 0};
  FieldTimings timings_;
};

}  // namespace vivp::spacetime
