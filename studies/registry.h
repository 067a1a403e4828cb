// The problems the variational solver knows by name (for `vivp converge`,
// tests and figures), each with its initial data and its exact solution or
// a reference computed from its Lagrangian.
//
// A problem joins with one registration statement in the file that defines
// it (lagrangians/register.h); the solver templates are instantiated there,
// once, not in every user of this header.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "solvers/variational/ivp_types.h"
#include "solvers/variational/march_types.h"
#include "studies/convergence.h"

namespace vivp::studies {

struct ExactState {
  std::vector<double> x, v, p;  // position, velocity, momentum ∂L/∂v
};

struct NamedProblem {
  std::string name;
  std::string description;
  variational::InitialData initial;
  std::function<variational::IvpSolution<double>(
      const variational::Grid&, const variational::SolveOptions&)>
      solve;
  // The observer (may be empty) sees every node once, in order.
  std::function<variational::MarchResult(const variational::Grid&,
                                         const variational::MarchOptions&,
                                         const variational::NodeObserver&)>
      march;
  // The closed form, or the reference trajectory computed when there is
  // none; `reference` says which.
  std::function<ExactState(double t)> exact;
  std::string reference;
  // The canonical momentum ∂L/∂ẋ at (x, ẋ), d components.
  std::function<std::vector<double>(const double* x, const double* v)> momentum;
};

// Adds a problem under its name (lagrangians/register.h does, during static
// initialization). Throws std::logic_error if the name is taken.
void AddProblem(NamedProblem problem);

// Every problem added, in the order of their names.
const std::vector<NamedProblem>& Registry();
std::string ProblemNameList();
// Throws std::invalid_argument naming the valid problems.
const NamedProblem& FindProblem(const std::string& name);
bool HasProblem(const std::string& name);

// Marches `problem` in windows of `slab_points` and measures like
// RunConvergence: x_N and (Dx)_N of the last window, and the handed-off
// (corrected) end state.
ConvergenceRow MarchRow(const NamedProblem& problem,
                        const variational::Grid& grid,
                        const variational::SolveOptions& options,
                        long long slab_points, const ExactState& exact);

// Marches `problem` under error control for every tolerance (absolute and
// relative both set to it) in windows of `window_points`, and measures the
// achieved errors against the exact solution: of the handed-off end state
// (err_x_corrected, err_p_corrected for the velocity), and the largest over
// every returned node (max_error); `points` is the number of nodes used.
ConvergenceStudy RunToleranceStudy(const NamedProblem& problem,
                                   variational::Grid grid,
                                   const std::vector<double>& tolerances,
                                   const variational::SolveOptions& options,
                                   long long window_points,
                                   double round_off_floor = 1e-13);

// Solves `problem` on every grid size and measures the errors at t_end; with
// slab_points > 0 it marches in windows of that many points instead.
ConvergenceStudy RunConvergence(const NamedProblem& problem,
                                variational::Grid grid,
                                const std::vector<long long>& points,
                                const variational::SolveOptions& options,
                                double round_off_floor = 1e-13,
                                long long slab_points = 0);

}  // namespace vivp::studies
