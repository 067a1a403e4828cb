// A field march stopped at a window boundary, and resumed from there
// (FieldSolveOptions::on_checkpoint, ::resume in solve.h).
//
// The continuation of a uniform march depends on more than the hand-off
// state (φ, φ_t) at the boundary: Newton starts the next window with chord
// steps on the factorization the last one left, the predictor starts with
// its last accepted step at the tolerance the last window settled on, and
// the time operator is kept while the step stays within 64 ε of the one it
// was built for. A checkpoint holds all of
// it (FieldWindowCarry), so that a resumed march gives the same fields, bit
// for bit, as the uninterrupted one with the space-diagonalized solve. (The
// sparse LU's factorization is not kept: a resumed march with it refactors
// its first window and agrees to rounding.) Error-controlled marches are
// not checkpointed: their step controller has a history of its own.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "solvers/spacetime/field_window.h"

namespace vivp::spacetime {

struct FieldCheckpoint {
  // The run it belongs to, checked on resume.
  std::string op;
  long long points = 0, window_points = 0;
  double t_end = 0;
  int space_points = 0, components = 0;
  // The grid node of the boundary, its time, the hand-off state there
  // (value j·m + a), the windows done, and what carries to the next window.
  long long node = 0;
  double t = 0;
  std::vector<double> phi, phi_t;
  int windows = 0;
  FieldWindowCarry carry;
};

// Why `c` cannot resume the uniform march of `op` on `points` nodes to
// t_end in windows of `window_points` over n = space points × m values
// (empty: it can).
inline std::string CannotResume(const FieldCheckpoint& c, const std::string& op,
                                long long points, long long window_points,
                                double t_end, int space_points, int m) {
  auto differs = [](const std::string& what, const std::string& was,
                    const std::string& now) {
    return "the checkpoint is of a run with " + what + " " + was +
           ", this one has " + now + "; resume with the run's own settings";
  };
  if (c.op != op) return differs("time operator", c.op, op);
  if (c.points != points)
    return differs("time points", std::to_string(c.points),
                   std::to_string(points));
  if (c.window_points != window_points)
    return differs("windows of", std::to_string(c.window_points),
                   std::to_string(window_points));
  if (c.t_end != t_end)
    return differs("t_end", std::to_string(c.t_end), std::to_string(t_end));
  if (c.space_points != space_points || c.components != m)
    return differs(
        "space points × components",
        std::to_string(c.space_points) + " × " + std::to_string(c.components),
        std::to_string(space_points) + " × " + std::to_string(m));
  const std::size_t n = std::size_t(space_points) * m;
  if (c.phi.size() != n || c.phi_t.size() != n)
    return "the checkpoint's state has " + std::to_string(c.phi.size()) +
           " values, the grid " + std::to_string(n);
  for (std::size_t k = 0; k < n; ++k)
    if (!std::isfinite(c.phi[k]) || !std::isfinite(c.phi_t[k]))
      return "the checkpoint's state is not finite (value " +
             std::to_string(k) + ")";
  const double f = c.carry.predictor_factor;
  if (!(f > 0.0 && f <= 1.0))
    return "the checkpoint's predictor tolerance factor " + std::to_string(f) +
           " is not in (0, 1]";
  if (c.node <= 0 || c.node >= points - 1 || c.node % (window_points - 1) != 0)
    return "the checkpoint's node " + std::to_string(c.node) +
           " is not a window boundary of this run";
  return "";
}

}  // namespace vivp::spacetime
