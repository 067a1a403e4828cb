// One entry point for every way vivp finds the critical point of the doubled
// SBP action (Rothkopf & Nordström 2023; docs/method.md §4–§8):
//
//   vivp::problems::Anharmonic anharmonic;
//   const vivp::variational::InitialData initial{.x = {1.0}, .v = {0.3}};
//   const vivp::variational::Grid grid{.op = "sbp42", .points = 4097, .t_end
//   = 10.0};
//   // one global solve: reduced Newton (default), full Newton or Ceres LM
//   auto sol = vivp::variational::Solve(anharmonic, initial, grid, {.path =
//   ...});
//   // a march in windows (uniform, or under error control with a
//   // tolerance), each window by the same three paths
//   vivp::variational::MarchOptions march;
//   march.window_points =
//   vivp::variational::DefaultWindowPoints(vivp::variational::Path::kCeresLm,
//                                                   grid.op);
//   march.solve.path = vivp::variational::Path::kCeresLm;
//   auto marched = vivp::variational::Solve(anharmonic, initial, grid, march);
//
// Either form checks the combination first (solver_choice.h) and throws
// std::invalid_argument with the refusal in the API's words (a front end
// checks first and words it in its own). The paths
// themselves: solve_ivp.h (Newton), ceres_lm.h (Levenberg–Marquardt),
// march.h (windows).
#pragma once

#include <stdexcept>

#include "core/action/erased_problem.h"
#include "solvers/variational/ceres_lm.h"
#include "solvers/variational/march.h"
#include "solvers/variational/solve_ivp.h"
#include "solvers/variational/solver_choice.h"

namespace vivp::variational {

namespace detail {

inline void Require(const SolveRequest& request) {
  const Refusal refusal = CheckSolveRequest(request);
  if (!refusal.ok()) throw std::invalid_argument(Describe(refusal).Sentence());
}

}  // namespace detail

// One global solve of the whole grid by options.path.
template <action::LagrangianProblem P>
IvpSolution<double> Solve(const P& problem, const InitialData& initial,
                          const Grid& grid, const SolveOptions& options = {}) {
  detail::Require({.path = options.path,
                   .op = grid.op,
                   .window_points = 0,
                   .extended_residual = options.extended_residual});
  if (options.path == Path::kCeresLm)
    return SolveIvpCeres(problem, initial, grid, options);
  return SolveIvp(problem, initial, grid, options);
}

// A march in windows of options.window_points (0: the solver's default),
// each window solved by options.solve.path; the observer (may be empty) sees
// every node once.
template <action::LagrangianProblem P>
MarchResult Solve(const P& problem, const InitialData& initial,
                  const Grid& grid, const MarchOptions& options,
                  const NodeObserver& observer = {}) {
  detail::Require(
      {.path = options.solve.path,
       .op = grid.op,
       .window_points = options.window_points > 0 ? options.window_points : -1,
       .tolerance = options.tolerance.enabled(),
       .extended_residual = options.solve.extended_residual});
  return MarchIvp(problem, initial, grid, options, observer);
}

}  // namespace vivp::variational

// Compiled once per dimension in the library (precompiled_dim.cc.in): a
// solve of action::Erase(problem) does not compile the solvers again.
namespace vivp::variational {
#define VIVP_EXTERN_SOLVE(D)                                                 \
  extern template IvpSolution<double> Solve(const action::ErasedProblem<D>&, \
                                            const InitialData&, const Grid&, \
                                            const SolveOptions&);            \
  extern template MarchResult Solve(const action::ErasedProblem<D>&,         \
                                    const InitialData&, const Grid&,         \
                                    const MarchOptions&, const NodeObserver&);
VIVP_PRECOMPILED_DIMS(VIVP_EXTERN_SOLVE)
#undef VIVP_EXTERN_SOLVE
}  // namespace vivp::variational
