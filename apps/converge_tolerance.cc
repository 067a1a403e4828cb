// `vivp converge --tolerance LIST`: a study of the march under error
// control over tolerances (converge_command.h).
#include <cmath>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "apps/command.h"
#include "apps/converge_command.h"

namespace vivp::apps {

std::vector<double> ParseTolerances(const std::string& list) {
  return ParseList<double>(
      list, "--tolerance", "tolerances in (0, 1)", "1e-4,1e-6,1e-8",
      [](const std::string& item) -> std::optional<double> {
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (end != item.c_str() + item.size() || !std::isfinite(v) ||
            !(v > 0) || !(v < 1))
          return std::nullopt;
        return v;
      });
}

namespace {

nlohmann::json TrackingJson(const studies::ToleranceTracking& t) {
  return {{"slope", JsonNumber(t.slope)},
          {"ratio_min", JsonNumber(t.min_ratio)},
          {"ratio_max", JsonNumber(t.max_ratio)}};
}

// The table of a study over tolerances: one row per tolerance. Returns
// whether every run converged.
bool PrintToleranceTable(std::ostream& human, const ConvergeOptions& o,
                         const studies::NamedProblem& problem,
                         const studies::ConvergenceStudy& study,
                         long long window) {
  human << problem.name << " (" << problem.description << "), " << o.op
        << ", solver " << o.solver << ", t_end = " << o.t_end
        << ", error control in windows of " << window
        << " points (tolerance = absolute = relative)\n";
  PrintReference(human, problem);
  human << std::setw(9) << "tol" << std::setw(10) << "points" << std::setw(9)
        << "windows" << std::setw(9) << "rejected" << std::setw(11) << "err x"
        << std::setw(11) << "err v" << std::setw(11) << "max err x"
        << std::setw(11) << "max err v" << std::setw(10) << "seconds\n";
  bool all_converged = true;
  for (const auto& r : study.rows) {
    // A run that stopped has no end error to speak of.
    auto error = [&](double e) { return ErrorCell(r.converged, e); };
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
  return all_converged;
}

// How the errors follow the tolerance: the fitted slope and the range of
// error/tolerance, for the end error and the largest node errors.
void PrintToleranceTracking(std::ostream& human,
                            const studies::ConvergenceStudy& study) {
  auto tracking = [](const studies::ToleranceTracking& t) {
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
}

nlohmann::json ToleranceStudyJson(const ConvergeOptions& o,
                                  const studies::NamedProblem& problem,
                                  const studies::ConvergenceStudy& study,
                                  long long window) {
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
  nlohmann::json j = StudyJson(o, problem, window);
  j["rows"] = rows;
  j["tracking"] = TrackingJson(study.tracking);
  j["tracking_max"] = TrackingJson(study.tracking_max);
  j["tracking_max_v"] = TrackingJson(study.tracking_max_v);
  return j;
}

}  // namespace

int RunToleranceConverge(const ConvergeOptions& o,
                         const studies::NamedProblem& problem,
                         const variational::Grid& grid,
                         const variational::SolveOptions& options) {
  const std::vector<double> tolerances = ParseTolerances(o.tolerances);
  // Resolved by the caller: the window given, or the solver's default.
  const long long window = o.slab_points;
  const studies::ConvergenceStudy study =
      RunToleranceStudy(problem, grid, tolerances, options, window);
  std::ostream& human = o.json == "-" ? std::cerr : std::cout;
  const bool all_converged =
      PrintToleranceTable(human, o, problem, study, window);
  PrintToleranceTracking(human, study);
  if (!o.json.empty())
    WriteJson(o.json, ToleranceStudyJson(o, problem, study, window));
  if (!all_converged) {
    std::cerr << "vivp: some runs did not converge (see the table)\n";
    return 1;
  }
  return 0;
}

}  // namespace vivp::apps
