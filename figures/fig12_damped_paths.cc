// Fig. 12 of Rothkopf & Nordström (2023): the paths x1 (red circles) and x2
// (blue crosses) of the damped oscillator, SBP21, N_t = 32, against the exact
// solution (gray): μẍ + ξẋ + κx = 0 from L = ½μẋ² − ½κx², Λ = −ξẋ₊x₋ (eq. 43),
// μ = 0.5, κ = 1, ξ = 0.00071. Usage: fig12_damped_paths [OUTPUT_DIR]
#include <iostream>

#include "figures/solver_figures.h"

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  std::cout << vivp::figures::PathsFigure(dir, "fig12_damped_paths", "damped",
                                          "damped oscillator, SBP21, N_t = 32")
                   .string()
            << "\n";
}
