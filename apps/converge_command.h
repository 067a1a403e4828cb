// Shared by the files of `vivp converge`: its options and the study over
// tolerances (converge_tolerance.cc). Private to apps/.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "studies/registry.h"

namespace vivp::apps {

struct ConvergeOptions {
  std::string problem;
  std::string op = "sbp42";
  std::string points = "16,32,64,128,256,512";
  std::string tolerances;  // error control: a study over tolerances
  std::string solver = "newton";
  double t_end = 1.0;
  std::string json;
  bool force = false;
  bool extended_residual = false;
  long long slab_points = 0;
  bool slab_points_given = false;  // --slab-points on the command line
  // --field NAME: a field problem (studies/field_problems.h), its spatial
  // points (a list: a study in space) and the order of its spatial operator
  // (0: the problem's default); the point-mechanics options that were given
  // (refused with --field) and whether --points was.
  std::string field;
  std::string space_points;
  int space_order = 0;
  std::vector<std::string> flags_given;
  bool points_given = false;
};

// The cells of a study's table: an error in two significant digits, "-"
// for a run that did not converge (it has no error to speak of); an order
// in two decimals, "n/a" with fewer than two converged runs and
// "round-off" when the errors are all at round-off.
std::string ErrorCell(bool converged, double e);
std::string OrderCell(double v, int converged);

// A study's fitted orders, and one row of a study over grid sizes, as the
// JSON of `vivp converge` has them.
nlohmann::json OrdersJson(const studies::ConvergenceOrders& o);
nlohmann::json ConvergenceRowJson(const studies::ConvergenceRow& r);

// The whole numbers of a comma-separated list option such as --points
// "16,32,64"; a bad item is a UsageError naming `flag`.
std::vector<long long> ParsePoints(const std::string& list,
                                   const std::string& flag);

// The tolerances of --tolerance, each in (0, 1); a bad item is a
// UsageError (converge_tolerance.cc).
std::vector<double> ParseTolerances(const std::string& list);

// `vivp converge --field NAME`: orders in Δt, or in Δx with a list of
// --space-points, or a study over --tolerance (converge_field.cc).
int RunFieldConverge(const ConvergeOptions& o);

// A line naming what the errors are measured against when the problem has
// no closed form (a reference it computes itself); nothing otherwise.
void PrintReference(std::ostream& human, const studies::NamedProblem& problem);

// The fields every study's JSON has besides its rows: the problem, what
// its errors are measured against, the operator, solver, span and windows.
nlohmann::json StudyJson(const ConvergeOptions& o,
                         const studies::NamedProblem& problem,
                         long long slab_points);

// `vivp converge --tolerance LIST`: the march under error control for each
// tolerance, the achieved errors, the points used and the time.
int RunToleranceConverge(const ConvergeOptions& o,
                         const studies::NamedProblem& problem,
                         const variational::Grid& grid,
                         const variational::SolveOptions& options);

}  // namespace vivp::apps
