// Newton's method on the reduced field system (core/action/field_system.h)
// with the exact sparse Jacobian and a sparse LU (sparse_lu.h). The stopping
// rules are those of point mechanics (solvers/variational/newton.h): never
// on an absolute residual; converged when a correction is at round-off,
// |δ|∞ ≤ tol·max(1, |y|∞), or when corrections stop shrinking below √ε;
// failed on a non-finite residual, a singular Jacobian, stagnation above
// √ε, or the iteration limit. Each factorization is followed by up to
// `refinement_steps` corrections with the same factors (iterative
// refinement for a linear field; simplified Newton steps otherwise).
//
// A factorization can outlive one solve (FieldFactorCache): marching solves
// window after window on the same grid, and for a linear field the Jacobian
// is the same matrix every time — factor once, back-substitute per window.
#pragma once

#include <Eigen/Core>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "solvers/fields/assembly.h"
#include "solvers/fields/sparse_lu.h"

namespace vivp::fields {

struct FieldNewtonOptions {
  int max_iterations = 30;
  int refinement_steps = 2;
  double step_tolerance = 0;  // 0: 64 ε
  SparseSolver solver = SparseSolver::kUmfpack;
};

struct FieldNewtonReport {
  bool converged = false;
  std::string reason;
  int iterations = 0;   // factorizations
  int corrections = 0;  // solves
  double last_step = 0;
  double residual_norm = 0;  // |F|∞ at the returned y
  long long jacobian_nonzeros = 0;
  double seconds_residual = 0, seconds_assembly = 0, seconds_factor = 0,
         seconds_solve = 0, seconds_total = 0;
};

struct FieldFactorCache {
  explicit FieldFactorCache(SparseSolver kind = SparseSolver::kUmfpack)
      : lu(kind) {}
  PatternedMatrix jacobian;
  SparseLu lu;
  int analyzed_pattern = 0;  // jacobian.patterns() when last analyzed
  bool valid = false;        // lu holds a factorization usable as a start
};

template <class System>
FieldNewtonReport FieldNewton(const System& system, Eigen::VectorXd& y,
                              const FieldNewtonOptions& options,
                              FieldFactorCache& cache) {
  using Clock = std::chrono::steady_clock;
  auto since = [](Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
  };
  const auto start = Clock::now();
  FieldNewtonReport report;
  const int n = system.size();
  const double eps = std::numeric_limits<double>::epsilon();
  const double tol =
      options.step_tolerance > 0 ? options.step_tolerance : 64 * eps;
  Eigen::VectorXd f(n), delta(n);
  auto residual = [&] {
    const auto t0 = Clock::now();
    system.Residual(y.data(), f.data());
    report.seconds_residual += since(t0);
    return f.allFinite();
  };
  auto finish = [&](bool ok, std::string why) {
    report.converged = ok;
    report.reason = std::move(why);
    report.residual_norm = f.allFinite()
                               ? f.cwiseAbs().maxCoeff()
                               : std::numeric_limits<double>::quiet_NaN();
    report.jacobian_nonzeros = cache.jacobian.matrix().nonZeros();
    report.seconds_total = since(start);
    return report;
  };
  if (y.size() != n) y = Eigen::VectorXd::Zero(n);
  if (!residual())
    return finish(false, "non-finite residual at the initial guess");
  bool stale = cache.valid;
  double previous = std::numeric_limits<double>::infinity();
  constexpr int kChordSteps = 8;
  while (report.iterations < options.max_iterations) {
    if (!cache.valid) {
      auto t0 = Clock::now();
      cache.jacobian.Assemble(
          n, [&](auto& sink) { system.Jacobian(y.data(), sink); });
      report.seconds_assembly += since(t0);
      t0 = Clock::now();
      if (cache.analyzed_pattern != cache.jacobian.patterns()) {
        cache.lu.Analyze(cache.jacobian.matrix());
        cache.analyzed_pattern = cache.jacobian.patterns();
      }
      const bool ok = cache.lu.Factorize(cache.jacobian.matrix());
      report.seconds_factor += since(t0);
      ++report.iterations;
      if (!ok)
        return finish(false, "singular Jacobian at iteration " +
                                 std::to_string(report.iterations) + ": " +
                                 cache.lu.message());
      cache.valid = true;
      stale = false;
    }
    const int inner = stale ? kChordSteps : options.refinement_steps;
    for (int r = 0; r <= inner; ++r) {
      auto t0 = Clock::now();
      cache.lu.Solve(f, delta);
      report.seconds_solve += since(t0);
      y -= delta;
      ++report.corrections;
      const double step = delta.cwiseAbs().maxCoeff();
      const double scale = std::max(1.0, y.cwiseAbs().maxCoeff());
      report.last_step = step;
      if (!residual())
        return finish(false, "non-finite residual after correction " +
                                 std::to_string(report.corrections));
      if (step <= tol * scale) return finish(true, "correction at round-off");
      const double theta = step / previous;
      previous = step;
      if (theta >= 0.5) {
        if (!stale && step <= std::sqrt(eps) * scale)
          return finish(true, "corrections stagnated at round-off level");
        if ((stale && r >= 2) || (!stale && r > 0)) break;
      }
    }
    cache.valid = false;
  }
  return finish(false, "no convergence in " +
                           std::to_string(options.max_iterations) +
                           " iterations (last correction " +
                           std::to_string(report.last_step) + ")");
}

}  // namespace vivp::fields
