// `vivp converge --field NAME`: the errors of φ at t = T and their fitted
// orders in Δt over --points, or in Δx over a list of --space-points at one
// --points (on a grid, an entry NXxNY gives the points per axis and a single
// N every axis; the order is in the Δx of the first axis that varies), or
// the march under error control over a list of --tolerance
// (studies/field_problems.h; docs/field_scenes.md §7). The JSON has the
// shape of the point-mechanics study: rows, orders, orders_true_dt (or
// tracking under error control).
#include <cmath>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "apps/command.h"
#include "apps/converge_command.h"
#include "core/sbp/builder.h"
#include "solvers/spacetime/composed.h"
#include "studies/field_problems.h"

namespace vivp::apps {

namespace {

// --space-points: comma-separated grids, each N (every axis) or NXxNY per
// axis, for a problem of p.Dim() axes.
std::vector<std::vector<long long>> ParseGrids(const std::string& list,
                                               const studies::FieldProblem& p) {
  const int d = p.Dim();
  const std::string example = d == 1 ? "64,128" : "16x64,32x64,64x64";
  return ParseList<std::vector<long long>>(
      list, "--space-points",
      d == 1 ? "whole numbers" : "grids N or NXxNY (one number per axis)",
      example,
      [&](const std::string& item) -> std::optional<std::vector<long long>> {
        std::vector<long long> axes;
        std::stringstream ss(item);
        std::string part;
        while (std::getline(ss, part, 'x')) {
          std::size_t used = 0;
          try {
            axes.push_back(std::stoll(part, &used));
          } catch (const std::exception&) {
            return std::nullopt;
          }
          if (used != part.size()) return std::nullopt;
        }
        if (axes.size() == 1) axes.assign(std::size_t(d), axes[0]);
        if (int(axes.size()) != d) return std::nullopt;
        return axes;
      });
}

// "64", or "16x64" on a grid.
std::string GridText(const std::vector<long long>& points) {
  std::string s;
  for (long long n : points) s += (s.empty() ? "" : "x") + std::to_string(n);
  return s;
}

// The study's options from the command line, every value checked before
// any work, each refusal naming its option.
studies::FieldStudyOptions FieldOptions(const ConvergeOptions& o,
                                        const studies::FieldProblem& p) {
  for (const auto& flag : o.flags_given)
    if (flag == "--solver" || flag == "--extended-residual")
      throw UsageError(flag +
                       " applies to --problem (point mechanics); a --field "
                       "study solves with Newton and the space-time window's "
                       "own linear solver, on the grids of --points and "
                       "--space-points");
  if (!(o.t_end > 0))
    throw UsageError("--t-end: expected a positive end time, got " +
                     std::to_string(o.t_end));
  studies::FieldStudyOptions so;
  so.op = o.op;
  so.points = o.points_given ? ParsePoints(o.points, "--points")
                             : std::vector<long long>{17, 33, 65, 129};
  so.space_points =
      o.space_points.empty()
          ? std::vector<std::vector<long long>>{std::vector<long long>(
                std::size_t(p.Dim()), p.space_points)}
          : ParseGrids(o.space_points, p);
  so.space_order = o.space_order > 0 ? o.space_order : p.space_order;
  so.t_end = o.t_end;
  so.window_points = o.slab_points;
  if (!o.tolerances.empty() && so.space_points.size() > 1)
    throw UsageError(
        "--tolerance is a study of the march under error control on one "
        "spatial grid; give one --space-points value");
  if (!o.tolerances.empty() && so.window_points == 0 && o.slab_points_given)
    throw UsageError(
        "--tolerance marches in windows, but --slab-points 0 asks for one "
        "global solve; expected --slab-points >= " +
        std::to_string(sbp::Table(so.op).min_points) +
        " or no --slab-points "
        "(16)");
  if (!o.tolerances.empty()) return so;
  if (so.space_points.size() > 1 && so.points.size() > 1)
    throw UsageError(
        "--space-points with a list is a study in Δx at one time grid; give "
        "one --points value (a fine one, e.g. --points 257)");
  if (so.space_order % 2 || so.space_order < 2 || so.space_order > 8)
    throw UsageError("--space-order: expected 2, 4, 6 or 8, got " +
                     std::to_string(so.space_order));
  for (const auto& nx : so.space_points) {
    try {
      (void)studies::FieldGridOf(p, so.space_order, nx);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--space-points: ") + e.what());
    }
  }
  for (long long nt : so.points) {
    try {
      (void)sbp::MakeOperator<double>(so.op, nt, 0.0, so.t_end);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--points: ") + e.what());
    }
    const long long w =
        so.window_points > 0 ? std::min(so.window_points, nt) : nt;
    for (const auto& grid : so.space_points) {
      long long nx = 1;
      for (long long n : grid) nx *= n;
      if (w * nx > spacetime::MaxSolvedAtOnce(so.op))
        throw UsageError("--points " + std::to_string(nt) +
                         " with --space-points " + GridText(grid) + ": " +
                         std::to_string(w * nx) +
                         " values solved at once exceed the " +
                         std::to_string(spacetime::MaxSolvedAtOnce(so.op)) +
                         " allowed for " + so.op +
                         "; march in windows with --slab-points 16");
    }
  }
  return so;
}

// Right-aligned in `width` columns of the terminal (UTF-8: a character
// is one column, whatever its bytes).
std::string Cell(const std::string& text, int width = 11) {
  int chars = 0;
  for (const char c : text)
    chars += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return std::string(std::size_t(std::max(width - chars, 0)), ' ') + text;
}

// The table and the fitted orders; returns whether every solve converged.
bool PrintFieldStudy(std::ostream& human, const studies::FieldProblem& p,
                     const studies::FieldStudyOptions& so,
                     const studies::FieldConvergenceStudy& study) {
  const auto dx = studies::FieldSpace(p, so.space_order, so.space_points[0][0]);
  human << p.name << " (" << p.description << "), " << so.op << ", "
        << dx.name() << " in space, t_end = " << so.t_end;
  if (study.in_space && p.Dim() > 1)
    human << ", refining axis "
          << "xyz"[study.refined_axis];
  if (so.window_points > 0)
    human << ", marching in windows of " << so.window_points << " points";
  human << "\n"
        << Cell("Nt", 7) << Cell("Nx", p.Dim() > 1 ? 10 : 7)
        << Cell(study.in_space ? "dx" : "dt") << Cell("err φ")
        << Cell("err D_tφ") << Cell("err φ+λ4") << Cell("err −λ3")
        << Cell("it", 6) << Cell("seconds", 10) << "\n";
  int converged = 0;
  for (const auto& r : study.rows) {
    human << std::setw(7) << r.points << std::setw(p.Dim() > 1 ? 10 : 7)
          << GridText(r.axis_points) << std::scientific << std::setprecision(2)
          << std::setw(11) << (study.in_space ? r.dx : r.dt) << std::setw(11)
          << ErrorCell(r.converged, r.err_x) << std::setw(11)
          << ErrorCell(r.converged, r.err_v) << std::setw(11)
          << ErrorCell(r.converged, r.err_x_corrected) << std::setw(11)
          << ErrorCell(r.converged, r.err_p_corrected) << std::defaultfloat
          << std::setw(6) << r.iterations << std::setw(10)
          << std::setprecision(3) << r.seconds
          << (r.converged ? "" : "  NOT CONVERGED: " + r.reason) << "\n";
    converged += r.converged ? 1 : 0;
  }
  auto orders = [&](const studies::ConvergenceOrders& f) {
    return "φ " + OrderCell(f.x, converged) + ", D_tφ " +
           OrderCell(f.v, converged) + ", φ+M⁻¹λ4 " +
           OrderCell(f.x_corrected, converged) + ", −λ3 " +
           OrderCell(f.p_corrected, converged);
  };
  if (study.in_space)
    human << "fitted order (dx = " << (p.periodic ? "L/Nx" : "L/(Nx−1)")
          << "):   " << orders(study.orders) << "\n";
  else
    human << "fitted order (dt = 1/Nt):     " << orders(study.orders)
          << "\nfitted order (dt = 1/(Nt−1)): " << orders(study.orders_true_dt)
          << "\n";
  if (converged < int(study.rows.size()))
    human << "(fitted over the " << converged << " converged grids of "
          << study.rows.size() << ")\n";
  return converged == int(study.rows.size());
}

// A field study's rows: a point-mechanics row with the spatial grid and
// the windows.
nlohmann::json FieldRowsJson(const studies::FieldConvergenceStudy& study) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : study.rows) {
    nlohmann::json row = ConvergenceRowJson(r);
    row["space_points"] = r.space_points;
    row["axis_points"] = r.axis_points;
    row["dx"] = r.dx;
    row["windows"] = r.windows;
    rows.push_back(row);
  }
  return rows;
}

