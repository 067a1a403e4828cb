// Options and results of time-slab marching (march.h).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "solvers/variational/ivp_types.h"

namespace vivp {

enum class HandOff { kCorrected, kNaive };

struct MarchOptions {
  // Default by measurement (bench/march_bench, SBP42, Nt = 2^18, points per
  // second): damped oscillator W = 16/32/48/64/128: 7.7/9.7/10.9/11.1/7.2 e6;
  // anharmonic 3.5/3.8/4.0/3.5/2.2 e6 (from 128 points on, the previous
  // window's Jacobian stops contracting and most windows refactor). 48 is
  // within noise of the best for both; end errors grow slowly with W
  // (damped at T = 3277: 4.9e-7 at 32, 5.8e-7 at 48).
  long long window_points = 48;
  HandOff hand_off = HandOff::kCorrected;
  int max_split_depth = 4;  // fallback: halve a failing window up to 4 times
  bool keep_trajectory = true;  // also keeps the per-window reports
  SolveOptions solve;           // per-window solver settings
  // Hard cases stay stable: when Δt·ω exceeds the operator's stability limit
  // (resolution.h), solve each window on a grid refined r times (output still
  // on the requested grid) instead of failing; r is reported. Off: such a
  // march stops with the under-resolution reason.
  bool stabilize = true;
  int max_refinement = 64;
};

struct WindowReport {
  double t_start = 0, t_end = 0;
  long long points = 0;
  int iterations = 0;   // Jacobian factorizations (0: an earlier one reused)
  int corrections = 0;  // Newton, chord and refinement steps
  int fallbacks = 0;    // splits needed below this window
  bool converged = false;
  double position_error_estimate = 0;  // |M⁻¹λ4|∞
  double velocity_error_estimate = 0;  // |(Dx)_N − M⁻¹(−λ3)|∞
};

struct MarchResult {
  Status status;
  std::vector<double> t;  // stitched grid (if kept)
  Eigen::MatrixXd x, v;   // positions and D x per node (if kept)
  std::vector<double> end_position, end_velocity;  // handed-off final state
  std::vector<WindowReport> windows;  // one per window, if keep_trajectory
  long long window_count = 0;
  int fallbacks = 0;
  int refinement = 1;   // solve grid = requested grid refined this many times
  int iterations = 0;   // Jacobian factorizations over all windows
  int corrections = 0;  // solves with a factorization over all windows
  double error_estimate = 0;  // Σ of the per-window position estimates
  // On failure: ‖F‖∞ of the failing window's system at the last iterate
  // (NaN if it was not finite or not evaluated); also named in the reason.
  double last_residual = std::numeric_limits<double>::quiet_NaN();
  double seconds = 0;
};

// Called with (t, x, v) of every node, in order, each node once.
using NodeObserver = std::function<void(double, const double*, const double*)>;

}  // namespace vivp
