// `vivp converge`: errors at t_end and fitted orders of the variational solver
// over a list of grid sizes (Rothkopf & Nordström 2023, Figs. 6-13).
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "apps/command.h"
#include "core/sbp/builder.h"
#include "studies/registry.h"

namespace vivp::app {
namespace {

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
};

std::vector<long long> ParsePoints(const std::string& list) {
  std::vector<long long> out;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) {
    long long v = 0;
    std::size_t used = 0;
    try {
      v = std::stoll(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || item.empty())
      throw UsageError(
          "--points: expected a comma-separated list of whole "
          "numbers such as 16,32,64, got '" +
          list + "'");
    out.push_back(v);
  }
  if (out.empty())
    throw UsageError(
        "--points: expected at least one grid size, such as "
        "16,32,64");
  return out;
}

std::vector<double> ParseTolerances(const std::string& list) {
  std::vector<double> out;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size() ||
        !std::isfinite(v) || !(v > 0) || !(v < 1))
      throw UsageError(
          "--tolerance: expected a comma-separated list of tolerances in (0, "
          "1) such as 1e-4,1e-6,1e-8, got '" +
          list + "'");
    out.push_back(v);
  }
  if (out.empty())
    throw UsageError(
        "--tolerance: expected at least one tolerance, such as "
        "1e-6");
  return out;
}

nlohmann::json TrackingJson(const ToleranceTracking& t) {
  return {{"slope", JsonNumber(t.slope)},
          {"ratio_min", JsonNumber(t.min_ratio)},
          {"ratio_max", JsonNumber(t.max_ratio)}};
}

nlohmann::json OrdersJson(const ConvergenceOrders& o) {
  return {{"x", JsonNumber(o.x)},
          {"v", JsonNumber(o.v)},
          {"x_corrected", JsonNumber(o.x_corrected)},
          {"p_corrected", JsonNumber(o.p_corrected)}};
}

Path ParseSolver(const std::string& s) {
  if (s == "newton") return Path::kReducedNewton;
  if (s == "full-newton") return Path::kFullNewton;
  if (s == "ceres-lm") return Path::kCeresLm;
  throw UsageError("--solver: '" + s +
                   "' is not a solver; valid: newton, full-newton, ceres-lm");
}

