// Work–precision of the space-time solve against the method of lines on the
// same spatial operator, for the sine-Gordon breather (docs/fields.md §9).
//
// The breather u(t, x) = 4 arctan[√(1 − ω²)/ω · sin ωt / cosh(√(1 − ω²) x)]
// is solved on the periodic interval [−L, L) with order-8 differences to
// t_end. The error of a run is the largest |φ − u| over every grid point and
// over the sample times t_end·k/8, k = 1 … 8: every method is asked for the
// same slices (the variational solve's nodes there, not a corrected end
// state). For each target error the spatial grid is the coarsest of the list
// whose own error — the semi-discrete flow integrated to round-off, its
// "floor" — is at most a quarter of the target, and every method gets that
// grid. Each configuration's step count is then raised until the target is
// met: doubled, and once two runs give an observed order, set from it. A
// configuration whose error stops falling (a floor) or whose predicted run
// exceeds the budget is reported as such.
//
//   auto r = vivp::studies::BreatherWorkPrecision({});
//   for (const auto& c : r.cheapest) …  // per target and method family
#pragma once

#include <string>
#include <vector>

namespace vivp::studies {

struct FieldWorkOptions {
  double omega = 0.5;                 // breather frequency
  double half_length = 30;            // domain [−L, L)
  double t_end = 12.566370614359172;  // one breather period 2π/ω at ω = ½
  std::vector<double> targets{1e-4, 1e-6, 1e-8};
  std::vector<int> space_points{300, 450, 600, 900, 1200};
  double budget_seconds = 60;  // longest single run a search may predict
  int repeats = 3;             // the cheapest run is timed as a median
};

// One run: a method family ("variational" or a method-of-lines integrator),
// its configuration, the grid and what it measured.
struct FieldWorkRun {
  std::string family, config;
  int space_points = 0;
  long long steps = 0;   // time intervals (variational: points − 1)
  double tolerance = 0;  // dopri5
  double error = 0, seconds = 0;
  bool converged = false;
  std::string message;
};

struct FieldWorkBest {
  double target = 0, floor = 0;  // the grid's semi-discrete error
  int space_points = 0;
  std::string family;
  bool found = false;
  FieldWorkRun run;  // the cheapest run of the family meeting the target
  std::string why;   // when not found
};

// Per target: the cheapest variational run's cost per time step, and one
// Gauss4 step's at the same Δt on the same grid (Gauss4 run with the same
// step count, timed as a median).
struct FieldStepCost {
  double target = 0;
  int space_points = 0;
  std::string config;
  long long steps = 0;
  double seconds_per_step = 0, gauss4_seconds_per_step = 0;
  bool gauss4_converged = false;
};

struct FieldWorkReport {
  FieldWorkOptions options;
  std::vector<FieldWorkRun> runs;  // every run of every search
  std::vector<FieldWorkBest> cheapest;
  std::vector<FieldStepCost> step_costs;
};

// The families, in table order: "variational" (the cheapest over SBP21,
// SBP42, SBP63 and SBP84 in time, marched in windows) then leapfrog, gauss4,
// gauss6, dopri5.
const std::vector<std::string>& FieldWorkFamilies();

// progress: called with one line per finished run (may be empty).
FieldWorkReport BreatherWorkPrecision(
    const FieldWorkOptions& options,
    void (*progress)(const std::string& line) = nullptr);

}  // namespace vivp::studies
