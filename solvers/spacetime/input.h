// The checks every field solve makes on what it is given, with one message
// per problem (the space-time solve of solve.h and the method of lines).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/sbp/space.h"

namespace vivp::spacetime {

// t_end positive and finite; φ(0) and φ_t(0) of m components at every
// spatial point, all finite (a non-finite value is named by its x).
inline void CheckFieldInput(double t_end,
                            const sbp::SpaceDerivative<double>& dx, int m,
                            const std::vector<double>& phi0,
                            const std::vector<double>& pi0) {
  if (!(t_end > 0) || !std::isfinite(t_end))
    throw std::invalid_argument("t_end must be positive and finite");
  const std::size_t n = static_cast<std::size_t>(dx.points()) * m;
  if (phi0.size() != n || pi0.size() != n)
    throw std::invalid_argument("initial data: expected " + std::to_string(n) +
                                " values of φ and of φ_t, got " +
                                std::to_string(phi0.size()) + " and " +
                                std::to_string(pi0.size()));
  for (std::size_t k = 0; k < n; ++k)
    if (!std::isfinite(phi0[k]) || !std::isfinite(pi0[k]))
      throw std::invalid_argument("initial data: non-finite value at x = " +
                                  std::to_string(dx.x(int(k / m))));
}

}  // namespace vivp::spacetime