// `vivp converge --tolerance LIST`: the march under error control for each
// tolerance, the achieved errors, the points used and the time.
int RunToleranceConverge(const ConvergeOptions& o, const NamedProblem& problem,
                         const Grid& grid, const SolveOptions& options) {
  const std::vector<double> tolerances = ParseTolerances(o.tolerances);
  const long long window = o.slab_points > 0 ? o.slab_points : 48;
  const ConvergenceStudy study =
      RunToleranceStudy(problem, grid, tolerances, options, window);
  std::ostream& human = o.json == "-" ? std::cerr : std::cout;
  human << problem.name << " (" << problem.description << "), " << o.op
        << ", solver " << o.solver << ", t_end = " << o.t_end
        << ", error control in windows of " << window
        << " points (tolerance = absolute = relative)\n";
  human << std::setw(9) << "tol" << std::setw(10) << "points" << std::setw(9)
        << "windows" << std::setw(9) << "rejected" << std::setw(11) << "err x"
        << std::setw(11) << "err v" << std::setw(11) << "max err x"
        << std::setw(11) << "max err v" << std::setw(10) << "seconds\n";
  bool all_converged = true;
  for (const auto& r : study.rows) {
    // A run that stopped has no end error to speak of.
    auto error = [&](double e) {
      std::ostringstream s;
      if (r.converged)
        s << std::scientific << std::setprecision(2) << e;
      else
        s << "-";
      return s.str();
    };
    human << std::scientific << std::setprecision(1) << std::setw(9)
          << r.tolerance << std::defaultfloat << std::setw(10) << r.points
          << std::setw(9) << r.windows << std::setw(9) << r.rejected
          << std::setw(11) << error(r.err_x_corrected) << std::setw(11)
          << error(r.err_p_corrected) << std::setw(11) << error(r.max_error)
          << std::setw(11) << error(r.max_error_v) << std::setw(10)
          << std::setprecision(3) << r.seconds
          << (r.converged ? "" : "  NOT CONVERGED: " + r.reason) << "\n";
    all_converged = all_converged && r.converged;
  }
  auto tracking = [](const ToleranceTracking& t) {
    if (std::isnan(t.slope)) return std::string("n/a (fewer than two rows)");
    std::ostringstream s;
    s << "slope " << std::fixed << std::setprecision(2) << t.slope
      << ", error/tolerance from " << std::scientific << std::setprecision(1)
      << t.min_ratio << " to " << t.max_ratio;
    return s.str();
  };
  human << "end error (position) against the tolerance:      "
        << tracking(study.tracking)
        << "\nlargest node error, position:                    "
        << tracking(study.tracking_max)
        << "\nlargest node error, velocity:                    "
        << tracking(study.tracking_max_v) << "\n";
  if (!o.json.empty()) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& r : study.rows)
      rows.push_back({{"tolerance", r.tolerance},
                      {"points", r.points},
                      {"windows", r.windows},
                      {"rejected", r.rejected},
                      {"fallbacks", r.fallbacks},
                      {"err_x_corrected", JsonNumber(r.err_x_corrected)},
                      {"err_p_corrected", JsonNumber(r.err_p_corrected)},
                      {"max_error", JsonNumber(r.max_error)},
                      {"max_error_v", JsonNumber(r.max_error_v)},
                      {"iterations", r.iterations},
                      {"seconds", r.seconds},
                      {"converged", r.converged},
                      {"status", r.reason}});
    WriteJson(o.json, {{"problem", problem.name},
                       {"operator", o.op},
                       {"solver", o.solver},
                       {"t_end", o.t_end},
                       {"slab_points", window},
                       {"rows", rows},
                       {"tracking", TrackingJson(study.tracking)},
                       {"tracking_max", TrackingJson(study.tracking_max)},
                       {"tracking_max_v", TrackingJson(study.tracking_max_v)}});
  }
  if (!all_converged) {
    std::cerr << "vivp: some runs did not converge (see the table)\n";
    return 1;
  }
  return 0;
}

