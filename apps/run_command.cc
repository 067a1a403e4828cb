// `vivp run [SCENE] [--out DIR] [--force]` and `vivp scene check FILE`: a
// scene file solved end to end, with its trajectory, summary, diagnostics and
// plots written into one directory (README "Scenes").
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "apps/command.h"
#include "scene/run.h"
#include "scene/scene.h"
#include "report/plot.h"

namespace vivp::app {
namespace {

namespace fs = std::filesystem;

struct RunCommandOptions {
  std::string scene;
  std::string out;
  bool force = false;
  bool quiet = false;
};

// Statistics of one column over the written nodes.
struct ColumnStats {
  double first = NAN, last = NAN;
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  void Add(double v) {
    if (std::isnan(first)) first = v;
    last = v;
    min = std::min(min, v);
    max = std::max(max, v);
  }
  nlohmann::json Json() const {
    return {{"initial", first},
            {"final", last},
            {"min", min},
            {"max", max},
            {"max_change", std::max(max - first, first - min)}};
  }
};

// Writes trajectory.csv and diagnostics.csv as the nodes arrive, keeps
// column statistics and the errors against the reference, and reports
// progress to a terminal.
class FileSink : public scene::RunSink {
 public:
  explicit FileSink(const fs::path& dir) : dir_(dir) {}

  void Begin(const scene::RunLayout& layout) override {
    layout_ = layout;
    const int d = layout.dof;
    trajectory_.open(dir_ / "trajectory.csv");
    trajectory_ << "t";
    for (int c = 0; c < d; ++c) trajectory_ << ",x" << c;
    for (int c = 0; c < d; ++c) trajectory_ << ",v" << c;
    trajectory_ << "\n"
                << std::setprecision(std::numeric_limits<double>::max_digits10);
    stats_.resize(layout.columns.size());
    if (!layout.columns.empty()) {
      diagnostics_.open(dir_ / "diagnostics.csv");
      diagnostics_ << "t";
      for (const auto& c : layout.columns) diagnostics_ << "," << c;
      diagnostics_ << "\n"
                   << std::setprecision(
                          std::numeric_limits<double>::max_digits10);
    }
  }

  void Node(double t, const double* x, const double* v,
            const double* columns) override {
    const int d = layout_.dof;
    trajectory_ << t;
    for (int c = 0; c < d; ++c) trajectory_ << "," << x[c];
    for (int c = 0; c < d; ++c) trajectory_ << "," << v[c];
    trajectory_ << "\n";
    if (!layout_.columns.empty()) {
      diagnostics_ << t;
      for (std::size_t k = 0; k < layout_.columns.size(); ++k) {
        diagnostics_ << "," << columns[k];
        stats_[k].Add(columns[k]);
      }
      diagnostics_ << "\n";
    }
    if (layout_.reference_x >= 0) {
      const double* xr = columns + layout_.reference_x;
      const double* vr = xr + d;
      double ex = 0, ev = 0;
      for (int c = 0; c < d; ++c) {
        ex = std::max(ex, std::abs(x[c] - xr[c]));
        ev = std::max(ev, std::abs(v[c] - vr[c]));
      }
      max_error_x_ = std::max(max_error_x_, ex);
      max_error_v_ = std::max(max_error_v_, ev);
      end_error_x_ = ex;
      end_error_v_ = ev;
      end_reference_.assign(xr, xr + 2 * d);
    }
    last_t_ = t;
    ++nodes_;
  }

  void Progress(double fraction) override { fraction_ = fraction; }

  void Finish() {
    trajectory_.close();
    if (!trajectory_) throw std::runtime_error("cannot write trajectory.csv");
    if (!layout_.columns.empty()) {
      diagnostics_.close();
      if (!diagnostics_)
        throw std::runtime_error("cannot write diagnostics.csv");
    }
  }

  const scene::RunLayout& layout() const { return layout_; }
  const std::vector<ColumnStats>& stats() const { return stats_; }
  double fraction() const { return fraction_; }
  long long nodes() const { return nodes_; }
  double last_t() const { return last_t_; }
  double max_error_x_ = 0, max_error_v_ = 0, end_error_x_ = 0, end_error_v_ = 0;
  std::vector<double> end_reference_;  // (x, v) of the reference at the end

