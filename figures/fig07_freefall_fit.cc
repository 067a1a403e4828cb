// Fig. 7 of Rothkopf & Nordström (2023): free fall, deviation of the value
// x_N from the exact solution at t_2 = 1 for regularized SBP21 (blue
// crosses) against Δt = 1/N_t, with the best power-law fit (gray line; the
// paper finds Δt^2.03, against the true spacing 1/(N_t − 1) it is 2.00).
// Usage: fig07_freefall_fit [OUTPUT_DIR]
#include <iostream>

#include "figures/solver_figures.h"

int main(int argc, char** argv) {
  using namespace vivp::figures;
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  std::cout << ConvergenceFigure(dir, "fig07_freefall_fit", "free fall",
                                 {{"SBP21", PaperStudy("freefall", "sbp21")}},
                                 {Quantity::kValue})
                   .string()
            << "\n";
}