nlohmann::json FieldStudyJson(const studies::FieldProblem& p,
                              const studies::FieldStudyOptions& so,
                              const studies::FieldConvergenceStudy& study) {
  const nlohmann::json rows = FieldRowsJson(study);
  const auto dx = studies::FieldSpace(p, so.space_order, so.space_points[0][0]);
  nlohmann::json j = {{"field", p.name},
                      {"axes", p.Dim()},
                      {"refined_axis", study.refined_axis},
                      {"description", p.description},
                      {"reference", "exact"},
                      {"operator", so.op},
                      {"space_operator", dx.name()},
                      {"boundary", p.periodic ? "periodic" : "natural"},
                      {"t_end", so.t_end},
                      {"slab_points", so.window_points},
                      {"study", study.in_space ? "space" : "time"},
                      {"step", study.in_space ? "dx" : "dt"},
                      {"rows", rows},
                      {"orders", OrdersJson(study.orders)}};
  if (!study.in_space) j["orders_true_dt"] = OrdersJson(study.orders_true_dt);
  return j;
}

// The table of a study over tolerances; returns whether every run converged.
bool PrintFieldTolerance(std::ostream& human, const studies::FieldProblem& p,
                         const studies::FieldStudyOptions& so,
                         const studies::FieldConvergenceStudy& study) {
  const auto dx = studies::FieldSpace(p, so.space_order, so.space_points[0][0]);
  human << p.name << " (" << p.description << "), " << so.op << ", "
        << dx.name() << " in space, " << GridText(so.space_points[0])
        << " points, t_end = " << so.t_end << ", error control in windows of "
        << (so.window_points > 0 ? so.window_points : 16)
        << " points (tolerance = absolute = relative)\n"
        << Cell("tol", 9) << Cell("points", 9) << Cell("windows", 9)
        << Cell("rejected", 9) << Cell("err φ") << Cell("err φ_t")
        << Cell("max err φ", 12) << Cell("max err φ_t", 12)
        << Cell("seconds", 10) << "\n";
  bool all = true;
  for (const auto& r : study.rows) {
    auto error = [&](double e) { return ErrorCell(r.converged, e); };
    human << std::scientific << std::setprecision(1) << std::setw(9)
          << r.tolerance << std::defaultfloat << std::setw(9) << r.points
          << std::setw(9) << r.windows << std::setw(9) << r.rejected
          << std::setw(11) << error(r.err_x_corrected) << std::setw(11)
          << error(r.err_p_corrected) << std::setw(12) << error(r.max_error)
          << std::setw(12) << error(r.max_error_v) << std::setw(10)
          << std::setprecision(3) << r.seconds
          << (r.converged ? "" : "  NOT CONVERGED: " + r.reason) << "\n";
    all = all && r.converged;
  }
  auto track = [](const studies::ToleranceTracking& t) {
    std::ostringstream s;
    s << std::setprecision(3) << "slope " << t.slope << ", error/tolerance "
      << t.min_ratio << " … " << t.max_ratio;
    return s.str();
  };
  human << "end error φ against the tolerance: " << track(study.tracking)
        << "\nmax error φ over the slices: " << track(study.tracking_max)
        << "\nmax error φ_t over the slices: " << track(study.tracking_max_v)
        << "\n";
  return all;
}