 private:
  fs::path dir_;
  scene::RunLayout layout_;
  std::ofstream trajectory_, diagnostics_;
  std::vector<ColumnStats> stats_;
  std::atomic<double> fraction_{0};
  long long nodes_ = 0;
  double last_t_ = 0;
};

// After a second, a line on stderr (when it is a terminal) every half
// second: elapsed time and, for marched and stepped runs, how far in time.
class ProgressLine {
 public:
  ProgressLine(const FileSink& sink, double t_start, double t_end, bool show)
      : sink_(sink), t_start_(t_start), t_end_(t_end) {
    if (show && isatty(STDERR_FILENO))
      thread_ = std::thread([this] { Loop(); });
  }
  ~ProgressLine() { Stop(); }
  void Stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
    if (printed_) std::cerr << "\r\033[K" << std::flush;
  }

 private:
  void Loop() {
    const auto start = std::chrono::steady_clock::now();
    std::unique_lock<std::mutex> lock(mutex_);
    if (wake_.wait_for(lock, std::chrono::seconds(1), [this] { return done_; }))
      return;
    do {
      const double seconds = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - start)
                                 .count();
      const double f = sink_.fraction();
      std::ostringstream line;
      line << "\r\033[Kvivp: ";
      if (f > 0)
        line << std::fixed << std::setprecision(0) << 100 * f
             << " % (t = " << std::setprecision(3)
             << t_start_ + f * (t_end_ - t_start_) << " of " << t_end_ << "), ";
      else
        line << "solving, ";
      line << std::fixed << std::setprecision(1) << seconds << " s";
      std::cerr << line.str() << std::flush;
      printed_ = true;
    } while (!wake_.wait_for(lock, std::chrono::milliseconds(500),
                             [this] { return done_; }));
  }

  const FileSink& sink_;
  double t_start_, t_end_;
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  bool printed_ = false;
};

