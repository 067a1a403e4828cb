// Fig. 5 of Rothkopf & Nordström (2023): the paths x1 (red circles) and x2
// (blue crosses) of the free fall, regularized SBP21, N_t = 32, against the
// exact solution (gray): L = ½ẋ² − x, x(0) = 1, ẋ(0) = 0.3 (eq. 30). x1 and x2
// coincide and follow the parabola: the regularized D̄ has no pi-mode. Usage:
// fig05_freefall_paths [OUTPUT_DIR]
#include <iostream>

#include "figures/solver_figures.h"

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  std::cout << vivp::figures::PathsFigure(
                   dir, "fig05_freefall_paths", "freefall",
                   "free fall, regularized SBP21, N_t = 32")
                   .string()
            << "\n";
}
