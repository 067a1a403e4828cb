// McLachlan & Offen 2023, Fig. 1 (docs/bea.md §5): the multistep method (4.1)
// with A = -0.2 I on U = exp(-|x|^2/2), x(0) = (1, -1), x'(0) = (0.1, -0.2),
// h = 0.15, 10^4 steps: the trajectory, and the deviations of H0,
// H0 + h^2 H2 and H0 + h^2 H2 + h^4 H4 along it (start values from the
// modified equation to h^4, x' by 6th-order central differences).
// Usage: fig_bea_fig1_energy [DIR]
#include <iostream>

#include "figures/bea_figures.h"

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  std::cout << vivp::figures::GaussianWellFigure(
                   dir, {.stem = "fig_bea_fig1_energy",
                         .name = "energy",
                         .title = "energies",
                         .first_column = 0,
                         .symbol = "H",
                         .titles = {"H_0", "H_0 + h^2 H_2",
                                    "H_0 + h^2 H_2 + h^4 H_4"}})
                   .string()
            << "\n";
}
