// What the field tests share: initial data of an exact solution, a checked
// solve, errors against the exact solution and fitted slopes.
#pragma once

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/linalg/fit.h"
#include "core/sbp/space.h"
#include "problems/fields/exact.h"
#include "solvers/spacetime/solve.h"

namespace fields_test {

using vivp::sbp::SpaceDerivative;
namespace fields = vivp::fields;
namespace spacetime = vivp::spacetime;
namespace linalg = vivp::linalg;

constexpr double kTwoPi = 2 * std::numbers::pi;

template <class U>
spacetime::FieldSolution Solve(
    const auto& density, const U& u, const SpaceDerivative<double>& dx,
    spacetime::FieldGrid grid,
    const spacetime::FieldSolveOptions& options = {}) {
  auto [phi, pi] = fields::InitialData(u, dx);
  auto s = spacetime::SolveField(density, dx, grid, phi, pi, options);
  BOOST_REQUIRE_MESSAGE(s.status.converged, s.status.reason);
  return s;
}

// max_j |φ(T, x_j) − u(T, x_j)| of the last node and of the corrected end.
template <class U>
std::pair<double, double> EndErrors(const spacetime::FieldSolution& s,
                                    const U& u,
                                    const SpaceDerivative<double>& dx,
                                    double t_end) {
  double node = 0, corrected = 0;
  for (int j = 0; j < dx.points(); ++j) {
    const double exact = u(t_end, dx.x(j));
    node = std::max(node, std::abs(s.end_phi_node[j] - exact));
    corrected = std::max(corrected, std::abs(s.end.phi[j] - exact));
  }
  return {node, corrected};
}

// max over every kept slice and point of |φ − u|.
template <class U>
double MaxError(const spacetime::FieldSolution& s, const U& u,
                const SpaceDerivative<double>& dx) {
  double e = 0;
  for (std::size_t k = 0; k < s.t.size(); ++k)
    for (int j = 0; j < dx.points(); ++j)
      e = std::max(e,
                   std::abs(s.phi[k * dx.points() + j] - u(s.t[k], dx.x(j))));
  return e;
}

// Whether f throws std::invalid_argument with `what` in its message (the
// message is logged).
template <class F>
bool Refused(F f, const char* what) {
  std::string m = "no error";
  try {
    f();
  } catch (const std::invalid_argument& e) {
    m = e.what();
  }
  BOOST_TEST_MESSAGE(m);
  return m.find(what) != std::string::npos;
}

inline double Slope(const std::vector<double>& h,
                    const std::vector<double>& e) {
  return linalg::FitPowerLaw(h, e).order;
}

}  // namespace fields_test
