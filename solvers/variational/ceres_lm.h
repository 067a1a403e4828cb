// The design's reference path: Ceres Levenberg–Marquardt on r = ∇S of the full
// doubled system, including the multiplier rows (Rothkopf & Nordström 2023
// minimise |∇S|² the same way).
//
// LM needs r and its Jacobian ∇²S by residual block. Both come from one O(Nt)
// evaluation of the whole system (pointwise AD through the stencils, as in the
// Newton paths), done once per evaluation point in an EvaluationCallback; the
// cost functions only copy their rows out of it. Parameter blocks are the
// nodes (x1_i, x2_i) and the two multiplier groups; each residual block is the
// gradient with respect to one parameter block and depends on the blocks
// within the Hessian's band, so Ceres sees the sparsity and factors the
// normal equations with a sparse Cholesky.
//
// Warning: the normal equations square the condition number (~Nt⁶ here):
// expect LM to stall near round-off far earlier than the Newton paths
// (docs/method.md §5). A stall is reported as non-convergence.
#pragma once

#include <ceres/ceres.h>

#include <memory>
#include <sstream>

#include "solvers/variational/solve_ivp.h"

namespace vivp::variational {

namespace detail {

// ∇S and ∇²S of a FullSystem at the point Ceres is about to evaluate.
template <class System>
class GradientCache : public ceres::EvaluationCallback {
 public:
  GradientCache(const System& system, std::vector<double>& u, int kl, int ku)
      : system_(system), u_(u), g_(u.size()), hessian_(int(u.size()), kl, ku) {}

  void PrepareForEvaluation(bool evaluate_jacobians,
                            bool new_evaluation_point) override {
    if (new_evaluation_point || !have_residual_) {
      system_.Residual(u_.data(), g_.data());
      have_residual_ = true;
      have_jacobian_ = false;
    }
    if (evaluate_jacobians && !have_jacobian_) {
      hessian_.SetZero();
      system_.Jacobian(u_.data(), hessian_);
      have_jacobian_ = true;
    }
  }

  const std::vector<double>& gradient() const { return g_; }
  const linalg::BandedMatrix<double>& hessian() const { return hessian_; }

