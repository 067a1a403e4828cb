// McLachlan & Offen 2023, Figs. 1 and 2 (docs/bea.md §5) share their
// experiment and their layout: the multistep method (4.1) with A = -0.2 I on
// U = exp(-|x|^2/2), h = 0.15, 10^4 steps; the trajectory on the left, the
// deviations of a conserved quantity and its modified forms to h^2 and h^4
// on the right. Only the quantity differs.
#pragma once

#include <array>
#include <filesystem>
#include <string>

namespace vivp::figures {

struct ModifiedQuantity {
  std::string stem;    // the figure's file name
  std::string name;    // of the data file
  std::string title;   // of the right panel: "modified <title>"
  int first_column;    // of its three deviations in Deviations(...).deviation
  std::string symbol;  // in the y label, e.g. "H" for |H(t) - H(0)|
  std::array<std::string, 3> titles;  // to h^0, h^2, h^4
};

// Draws the figure into dir and returns the PNG's path.
std::filesystem::path GaussianWellFigure(const std::filesystem::path& dir,
                                         const ModifiedQuantity& q);

}  // namespace vivp::figures
