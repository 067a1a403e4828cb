// `vivp converge`: errors at t_end and fitted orders of the variational solver
// over a list of grid sizes (Rothkopf & Nordström 2023, Figs. 6-13).
#include "apps/converge_command.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "apps/command.h"
#include "core/sbp/builder.h"
#include "solvers/variational/solver_choice.h"
#include "studies/field_problems.h"
#include "studies/registry.h"

namespace vivp::apps {

void PrintReference(std::ostream& human, const studies::NamedProblem& problem) {
  if (problem.reference != "exact")
    human << "no closed form; errors against the reference "
          << problem.reference << "\n";
}

nlohmann::json StudyJson(const ConvergeOptions& o,
                         const studies::NamedProblem& problem,
                         long long slab_points) {
  return {{"problem", problem.name}, {"reference", problem.reference},
          {"operator", o.op},        {"solver", o.solver},
          {"t_end", o.t_end},        {"slab_points", slab_points}};
}

std::string ErrorCell(bool converged, double e) {
  std::ostringstream s;
  if (converged)
    s << std::scientific << std::setprecision(2) << e;
  else
    s << "-";
  return s.str();
}

std::string OrderCell(double v, int converged) {
  // NaN when fewer than two errors lie above round-off (e.g. free fall
  // with SBP42, exact on parabolas): say so instead of "nan".
  if (std::isnan(v)) return converged < 2 ? "n/a" : "round-off";
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << v;
  return s.str();
}

nlohmann::json OrdersJson(const studies::ConvergenceOrders& o) {
  return {{"x", JsonNumber(o.x)},
          {"v", JsonNumber(o.v)},
          {"x_corrected", JsonNumber(o.x_corrected)},
          {"p_corrected", JsonNumber(o.p_corrected)}};
}

nlohmann::json ConvergenceRowJson(const studies::ConvergenceRow& r) {
  nlohmann::json row = {{"points", r.points},
                        {"dt", r.dt},
                        {"dt_true", r.dt_true},
                        {"err_x", JsonNumber(r.err_x)},
                        {"err_v", JsonNumber(r.err_v)},
                        {"err_x_corrected", JsonNumber(r.err_x_corrected)},
                        {"err_p_corrected", JsonNumber(r.err_p_corrected)},
                        {"error_estimate", JsonNumber(r.error_estimate)},
                        {"iterations", r.iterations},
                        {"fallbacks", r.fallbacks},
                        {"seconds", r.seconds},
                        {"converged", r.converged},
                        {"status", r.reason}};
  // A march under error control: its tolerance, the largest errors over
  // every returned node, its windows and the rejected ones.
  if (std::isfinite(r.tolerance)) {
    row["tolerance"] = r.tolerance;
    row["max_error"] = JsonNumber(r.max_error);
    row["max_error_v"] = JsonNumber(r.max_error_v);
    row["windows"] = r.windows;
    row["rejected"] = r.rejected;
  }
  return row;
}

std::vector<long long> ParsePoints(const std::string& list,
                                   const std::string& flag) {
  return ParseList<long long>(
      list, flag, "whole numbers", "16,32,64",
      [](const std::string& item) -> std::optional<long long> {
        std::size_t used = 0;
        long long v = 0;
        try {
          v = std::stoll(item, &used);
        } catch (const std::exception&) {
          return std::nullopt;
        }
        if (used != item.size()) return std::nullopt;
        return v;
      });
}

namespace {

// The solver of --solver and its options.
variational::SolveOptions ConvergeSolveOptions(const ConvergeOptions& o) {
  variational::SolveOptions options;
  try {
    options.path = variational::ParseSolver(o.solver);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--solver: ") + e.what());
  }
  options.extended_residual = o.extended_residual;
  return options;
}

// The settings of a refusal as the command line writes them: `--slab-points
// 0`, `--solver ceres-lm`.
class CommandLineSpelling : public variational::SettingSpelling {
 public:
  using Setting = variational::Setting;
  std::string Name(Setting s) const override {
    switch (s) {
      case Setting::kSolver:
        return "--solver";
      case Setting::kOperator:
        return "--operator";
      case Setting::kWindowPoints:
        return "--slab-points";
      case Setting::kTolerance:
        return "--tolerance";
      case Setting::kExtendedResidual:
        return "--extended-residual";
    }
    return variational::SettingName(s);
  }
};

// The options with the window resolved: --slab-points as given, or the
// solver's default (Ceres LM marches unless --slab-points 0; a tolerance
// marches in 48 for Newton). An impossible combination is the user's error,
// refused before any work.
ConvergeOptions Resolved(const ConvergeOptions& o,
                         const variational::SolveOptions& solve) {
  const variational::SolveRequest request{
      .path = solve.path,
      .op = o.op,
      .window_points = o.slab_points_given ? o.slab_points : -1,
      .tolerance = !o.tolerances.empty(),
      .extended_residual = solve.extended_residual};
  const variational::Refusal refusal = CheckSolveRequest(request);
  if (!refusal.ok())
    throw UsageError(Describe(refusal, CommandLineSpelling()).Sentence());
  ConvergeOptions r = o;
  r.slab_points = WindowPoints(request);
  return r;
}

// The grid sizes of --points. Every grid is checked before any work, so
// that a bad size is the user's error (exit 2), not a study cut short.
std::vector<long long> CheckedGridSizes(const ConvergeOptions& o) {
  const std::vector<long long> points = ParsePoints(o.points, "--points");
  for (long long n : points) {
    try {
      sbp::MakeOperator<double>(o.op, n, 0.0, o.t_end);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--points: ") + e.what());
    }
    if (o.slab_points_given && o.slab_points > n)
      throw UsageError("--slab-points " + std::to_string(o.slab_points) +
                       " exceeds the grid of " + std::to_string(n) +
                       " points; use --slab-points <= " + std::to_string(n));
  }
  return points;
}

// The table of a study over grid sizes: one row per size. Returns whether
// every solve converged.
bool PrintConvergenceTable(std::ostream& human, const ConvergeOptions& o,
                           const studies::NamedProblem& problem,
                           const studies::ConvergenceStudy& study) {
  human << problem.name << " (" << problem.description << "), " << o.op
        << ", solver " << o.solver << ", t_end = " << o.t_end;
  if (o.slab_points > 0)
    human << ", marching in windows of " << o.slab_points << " points";
  if (o.slab_points > 0 && !o.slab_points_given)
    human << " (the default of " << o.solver
          << "; --slab-points 0 for one global solve)";
  human << "\n";
  PrintReference(human, problem);
  human << std::setw(7) << "Nt" << std::setw(11) << "dt" << std::setw(11)
        << "err x" << std::setw(11) << "err Dx" << std::setw(11) << "err x+λ4"
        << std::setw(11) << "err −λ3" << std::setw(6) << "it" << std::setw(10)
        << "seconds\n";
  bool all_converged = true;
  for (const auto& r : study.rows) {
    // A run that did not converge has no errors to speak of: a march that
    // stopped in its first window would show the untouched zeros of its end
    // state, a global solve the errors of its last iterate.
    auto error = [&](double e) { return ErrorCell(r.converged, e); };
    human << std::setw(7) << r.points << std::scientific << std::setprecision(2)
          << std::setw(11) << r.dt << std::setw(11) << error(r.err_x)
          << std::setw(11) << error(r.err_v) << std::setw(11)
          << error(r.err_x_corrected) << std::setw(11)
          << error(r.err_p_corrected) << std::defaultfloat << std::setw(6)
          << r.iterations << std::setw(10) << std::setprecision(3) << r.seconds
          << (r.converged ? "" : "  NOT CONVERGED: " + r.reason) << "\n";
    all_converged = all_converged && r.converged;
  }
  return all_converged;
}

// The orders fitted over the converged grid sizes, against both step
// conventions.
void PrintFittedOrders(std::ostream& human,
                       const studies::ConvergenceStudy& study) {
  // An order is NaN when fewer than two errors lie above round-off (e.g.
  // free fall with SBP42, exact on parabolas): say so instead of "nan".
  int converged = 0;
  for (const auto& r : study.rows) converged += r.converged ? 1 : 0;
  auto order = [&](double v) { return OrderCell(v, converged); };
  auto orders = [&](const auto& f) {
    return "x " + order(f.x) + ", Dx " + order(f.v) + ", x+M⁻¹λ4 " +
           order(f.x_corrected) + ", −λ3 " + order(f.p_corrected);
  };
  human << "fitted order (dt = 1/Nt):     " << orders(study.orders)
        << "\nfitted order (dt = 1/(Nt−1)): " << orders(study.orders_true_dt)
        << "\n";
  if (converged < 2)
    human << "(an order needs two converged grid sizes; " << converged << " of "
          << study.rows.size() << " converged)\n";
  else if (converged < int(study.rows.size()))
    human << "(fitted over the " << converged << " converged grid sizes of "
          << study.rows.size() << ")\n";
}

nlohmann::json ConvergenceStudyJson(const ConvergeOptions& o,
                                    const studies::NamedProblem& problem,
                                    const studies::ConvergenceStudy& study) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : study.rows) rows.push_back(ConvergenceRowJson(r));
  nlohmann::json j = StudyJson(o, problem, o.slab_points);
  j["rows"] = rows;
  j["orders"] = OrdersJson(study.orders);
  j["orders_true_dt"] = OrdersJson(study.orders_true_dt);
  return j;
}

