// The variational runner's parts that are no template (run_impl.h): the
// march's options from the scene and its results in the outcome.
#include <iomanip>
#include <sstream>

#include "scene/run_impl.h"

namespace vivp::scene::detail {

variational::MarchOptions MarchOptionsFor(const Scene& s) {
  variational::MarchOptions options;
  options.window_points = s.method.slab_points;
  options.keep_trajectory = false;
  options.solve.path = variational::ParseSolver(s.method.solver);
  options.tolerance = s.method.tolerance;
  return options;
}

std::string MarchDescription(const Scene& s,
                             const variational::MarchOptions& options) {
  std::string method = ", marched in windows of " +
                       std::to_string(s.method.slab_points) + " points";
  if (options.tolerance.enabled()) {
    std::ostringstream tol;
    tol << std::setprecision(3) << ", error control to "
        << options.tolerance.absolute << " + " << options.tolerance.relative
        << "·|value|";
    method += tol.str();
  }
  return method;
}

void RecordMarch(const variational::MarchResult& r,
                 const variational::MarchOptions& options, RunOutcome& out) {
  nlohmann::json& j = out.solver;
  out.converged = r.status.converged;
  out.status = r.status.converged ? "converged" : r.status.reason;
  if (r.status.converged && !r.status.reason.empty())
    out.status += " (" + r.status.reason + ")";
  j["windows"] = r.window_count;
  j["fallbacks"] = r.fallbacks;
  j["check_failures"] = r.check_failures;
  j["refinement"] = r.refinement;
  j["factorizations"] = r.iterations;
  j["corrections"] = r.corrections;
  j["error_estimate"] = r.error_estimate;
  j["predictor_steps"] = r.predictor_steps;
  if (options.tolerance.enabled()) {
    j["tolerance"] = {{"absolute", options.tolerance.absolute},
                      {"relative", options.tolerance.relative}};
    j["rejected"] = r.rejected;
    j["min_step"] = r.min_step;
    j["max_step"] = r.max_step;
  }
  if (!r.status.converged) {
    j["failed_at"] = r.failed_at;
    j["last_residual"] = r.last_residual;
  }
  out.end_x = r.end_position;
  out.end_v = r.end_velocity;
  out.points = r.points;
}

}  // namespace vivp::scene::detail
