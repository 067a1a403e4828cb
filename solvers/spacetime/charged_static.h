// Static critical points of a charged field on a periodic grid: the
// minimum of the slice's potential energy U (core/action/charged_terms.h,
// ChargedSlicePotential: Σ_j Hˣ_j [Σ_b |D_bφ|² + V(|φ|²) + (1/(2e²))
// Σ_{b<c} F_bc²]) over φ and the spatial links, from a start the caller
// gives (a vortex ansatz, studies/vortex.h). A static solution of the
// field equations with A₀ = 0, E = 0 and D_0φ = 0 is exactly a critical
// point of U: its data (π = 0) satisfy Gauss's law (ρ = 0) and every
// window of the space-time action is solved by the static path.
//
// The minimizer is Ceres' L-BFGS on U with its analytic gradient (a
// ceres::GradientProblem): one gradient is one sweep over the links, and
// U's gauge directions are flat, which a quasi-Newton method does not need
// removed. Its line search compares values of U, and stops where their
// changes reach round-off (a residual near 1e-7); Newton steps on U's
// sparse Hessian, its gauge directions damped as in normal_solver.h, take
// the residual from there to round-off.
#pragma once

#include <string>
#include <vector>

#include "core/sbp/space_grid.h"
#include "problems/fields/charged.h"

namespace vivp::spacetime {

struct StaticOptions {
  int max_iterations = 20000;
  // Stop when max_k |∂U/∂x_k| / Hˣ (the static field equations' residual
  // per unit volume) is below this.
  double residual = 1e-11;
  int memory = 20;  // L-BFGS pairs
  // Newton steps on U's sparse Hessian after L-BFGS: its line search stops
  // where U's changes reach round-off, near a residual of 1e-7.
  int newton_steps = 8;
};

struct StaticReport {
  bool converged = false;
  int iterations = 0;  // L-BFGS
  int newton = 0;      // Newton steps after it
  double energy = 0;
  // max_k |∂U/∂x_k| / Hˣ at the start and at the end: the static equations'
  // residual, in the units of the field equations (each term O(1) for
  // e = v = 1).
  double start_residual = 0, lbfgs_residual = 0, residual = 0;
  double lbfgs_seconds = 0, seconds = 0;
  std::string message;  // Ceres' termination message
};

// Relaxes x (ChargedLayout<d>: Re φ, Im φ, A_0 … A_{d−1}, χ per point; χ is
// left as given) towards a critical point of U at e = e(t).
StaticReport RelaxChargedSlice2(const fields::ScalarQed& model,
                                const sbp::SpaceGrid<double>& grid, double t,
                                std::vector<double>& x,
                                const StaticOptions& options = {});

// max_k |∂U/∂x_k| / Hˣ of x on a grid of two axes.
double StaticResidual2(const fields::ScalarQed& model,
                       const sbp::SpaceGrid<double>& grid, double t,
                       const std::vector<double>& x);

}  // namespace vivp::spacetime
