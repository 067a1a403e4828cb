// McLachlan & Offen 2023, Fig. 2 (docs/bea.md §5): the multistep method (4.1)
// with A = -0.2 I on U = exp(-|x|^2/2), x(0) = (1, -1), x'(0) = (0.1, -0.2),
// h = 0.15, 10^4 steps: the trajectory, and the deviations of the angular
// momentum l = I0, I0 + h^2 I2 and I0 + h^2 I2 + h^4 I4 (Noether charge of
// rotations) along it (start values from the modified equation to h^4, x' by
// 6th-order central differences). Usage: fig_bea_fig2_momentum [DIR]
#include <iostream>

#include "figures/bea_figures.h"

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  std::cout << vivp::figures::GaussianWellFigure(
                   dir, {.stem = "fig_bea_fig2_momentum",
                         .name = "momentum",
                         .title = "angular momenta",
                         .first_column = 3,
                         .symbol = "I",
                         .titles = {"l = I_0", "I_0 + h^2 I_2",
                                    "I_0 + h^2 I_2 + h^4 I_4"}})
                   .string()
            << "\n";
}
