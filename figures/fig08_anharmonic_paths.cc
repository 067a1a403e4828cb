// Fig. 8 of Rothkopf & Nordström (2023): the paths x1 (red circles) and x2
// (blue crosses) of the anharmonic oscillator, κ = 20, SBP21, N_t = 32, against
// the exact solution (gray): L = ½ẋ² − ¼κx⁴, x(0) = 1, ẋ(0) = 0.3 (eq. 33),
// against the Jacobi-elliptic exact solution. Usage: fig08_anharmonic_paths
// [OUTPUT_DIR]
#include <iostream>

#include "figures/solver_figures.h"

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  std::cout << vivp::figures::PathsFigure(
                   dir, "fig08_anharmonic_paths", "anharmonic",
                   "anharmonic oscillator, κ = 20, SBP21, N_t = 32")
                   .string()
            << "\n";
}
