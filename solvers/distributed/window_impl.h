// DistributedWindow (window.h): the Window concept of
// solvers/variational/window_solve.h on one rank's slab.
#pragma once

namespace vivp::distributed {

template <class Density>
class DistributedWindow {
 public:
  static constexpr int m = Density::kDim;
  using System = action::FieldSystem<Density>;
  using Clock = std::chrono::steady_clock;

  DistributedWindow(const Comm& comm, const Density& density,
                    const sbp::SpaceGrid<double>& grid, const std::string& op,
                    const spacetime::FieldWindowOptions& options)
      : comm_(comm),
        density_(density),
        slab_(comm, grid),
        op_(op),
        options_(options),
        n_(grid.points() * m),
        rho_(spacetime::SpectralRadius(grid)),
        solver_(density) {}

  int dim() const { return n_; }
  int order() const { return 2; }
  const std::string& op() const { return op_; }
  // ω_max over the whole grid: each rank's points, then the largest.
  double FastestFrequency(const double* x, const double* v) const {
    const int first = slab_.first_point();
    double omega[1] = {spacetime::FastestFieldFrequency(
        density_, slab_.grid(), rho_, std::span<const double>(x, n_),
        std::span<const double>(v, n_), first, first + slab_.own_points())};
    comm_.Max(omega);
    return omega[0];
  }
  const std::string& unchecked() const { return unchecked_; }

  // No independent integration: the Newton start is the Taylor path of
  // window_parts.h (the same on every rank: each holds the whole slice), and
  // no bound (the checks then pass; FieldSolution::unchecked says so).
  variational::PredictorReport Predict(double, const double* x0,
                                       const double* v0, const double* tau,
                                       int points, double, double, double* px,
                                       double* pv) {
    const auto lap = Clock::now();
    const double* acc = nullptr;
    if (Accelerate(x0, v0)) {
      acc_.resize(n_);
      (*accel_)(std::span<const double>(x0, n_), acc_);
      acc = acc_.data();
    }
    spacetime::detail::TaylorStart(x0, v0, acc, tau, points, n_, px, pv);
    timings_.predictor += Since(lap);
    variational::PredictorReport r;
    r.error_x = r.error_v = std::numeric_limits<double>::infinity();
    return r;
  }

  bool Solve(variational::detail::WindowAttempt& a, double t0,
             const variational::InitialData& initial,
             const std::vector<double>& px, const std::vector<double>& pv,
             bool fresh, bool nodes) {
    auto lap = Clock::now();
    const int points = a.points, own = slab_.own_points();
    if (time_.Set(op_, points, a.dt) || !system_)
      system_ = std::make_unique<System>(density_, *time_.dbar, slab_.wide(),
                                         slab_.Widen(initial.x, m),
                                         slab_.Widen(initial.v, m));
    else
      system_->SetInitial(slab_.Widen(initial.x, m), slab_.Widen(initial.v, m));
    SlabSystem<Density> sys(comm_, slab_, *system_);
    const int first = slab_.first_point();
    y_.assign(sys.size(), 0.0);
    for (int j = 0; j < own; ++j)
      for (int i = 0; i < points; ++i)
        for (int c = 0; c < m; ++c)
          y_[std::size_t(j) * system_->block() + i * m + c] =
              px[std::size_t(i) * n_ + (first + j) * m + c];
    // λ3 at minus the start path's end momentum M φ_t (window_impl.h's
    // Gather reads the momentum back as −λ3).
    if (accel_) {
      const double* v = &pv[std::size_t(points - 1) * n_];
      for (int j = 0; j < own; ++j) {
        const Eigen::Map<const Eigen::Matrix<double, m, 1>> vj(
            v + std::size_t(first + j) * m);
        Eigen::Map<Eigen::Matrix<double, m, 1>> lambda3(
            &y_[std::size_t(j) * system_->block() + points * m]);
        lambda3 = -mass_ * vj;
      }
    }
    timings_.setup += Since(lap);
    if (fresh) solver_.Invalidate();
    const auto r =
        variational::Newton<double>(sys, y_, options_.newton, solver_);
    if (!spacetime::detail::AccountNewton(r, a, timings_, residual_))
      return false;
    lap = Clock::now();
    Gather(a, sys, px, nodes);
    timings_.handoff += Since(lap);
    if (options_.check_resolution &&
        !resolution_.Check(
            [this](const double* x, const double* v) {
              return FastestFrequency(x, v);
            },
            a, t0, initial, op_, options_.t_end, timings_.check))
      return false;
    resolution_.Handed(a.end.position, a.end.velocity);
    last_phi_ = a.x_end;
    return true;
  }

