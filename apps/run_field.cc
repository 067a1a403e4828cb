// `vivp run` on a field scene: solve, then write field.csv (or field.bin),
// diagnostics.csv, the plots and summary.json (docs/field_scenes.md §5).
#include "apps/run_field.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include "apps/command.h"
#include "apps/run_progress.h"
#include "apps/run_sink.h"
#include "solvers/distributed/comm.h"

namespace vivp::apps {

namespace {

namespace fs = std::filesystem;

std::string Rounded(double v) {
  std::ostringstream s;
  s << std::setprecision(4) << v;
  return s.str();
}

// Each diagnostic's statistics over every slice, in the summary and on a
// line each.
nlohmann::json Diagnostics(const scene::FieldRun& run, std::ostream& human) {
  nlohmann::json d = nlohmann::json::object();
  for (std::size_t c = 0; c < run.columns.size(); ++c) {
    const std::string& name = run.columns[c];
    const auto& values = run.values[c];
    // Statistics would skip a NaN; say that there is one instead.
    if (!std::all_of(values.begin(), values.end(),
                     [](double v) { return std::isfinite(v); })) {
      d[name] = {{"finite", false}};
      human << "  " << name << ": not finite at some slices\n";
      continue;
    }
    ColumnStats stats;
    for (double v : values) stats.Add(v);
    nlohmann::json j = stats.Json();
    if (name == "gauss" || name == "gauss_textbook") {
      // A residual, not a conserved quantity: its largest value.
      j = {{"max", stats.max}, {"final", stats.last}};
      human << "  " << name << ": max " << Rounded(stats.max)
            << " relative over the slices, last " << Rounded(stats.last)
            << "\n";
    } else if (name == "error") {
      j = {{"max", stats.max},
           {"final", stats.last},
           {"end_state", JsonNumber(run.end_state_error)}};
      human << "  error against the exact solution: max " << Rounded(stats.max)
            << ", last slice " << Rounded(stats.last)
            << ", corrected end state " << Rounded(run.end_state_error) << "\n";
    } else {
      const double drift = j["max_change"].get<double>();
      double interior = 0;
      for (std::size_t k = 0; k < run.values[c].size(); ++k)
        if (!run.closure[k])
          interior =
              std::max(interior, std::abs(run.values[c][k] - stats.first));
      j["relative_drift"] =
          JsonNumber(drift / std::max(std::abs(stats.first), 1e-300));
      j["max_change_interior"] = interior;
      human << "  " << name << ": " << Rounded(stats.first) << " → "
            << Rounded(stats.last) << " (max change " << Rounded(drift) << "; "
            << Rounded(interior) << " before the last slice)\n";
    }
    d[name] = j;
  }
  return d;
}

// A charged field's spatial differences are its links' covariant forward
// differences (core/action/charged_terms.h), whatever space_order says.
nlohmann::json AxisJson(const scene::FieldAxis& x, bool links) {
  const auto dx = x.Space();
  return {{"operator", links ? "links" : dx.name()},
          {"order", links ? 2 : dx.order()},
          {"boundary", x.boundary},
          {"points", dx.points()},
          {"x0", x.x0},
          {"x1", x.x1},
          {"dx", dx.dx()}};
}

nlohmann::json GridJson(const scene::FieldScene& s,
                        const scene::FieldRun& run) {
  const auto& sol = run.solution;
  nlohmann::json space = AxisJson(s, s.Charged());
  if (s.Dim() > 1) {
    space = {{"axes", nlohmann::json::array()}, {"points", s.GridPoints()}};
    for (int a = 0; a < s.Dim(); ++a)
      space["axes"].push_back(AxisJson(s.Axis(a), s.Charged()));
  }
  return {{"space", space},
          {"time",
           {{"operator", s.method.op},
            {"points", sol.points},
            {"t_end", s.t_end},
            {"dt", sol.dt},
            {"min_step", sol.min_step},
            {"max_step", sol.max_step},
            {"window_points", s.method.window_points},
            {"windows", sol.windows},
            {"rejected", sol.rejected}}}};
}

}  // namespace

std::vector<std::size_t> WrittenSlices(const scene::FieldScene& s,
                                       const scene::FieldRun& run) {
  std::vector<std::size_t> k;
  const std::size_t n = run.solution.t.size();
  // Every stride-th node of the whole run, so that a resumed run writes the
  // slices the uninterrupted one does.
  const auto stride = std::size_t(s.output.stride);
  const std::size_t first =
      (stride - std::size_t(run.first_node) % stride) % stride;
  for (std::size_t i = first; i < n; i += stride) k.push_back(i);
  if (n > 0 && (k.empty() || k.back() != n - 1)) k.push_back(n - 1);
  return k;
}

namespace {

// The solve, with the progress line of a terminal: windows done of all.
scene::FieldRun SolveShowingProgress(const scene::FieldScene& s, bool quiet,
                                     const scene::FieldRunHooks& hooks) {
  std::atomic<int> done{0}, total{0};
  std::atomic<double> reached{0};
  ProgressLine progress(
      [&]() -> std::string {
        if (total == 0) return "";
        std::ostringstream line;
        line << "window " << done << " of " << total
             << " (t = " << std::setprecision(3) << reached.load() << " of "
             << s.t_end << "), ";
        return line.str();
      },
      !quiet, [&] { return s.t_end > 0 ? reached.load() / s.t_end : 0.0; });
  return scene::RunFieldScene(
      s,
      [&](int d, int n, double t) {
        done = d;
        total = n;
        reached = t;
      },
      hooks);
}

// The title, the grids and the solver's account, for the reader.
// " with ends dirichlet (0) / natural" on an interval.
std::string Ends(const scene::FieldAxis& s) {
  if (s.boundary == "periodic") return "";
  std::ostringstream o;
  o << " with ends";
  for (int side = 0; side < 2; ++side) {
    o << (side ? " / " : " ") << s.ends[side];
    if (s.ends[side] != "natural")
      o << " (" << Rounded(s.boundary_values[side]) << ")";
  }
  return o.str();
}

// "sbp42 on [0, 1] with ends …, 64 points", or per axis on a grid:
// "64 × 64 points: x sbp42 on [0, 1] …; y order-8 periodic on [0, 1)".
std::string SpaceText(const scene::FieldScene& s) {
  std::ostringstream o;
  auto axis = [&](const scene::FieldAxis& x) {
    o << (s.Charged() ? "links" : x.Space().name()) << " on [" << Rounded(x.x0)
      << ", " << Rounded(x.x1) << (x.boundary == "periodic" ? ")" : "]")
      << Ends(x);
  };
  if (s.Dim() == 1) {
    axis(s);
    o << ", " << s.space_points << " points";
    return o.str();
  }
  for (int a = 0; a < s.Dim(); ++a)
    o << (a ? " × " : "") << s.Axis(a).space_points;
  o << " points:";
  for (int a = 0; a < s.Dim(); ++a) {
    o << (a ? "; " : " ") << "xyz"[a] << " ";
    axis(s.Axis(a));
  }
  return o.str();
}

void PrintRun(std::ostream& human, const scene::FieldScene& s,
              const spacetime::FieldSolution& sol) {
  human << (s.title.empty() ? s.source : s.title)
        << "\n  field: " << s.components
        << (s.components == 1 ? " component, " : " components, ")
        << SpaceText(s) << "\n  " << s.method.op << ", " << sol.points
        << " time points on [0, " << Rounded(s.t_end) << "]";
  if (s.method.tolerance.enabled())
    human << " under error control (tolerance " << s.method.tolerance.absolute
          << " absolute, " << s.method.tolerance.relative << " relative; Δt "
          << Rounded(sol.min_step) << " … " << Rounded(sol.max_step) << ", "
          << sol.rejected << " windows rejected)";
  if (sol.windows > 1) human << ", " << sol.windows << " windows";
  if (sol.ranks > 0)
    human << ", space on " << sol.ranks
          << (sol.ranks == 1 ? " rank" : " ranks");
  // The mode solve keeps its factorization across windows: Newton steps
  // and factorizations are two counts.
  human << ": " << sol.status.reason << ", " << sol.corrections
        << " Newton steps on " << sol.factorizations << " factorizations, "
        << Rounded(sol.seconds_total) << " s\n"
        << "  Δt·ω_max = " << Rounded(sol.omega_dt) << " (limit "
        << Rounded(sol.limit) << ")\n";
  if (!sol.unchecked.empty()) human << "  note: " << sol.unchecked << "\n";
}

nlohmann::json SolverJson(const spacetime::FieldSolution& sol) {
  return {{"windows", sol.windows},
          {"newton_iterations", sol.factorizations},
          {"corrections", sol.corrections},
          {"linear_solver", sol.linear_solver},
          {"ranks", sol.ranks},
          {"mode_factorizations", sol.mode_factorizations},
          {"sparse_lu_fallbacks", sol.fallbacks},
          {"march_fallbacks", sol.march_fallbacks},
          {"check_failures", sol.check_failures},
          {"unchecked", sol.unchecked},
          {"jacobian_nonzeros", sol.jacobian_nonzeros},
          {"residual_norm", sol.residual_norm},
          {"end_phi_estimate", sol.end.phi_estimate},
          {"end_phi_t_estimate", sol.end.phi_t_estimate}};
}

}  // namespace

int RunFieldScene(const scene::FieldScene& s, const fs::path& out, bool quiet,
                  const FieldRunControl& control) {
  CheckFieldRunControl(s, control);
  // Under mpirun every rank solves its slab; rank 0 alone reports and writes.
  const auto& comm = distributed::Comm::World();
  if (!comm.root()) quiet = true;
  if (comm.root())
    for (const auto& w : s.warnings)
      std::cerr << "vivp: warning: " << w << "\n";
  const auto start = std::chrono::steady_clock::now();
  std::optional<spacetime::FieldCheckpoint> resume;
  if (!control.resume.empty()) resume = ReadResume(control);
  scene::FieldRun run;
  scene::FieldRunHooks hooks =
      MakeFieldRunHooks(control, resume ? &*resume : nullptr, start);
  if (distributed::Launched()) hooks.comm = &comm;
  try {
    run = SolveShowingProgress(s, quiet, hooks);
  } catch (const FieldRunStopped& stop) {
    return ReportStopped(stop, s, control);
  }
  const auto& sol = run.solution;
  if (!sol.status.converged) {
    // The grid is the scene's: refused like any other bad value.
    if (sol.status.reason.rfind("under-resolved", 0) == 0)
      throw scene::SceneError(s.where_time_points + sol.status.reason);
    if (!comm.root()) return 1;
    std::cerr << "vivp: the solve did not converge: " << sol.status.reason
              << "; nothing was written\n";
    return 1;
  }
  if (!comm.root()) return 0;
  const fs::path staging = MakeStagingDirectory(out);
  const StagingCleanup cleanup{staging};
  const auto slices = WrittenSlices(s, run);
  const bool hdf5 = s.output.format == "hdf5";
  std::vector<std::string> files = {hdf5                          ? "field.h5"
                                    : s.output.format == "binary" ? "field.bin"
                                                                  : "field.csv",
                                    "summary.json"};
  const nlohmann::json layout = hdf5 ? WriteFieldHdf5(staging, s, run, slices)
                                     : WriteField(staging, s, run, slices);
  if (!run.columns.empty()) {
    WriteDiagnostics(staging, run, slices);
    files.push_back("diagnostics.csv");
  }
  std::vector<std::string> warnings;
  for (const auto& f : WriteFieldPlots(staging, s, run, warnings))
    files.push_back(f);
  nlohmann::json pictures = nullptr, spectra;
  for (const auto& f : WriteSpectra(staging, s, run, warnings, spectra))
    files.push_back(f);
  if (s.Dim() > 1)
    for (const auto& f :
         WriteSlicePictures(staging, s, run, slices, warnings, pictures))
      files.push_back(f);
  std::ostringstream human;
  PrintRun(human, s, sol);
  const nlohmann::json diagnostics = Diagnostics(run, human);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  const nlohmann::json summary = {
      {"scene", scene::FieldSceneJson(s)},
      {"kind", "field"},
      {"status",
       {{"converged", sol.status.converged}, {"message", sol.status.reason}}},
      {"grid", GridJson(s, run)},
      {"resolution", {{"omega_dt", sol.omega_dt}, {"limit", sol.limit}}},
      {"solver", SolverJson(sol)},
      {"seconds",
       {{"solve", sol.seconds_total},
        {"total", seconds},
        {"residuals", sol.seconds_residual},
        {"blocks_or_assembly", sol.seconds_assembly},
        {"factorizations", sol.seconds_factor},
        {"linear_solves", sol.seconds_solve},
        {"predictor", sol.seconds_predictor},
        {"handoff", sol.seconds_handoff},
        {"checks", sol.seconds_check}}},
      {"diagnostics", diagnostics},
      {"gauss_residual", JsonNumber(run.gauss_residual)},
      {"gauss_textbook", JsonNumber(run.gauss_textbook)},
      {"relaxation_residual", JsonNumber(run.relaxation_residual)},
      {"layout", layout},
      {"pictures", pictures},
      {"spectra", spectra},
      {"resumed_from", resume ? nlohmann::json{{"file", control.resume},
                                               {"t", resume->t},
                                               {"node", resume->node},
                                               {"windows", resume->windows}}
                              : nlohmann::json(nullptr)},
      {"written_slices", slices.size()},
      {"files", files},
      {"warnings", warnings}};
  {
    std::ofstream f(staging / "summary.json");
    f << summary.dump(1) << "\n";
    if (!f) throw std::runtime_error("cannot write summary.json");
  }
  MoveInto(staging, out);
  human << "  wrote " << out.string() << "/:";
  for (const auto& f : files) human << " " << f;
  std::cout << human.str() << "\n";
  for (const auto& w : warnings) std::cerr << "vivp: warning: " << w << "\n";
  return 0;
}

int CheckFieldScene(const scene::FieldScene& s) {
  for (const auto& w : s.warnings) std::cerr << "vivp: warning: " << w << "\n";
  std::cout << s.source << ": ok";
  if (!s.title.empty()) std::cout << " — " << s.title;
  std::cout << "\n  field of " << s.components << " component(s), "
            << SpaceText(s) << "; " << s.terms.size() << " term(s):";
  for (const auto& t : s.terms) std::cout << " " << t.type->name;
  std::cout << "\n  profile " << s.initial.profile
            << (s.exact ? " (exact solution known)" : "") << "; " << s.method.op
            << (s.method.window_points
                    ? ", windows of " + std::to_string(s.method.window_points)
                    : std::string(", one global solve"))
            << (s.method.tolerance.enabled()
                    ? std::string(", error control")
                    : ", " + std::to_string(s.time_points) + " points")
            << " on [0, " << s.t_end << "]\n";
  return 0;
}

}  // namespace vivp::apps
