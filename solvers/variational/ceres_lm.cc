// Ceres Levenberg–Marquardt on ∇S of a full doubled system (ceres_lm.h),
// compiled once for every problem: the problem enters only through
// LmSystem's gradient and banded Hessian.
#include "solvers/variational/ceres_lm.h"

#include <ceres/ceres.h>

#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

namespace vivp::variational::detail {
namespace {

// ∇S and ∇²S at the point Ceres is about to evaluate.
class GradientCache : public ceres::EvaluationCallback {
 public:
  GradientCache(const LmSystem& system, std::vector<double>& u)
      : system_(system),
        u_(u),
        g_(u.size()),
        hessian_(int(u.size()), system.band.kl, system.band.ku) {}

  void PrepareForEvaluation(bool evaluate_jacobians,
                            bool new_evaluation_point) override {
    if (new_evaluation_point || !have_residual_) {
      system_.gradient(u_.data(), g_.data());
      have_residual_ = true;
      have_jacobian_ = false;
    }
    if (evaluate_jacobians && !have_jacobian_) {
      hessian_.SetZero();
      system_.hessian(u_.data(), hessian_);
      have_jacobian_ = true;
    }
  }

  const std::vector<double>& gradient() const { return g_; }
  const linalg::BandedMatrix<double>& hessian() const { return hessian_; }

 private:
  const LmSystem& system_;
  std::vector<double>& u_;
  std::vector<double> g_;
  linalg::BandedMatrix<double> hessian_;
  bool have_residual_ = false, have_jacobian_ = false;
};

// Rows [row0, row0 + rows) of ∇S, depending on parameter blocks given by
// their starting offsets and sizes.
class GradientRows : public ceres::CostFunction {
 public:
  GradientRows(const GradientCache& cache, int row0, int rows,
               std::vector<int> block_offsets, std::vector<int> block_sizes)
      : cache_(cache), row0_(row0), offsets_(std::move(block_offsets)) {
    set_num_residuals(rows);
    for (int s : block_sizes) mutable_parameter_block_sizes()->push_back(s);
  }

  bool Evaluate(double const* const* /*parameters*/, double* residuals,
                double** jacobians) const override {
    const int rows = num_residuals();
    for (int r = 0; r < rows; ++r) residuals[r] = cache_.gradient()[row0_ + r];
    if (jacobians == nullptr) return true;
    const auto& sizes = parameter_block_sizes();
    for (std::size_t b = 0; b < offsets_.size(); ++b) {
      if (jacobians[b] == nullptr) continue;
      for (int r = 0; r < rows; ++r)
        for (int c = 0; c < sizes[b]; ++c)
          jacobians[b][r * sizes[b] + c] =
              cache_.hessian()(row0_ + r, offsets_[b] + c);
    }
    return true;
  }

