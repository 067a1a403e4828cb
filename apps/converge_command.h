// Shared by the files of `vivp converge`: its options and the study over
// tolerances (converge_tolerance.cc). Private to apps/.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

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
};

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
