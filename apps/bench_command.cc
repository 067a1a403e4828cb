// `vivp bench`: what accuracy costs in time. For each method and step count
// (or tolerance, for odeint's adaptive dopri5) on one problem: final-time
// error against the problem's reference, maximum energy and invariant
// errors, median wall time of --repeats runs, function evaluations and
// implicit iterations; as a table, or as JSON with --json FILE|-.
//
// With --rounds R (and the points given by --steps) every point is measured
// R times in turn, each time with --repeats runs, and its time is the median
// of the R medians: where a VM's speed drifts over seconds (by up to a
// factor of two within minutes on the 2-core machines vivp is measured
// on), the drift falls on every method in turn instead of on one method's
// block of runs. It may still slow some methods more than others
// (docs/performance.md §4: the variational marches' times spread by 40 %
// between rounds, McLachlan's RKN's by 2 %).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "apps/command.h"
#include "core/sbp/builder.h"
#include "studies/bench_problems.h"

namespace vivp::apps {
namespace {

struct BenchOptions {
  std::string problem;
  std::string methods;  // comma-separated; empty: all for the problem
  std::string steps;    // comma-separated; empty: the default sweep
  long long repeats = 5;
  long long rounds = 1;
  double budget = 1.0;
  long long slab_points = 0;  // 0: the solver's default window
  std::string json;
  bool force = false;
};

std::vector<std::string> SplitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

std::string Join(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) {
    out += out.empty() ? "" : ", ";
    out += s;
  }
  return out;
}

std::string ProblemNames() {
  std::vector<std::string> names;
  for (const auto& p : studies::BenchProblems()) names.push_back(p.name);
  return Join(names);
}

std::vector<double> ParseSteps(const std::string& s) {
  std::vector<double> out;
  for (const auto& item : SplitList(s)) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (end != item.c_str() + item.size() || !std::isfinite(v) || !(v > 0))
      throw UsageError(
          "--steps: expected positive numbers (step counts, or "
          "tolerances for odeint_dopri5), got '" +
          item + "'");
    out.push_back(v);
  }
  return out;
}

nlohmann::json RowJson(const studies::WorkPoint& w) {
  return {{"method", w.method},
          {"steps", w.steps},
          {"tolerance", JsonNumber(w.tolerance)},
          {"h", JsonNumber(w.h)},
          {"error", JsonNumber(w.error)},
          {"energy_error", JsonNumber(w.energy_error)},
          {"invariant_error", JsonNumber(w.invariant_error)},
          {"seconds", JsonNumber(w.seconds)},
          {"evaluations", w.evaluations},
          {"iterations", w.iterations},
          {"iterations_per_step", w.iterations_per_step},
          {"status", w.status}};
}

void PrintRow(std::ostream& out, const studies::WorkPoint& w) {
  // The status goes after the fixed-width columns: it can be a long reason.
  char line[160];
  std::snprintf(line, sizeof line,
                "%-22s %9ld %9.1e %10.3e %10.3e %10.3e %10.3e %10ld %6.2f ",
                w.method.c_str(), w.steps, w.tolerance, w.error, w.energy_error,
                w.invariant_error, w.seconds, w.evaluations,
                w.iterations_per_step);
  out << line << w.status << '\n';
}

// --slab-points: at least the minimum window of every finite-difference
// variational method selected, and at least one selected.
void CheckSlabPoints(const BenchOptions& o,
                     const std::vector<std::string>& methods) {
  if (o.slab_points <= 0) return;
  bool variational = false;
  for (const auto& m : methods) {
    if (!studies::IsVariationalMethod(m)) continue;
    // A spectral element's window is the element: --slab-points does not
    // apply to it.
    const std::string op = studies::VariationalOperator(m);
    if (sbp::IsElement(op)) continue;
    variational = true;
    const int minimum = sbp::Table(op).min_points;
    if (o.slab_points < minimum)
      throw UsageError(
          "--slab-points " + std::to_string(o.slab_points) +
          " is below the minimum window of " + op + " (" +
          std::to_string(minimum) +
          " points); use --slab-points >= " + std::to_string(minimum));
  }
  if (!variational)
    throw UsageError(
        "--slab-points sets the window of the finite-difference variational "
        "methods, and none is selected; add one to --methods (e.g. "
        "variational_sbp84_uniform) or drop --slab-points");
}

// The methods asked for (all of the problem's by default), each checked.
std::vector<std::string> CheckedMethods(const BenchOptions& o,
                                        const studies::BenchProblem& problem,
                                        const std::vector<double>& steps) {
  std::vector<std::string> methods =
      o.methods.empty() ? problem.methods : SplitList(o.methods);
  for (const auto& m : methods)
    if (std::find(problem.methods.begin(), problem.methods.end(), m) ==
        problem.methods.end())
      throw UsageError("--methods: unknown or inapplicable method '" + m +
                       "' for " + problem.name +
                       "; valid: " + Join(problem.methods));
  if (o.rounds > 1 && steps.empty())
    throw UsageError(
        "--rounds interleaves the points given by --steps, and none are "
        "given (a sweep chooses its points as it runs); add --steps or drop "
        "--rounds");
  for (const auto& m : methods)
    for (double k : steps)
      if (!studies::IsAdaptive(m) && k != std::floor(k))
        throw UsageError("--steps: step counts must be whole numbers for " + m +
                         ", got " + std::to_string(k));
  CheckSlabPoints(o, methods);
  return methods;
}

