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

#include <chrono>
#include <functional>
#include <vector>

#include "core/linalg/banded.h"
#include "solvers/variational/solve_ivp.h"

namespace vivp::variational {

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

// A full system as Ceres sees it, whatever the problem: ∇S, ∇²S into a
// banded matrix, its band, and the parameter blocks — the lead multipliers,
// one block (x1_i, x2_i) per node, the tail multipliers — as offsets and
// sizes into the unknowns. Everything that touches Ceres is compiled once,
// in ceres_lm.cc, for every problem.
struct LmSystem {
  int size = 0;
  linalg::BandwidthProbe band;
  std::vector<int> block_offsets, block_sizes;
  std::function<void(const double* u, double* g)> gradient;
  std::function<void(const double* u, linalg::BandedMatrix<double>& h)> hessian;
};

// Ceres' LM on r = ∇S from u (updated in place). The report judges the end
// point on ∇S itself (ceres_lm.cc).
NewtonReport RunCeresLm(const LmSystem& system, std::vector<double>& u,
                        const CeresOptions& options);

template <class System>
LmSystem MakeLmSystem(const System& full, const std::vector<double>& u) {
  LmSystem s;
  s.size = full.size();
  s.band = linalg::ProbeBand(full, u.data(), full.points(), 32);
  s.block_offsets.push_back(0);
  s.block_sizes.push_back(full.lead());
  for (int i = 0; i < full.points(); ++i) {
    s.block_offsets.push_back(full.X(0, i, 0));
    s.block_sizes.push_back(2 * System::d);
  }
  s.block_offsets.push_back(full.Lambda3(0));
  s.block_sizes.push_back(full.lead());
  s.gradient = [&full](const double* x, double* g) { full.Residual(x, g); };
  s.hessian = [&full](const double* x, linalg::BandedMatrix<double>& h) {
    full.Jacobian(x, h);
  };
  return s;
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
  NewtonReport report =
      detail::RunCeresLm(detail::MakeLmSystem(full, u), u, ceres_options);
  report.phases.total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  IvpSolution<double> s =
      detail::Finish(problem, prep.dbar, full, u, report, Path::kCeresLm);
  detail::CheckResolution(problem, grid, s);
  return s;
}

}  // namespace vivp::variational