int RunConverge(const ConvergeOptions& given) {
  if (!given.json.empty() && given.json != "-")
    CheckOutputFile(given.json, given.force);
  if (!given.field.empty()) return RunFieldConverge(given);
  if (given.problem.empty())
    throw UsageError(
        "--problem NAME or --field NAME is required; point-mechanics "
        "problems: " +
        studies::ProblemNameList() +
        "; field problems: " + studies::FieldProblemNameList());
  for (const char* flag : {"--space-points", "--space-order"})
    if (std::find(given.flags_given.begin(), given.flags_given.end(), flag) !=
        given.flags_given.end())
      throw UsageError(std::string(flag) +
                       " applies to --field problems only; drop it or use "
                       "--field NAME");
  const studies::NamedProblem& problem = studies::FindProblem(given.problem);
  const variational::SolveOptions options = ConvergeSolveOptions(given);
  const ConvergeOptions o = Resolved(given, options);
  variational::Grid grid;
  grid.op = o.op;
  grid.t_end = o.t_end;
  if (!o.tolerances.empty())
    return RunToleranceConverge(o, problem, grid, options);
  const std::vector<long long> points = CheckedGridSizes(o);
  const studies::ConvergenceStudy study =
      RunConvergence(problem, grid, points, options, 1e-13, o.slab_points);

  std::ostream& human = o.json == "-" ? std::cerr : std::cout;
  const bool all_converged = PrintConvergenceTable(human, o, problem, study);
  PrintFittedOrders(human, study);
  if (!o.json.empty())
    WriteJson(o.json, ConvergenceStudyJson(o, problem, study));
  if (!all_converged) {
    std::cerr << "vivp: some solves did not converge (see the table)\n";
    return 1;
  }
  return 0;
}

}  // namespace