int RunConverge(const ConvergeOptions& o) {
  if (!o.json.empty() && o.json != "-") CheckOutputFile(o.json, o.force);
  const NamedProblem& problem = FindProblem(o.problem);
  SolveOptions options;
  options.path = ParseSolver(o.solver);
  options.extended_residual = o.extended_residual;
  Grid grid;
  grid.op = o.op;
  grid.t_end = o.t_end;
  if (options.path == Path::kCeresLm &&
      (o.slab_points > 0 || !o.tolerances.empty()))
    throw UsageError(
        "--solver ceres-lm solves globally and cannot march; use --solver "
        "newton with --slab-points or --tolerance");
  if (!o.tolerances.empty())
    return RunToleranceConverge(o, problem, grid, options);
  const std::vector<long long> points = ParsePoints(o.points);
  // Every grid is checked before any work, so that a bad size is the
  // user's error (exit 2), not a study cut short.
  for (long long n : points) {
    try {
      sbp::MakeOperator<double>(o.op, n, 0.0, o.t_end);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--points: ") + e.what());
    }
    if (o.slab_points > n)
      throw UsageError("--slab-points " + std::to_string(o.slab_points) +
                       " exceeds the grid of " + std::to_string(n) +
                       " points; use --slab-points <= " + std::to_string(n));
  }
  const ConvergenceStudy study =
      RunConvergence(problem, grid, points, options, 1e-13, o.slab_points);

  std::ostream& human = o.json == "-" ? std::cerr : std::cout;
  human << problem.name << " (" << problem.description << "), " << o.op
        << ", solver " << o.solver << ", t_end = " << o.t_end;
  if (o.slab_points > 0)
    human << ", marching in windows of " << o.slab_points << " points";
  human << "\n";
  human << std::setw(7) << "Nt" << std::setw(11) << "dt" << std::setw(11)
        << "err x" << std::setw(11) << "err Dx" << std::setw(11) << "err x+λ4"
        << std::setw(11) << "err −λ3" << std::setw(6) << "it" << std::setw(10)
        << "seconds\n";
  bool all_converged = true;
  for (const auto& r : study.rows) {
    // A run that did not converge has no errors to speak of: a march that
    // stopped in its first window would show the untouched zeros of its end
    // state, a global solve the errors of its last iterate.
    auto error = [&](double e) {
      std::ostringstream s;
      if (r.converged)
        s << std::scientific << std::setprecision(2) << e;
      else
        s << "-";
      return s.str();
    };
    human << std::setw(7) << r.points << std::scientific << std::setprecision(2)
          << std::setw(11) << r.dt << std::setw(11) << error(r.err_x)
          << std::setw(11) << error(r.err_v) << std::setw(11)
          << error(r.err_x_corrected) << std::setw(11)
          << error(r.err_p_corrected) << std::defaultfloat << std::setw(6)
          << r.iterations << std::setw(10) << std::setprecision(3) << r.seconds
          << (r.converged ? "" : "  NOT CONVERGED: " + r.reason) << "\n";
    all_converged = all_converged && r.converged;
  }
  // An order is NaN when fewer than two errors lie above round-off (e.g.
  // free fall with SBP42, exact on parabolas): say so instead of "nan".
  int converged = 0;
  for (const auto& r : study.rows) converged += r.converged ? 1 : 0;
  auto order = [&](double v) {
    if (std::isnan(v)) return std::string(converged < 2 ? "n/a" : "round-off");
    std::ostringstream s;
    s << std::fixed << std::setprecision(2) << v;
    return s.str();
  };
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

  if (!o.json.empty()) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& r : study.rows)
      rows.push_back({{"points", r.points},
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
                      {"status", r.reason}});
    const nlohmann::json j = {
        {"problem", problem.name},
        {"operator", o.op},
        {"solver", o.solver},
        {"t_end", o.t_end},
        {"slab_points", o.slab_points},
        {"rows", rows},
        {"orders", OrdersJson(study.orders)},
        {"orders_true_dt", OrdersJson(study.orders_true_dt)}};
    WriteJson(o.json, j);
  }
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
  cmd->add_option("--problem", o->problem, "problem: " + ProblemNameList())
      ->required();
  std::vector<std::string> names(sbp::kOperatorNames.begin(),
                                 sbp::kOperatorNames.end());
  cmd->add_option("--operator", o->op, "SBP operator")
      ->check(CLI::IsMember(names))
      ->capture_default_str();
  CLI::Option* points =
      cmd->add_option("--points", o->points, "comma-separated grid sizes Nt")
          ->capture_default_str();
  cmd->add_option("--tolerance", o->tolerances,
                  "error control: comma-separated tolerances (absolute = "
                  "relative), a study of the achieved error, points and time "
                  "per tolerance; marches in windows of --slab-points "
                  "(default 48)")
      ->excludes(points);
  cmd->add_option("--solver", o->solver, "newton | full-newton | ceres-lm")
      ->capture_default_str();
  cmd->add_option("--t-end", o->t_end, "end time (start is 0)")
      ->check(FiniteNumber())
      ->capture_default_str();
  cmd->add_option("--json", o->json, "write the study as JSON (- for stdout)");
  cmd->add_flag("--force", o->force, "overwrite an existing JSON file");
  cmd->add_option("--slab-points", o->slab_points,
                  "march in windows of this many points (0: one global "
                  "solve)")
      ->check(WholeNumberAtLeast(0, ">= 0 (0: one global solve)"))
      ->capture_default_str();
  cmd->add_flag("--extended-residual", o->extended_residual,
                "reduced Newton: refinement residual in long double");
  return [o] { return RunConverge(*o); };
}

}  // namespace vivp::app
