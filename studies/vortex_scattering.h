// Two vortices of the Abelian Higgs model at critical coupling colliding
// head-on in 2 + 1 D, marched with the space-time action (docs/gauge.md §9):
// they scatter at 90° (Ruback 1988; Moriarty, Myers & Rebbi 1988), which
// the tracks of the zeros of φ measure.
//
// The data are VortexCollisionData (solvers/spacetime/vortex_data.h) on
// [−L/2, L/2)², about its plaquette centre c = (h/2, h/2): the vortices at
// c ± (a, 0) moving towards c with speed u; the torus holds windings
// summing to zero, so two antivortices sit far from the collision, at
// c + (L/2, ±3L/8), where the attraction of a vortex decays as
// exp(−√2 e v r).
#pragma once

#include <string>
#include <vector>

namespace vivp::studies {

struct ScatteringSetup {
  int n = 32;             // points per axis
  double length = 16;     // the periodic square [−L/2, L/2)²
  double offset = 3;      // the vortices start at (±a, 0)
  double speed = 0.4;     // towards the centre
  double transition = 1;  // width of the velocity's change of sign at x = 0
  std::string op = "sbp21";
  int window = 8;
  double dt = 0.1;
  double t_end = 14;
};

struct TrackSample {
  double t = 0, x = 0, y = 0;
  int winding = 0;
};

struct ScatteringRun {
  bool ok = false;
  std::string reason;
  double relax_residual = 0;        // the static start's residual (per volume)
  std::vector<TrackSample> tracks;  // every vortex and antivortex per node
  // The outgoing direction of the vortices, in degrees from the x axis of
  // the incoming ones, fitted on their tracks after the collision (the
  // last `fit` of the run), one per vortex; and their mean.
  std::vector<double> outgoing;
  double angle = 0;
  double collision_time = 0;  // when the vortices are nearest each other
  double closest = 0;         // their least distance
  double gauss = 0;           // the action's Gauss law, max over nodes
  double energy_drift = 0;    // of the handed states, relative
  long long newton = 0;
  int windows = 0;
  double seconds = 0;
};

ScatteringRun ScatterVortices(const ScatteringSetup& setup);

}  // namespace vivp::studies