  void RecordResidual(variational::detail::WindowAttempt& a) const {
    if (!system_) return;
    SlabSystem<Density> sys(comm_, slab_, *system_);
    std::vector<double> f(sys.size());
    sys.Residual(y_.data(), f.data());
    double worst[1] = {0};
    for (double v : f)
      worst[0] = std::isfinite(v) ? std::max(worst[0], std::abs(v)) : NAN;
    comm_.Max(worst);
    a.residual = worst[0];
  }

  // The one-process window's reports (solve.h reads them).
  using Carry = spacetime::FieldWindowCarry;
  Carry Save() const { return {}; }
  void Restore(const Carry&) {}
  bool ReusesFactorizations() const { return true; }
  long long factorizations() const { return solver_.factorizations(); }
  long long mode_factorizations() const { return solver_.factorizations(); }
  long long lu_factorizations() const { return 0; }
  int fallbacks() const { return 0; }
  std::size_t factor_bytes() const { return solver_.factor_bytes(); }
  long long jacobian_nonzeros() const { return 0; }
  double omega_dt() const { return resolution_.omega_dt(); }
  double residual_norm() const { return residual_; }
  const spacetime::FieldTimings& timings() const { return timings_; }
  // No independent integration: the factor never changes (window_solve.h).
  double predictor_factor() const { return 1.0; }
  void set_predictor_factor(double) {}
  const std::vector<double>& last_node() const { return last_phi_; }
  std::pair<double, double> last_estimates() const { return last_estimates_; }
  const Slab& slab() const { return slab_; }

 private:
  // The semi-discrete acceleration of the whole grid, built at the first
  // window's data; false when the density is not ½ φ_tᵀMφ_t − U
  // (FieldAcceleration's check), and the start is then the straight path.
  bool Accelerate(const double* x0, const double* v0) {
    if (!accel_tried_) {
      accel_tried_ = true;
      try {
        accel_.emplace(density_, slab_.grid(), std::span<const double>(x0, n_),
                       std::span<const double>(v0, n_));
        mass_ = accel_->inverse_mass().inverse();
      } catch (const std::invalid_argument&) {
        accel_.reset();
      }
    }
    return accel_.has_value();
  }

  static double Since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  }

  // The converged window's end state, estimates and (with `nodes`) its
  // nodes, from this rank's points to the whole grid on every rank.
  void Gather(variational::detail::WindowAttempt& a,
              const SlabSystem<Density>& sys, const std::vector<double>& px,
              bool nodes);

  const Comm& comm_;
  const Density& density_;
  Slab slab_;
  std::string op_;
  const spacetime::FieldWindowOptions& options_;
  int n_;
  double rho_;
  SlabModesSolver<Density> solver_;
  std::optional<spacetime::FieldAcceleration<Density>> accel_;
  bool accel_tried_ = false;
  Eigen::Matrix<double, m, m> mass_;
  std::vector<double> acc_;
  spacetime::detail::WindowOperator time_;
  std::unique_ptr<System> system_;  // of the last solve (refers to time_)
  std::vector<double> y_, last_phi_, local_, all_;
  action::FieldValues<double> values_;
  spacetime::detail::WindowResolution resolution_;
  double residual_ = 0;
  std::pair<double, double> last_estimates_{0, 0};
  std::string unchecked_ =
      "the windows of a distributed march are not checked against an "
      "independent integration (its predictor runs on one process; Newton "
      "starts from the Taylor path)";
  spacetime::FieldTimings timings_;
};

