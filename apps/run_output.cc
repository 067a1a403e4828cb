// summary.json of `vivp run` and the lines printed for the reader.
#include "apps/run_output.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace vivp::apps {
namespace {

std::string Short(double v) {
  std::ostringstream s;
  s << std::setprecision(4) << v;
  return s.str();
}

std::string Vector(const std::vector<double>& v) {
  std::string out = v.size() == 1 ? "" : "(";
  for (std::size_t i = 0; i < v.size(); ++i)
    out += (i ? ", " : "") + Short(v[i]);
  return out + (v.size() == 1 ? "" : ")");
}

double MaxDifference(const std::vector<double>& a, const double* b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

// The title, the method's status and figures, and the end state.
void PrintRunStatus(std::ostream& human, const scene::Scene& s,
                    scene::RunOutcome& r, const FileSink& sink) {
  human << (s.title.empty() ? s.source : s.title) << "\n  " << r.method << ": "
        << r.status;
  if (r.solver.contains("iterations"))
    human << ", " << r.solver["iterations"] << " iterations";
  if (r.solver.contains("gradient_norm"))
    human << ", ‖∇S‖ = " << Short(r.solver["gradient_norm"].get<double>());
  if (r.solver.contains("windows"))
    human << ", " << r.solver["windows"] << " windows, "
          << r.solver["fallbacks"] << " fallbacks";
  human << ", " << Short(r.seconds) << " s\n  " << r.points << " points on ["
        << Short(s.t_start) << ", " << Short(s.t_end) << "]";
  if (r.converged || sink.nodes() > 0) {
    // A failed march returns the state it had handed on last.
    human << (r.converged ? "; end state x = " : "; last state x = ")
          << Vector(r.end_x);
    if (s.order == 2) human << ", v = " << Vector(r.end_v);
  }
  if (!r.converged && sink.nodes() > 0)
    human << " (returned up to t = " << Short(sink.last_t()) << ")";
  human << "\n";
}

// The errors against the reference, in the summary and on one line.
void ReportReferenceErrors(nlohmann::json& summary, std::ostream& human,
                           const scene::Scene& s, scene::RunOutcome& r,
                           const FileSink& sink) {
  const int d = s.dof;
  const double* ref = sink.end_reference_.data();
  nlohmann::json e = {{"kind", s.output.reference},
                      {"description", r.solver["reference"]},
                      {"max_error_x", sink.max_error_x_},
                      {"max_error_v", sink.max_error_v_},
                      {"end_error_x", sink.end_error_x_},
                      {"end_error_v", sink.end_error_v_},
                      {"end_state_error_x", MaxDifference(r.end_x, ref)}};
  if (s.order == 2) e["end_state_error_v"] = MaxDifference(r.end_v, ref + d);
  summary["reference"] = e;
  human << "  against the reference ("
        << r.solver["reference"].get<std::string>() << "): max error x "
        << Short(sink.max_error_x_) << ", at the end "
        << Short(sink.end_error_x_) << " (end state "
        << Short(MaxDifference(r.end_x, ref)) << ")\n";
}

// The statistics of each diagnostic column (the reference's own columns
// aside) in the summary; energy and angular momentum also on a line each.
void ReportDiagnostics(nlohmann::json& summary, std::ostream& human,
                       const FileSink& sink) {
  nlohmann::json diagnostics = nlohmann::json::object();
  for (std::size_t k = 0; k < sink.layout().columns.size(); ++k) {
    const std::string& name = sink.layout().columns[k];
    if (name.rfind("x_reference", 0) == 0 || name.rfind("v_reference", 0) == 0)
      continue;
    diagnostics[name] = sink.stats()[k].Json();
    if ((name == "energy" || name == "angular_momentum") && sink.nodes() > 0)
      human << "  " << name << ": " << Short(sink.stats()[k].first) << " → "
            << Short(sink.stats()[k].last) << " (max change "
            << Short(sink.stats()[k].Json()["max_change"].get<double>())
            << ")\n";
  }
  summary["diagnostics"] = diagnostics;
}

}  // namespace

void WriteSummary(const std::filesystem::path& dir, const scene::Scene& s,
                  scene::RunOutcome& r, const FileSink& sink,
                  const std::vector<std::string>& files,
                  const std::vector<std::string>& warnings, double total,
                  std::ostream& human) {
  nlohmann::json summary = {
      {"scene", scene::SceneJson(s)},
      {"method", r.method},
      {"operator", s.variational() ? nlohmann::json(s.method.op) : nullptr},
      {"points", r.points},
      {"status", {{"converged", r.converged}, {"message", r.status}}},
      {"solver", r.solver},
      {"seconds", {{"solve", r.seconds}, {"total", total}}},
      {"end", {{"t", s.t_end}, {"x", r.end_x}, {"v", r.end_v}}},
      {"written_nodes", sink.nodes()},
      {"files", files}};
  PrintRunStatus(human, s, r, sink);
  // The comparison with the reference needs at least one node (a march that
  // failed in its first window returns none).
  if (sink.layout().reference_x >= 0 && !sink.end_reference_.empty())
    ReportReferenceErrors(summary, human, s, r, sink);
  ReportDiagnostics(summary, human, sink);
  summary["warnings"] = warnings;
  std::ofstream f(dir / "summary.json");
  f << summary.dump(1) << "\n";
  if (!f) throw std::runtime_error("cannot write summary.json");
}

}  // namespace vivp::apps
