#include "solvers/spacetime/charged_march_2d.h"

#include <Eigen/CholmodSupport>

namespace vivp::spacetime {

ChargedMarch MarchChargedSupernodal(const fields::ScalarQed& model,
                                    const sbp::SpaceGrid<double>& grid,
                                    std::vector<double> phi,
                                    std::vector<double> pi,
                                    const ChargedMarchOptions& options,
                                    const ChargedWindowObserver2& on_window) {
  using Solver = NormalEquationsSolverOf<
      Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>>>;
  return MarchCharged<fields::ScalarQed, 2, Solver>(
      model, grid, std::move(phi), std::move(pi), options, on_window);
}

}  // namespace vivp::spacetime