template <class Density>
void DistributedWindow<Density>::Gather(variational::detail::WindowAttempt& a,
                                        const SlabSystem<Density>& sys,
                                        const std::vector<double>& px,
                                        bool nodes) {
  const System& wide = sys.wide();
  const double* y = sys.Widen(y_.data());
  wide.Fields(y, values_);
  const int own = slab_.own_points(), halo = slab_.halo_points();
  const int first = slab_.first_point(), points = wide.time_points();
  const int last = points - 1, wn = wide.space_points();
  const spacetime::FieldEnd e =
      spacetime::CorrectFieldEnd(wide, y, values_, halo, halo + own);
  const auto& D = time_.dbar->base();
  // Per point and component: x_N, (Dφ)_N, its round-off, the corrected
  // position, velocity, momentum; then, with `nodes`, φ and φ_t at the nodes.
  const int fields = 6 + (nodes ? 2 * points : 0);
  const std::size_t per = std::size_t(own) * m;
  local_.assign(per * fields, 0.0);
  std::vector<double> column(points);
  double deviation = 0;
  for (int j = 0; j < own; ++j)
    for (int c = 0; c < m; ++c) {
      const std::size_t k = std::size_t(j) * m + c;
      double xmax = 0;
      for (int i = 0; i < points; ++i) {
        column[i] = values_.phi[(std::size_t(i) * wn + halo + j) * m + c];
        xmax = std::max(xmax, std::abs(column[i]));
        deviation = std::max(
            deviation, std::abs(column[i] -
                                px[std::size_t(i) * n_ + (first + j) * m + c]));
        if (nodes) {
          local_[(6 + i) * per + k] = column[i];
          local_[(6 + points + i) * per + k] =
              values_.phi_t[(std::size_t(i) * wn + halo + j) * m + c];
        }
      }
      local_[k] = column[last];
      local_[per + k] = D.ApplyRow(last, column.data());
      local_[2 * per + k] = std::numeric_limits<double>::epsilon() *
                            time_.row_sum * D.inv_dt() * xmax;
      local_[3 * per + k] = e.phi[k];
      local_[4 * per + k] = e.phi_t[k];
      local_[5 * per + k] = -y_[std::size_t(j) * wide.block() + points * m + c];
    }
  all_.resize(local_.size() * comm_.size());
  comm_.Allgather(local_, all_);
  // Rank r's field f at all_[(r·fields + f)·per …]; its points follow rank
  // r − 1's in the grid's flat index.
  auto field = [&](int f, double* out) {
    for (int r = 0; r < comm_.size(); ++r)
      std::copy_n(all_.begin() + (std::size_t(r) * fields + f) * per, per,
                  out + std::size_t(r) * per);
  };
  field(0, a.x_end.data());
  field(1, a.v_end.data());
  field(2, a.roundoff_v.data());
  a.end.position.resize(n_);
  a.end.velocity.resize(n_);
  a.end.momentum.resize(n_);
  field(3, a.end.position.data());
  field(4, a.end.velocity.data());
  field(5, a.end.momentum.data());
  double scalars[3] = {e.phi_estimate, e.phi_t_estimate, deviation};
  comm_.Max(scalars);
  a.end.position_error_estimate = scalars[0];
  a.end.velocity_error_estimate = scalars[1];
  a.deviation = scalars[2];
  for (int k = 0; k < n_; ++k) {
    a.est_x[k] = std::abs(a.end.position[k] - a.x_end[k]);
    a.est_v[k] = std::abs(a.v_end[k] - a.end.velocity[k]);
  }
  a.data.assign(n_, 0);
  if (nodes) {
    a.x.resize(std::size_t(points) * n_);
    a.v.resize(a.x.size());
    for (int i = 0; i < points; ++i) {
      field(6 + i, a.x.data() + std::size_t(i) * n_);
      field(6 + points + i, a.v.data() + std::size_t(i) * n_);
    }
  }
  last_estimates_ = {scalars[0], scalars[1]};
}

}  // namespace vivp::distributed
