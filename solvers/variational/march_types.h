// Options and results of time-slab marching (march.h).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "solvers/variational/ivp_types.h"
#include "solvers/variational/step_control.h"

namespace vivp::variational {

enum class HandOff { kCorrected, kNaive };

// How error control estimates a spectral element's error
// (docs/error_control.md, "Spectral elements"):
// - kHalves: step doubling — the element whole and as two halves, which
//   are kept; the tolerance bounds each hand-off's local error (order
//   2n − 1), three element solves per two kept.
// - kEmbedded: the element's own end-node estimates, as a finite-difference
//   window's — the tolerance bounds the local error of every node it
//   returns (the end node's, of order about n), one solve per element; the
//   hand-off, of order 2n − 1, ends far below the tolerance.
// - kAuto (the default): kEmbedded where the tolerance (the larger of its
//   absolute and relative parts) is at least kEmbeddedFrom, kHalves below.
//   The embedded estimates are measured to bound every node down to 10⁻⁸
//   (at 10⁻¹⁰ an lgl16 position estimate fell 7.7 times short) and their
//   end error stops falling near 10⁻¹¹; down to there they are the faster
//   (Kepler e = 0.9 to 10⁻¹⁰: lgl12 in 0.48 ms, the halves' best 0.87 ms;
//   docs/error_control.md, "Which to take"). The halves' end error
//   follows the tolerance down to 10⁻¹² and below.
enum class ElementEstimate { kAuto, kHalves, kEmbedded };
inline constexpr double kEmbeddedFrom = 1e-8;

// One accepted window as seen by a WindowObserver: where it started, its end
// node (x_N, (Dx)_N), the state it hands off and its embedded estimates, per
// component (d values each; velocities empty for a first-order system).
struct WindowSample {
  double t_start = 0, t_end = 0, dt = 0;
  int points = 0;
  const double *x0, *v0;                // initial data of the window
  const double *x_end, *v_end;          // x_N and (Dx)_N
  const double *handoff_x, *handoff_v;  // the next window's initial data
  const double *est_x, *est_v;          // embedded estimates of x_N, (Dx)_N
};
using WindowObserver = std::function<void(const WindowSample &)>;

// Where a march's time goes (MarchOptions::phase_timings), in seconds over
// all windows, rejected and failed ones included.
struct MarchPhases {
  double predictor = 0;  // the windows' starting paths (predictor.h)
  double setup = 0;      // operators rebuilt for a new step (window_engine.h)
  // Newton's phases (newton.h): matrix-free residuals, Jacobian assembly,
  // factorizations, triangular solves (the band probe, once per window
  // size, falls under "other").
  double residual = 0, assembly = 0, factorization = 0, solve = 0;
  double end = 0;     // after Newton: ω at the ends, the corrected end state,
                      // the estimates and the nodes' velocities
  double checks = 0;  // the a-posteriori checks (window_checks.h)
  double total = 0;   // the whole march; total − the rest is the step
                      // control, acceptance, node copies and allocation
  // Of setup … end above: the spectral elements' whole elements, which
  // step doubling solves only for its estimate and the halves' start
  // (element_halves.h); 0 for other operators.
  double whole_elements = 0;
  // The solve itself: setup, Newton's phases and the end state.
  double Solving() const {
    return setup + residual + assembly + factorization + solve + end;
  }
  MarchPhases &operator+=(const MarchPhases &o) {
    predictor += o.predictor;
    setup += o.setup;
    residual += o.residual;
    assembly += o.assembly;
    factorization += o.factorization;
    solve += o.solve;
    end += o.end;
    checks += o.checks;
    whole_elements += o.whole_elements;
    return *this;
  }
};

// A window of a march on given windows (MarchOptions::given_windows): where
// it ends, and its points, evenly spaced from the window before's end.
struct GivenWindow {
  double t_end = 0;
  long long points = 0;
};

struct MarchOptions {
  // Points per window; 0: DefaultWindowPoints of the solver (solver_choice.h)
  // — for Newton 48 on a uniform grid and 24 under error control. On a
  // uniform grid by measurement (bench/march_bench, SBP42, Nt = 2^18,
  // points per second): damped oscillator W = 16/32/48/64/128:
  // 7.7/9.7/10.9/11.1/7.2 e6; anharmonic 3.5/3.8/4.0/3.5/2.2 e6 (from 128
  // points on, the previous window's Jacobian stops contracting and most
  // windows refactor). 48 is within noise of the best for both; end errors
  // grow slowly with W (damped at T = 3277: 4.9e-7 at 32, 5.8e-7 at 48).
  long long window_points = 0;
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
  // Error control. Enabled (absolute or relative > 0): the march chooses
  // each window's Δt from the windows' embedded error estimates so that the
  // local error of every node it returns stays below absolute +
  // relative·|value| (positions and velocities); grid.points is then not
  // used, and the nodes are not uniform in time. Disabled: the uniform grid
  // of grid.points nodes.
  Tolerance tolerance;
  // Error control on a spectral element: step doubling, its embedded
  // estimates, or by the tolerance (ElementEstimate above).
  ElementEstimate element_estimate = ElementEstimate::kAuto;
  // Error control: the first window's Δt; 0 chooses it from the fastest
  // frequency of the initial state.
  double initial_step = 0;
  // Error control: give up (reported, with the time) when a run would need
  // more than this many nodes.
  long long max_points = 100'000'000;
  // Uniform grid: a window whose nodes deviate from the predictor by more
  // than this fraction of the solution's size is reported as
  // under-resolved (window_solve.h, check 3).
  double max_relative_deviation = 1e-2;
  // Sees every accepted window (studies of the error estimates).
  WindowObserver window_observer;
  // Uniform grid: resume at this node of the grid (the state given to Run is
  // the hand-off state there, which at_boundary reported), and see the
  // march's state after every window of window_points, never inside a split
  // one: where a march can be stopped and resumed.
  long long start_node = 0;
  std::function<void(long long node, const InitialData &state)> at_boundary;
  // Uniform grid only: march these windows instead, one after another from
  // t_start, the last ending at t_end; a window's points are evenly spaced
  // (an element's at its Gauss–Lobatto nodes), and grid.points and
  // window_points are not used. The windows a march under error control
  // accepted (MarchResult::windows), marched again so, give the same nodes
  // without the machinery that chose them: its price apart from the
  // solves' (bench/march_phases_bench).
  std::vector<GivenWindow> given_windows;
  // Time the phases of every window (MarchResult::phases). Off by default:
  // a window of SBP84 is solved in tens of microseconds, and the clock reads
  // cost a few per cent of it.
  bool phase_timings = false;
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
  double dt = 0;                       // node spacing of the solve grid
  double error_norm = 0;  // error control: the estimates over the tolerance
};

struct MarchResult {
  Summary status;  // iterations: Jacobian factorizations over all windows
  std::vector<double> t;  // time of every node (if kept); error control:
                          // not uniform
  Eigen::MatrixXd x, v;   // positions and D x per node (if kept)
  std::vector<double> end_position, end_velocity;  // handed-off final state
  std::vector<WindowReport> windows;  // one per window, if keep_trajectory
  long long window_count = 0;
  long long points = 0;    // nodes returned (uniform grid: grid.points)
  int fallbacks = 0;       // windows solved again: split, refactored, refined
  int rejected = 0;        // error control: windows whose error was too large
  int check_failures = 0;  // windows that failed an a-posteriori check
  double min_step = 0, max_step = 0;  // smallest and largest Δt used
  int refinement = 1;   // solve grid = requested grid refined this many times
  int iterations = 0;   // Jacobian factorizations over all windows
  int corrections = 0;  // solves with a factorization over all windows
  double error_estimate = 0;  // Σ of the per-window position estimates
  // On failure: ‖F‖∞ of the failing window's system at the last iterate
  // (NaN if it was not finite or not evaluated); also named in the reason.
  double last_residual = std::numeric_limits<double>::quiet_NaN();
  // On failure: the start of the window that failed (NaN on success).
  double failed_at = std::numeric_limits<double>::quiet_NaN();
  long predictor_steps = 0;  // Dormand–Prince steps of the window starts
  double seconds = 0;
  MarchPhases phases;  // with MarchOptions::phase_timings, else zeros
};

// The windows a march accepted (kept with its trajectory), as the given
// windows of a march over the same grid: each ends where the next starts,
// the last at grid.t_end.
inline std::vector<GivenWindow> AcceptedWindows(const MarchResult &m,
                                                const Grid &grid) {
  std::vector<GivenWindow> w;
  for (std::size_t k = 0; k < m.windows.size(); ++k)
    w.push_back(
        {k + 1 < m.windows.size() ? m.windows[k + 1].t_start : grid.t_end,
         m.windows[k].points});
  return w;
}

// Called with (t, x, v) of every node, in order, each node once.
using NodeObserver =
    std::function<void(double, const double *, const double *)>;

}  // namespace vivp::variational