// Round r measures every (method, point) once, in the order of the table;
// the rows keep round 1's errors and counts (every round runs the same
// computation) and the median of the rounds' times.
std::vector<studies::WorkPoint> MeasureInRounds(
    const BenchOptions& o, const studies::BenchProblem& problem,
    const std::vector<std::string>& methods, const std::vector<double>& steps) {
  std::vector<studies::WorkPoint> points;
  std::vector<std::vector<double>> times;
  for (long long r = 0; r < o.rounds; ++r) {
    std::size_t i = 0;
    for (const auto& m : methods)
      for (double k : steps) {
        const studies::WorkPoint w =
            problem.measure(m, k, static_cast<int>(o.repeats));
        if (r == 0) {
          points.push_back(w);
          times.emplace_back();
        }
        times[i++].push_back(w.seconds);
      }
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    auto& t = times[i];
    std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
    points[i].seconds = t[t.size() / 2];
  }
  return points;
}

int RunBench(const BenchOptions& o) {
  const studies::BenchProblem* problem = nullptr;
  try {
    problem = &studies::FindBenchProblem(o.problem);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--problem: ") + e.what());
  }
  const std::vector<double> steps = ParseSteps(o.steps);
  const std::vector<std::string> methods = CheckedMethods(o, *problem, steps);
  studies::SetVariationalWindowPoints(o.slab_points);
  if (!o.json.empty() && o.json != "-") CheckOutputFile(o.json, o.force);

  std::ostream& human = o.json == "-" ? std::cerr : std::cout;
  human << "# " << problem->description << "; reference: " << problem->reference
        << "; median of " << o.repeats << " runs";
  if (o.rounds > 1)
    human << ", the median of " << o.rounds << " interleaved rounds of them";
  if (o.slab_points > 0)
    human << "; variational windows of " << o.slab_points << " points";
  human << '\n';
  human << "# method                  steps       tol      error  max|dH|/H "
           " max|dI|    seconds      evals  it/st status\n";
  nlohmann::json rows = nlohmann::json::array();
  if (o.rounds > 1) {
    for (const auto& w : MeasureInRounds(o, *problem, methods, steps)) {
      PrintRow(human, w);
      rows.push_back(RowJson(w));
    }
  } else {
    for (const auto& m : methods) {
      std::vector<studies::WorkPoint> sweep;
      if (steps.empty()) {
        sweep =
            studies::Sweep(*problem, m, static_cast<int>(o.repeats), o.budget);
      } else {
        for (double k : steps)
          sweep.push_back(problem->measure(m, k, static_cast<int>(o.repeats)));
      }
      for (const auto& w : sweep) {
        PrintRow(human, w);
        rows.push_back(RowJson(w));
      }
    }
  }
  if (!o.json.empty()) {
    const nlohmann::json j = {{"problem", problem->name},
                              {"description", problem->description},
                              {"reference", problem->reference},
                              {"t_end", problem->t_end},
                              {"invariants", problem->invariant_names},
                              {"repeats", o.repeats},
                              {"rounds", o.rounds},
                              {"slab_points", o.slab_points},
                              {"rows", rows}};
    WriteJson(o.json, j, 2);
  }
  return 0;
}

}  // namespace

Runner AddBenchCommand(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "What accuracy costs in time: error, invariants, wall time and "
      "evaluations per method and step on one problem");
  cmd->add_option("--problem", o->problem, "problem: " + ProblemNames())
      ->required();
  cmd->add_option("--methods", o->methods,
                  "comma-separated methods (default: all that apply)");
  cmd->add_option("--steps", o->steps,
                  "comma-separated step counts (tolerances for odeint_dopri5); "
                  "default: a doubling sweep to round-off or --budget");
  cmd->add_option("--repeats", o->repeats, "timed runs per point (median)")
      ->check(WholeNumberAtLeast(5, "at least 5"))
      ->capture_default_str();
  cmd->add_option("--rounds", o->rounds,
                  "measure the --steps points in this many interleaved "
                  "rounds of --repeats runs each (median of the rounds)")
      ->check(WholeNumberAtLeast(1, "at least 1"))
      ->capture_default_str();
  cmd->add_option("--budget", o->budget,
                  "stop a sweep after a run slower than this many seconds")
      ->check(FiniteNumber())
      ->capture_default_str();
  cmd->add_option("--slab-points", o->slab_points,
                  "points per window of the variational methods' marches "
                  "(default: the solver's, 48 on a uniform grid, 24 under "
                  "error control)")
      ->check(WholeNumberAtLeast(2, "at least 2"));
  cmd->add_option("--json", o->json, "write the rows as JSON (- for stdout)");
  cmd->add_flag("--force", o->force, "overwrite an existing JSON file");
  return [o] {
    if (!(o->budget > 0))
      throw UsageError("--budget: must be positive, got " +
                       std::to_string(o->budget));
    return RunBench(*o);
  };
}

}  // namespace vivp::apps
