// What a field window is given and what it hands on (field_window.h): the
// boundary data of one spatial axis and the Neumann faces of more, the
// window's options, where its time goes, and what carries from one window
// to the next; the boundary data set on a window's system at its nodes.
#pragma once

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/action/field_boundary.h"
#include "core/action/field_faces.h"
#include "solvers/spacetime/input.h"
#include "solvers/spacetime/window_solver.h"
#include "solvers/variational/newton.h"

namespace vivp::spacetime {

// One end of an interval: the natural condition ∂L/∂φ_x = 0 of the discrete
// action, or Dirichlet / Neumann data imposed by multipliers
// (core/action/field_boundary.h); value(t, a) is g or h of component a
// (empty: 0).
struct FieldBoundarySide {
  action::BoundaryKind kind = action::BoundaryKind::kNatural;
  std::function<double(double t, int a)> value;
};
struct FieldBoundary {
  FieldBoundarySide left, right;  // the ends of one spatial axis
  std::vector<FieldFace> faces;   // Neumann faces in d > 1 (input.h)
};

// What carries from one field window to the next besides the hand-off
// state (FieldWindow::Save): the time operator's points and step (kept
// while the step stays within 64 ε), the predictor's first step, the mode
// solve's factorization, the factor on the predictor's tolerance.
struct FieldWindowCarry {
  int points = 0;
  double dt = 0, predictor_step = 0;
  ModesSnapshot modes;
  double predictor_factor = 1.0;
};

// What a field window needs besides the density and the grids.
struct FieldWindowOptions {
  variational::NewtonOptions newton;
  WindowLinearSolver linear = WindowLinearSolver::kModes;
  SparseSolver sparse = SparseSolver::kUmfpack;
  FieldBoundary boundary;
  bool check_resolution = true;
  double t_end = 0;  // of the march (the points an under-resolved run needs)
};

// Where a field march's time goes (bench/fields_bench --profile).
struct FieldTimings {
  double residual = 0, assembly = 0, factorization = 0, solve = 0;
  double setup = 0, check = 0, handoff = 0, predictor = 0;
};

namespace detail {

// The window's boundary data at its nodes t0 + iΔt.
template <class System>
void SetBoundaryData(System& sys, const FieldBoundary& b, double t0,
                     double dt) {
  constexpr int m = System::m;
  const FieldBoundarySide* sides[2] = {&b.left, &b.right};
  for (int side = 0; side < 2; ++side) {
    if (sides[side]->kind == action::BoundaryKind::kNatural) continue;
    std::vector<double> values(std::size_t(sys.time_points()) * m, 0.0);
    if (sides[side]->value)
      for (int i = 0; i < sys.time_points(); ++i)
        for (int a = 0; a < m; ++a) {
          const double t = t0 + dt * i;
          values[i * m + a] = sides[side]->value(t, a);
          if (!std::isfinite(values[i * m + a]))
            throw std::invalid_argument(
                std::string(side == 0 ? "left" : "right") + " " +
                action::BoundaryName(sides[side]->kind) +
                " data: non-finite value at t = " + std::to_string(t));
        }
    sys.SetBoundary(side, sides[side]->kind, std::move(values));
  }
  const auto& g = sys.space_grid();
  for (const FieldFace& face : b.faces) {
    const auto points = action::detail::FacePoints(g, face.axis, face.side);
    std::vector<double> slopes(std::size_t(sys.time_points()) * points.size() *
                               m);
    double x[3];
    for (int i = 0; i < sys.time_points(); ++i)
      for (std::size_t k = 0; k < points.size(); ++k) {
        for (int a = 0; a < g.dim(); ++a) x[a] = g.x(points[k], a);
        for (int c = 0; c < m; ++c) {
          double& h = slopes[(i * points.size() + k) * m + c];
          h = face.slope ? face.slope(t0 + dt * i, x, c) : 0.0;
          if (!std::isfinite(h))
            throw std::invalid_argument(
                "Neumann data of face " + std::to_string(face.side) +
                " of axis " + std::to_string(face.axis) +
                ": non-finite slope at t = " + std::to_string(t0 + dt * i));
        }
      }
    sys.SetFace(face.axis, face.side, slopes);
  }
}

}  // namespace detail

}  // namespace vivp::spacetime
