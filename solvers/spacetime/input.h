// The checks every field solve makes on what it is given, with one message
// per problem (the space-time solve of solve.h and the method of lines).
#pragma once

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/sbp/space_grid.h"

namespace vivp::spacetime {

// Where grid point j is, for a message: "x = …" on one axis, "(x, y) = (…)"
// on two, "(x, y, z) = (…)" on three.
inline std::string PointName(const sbp::SpaceGrid<double>& grid, int j) {
  if (grid.dim() == 1) return "x = " + std::to_string(grid.x(j, 0));
  std::string at = grid.dim() > 2 ? "(x, y, z) = (" : "(x, y) = (";
  for (int a = 0; a < grid.dim(); ++a)
    at += (a ? ", " : "") + std::to_string(grid.x(j, a));
  return at + ")";
}

// Neumann data on a face of a grid of d > 1 axes (core/action/field_faces.h):
// slope(t, x, a) is ∂_axisφ_a prescribed at time t and the face point x
// (its d coordinates); side 0 is the face at the axis' first point.
struct FieldFace {
  int axis = 0, side = 0;
  std::function<double(double t, const double* x, int a)> slope;
};

// Faces with data only on interval axes of a grid of d > 1 axes, each face
// once.
inline void CheckFaces(const sbp::SpaceGrid<double>& grid,
                       const std::vector<FieldFace>& faces) {
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const FieldFace& f = faces[k];
    const std::string name =
        "face " + std::to_string(f.side) + " of axis " + std::to_string(f.axis);
    if (grid.dim() < 2)
      throw std::invalid_argument(
          "Neumann faces are for grids of 2 or 3 axes; a one-dimensional "
          "field takes data at its ends (left, right)");
    if (f.axis < 0 || f.axis >= grid.dim() || (f.side != 0 && f.side != 1))
      throw std::invalid_argument(name + ": the grid has axes 0 to " +
                                  std::to_string(grid.dim() - 1) +
                                  " with sides 0 and 1");
    if (grid.axis(f.axis).periodic())
      throw std::invalid_argument(name + ": the axis is periodic, no face");
    for (std::size_t l = 0; l < k; ++l)
      if (faces[l].axis == f.axis && faces[l].side == f.side)
        throw std::invalid_argument(name + " has data twice");
  }
}

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
      throw std::invalid_argument("initial data: non-finite value at " +
                                  PointName(grid, j));
    }
}

}  // namespace vivp::spacetime
