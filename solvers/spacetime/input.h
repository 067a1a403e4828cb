// The checks every field solve makes on what it is given, with one message
// per problem (the space-time solve of solve.h and the method of lines).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/sbp/space_grid.h"

namespace vivp::spacetime {

// t_end positive and finite; φ(0) and φ_t(0) of m components at every
// point of the grid, all finite (a non-finite value is named by where it is).
inline void CheckFieldInput(double t_end, const sbp::SpaceGrid<double>& grid,
                            int m, const std::vector<double>& phi0,
                            const std::vector<double>& pi0) {
  if (!(t_end > 0) || !std::isfinite(t_end))
    throw std::invalid_argument("t_end must be positive and finite");
  const std::size_t n = static_cast<std::size_t>(grid.points()) * m;
  if (phi0.size() != n || pi0.size() != n)
    throw std::invalid_argument("initial data: expected " + std::to_string(n) +
                                " values of φ and of φ_t, got " +
                                std::to_string(phi0.size()) + " and " +
                                std::to_string(pi0.size()));
  for (std::size_t k = 0; k < n; ++k)
    if (!std::isfinite(phi0[k]) || !std::isfinite(pi0[k])) {
      const int j = int(k / m);
      std::string at = "x = " + std::to_string(grid.x(j, 0));
      if (grid.dim() > 1) {
        at = "(x, y";
        at += grid.dim() > 2 ? ", z) = (" : ") = (";
        for (int a = 0; a < grid.dim(); ++a)
          at += (a ? ", " : "") + std::to_string(grid.x(j, a));
        at += ")";
      }
      throw std::invalid_argument("initial data: non-finite value at " + at);
    }
}

}  // namespace vivp::spacetime
