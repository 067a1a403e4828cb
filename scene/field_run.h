// Running a field scene: its terms become one density
// (problems/fields/terms.h), SolveField (solvers/spacetime/solve.h) solves it
// globally or marching in windows, and the diagnostics the scene lists are
// computed at every slice from the density alone (core/action/
// field_charges.h) and, for the error, from the profile's exact solution.
// Nothing is written here: apps/ writes the files.
#pragma once

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "scene/field_scene.h"
#include "solvers/distributed/comm.h"
#include "solvers/spacetime/solve.h"

namespace vivp::scene {

struct FieldRun {
  spacetime::FieldSolution solution;  // every slice kept
  std::vector<double> x;  // one axis: its points (a grid: FieldScene::Grid())
  // The scene's diagnostics in its order, one value per slice of solution.t:
  // energy, momentum, charge (∑ Hˣ of the densities), error (max over x
  // and components of |φ − φ_exact|; of E − E_exact for a gauge field),
  // gauss and gauss_textbook (a gauge field's Gauss laws, relative).
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;
  // Per slice: whether its φ_t is the closure row of D_t, an order less
  // accurate (docs/fields.md §6): the march's last slice only, since where
  // two windows meet the slice is the corrected hand-off state (§4).
  std::vector<char> closure;
  // The time node of the first kept slice: 0, or a resumed run's checkpoint
  // node.
  long long first_node = 0;
  // The corrected end state against the exact solution, NaN without one.
  double end_state_error = 0;
  // A gauge field: the largest relative residual of Gauss's law of the
  // action (A₀'s equation) and of the textbook law over every slice
  // (core/action/field_constraints.h); NaN for other fields.
  double gauss_residual = NAN, gauss_textbook = NAN;
  // A charged field on two axes: the vortices (zeros of φ, gauge
  // invariantly, core/action/vortex_tracks.h) of every kept slice.
  struct VortexAt {
    double t = 0, x = 0, y = 0;
    int winding = 0;
  };
  std::vector<VortexAt> vortices;
  // A vortex profile: the residual its start was relaxed to; NaN otherwise.
  double relaxation_residual = NAN;
};

// on_window(done, total, t) after each window (see FieldSolveOptions).
// An under-resolved grid or a failed Newton solve returns
// solution.status.converged = false with SolveField's reason.
// A uniform march's checkpoints and its restart (solve.h,
// FieldSolveOptions::on_checkpoint and ::resume).
// With `comm`, a grid of 2 or 3 axes is marched with space spread over its
// ranks (solvers/distributed/solve.h; every rank calls RunFieldScene, and
// only rank 0's FieldRun holds the slices and diagnostics); a field on one
// axis is refused when there is more than one rank.
struct FieldRunHooks {
  std::function<void(const spacetime::FieldCheckpoint&)> on_checkpoint;
  const spacetime::FieldCheckpoint* resume = nullptr;
  const distributed::Comm* comm = nullptr;
};

FieldRun RunFieldScene(
    const FieldScene& scene,
    const std::function<void(int, int, double)>& on_window = {},
    const FieldRunHooks& hooks = {});

}  // namespace vivp::scene