nlohmann::json FieldToleranceJson(const studies::FieldProblem& p,
                                  const studies::FieldStudyOptions& so,
                                  const studies::FieldConvergenceStudy& study) {
  const nlohmann::json rows = FieldRowsJson(study);
  auto track = [](const studies::ToleranceTracking& t) {
    return nlohmann::json{{"slope", JsonNumber(t.slope)},
                          {"ratio_min", JsonNumber(t.min_ratio)},
                          {"ratio_max", JsonNumber(t.max_ratio)}};
  };
  const auto dx = studies::FieldSpace(p, so.space_order, so.space_points[0][0]);
  return {{"field", p.name},
          {"description", p.description},
          {"reference", "exact"},
          {"operator", so.op},
          {"space_operator", dx.name()},
          {"boundary", p.periodic ? "periodic" : "natural"},
          {"t_end", so.t_end},
          {"slab_points", so.window_points > 0 ? so.window_points : 16},
          {"study", "tolerance"},
          {"rows", rows},
          {"tracking", track(study.tracking)},
          {"tracking_max", track(study.tracking_max)},
          {"tracking_max_v", track(study.tracking_max_v)}};
}

}  // namespace

int RunFieldConverge(const ConvergeOptions& o) {
  const studies::FieldProblem& p = studies::FindFieldProblem(o.field);
  const studies::FieldStudyOptions so = FieldOptions(o, p);
  if (!o.tolerances.empty()) {
    const auto tolerances = ParseTolerances(o.tolerances);
    const auto study = studies::RunFieldTolerance(p, so, tolerances);
    std::ostream& human = o.json == "-" ? std::cerr : std::cout;
    const bool all = PrintFieldTolerance(human, p, so, study);
    if (!o.json.empty()) WriteJson(o.json, FieldToleranceJson(p, so, study));
    if (!all) {
      std::cerr << "vivp: some marches did not converge (see the table)\n";
      return 1;
    }
    return 0;
  }
  const studies::FieldConvergenceStudy study =
      studies::RunFieldConvergence(p, so);
  std::ostream& human = o.json == "-" ? std::cerr : std::cout;
  const bool all_converged = PrintFieldStudy(human, p, so, study);
  if (!o.json.empty()) WriteJson(o.json, FieldStudyJson(p, so, study));
  if (!all_converged) {
    std::cerr << "vivp: some solves did not converge (see the table)\n";
    return 1;
  }
  return 0;
}

}  // namespace vivp::apps