// gnuplot scripts next to the PNGs; they read the CSV files directly. A
// plot that cannot be drawn is a warning (in `warnings`), not a failure of
// the run: the data and the scripts are written either way.
std::vector<std::string> WritePlots(const fs::path& dir, const scene::Scene& s,
                                    const scene::RunLayout& layout,
                                    const std::vector<ColumnStats>& stats,
                                    std::vector<std::string>& warnings) {
  std::vector<std::string> files;
  auto render = [&](plot::Figure& fig, const std::string& png) {
    try {
      fig.Render();
      files.push_back(png);
    } catch (const std::exception& e) {
      warnings.push_back(e.what());
    }
  };
  const int d = layout.dof;
  auto column = [&](const std::string& name) {
    for (std::size_t k = 0; k < layout.columns.size(); ++k)
      if (layout.columns[k] == name) return int(k) + 2;  // after t
    return 0;
  };
  const std::string title = s.title.empty() ? s.source : s.title;
  auto header = [&](plot::Figure& fig) {
    fig.script() << "set datafile separator ','\nset title \"" << title
                 << "\" noenhanced\n"
                    "set key outside below horizontal maxrows 2\nset grid\n";
  };
  // Time axes span exactly the scene's interval (gnuplot would round it up).
  auto time_axis = [&](plot::Figure& fig) {
    fig.script() << std::setprecision(17) << "set xrange [" << s.t_start << ":"
                 << s.t_end << "]\n";
  };
  {
    plot::Figure fig(dir, "trajectory");
    header(fig);
    auto& g = fig.script();
    if (d == 2) {
      g << "set size ratio -1\nset xlabel 'x_0'\nset ylabel 'x_1'\nplot "
           "'trajectory.csv' using 2:3 with lines lw 2 title 'vivp'";
      if (layout.reference_x >= 0)
        g << ", 'diagnostics.csv' using " << layout.reference_x + 2 << ":"
          << layout.reference_x + 3
          << " with lines dt 2 lc rgb 'black' title 'reference'";
    } else {
      time_axis(fig);
      g << "set xlabel 't'\nset ylabel 'x'\n";
      if (d > 8) g << "unset key\n";
      g << "plot ";
      for (int c = 0; c < d; ++c)
        g << (c ? ", " : "") << "'trajectory.csv' using 1:" << c + 2
          << " with lines lw 2 title 'x_" << c << "'";
      if (layout.reference_x >= 0)
        for (int c = 0; c < d; ++c)
          g << ", 'diagnostics.csv' using 1:" << layout.reference_x + 2 + c
            << " with lines dt 2 lc rgb 'black' title 'reference x_" << c
            << "'";
    }
    g << "\n";
    render(fig, "trajectory.png");
  }
  auto series =
      [&](const std::string& stem, const std::string& ylabel,
          const std::vector<std::pair<std::string, std::string>>& curves,
          bool log) {
        plot::Figure fig(dir, stem);
        header(fig);
        time_axis(fig);
        // A quantity that stays within 1e-3 (relative) of its initial value is
        // plotted as its change q(t) − q(0): the conservation error is what a
        // reader wants to see, and tick labels could not resolve it otherwise.
        bool deviation = !log;
        for (const auto& curve : curves) {
          const ColumnStats& c = stats[column(curve.first) - 2];
          deviation = deviation && std::isfinite(c.first) &&
                      std::max(c.max - c.first, c.first - c.min) <=
                          1e-3 * std::max(std::abs(c.first), 1e-300);
        }
        fig.script() << "set xlabel 't'\nset ylabel '" << ylabel
                     << (deviation ? ": change since the start" : "") << "'\n"
                     << (log || deviation ? "set format y '%.1e'\n" : "")
                     << (log ? "set logscale y\n" : "") << "plot "
                     << std::setprecision(17);
        for (std::size_t k = 0; k < curves.size(); ++k) {
          const int col = column(curves[k].first);
          fig.script() << (k ? ", " : "") << "'diagnostics.csv' using 1:";
          if (deviation)
            fig.script() << "($" << col << " - (" << stats[col - 2].first
                         << "))";
          else
            fig.script() << col;
          fig.script() << " with lines lw 2 title '" << curves[k].second << "'";
        }
        fig.script() << "\n";
        render(fig, stem + ".png");
      };
  for (const auto& diag : s.output.diagnostics) {
    if (diag == "energy") {
      std::vector<std::pair<std::string, std::string>> c = {{"energy", "vivp"}};
      if (column("energy_reference"))
        c.push_back({"energy_reference", "reference"});
      series("energy", "energy v·∂L/∂v − L", c, false);
    } else if (diag == "momentum") {
      std::vector<std::pair<std::string, std::string>> c;
      for (int k = 0; k < d; ++k)
        c.push_back({"p" + std::to_string(k), "p_" + std::to_string(k)});
      series("momentum", "momentum ∂L/∂v", c, false);
    } else if (diag == "angular_momentum") {
      std::vector<std::pair<std::string, std::string>> c;
      if (d == 2)
        c.push_back({"angular_momentum", "x × p"});
      else
        for (const char* a : {"x", "y", "z"})
          c.push_back(
              {std::string("angular_momentum_") + a, std::string("L_") + a});
      series("angular_momentum", "angular momentum", c, false);
    } else if (diag == "error") {
      series("error", "error against the reference",
             {{"error_x", "max_i |x_i − x_i^{ref}|"},
              {"error_v", "max_i |v_i − v_i^{ref}|"}},
             true);
    }
  }
  return files;
}

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

