// Fig. 6 of Rothkopf & Nordström (2023): free fall, deviation of the value
// x_N (left) and of the derivative (Dx)_N (right) from the exact solution at
// t_2 = 1 against Δt = 1/N_t, regularized SBP21 (blue crosses) and SBP42 (red
// circles). SBP42 differentiates the parabola exactly, so its deviations are
// round-off (exact zeros have no logarithm and are left out).
// Usage: fig06_freefall_convergence [OUTPUT_DIR]
#include <iostream>

#include "figures/solver_figures.h"

int main(int argc, char** argv) {
  using namespace vivp::figures;
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  std::cout << ConvergenceFigure(
                   dir, "fig06_freefall_convergence", "free fall",
                   {{"SBP21", PaperStudy("freefall", "sbp21"), false},
                    {"SBP42", PaperStudy("freefall", "sbp42"), false}},
                   {Quantity::kValue, Quantity::kDerivative})
                   .string()
            << "\n";
}
