// The paper's two figure kinds for any registered Lagrangian
// (lagrangians/register.h): the paths x1, x2 of the doubled system against
// the exact solution or reference (regularized SBP21, Nt = 32 on [0, 1], as
// Figs. 5, 8, 10, 12 of Rothkopf & Nordström 2023), and the convergence of
// x_N and (Dx)_N against Δt for SBP21 and SBP42 with fitted slopes (as
// Figs. 6, 9, 11, 13). A Lagrangian registered in its own file gets both
// with nothing else edited.
// Usage: fig_problem [OUTPUT_DIR [NAME...]]  (no NAME: every registered one)
#include <iostream>
#include <string>
#include <vector>

#include "figures/solver_figures.h"

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "figures";
  std::vector<std::string> names(argv + std::min(argc, 2), argv + argc);
  if (names.empty())
    for (const auto& p : vivp::studies::Registry()) names.push_back(p.name);
  try {
    for (const auto& name : names) {
      const vivp::studies::NamedProblem& p = vivp::studies::FindProblem(name);
      std::cout << vivp::figures::PathsFigure(dir, "problem_" + name + "_paths",
                                              name, p.description)
                       .string()
                << "\n"
                << vivp::figures::OperatorPairConvergenceFigure(
                       dir, "problem_" + name + "_convergence", name,
                       p.description)
                       .string()
                << "\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "fig_problem: " << e.what() << "\n";
    return 1;
  }
}