 private:
  const GradientCache& cache_;
  int row0_;
  std::vector<int> offsets_;
};

// The Ceres problem: each residual block is ∇S with respect to one
// parameter block and depends on the blocks whose columns meet the Hessian's
// band in its rows.
void AddGradientBlocks(const LmSystem& system, std::vector<double>& u,
                       const GradientCache& cache, ceres::Problem& cp) {
  const std::vector<int>& offsets = system.block_offsets;
  const std::vector<int>& sizes = system.block_sizes;
  const linalg::BandwidthProbe& probe = system.band;
  for (std::size_t b = 0; b < offsets.size(); ++b)
    cp.AddParameterBlock(u.data() + offsets[b], sizes[b]);
  for (std::size_t b = 0; b < offsets.size(); ++b) {
    const int r0 = offsets[b], r1 = offsets[b] + sizes[b];
    std::vector<int> dep_offsets, dep_sizes;
    std::vector<double*> deps;
    for (std::size_t k = 0; k < offsets.size(); ++k) {
      const int c0 = offsets[k], c1 = offsets[k] + sizes[k];
      if (c1 - 1 >= r0 - probe.ku && c0 <= r1 - 1 + probe.kl) {
        dep_offsets.push_back(c0);
        dep_sizes.push_back(sizes[k]);
        deps.push_back(u.data() + c0);
      }
    }
    cp.AddResidualBlock(
        new GradientRows(cache, r0, sizes[b], dep_offsets, dep_sizes), nullptr,
        deps);
  }
}

// Ceres logs a line through glog each time LM's normal equations fail to
// factor (it then raises the damping and tries again); a solve reports its
// outcome in its status, so without `verbose` those lines would only flood
// stderr.
void QuietCeres() {
  if (FLAGS_minloglevel < google::GLOG_ERROR)
    FLAGS_minloglevel = google::GLOG_ERROR;
}

// Ceres' LM with the stopping rules of this solver: stop only when no step
// decreases |∇S|² any more (the tolerances are below round-off), and judge
// the result on ∇S itself afterwards.
ceres::Solver::Options LmOptions(const CeresOptions& o) {
  ceres::Solver::Options so;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  so.max_num_iterations = o.max_iterations;
  so.function_tolerance = 1e-32;
  so.gradient_tolerance = 1e-32;
  so.parameter_tolerance = o.parameter_tolerance;
  so.initial_trust_region_radius = o.initial_radius;
  so.minimizer_progress_to_stdout = o.verbose;
  so.logging_type = o.verbose ? ceres::PER_MINIMIZER_ITERATION : ceres::SILENT;
  so.num_threads = 1;
  return so;
}

// The round-off level of ∇S at u, ε·max_i Σ_j |∂²S/∂u_i∂u_j|·|u_j|: the
// rounding of a gradient evaluated at a point of u's size. (At Newton's
// solutions ‖∇S‖∞ is 0.1–0.3 of it: SBP21–84, windows of 16–256 points of
// the anharmonic oscillator.)
double GradientRoundOff(const LmSystem& system, const std::vector<double>& u) {
  const linalg::BandwidthProbe& probe = system.band;
  linalg::BandedMatrix<double> h(system.size, probe.kl, probe.ku);
  system.hessian(u.data(), h);
  double level = 0;
  for (int i = 0; i < system.size; ++i) {
    double row = 0;
    const int j1 = std::min(system.size - 1, i + probe.ku);
    for (int j = std::max(0, i - probe.kl); j <= j1; ++j)
      row += std::abs(h(i, j)) * std::abs(u[j]);
    level = std::max(level, row);
  }
  return std::numeric_limits<double>::epsilon() * level;
}

// LM only knows it can no longer decrease |∇S|²; whether that is a critical
// point is judged on ∇S itself: it must have fallen by sqrt(eps) relative to
// the initial guess (Newton reaches eps on these problems), or to its
// round-off level — a start already close to the solution (a march's window
// from its predictor) cannot fall by sqrt(eps) below that.
NewtonReport LmReport(const ceres::Solver::Summary& summary,
                      double initial_gradient, double final_gradient,
                      double roundoff) {
  NewtonReport report;
  report.iterations = static_cast<int>(summary.iterations.size()) - 1;
  report.corrections = report.iterations;
  report.last_residual = final_gradient;
  const double floor = std::max(
      std::sqrt(std::numeric_limits<double>::epsilon()) * initial_gradient,
      roundoff);
  report.converged = summary.termination_type == ceres::CONVERGENCE &&
                     report.last_residual <= floor;
  std::ostringstream why;
  why << "Ceres LM: "
      << ceres::TerminationTypeToString(summary.termination_type) << " after "
      << report.iterations << " iterations, |∇S|∞ = " << report.last_residual;
  if (!report.converged) why << " (above the acceptance bound " << floor << ")";
  report.reason = why.str();
  return report;
}

}  // namespace

NewtonReport RunCeresLm(const LmSystem& system, std::vector<double>& u,
                        const CeresOptions& options) {
  std::vector<double> g(system.size);
  system.gradient(u.data(), g.data());
  const double initial_gradient = MaxAbs(g);
  GradientCache cache(system, u);
  ceres::Problem::Options problem_options;
  problem_options.evaluation_callback = &cache;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem cp(problem_options);
  AddGradientBlocks(system, u, cache, cp);
  if (!options.verbose) QuietCeres();
  ceres::Solver::Summary summary;
  ceres::Solve(LmOptions(options), &cp, &summary);
  system.gradient(u.data(), g.data());
  return LmReport(summary, initial_gradient, MaxAbs(g),
                  GradientRoundOff(system, u));
}

}  // namespace vivp::variational::detail
