// Electromagnetism in 2 + 1 D on a periodic grid, measured (docs/gauge.md
// §5, §6): the field strengths of a slice, the exact plane wave of the
// spatially discrete equations, and one run of the Gauss-law study — a
// plane wave marched window by window with the gauge free, its action's
// Gauss law at every slice and the textbook law beside it.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/sbp/space_grid.h"
#include "solvers/spacetime/solve.h"

namespace vivp::studies {

// (A₀, A₁, A₂) and its time derivative at every point, value j·3 + a.
struct MaxwellSlice {
  std::vector<double> phi, phi_t;
};

// E_b = −D_bA₀ − ∂_tA_b (value j·2 + b) and B = D_0A₁ − D_1A₀ of a slice.
struct MaxwellFields {
  std::vector<double> e, b;
};
MaxwellFields FieldsOf(const sbp::SpaceGrid<double>& grid,
                       std::span<const double> phi,
                       std::span<const double> phi_t);

// A = ε sin(k·x − ωt), A₀ = 0, exact for the spatially discrete equations:
// D_b sin(k_b x + c) = σ_b cos(k_b x + c) for central stencils, so ω = |σ|
// and ε ⊥ σ (transverse for the stencil, not for k).
class MaxwellPlaneWave {
 public:
  MaxwellPlaneWave(const sbp::SpaceGrid<double>& grid, int kx, int ky);
  MaxwellSlice At(double t) const;
  // The largest errors of E and B at t, relative to their amplitudes.
  struct Error {
    double e = 0, b = 0;
  };
  Error Errors(std::span<const double> phi, std::span<const double> phi_t,
               double t) const;
  double omega() const { return omega_; }

 private:
  double Phase(int j, double t) const;
  const sbp::SpaceGrid<double>& grid_;
  double k_[2], sigma_[2], eps_[2], omega_;
};

// The textbook Gauss law ∇·E of a slice with the exact derivative of the
// grid's trigonometric interpolant, relative to the largest |∂_bE_b|
// summed over the axes (core/action/field_constraints.h): what the
// action's law (the stencil's D·E) becomes as Δx → 0.
double TextbookGauss(const sbp::SpaceGrid<double>& grid,
                     std::span<const double> phi,
                     std::span<const double> phi_t);

// One run: the wave k = (1, 2) on the periodic [0, 2π)², n² points,
// central differences of order `space_order`, marched to t_end with
// `window` points per window at Δt = fraction × (the operator's limit / ω_max).
struct GaussRun {
  std::string op;
  int window = 0, n = 0, space_order = 0, windows = 0;
  double dt = 0, fraction = 0;
  double gauss = 0;     // the action's law, max over slices, relative
  double textbook = 0;  // ∇·E with the exact derivative, max over slices
  double handoff = 0;   // the action's law at the corrected end state
  double error_e = 0;   // E at t_end against the exact wave
  long long newton = 0;
  double seconds = 0;
  std::string failure;  // empty when the march converged
};
GaussRun RunGauss(const std::string& op, int window, double fraction, int n,
                  int space_order, double t_end);

// How the gauge moves in a long march of the wave (16², order 8, `op` in
// windows of `window` at 1/4 of the limit): the largest |A₀| and |D·A|
// (both 0 in the data, and in no observable) over the slices up to each of
// `times`, and the action's Gauss law there.
struct GaugeDriftRow {
  double t = 0, a0 = 0, divergence = 0, gauss = 0;
};
std::vector<GaugeDriftRow> GaugeDrift(const std::string& op, int window,
                                      const std::vector<double>& times);

// One window of the wave above (k = (1, 2), n², order 2 in space, SBP `op`
// with `window` points to t = 0.2·(window − 1)/15), solved from the same
// start (A₀ = 0, A = A(0) + t ∂_tA(0), multipliers 0) by Newton with the
// Fourier window solve and by Ceres Levenberg–Marquardt: their cost, the
// action's Gauss law, how far apart their gauge-invariant E and their
// potentials are, and the size of each one's correction from the start
// (the Fourier solve's is the minimum-norm one).
struct WindowSolveComparison {
  struct Side {
    int iterations = 0;
    double seconds = 0, residual = 0, gauss = 0, correction = 0;
    bool converged = false;
    std::string message;
  } fourier, lm;
  double e_difference = 0;   // max |E_F − E_LM| / max |E_F|
  double a0_difference = 0;  // max |A₀_F − A₀_LM| / max |A|
  int unknowns = 0;
};
WindowSolveComparison CompareWindowSolves(const std::string& op, int window,
                                          int n);

}  // namespace vivp::studies