// Runs the scene into a staging directory beside DIR and moves the files
// into DIR when done, so a failure leaves nothing behind and a user's other
// files in DIR stay untouched.
int RunScene(const RunCommandOptions& o) {
  const scene::Scene s =
      o.scene.empty()
          ? scene::ParseScene(scene::DefaultSceneText(), "<default scene>")
          : scene::ReadScene(o.scene);
  const fs::path out =
      !o.out.empty()    ? fs::path(o.out)
      : o.scene.empty() ? fs::path("default.out")
                        : fs::path(fs::path(o.scene).stem().string() + ".out");
  CheckOutputDirectory(out, o.force);
  const fs::path parent = out.has_parent_path() ? out.parent_path() : ".";
  fs::create_directories(parent);
  const fs::path staging = parent / ("." + out.filename().string() +
                                     ".partial-" + std::to_string(getpid()));
  fs::remove_all(staging);
  fs::create_directories(staging);
  struct Cleanup {
    fs::path dir;
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  } cleanup{staging};

  FileSink sink(staging);
  const auto start = std::chrono::steady_clock::now();
  scene::RunOutcome r;
  {
    ProgressLine progress(sink, s.t_start, s.t_end, !o.quiet);
    r = scene::RunScene(s, sink);
  }
  sink.Finish();
  std::vector<std::string> files = {"trajectory.csv", "summary.json"};
  if (!sink.layout().columns.empty()) files.push_back("diagnostics.csv");
  std::vector<std::string> warnings;
  if (sink.nodes() > 1) {
    for (const auto& f :
         WritePlots(staging, s, sink.layout(), sink.stats(), warnings))
      files.push_back(f);
  } else {
    warnings.push_back("no plots: the run returned " +
                       std::to_string(sink.nodes()) + " nodes");
  }
  const double total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();

  const int d = s.dof;
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
  std::ostringstream human;
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
  // The comparison with the reference needs at least one node (a march that
  // failed in its first window returns none).
  if (sink.layout().reference_x >= 0 && !sink.end_reference_.empty()) {
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
  summary["warnings"] = warnings;
  {
    std::ofstream f(staging / "summary.json");
    f << summary.dump(1) << "\n";
    if (!f) throw std::runtime_error("cannot write summary.json");
  }
  fs::create_directories(out);
  for (const auto& entry : fs::directory_iterator(staging))
    fs::rename(entry.path(), out / entry.path().filename());
  human << "  wrote " << out.string() << "/:";
  for (const auto& f : files) human << " " << f;
  std::cout << human.str() << "\n";
  for (const auto& w : warnings) std::cerr << "vivp: warning: " << w << "\n";
  if (!r.converged) {
    std::cerr << "vivp: the solve did not converge: " << r.status << "\n";
    return 1;
  }
  return 0;
}

int CheckScene(const std::string& file) {
  const scene::Scene s = scene::ReadScene(file);
  std::cout << file << ": ok";
  if (!s.title.empty()) std::cout << " — " << s.title;
  std::cout << "\n  dof " << s.dof << ", order " << s.order << ", "
            << s.effects.size() << " effect(s):";
  for (const auto& e : s.effects) std::cout << " " << e.type->name;
  std::cout << "\n  " << s.method.kind;
  if (s.variational())
    std::cout << " (" << s.method.op << ", " << s.method.solver
              << (s.method.slab_points
                      ? ", windows of " + std::to_string(s.method.slab_points)
                      : std::string(""))
              << ")";
  if (s.method.tolerance.enabled())
    std::cout << ", error control to " << s.method.tolerance.absolute << " + "
              << s.method.tolerance.relative << "·|value| on [" << s.t_start
              << ", " << s.t_end << "]\n";
  else
    std::cout << ", " << s.points << " points on [" << s.t_start << ", "
              << s.t_end << "]\n";
  return 0;
}

}  // namespace

Runner AddRunCommand(CLI::App& app) {
  auto o = std::make_shared<RunCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "run",
      "Solve a scene (a TOML file of effects, initial data, time span, method "
      "and outputs); without SCENE the default scene (Rothkopf & Nordström "
      "2023, Fig. 14)");
  cmd->add_option("scene", o->scene, "scene file (TOML)");
  cmd->add_option("--out", o->out,
                  "output directory (default: SCENE-STEM.out, default.out)");
  cmd->add_flag("--force", o->force,
                "write into an existing non-empty output directory, "
                "overwriting the files of the same names");
  cmd->add_flag("--quiet", o->quiet, "no progress line on stderr");
  cmd->footer(scene::SchemaHelp());
  return [o] { return RunScene(*o); };
}

Runner AddSceneCommand(CLI::App& app) {
  auto file = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("scene", "Scene files");
  cmd->require_subcommand(1);
  CLI::App* check =
      cmd->add_subcommand("check", "Validate a scene file without solving it");
  check->add_option("file", *file, "scene file (TOML)")->required();
  check->footer(scene::SchemaHelp());
  return [file] { return CheckScene(*file); };
}

}  // namespace vivp::app
