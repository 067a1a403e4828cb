// Fig. 10 of Rothkopf & Nordström (2023): the paths x1 (red circles) and x2
// (blue crosses) of the exponential growth, SBP21, N_t = 32, against the exact
// solution (gray): the first-order system ẋ = 5x/2 from L = −5x²/4, Λ = ẋ₊x₋
// (eq. 39). Usage: fig10_exponential_paths [OUTPUT_DIR]
#include <iostream>

#include "figures/solver_figures.h"

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  std::cout << vivp::figures::PathsFigure(dir, "fig10_exponential_paths",
                                          "exponential",
                                          "exponential growth, SBP21, N_t = 32")
                   .string()
            << "\n";
}
