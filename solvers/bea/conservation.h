// Conservation of modified quantities along computed trajectories (McLachlan
// & Offen 2023, Figs. 1-2, and the step-size sweeps of docs/bea.md §5).
//
// The method is run from x(0), x'(0), taken as initial data of the modified
// equation; at every step where the central difference is defined, x'_n is
// recovered and H_mod truncated at h^0, h^2, ..., h^N (names "H0", "H2", ...)
// and the Noether charge ("I0", "I2", ...) are compared with their values at
// (x(0), x'(0)).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "solvers/bea/derivation.h"
#include "solvers/bea/evaluator.h"
#include "solvers/bea/multistep.h"

namespace vivp::bea {

struct ConservationSetup {
  Eigen::VectorXd x0, v0;
  double t_end = 100;
  int difference_order = 6;
  int start_order = -1;  // -1: the derivation's order
  int rk_substeps = 64;
};

struct DeviationSeries {
  std::vector<std::string> names;  // H0, H2, ..., I0, I2, ...
  Eigen::VectorXd t;
  Eigen::MatrixXd deviation;  // rows: time points, columns: names
  MultistepRun run;
};

// One trajectory at step h (steps = round(t_end / h)).
DeviationSeries Deviations(const BeaResult& r, const ModifiedQuantities& q,
                           const NumericPotential& potential,
                           const ConservationSetup& setup, double h);

struct SweepRow {
  double h = 0;
  int steps = 0;
  std::vector<double> max_deviation;  // per name
};

struct Sweep {
  std::vector<std::string> names;
  std::vector<SweepRow> rows;
  std::vector<double> slopes;  // log-log slope per name (with >= 2 rows)
};

Sweep ConservationSweep(const BeaResult& r, const ModifiedQuantities& q,
                        const NumericPotential& potential,
                        const ConservationSetup& setup,
                        const std::vector<double>& steps);

// Least-squares slope of log y against log x.
double LogLogSlope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace vivp::bea
