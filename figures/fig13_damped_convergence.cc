// Fig. 13 of Rothkopf & Nordström (2023): deviation of the value x_N (left)
// and of the derivative (Dx)_N (right) from the exact solution at t_2 = 1 for
// the damped oscillator, against Δt = 1/N_t (N_t = 16 ... 512), regularized
// SBP21 (blue crosses) and SBP42 (red circles) with power-law fits (gray); the
// fitted slopes are in the key (paper: SBP21 Δt^2.03 / Δt^1.01, SBP42 Δt^3.04 /
// Δt^2.06). Usage: fig13_damped_convergence [OUTPUT_DIR]
#include <iostream>

#include "figures/solver_figures.h"

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  std::cout << vivp::figures::OperatorPairConvergenceFigure(
                   dir, "fig13_damped_convergence", "damped",
                   "damped oscillator")
                   .string()
            << "\n";
}
