// Inputs and result of the variational IVP solver (solve_ivp.h).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "solvers/variational/newton.h"
#include "solvers/variational/summary.h"

namespace vivp::variational {

struct InitialData {
  std::vector<double> x;  // x(t_start), one entry per degree of freedom
  std::vector<double> v;  // ẋ(t_start); empty for a first-order system
};

struct Grid {
  std::string op = "sbp42";  // sbp21, sbp42, sbp63, sbp84
  long long points = 64;
  double t_start = 0.0;
  double t_end = 1.0;
  double sigma0 = -1.0;  // SAT parameter of D̄; 0 switches regularization off
};

enum class Path { kReducedNewton, kFullNewton, kCeresLm };

inline const char* PathName(Path p) {
  switch (p) {
    case Path::kReducedNewton:
      return "newton";
    case Path::kFullNewton:
      return "full-newton";
    case Path::kCeresLm:
      return "ceres-lm";
  }
  return "?";
}

struct SolveOptions {
  Path path = Path::kReducedNewton;
  variational::NewtonOptions newton;
  // Reduced Newton in double: evaluate the refinement residual in long double
  // (mixed-precision iterative refinement). Removes the round-off that the
  // Nt³ conditioning amplifies (free fall SBP42 exact to 1 ulp at Nt = 65536;
  // since D is evaluated on differences plain double reaches that too)
  // for about twice the cost of a double residual.
  bool extended_residual = false;
  // Optional initial guess for the path, node-major (points x dof values);
  // empty: the initial data continued linearly.
  std::vector<double> guess;
};

// The multiplier-corrected end state (docs/method.md §7).
template <class Real>
struct CorrectedEnd {
  std::vector<Real> position;  // x_N + M⁻¹λ4 (first order: x_N + C⁻¹λ3)
  std::vector<Real> momentum;  // −λ3 (second order)
  std::vector<Real> velocity;  // M⁻¹(−λ3) (second order)
  double position_error_estimate = 0;  // |M⁻¹λ4|∞: estimates the error of x_N
  double velocity_error_estimate = 0;  // |(Dx)_N − M⁻¹(−λ3)|∞

  // As a new one, its arrays' storage kept.
  void Clear() {
    position.clear();
    momentum.clear();
    velocity.clear();
    position_error_estimate = velocity_error_estimate = 0;
  }
};

template <class Real>
struct IvpSolution {
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
  Path path = Path::kReducedNewton;
  int order = 2;
  std::vector<Real> t;
  Matrix x1, x2;                // paths, points x dof
  Matrix velocity;              // D x1
  Matrix velocity_regularized;  // D̄ x̄1
  std::vector<Real> lambda1, lambda2, lambda3,
      lambda4;  // d each (λ2, λ4: order 2)
  CorrectedEnd<Real> corrected;
  Summary status;
  int iterations = 0;
  double gradient_norm = 0;        // ‖∇S‖∞ of the full doubled action
  double residual_norm = 0;        // ‖F‖∞ of the system that was solved
  double max_path_difference = 0;  // max |x1 − x2|
  variational::Timings seconds;

  int points() const { return static_cast<int>(t.size()); }
  int dof() const { return static_cast<int>(x1.cols()); }
};

}  // namespace vivp::variational
