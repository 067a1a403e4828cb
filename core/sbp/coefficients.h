// Coefficient tables of diagonal-norm first-derivative SBP operators.
//
// A table holds exact rationals per unit grid spacing: the derivative is D/dt
// and the norm is dt*H. It describes one operator completely:
//   * norm_weights: H_00, H_11, ... of the left closure (all other weights 1,
//     the right closure mirrored);
//   * boundary_block: rows 0..r-1 of D, each starting at column 0;
//   * interior_stencil: the centred stencil on offsets -k..k used by every row
//     between the closures.
// The right closure follows by antisymmetry, D[N-1-i][N-1-j] = -D[i][j].
// The finite-difference tables are facts from the cited papers; the
// spectral elements' (lobatto.h) are computed, rounded to dyadic rationals.
// builder.h turns a table into an Operator in any floating-point type. Beside
// them each table carries the row `measured`: what this code measured of the
// operator as a time derivative, the one place a solver looks up a constant of
// an operator.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace vivp::sbp {

// An exact rational p/q, lifted into a floating-point type as the correctly
// rounded quotient of two exactly representable integers.
struct Rational {
  std::int64_t num;
  std::int64_t den;

  template <class Real>
  Real As() const {
    return static_cast<Real>(num) / static_cast<Real>(den);
  }
};

// What was measured of an operator as the time derivative of the variational
// method: every constant and behaviour that the solvers take per operator.
// One row per operator, in its coefficient file; each field says what was
// measured, where, and how to measure it for a new operator.
struct Measured {
  // The largest Δt·ω at which the discrete critical point of the harmonic
  // oscillator ẍ = −ω²x stays bounded (solvers/variational/resolution.h):
  // a global solve over 400 steps, max|x| < 1.5 as "bounded"; reproduce with
  // tests/variational_resolution_test.
  double stability_limit;
  // Whether a window's position estimate |M⁻¹λ4| estimates the error of x_N
  // (its ratio to the true error, bench/window_estimates_bench;
  // docs/error_control.md). Where it does not, error control estimates by
  // step doubling (solvers/variational/march_adaptive.h) and the hand-off
  // check bounds the position by the velocity estimate over the window's
  // length, L·e_v (solvers/variational/window_checks.h).
  bool position_estimate;
  // The order in Δt of the dominant error estimate at a fixed number of
  // points per window (a window's length shrinks with Δt), which the
  // step-size controller assumes (solvers/variational/step_control.h):
  // the slope of the estimates over Δt = 0.02 … 0.0006 on the anharmonic
  // oscillator and Kepler e = 0.6 (the velocity estimate, whose closure row
  // is the least accurate; bench/window_estimates_bench). The lower end of
  // the measured range: a controller that assumes too high an order
  // overshoots and is rejected.
  double estimate_order;
  // The window in which Ceres Levenberg–Marquardt marches by default
  // (solvers/variational/solver_choice.h): the largest in which it keeps the
  // Newton march's accuracy and iteration count, measured by
  // bench/lm_window_bench (docs/method.md §8); its normal equations square a
  // condition number that grows with the window. 0: no window keeps them.
  int lm_window_points;
  // The most values (time points × spatial points × components) that a field
  // scene or study solves at once by the sparse LU of the whole window (the
  // reference linear solver), in one global solve or one window; beyond it,
  // march in windows (solvers/spacetime/composed.h). Set by the peak memory of
  // a global Klein–Gordon solve (docs/fields.md §8). The space-diagonalized
  // solve, which does not fill, has one bound for every operator there.
  long long field_values_at_once;
};

struct Coefficients {
  std::string_view name;  // "sbp21", "sbp42", ...
  std::string_view citation;
  int interior_order;
  int boundary_order;
  // Smallest grid on which the two closures do not overlap (2 * rows).
  int min_points;
  std::vector<Rational> norm_weights;
  std::vector<std::vector<Rational>> boundary_block;
  std::vector<Rational> interior_stencil;
  Measured measured;
  // A spectral element (lobatto.h) is one window of exactly this many
  // points; 0 for a finite-difference operator, which takes any number from
  // min_points.
  int max_points = 0;
  // The nodes' positions in units of dt, t_i = t_start + dt·offset_i (dt
  // the interval over points − 1); empty for a uniform grid (offset_i = i).
  std::vector<Rational> node_offsets;

  // Node i's position in units of dt: i on a uniform grid, else its offset.
  template <class Real>
  Real Offset(int i) const {
    return node_offsets.empty() ? static_cast<Real>(i)
                                : node_offsets[std::size_t(i)].As<Real>();
  }

  int boundary_rows() const { return static_cast<int>(boundary_block.size()); }
  int half_width() const {
    return static_cast<int>(interior_stencil.size()) / 2;
  }
};

}  // namespace vivp::sbp
