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

namespace vivp {

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
};

template <action::LagrangianProblem P>
IvpSolution<double> SolveIvpCeres(const P& problem, const InitialData& initial,
                                  const Grid& grid,
                                  const SolveOptions& options = {},
                                  const CeresOptions& ceres_options = {}) {
  using System = action::FullSystem<P, double>;
  constexpr int d = P::kDim;
  const auto start = std::chrono::steady_clock::now();
  const detail::Prepared<P, double> prep(problem, initial, grid, options);
  const int n = prep.D.points();
  const System full(problem, prep.dbar, prep.x0, prep.v0, prep.order);
  std::vector<double> u = prep.FullGuess(full);

  const linalg::BandwidthProbe probe =
      linalg::ProbeBand(full, u.data(), full.points(), 32);
  std::vector<double> g(full.size());
  full.Residual(u.data(), g.data());
  const double initial_gradient = solvers::detail::MaxAbs(g);
  detail::GradientCache<System> cache(full, u, probe.kl, probe.ku);

  // Parameter blocks: the lead multipliers, one per node, the tail multipliers.
  std::vector<int> offsets, sizes;
  offsets.push_back(0);
  sizes.push_back(full.lead());
  for (int i = 0; i < n; ++i) {
    offsets.push_back(full.X(0, i, 0));
    sizes.push_back(2 * d);
  }
  offsets.push_back(full.Lambda3(0));
  sizes.push_back(full.lead());

  ceres::Problem::Options problem_options;
  problem_options.evaluation_callback = &cache;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem cp(problem_options);
  for (std::size_t b = 0; b < offsets.size(); ++b)
    cp.AddParameterBlock(u.data() + offsets[b], sizes[b]);
  for (std::size_t b = 0; b < offsets.size(); ++b) {
    const int r0 = offsets[b], r1 = offsets[b] + sizes[b];
    std::vector<int> dep_offsets, dep_sizes;
    std::vector<double*> deps;
    for (std::size_t k = 0; k < offsets.size(); ++k) {
      const int c0 = offsets[k], c1 = offsets[k] + sizes[k];
      // Blocks whose columns meet the band of rows [r0, r1).
      if (c1 - 1 >= r0 - probe.ku && c0 <= r1 - 1 + probe.kl) {
        dep_offsets.push_back(c0);
        dep_sizes.push_back(sizes[k]);
        deps.push_back(u.data() + c0);
      }
    }
    cp.AddResidualBlock(new detail::GradientRows<System>(
                            cache, r0, sizes[b], dep_offsets, dep_sizes),
                        nullptr, deps);
  }

  ceres::Solver::Options so;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  so.max_num_iterations = ceres_options.max_iterations;
  so.function_tolerance = 1e-32;
  so.gradient_tolerance = 1e-32;
  so.parameter_tolerance = 1e-16;
  so.minimizer_progress_to_stdout = ceres_options.verbose;
  so.logging_type =
      ceres_options.verbose ? ceres::PER_MINIMIZER_ITERATION : ceres::SILENT;
  so.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &cp, &summary);

  solvers::NewtonReport report;
  report.iterations = static_cast<int>(summary.iterations.size()) - 1;
  full.Residual(u.data(), g.data());
  report.residual_norm = solvers::detail::MaxAbs(g);
  // LM only knows it can no longer decrease |∇S|²; whether that is a
  // critical point is judged on ∇S itself: it must have fallen by sqrt(eps)
  // relative to the initial guess (Newton reaches eps on these problems).
  const double floor =
      std::sqrt(std::numeric_limits<double>::epsilon()) * initial_gradient;
  report.converged = summary.termination_type == ceres::CONVERGENCE &&
                     report.residual_norm <= floor;
  std::ostringstream why;
  why << "Ceres LM: "
      << ceres::TerminationTypeToString(summary.termination_type) << " after "
      << report.iterations << " iterations, |∇S|∞ = " << report.residual_norm;
  if (!report.converged) why << " (above the acceptance bound " << floor << ")";
  report.reason = why.str();
  report.seconds.total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  IvpSolution<double> s =
      detail::Finish(problem, prep.dbar, full, u, report, Path::kCeresLm);
  detail::CheckResolution(problem, grid, s);
  return s;
}

}  // namespace vivp