 private:
  const System& system_;
  std::vector<double>& u_;
  std::vector<double> g_;
  linalg::BandedMatrix<double> hessian_;
  bool have_residual_ = false, have_jacobian_ = false;
};

// Rows [row0, row0 + rows) of ∇S, depending on parameter blocks given by
// their starting offsets and sizes.
template <class System>
class GradientRows : public ceres::CostFunction {
 public:
  GradientRows(const GradientCache<System>& cache, int row0, int rows,
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
  const GradientCache<System>& cache_;
  int row0_;
  std::vector<int> offsets_;
};

}  // namespace detail

struct CeresOptions {
  int max_iterations = 200;
  bool verbose = false;  // Ceres' own per-iteration log to stdout
  // The start of λ3, one value per DOF (empty: 0). A march starts each
  // window's λ3 at the predictor's −p, as its Newton engine does
  // (window_solve.h).
  std::vector<double> lambda3;
  // Ceres' initial trust-region radius (the inverse of LM's first damping)
  // and its stop on a relative step.
  double initial_radius = 1e4;
  double parameter_tolerance = 1e-16;
};

namespace detail {

// The Ceres problem of a FullSystem: parameter blocks are the lead
// multipliers, one block (x1_i, x2_i) per node and the tail multipliers;
// each residual block is ∇S with respect to one parameter block and depends
// on the blocks whose columns meet the Hessian's band in its rows.
template <class System>
void AddGradientBlocks(const System& full, std::vector<double>& u,
                       const GradientCache<System>& cache,
                       const linalg::BandwidthProbe& probe,
                       ceres::Problem& cp) {
  std::vector<int> offsets, sizes;
  offsets.push_back(0);
  sizes.push_back(full.lead());
  for (int i = 0; i < full.points(); ++i) {
    offsets.push_back(full.X(0, i, 0));
    sizes.push_back(2 * System::d);
  }
  offsets.push_back(full.Lambda3(0));
  sizes.push_back(full.lead());
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
        new GradientRows<System>(cache, r0, sizes[b], dep_offsets, dep_sizes),
        nullptr, deps);
  }
}

// Ceres logs a line through glog each time LM's normal equations fail to
// factor (it then raises the damping and tries again); a solve reports its
// outcome in its status, so without `verbose` those lines would only flood
// stderr.
inline void QuietCeres() {
  if (FLAGS_minloglevel < google::GLOG_ERROR)
    FLAGS_minloglevel = google::GLOG_ERROR;
}

// Ceres' LM with the stopping rules of this solver: stop only when no step
// decreases |∇S|² any more (the tolerances are below round-off), and judge
// the result on ∇S itself afterwards.
inline ceres::Solver::Options LmOptions(const CeresOptions& o) {
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
template <class System>
double GradientRoundOff(const System& full, const std::vector<double>& u,
                        const linalg::BandwidthProbe& probe) {
  linalg::BandedMatrix<double> h(full.size(), probe.kl, probe.ku);
  full.Jacobian(u.data(), h);
  double level = 0;
  for (int i = 0; i < full.size(); ++i) {
    double row = 0;
    const int j1 = std::min(full.size() - 1, i + probe.ku);
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
inline variational::NewtonReport LmReport(const ceres::Solver::Summary& summary,
                                          double initial_gradient,
                                          double final_gradient,
                                          double roundoff) {
  variational::NewtonReport report;
  report.iterations = static_cast<int>(summary.iterations.size()) - 1;
  report.corrections = report.iterations;
  report.residual_norm = final_gradient;
  const double floor = std::max(
      std::sqrt(std::numeric_limits<double>::epsilon()) * initial_gradient,
      roundoff);
  report.converged = summary.termination_type == ceres::CONVERGENCE &&
                     report.residual_norm <= floor;
  std::ostringstream why;
  why << "Ceres LM: "
      << ceres::TerminationTypeToString(summary.termination_type) << " after "
      << report.iterations << " iterations, |∇S|∞ = " << report.residual_norm;
  if (!report.converged) why << " (above the acceptance bound " << floor << ")";
  report.reason = why.str();
  return report;
}

}  // namespace detail

template <action::LagrangianProblem P>
IvpSolution<double> SolveIvpCeres(const P& problem, const InitialData& initial,
                                  const Grid& grid,
                                  const SolveOptions& options = {},
                                  const CeresOptions& ceres_options = {}) {
  using System = action::FullSystem<P, double>;
  const auto start = std::chrono::steady_clock::now();
  const detail::Prepared<P, double> prep(problem, initial, grid, options);
  const System full(problem, prep.dbar, prep.x0, prep.v0, prep.order);
  std::vector<double> u = prep.FullGuess(full);
  if (!ceres_options.lambda3.empty())
    for (int c = 0; c < P::kDim; ++c)
      u[full.Lambda3(c)] = ceres_options.lambda3[c];

  const linalg::BandwidthProbe probe =
      linalg::ProbeBand(full, u.data(), full.points(), 32);
  std::vector<double> g(full.size());
  full.Residual(u.data(), g.data());
  const double initial_gradient = variational::detail::MaxAbs(g);
  detail::GradientCache<System> cache(full, u, probe.kl, probe.ku);

  ceres::Problem::Options problem_options;
  problem_options.evaluation_callback = &cache;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem cp(problem_options);
  detail::AddGradientBlocks(full, u, cache, probe, cp);
  if (!ceres_options.verbose) detail::QuietCeres();
  ceres::Solver::Summary summary;
  ceres::Solve(detail::LmOptions(ceres_options), &cp, &summary);

  full.Residual(u.data(), g.data());
  variational::NewtonReport report = detail::LmReport(
      summary, initial_gradient, variational::detail::MaxAbs(g),
      detail::GradientRoundOff(full, u, probe));
  report.seconds.total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  IvpSolution<double> s =
      detail::Finish(problem, prep.dbar, full, u, report, Path::kCeresLm);
  detail::CheckResolution(problem, grid, s);
  return s;
}

}  // namespace vivp::variational