Runner AddConvergeCommand(CLI::App& app) {
  auto o = std::make_shared<ConvergeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "converge",
      "Errors at t_end and fitted orders of the variational solver over grid "
      "sizes");
  CLI::Option* problem = cmd->add_option(
      "--problem", o->problem, "problem: " + studies::ProblemNameList());
  CLI::Option* field = cmd->add_option(
      "--field", o->field,
      "field problem (instead of --problem): " +
          studies::FieldProblemNameList() +
          "; its --points default to 17,33,65,129 (docs/field_scenes.md §7)");
  problem->excludes(field);
  cmd->add_option("--operator", o->op, "SBP operator")
      ->check(CLI::IsMember(sbp::OperatorNames()))
      ->capture_default_str();
  CLI::Option* points =
      cmd->add_option("--points", o->points, "comma-separated grid sizes Nt")
          ->capture_default_str();
  cmd->add_option("--tolerance", o->tolerances,
                  "error control: comma-separated tolerances (absolute = "
                  "relative), a study of the achieved error, points and time "
                  "per tolerance; marches in windows of --slab-points "
                  "(default 24)")
      ->excludes(points);
  cmd->add_option("--solver", o->solver,
                  "newton | full-newton | ceres-lm (Ceres LM marches in "
                  "windows by default: --slab-points)")
      ->capture_default_str();
  cmd->add_option("--t-end", o->t_end, "end time (start is 0)")
      ->check(FiniteNumber())
      ->capture_default_str();
  cmd->add_option("--json", o->json, "write the study as JSON (- for stdout)");
  cmd->add_flag("--force", o->force, "overwrite an existing JSON file");
  CLI::Option* slab =
      cmd->add_option("--slab-points", o->slab_points,
                      "march in windows of this many points (0: one global "
                      "solve; default 0 for Newton, for ceres-lm its "
                      "measured window per operator)")
          ->check(WholeNumberAtLeast(0, ">= 0 (0: one global solve)"));
  cmd->add_flag("--extended-residual", o->extended_residual,
                "reduced Newton: refinement residual in long double");
  cmd->add_option("--space-points", o->space_points,
                  "--field: spatial points, or a comma-separated list for "
                  "orders in Δx at one --points (default: the problem's)");
  cmd->add_option("--space-order", o->space_order,
                  "--field: order 2, 4, 6, 8 of the spatial operator "
                  "(periodic differences, or sbp21 … sbp84 on an interval; "
                  "default: the problem's)")
      ->check(WholeNumberAtLeast(2, ">= 2 (2, 4, 6 or 8)"));
  return [o, slab, points, cmd] {
    o->slab_points_given = slab->count() > 0;
    o->points_given = points->count() > 0;
    for (const char* flag : {"--tolerance", "--solver", "--extended-residual",
                             "--space-points", "--space-order"})
      if (cmd->get_option(flag)->count() > 0) o->flags_given.push_back(flag);
    return RunConverge(*o);
  };
}

}  // namespace vivp::apps
