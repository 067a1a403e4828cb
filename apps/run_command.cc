// `vivp run [SCENE] [--out DIR] [--force]` and `vivp scene check FILE`: a
// scene file solved end to end, with its trajectory, summary, diagnostics and
// plots written into one directory (docs/scenes.md §4).
#include <chrono>
#include <iostream>
#include <sstream>

#include "apps/command.h"
#include "apps/run_field.h"
#include "apps/run_output.h"
#include "apps/run_progress.h"
#include "apps/run_sink.h"
#include "scene/field_scene.h"
#include "scene/run.h"
#include "scene/scene.h"
#include "solvers/distributed/comm.h"

namespace vivp::apps {
namespace {

namespace fs = std::filesystem;

struct RunCommandOptions {
  std::string scene;
  std::string out;
  bool force = false;
  bool quiet = false;
  FieldRunControl field;  // --checkpoint, --resume, … of a field scene
};

// The output directory: --out, else named after the scene file.
fs::path RunOutputDirectory(const RunCommandOptions& o) {
  return !o.out.empty() ? fs::path(o.out)
         : o.scene.empty()
             ? fs::path("default.out")
             : fs::path(fs::path(o.scene).stem().string() + ".out");
}

// Runs the scene into a staging directory beside DIR and moves the files
// into DIR when done, so a failure leaves nothing behind and a user's other
// files in DIR stay untouched.
int RunScene(const RunCommandOptions& o) {
  const scene::AnyScene any =
      o.scene.empty()
          ? scene::ParseAnyScene(scene::DefaultSceneText(), "<default scene>")
          : scene::ReadAnyScene(o.scene);
  const fs::path out = RunOutputDirectory(o);
  CheckOutputDirectory(out, o.force);
  FieldRunControl control = o.field;
  control.force = o.force;
  control.scene_file = o.scene;
  if (const auto* field = std::get_if<scene::FieldScene>(&any))
    return RunFieldScene(*field, out, o.quiet, control);
  if (distributed::Comm::World().size() > 1)
    throw UsageError(
        "a point-mechanics scene runs on one process: run it without mpirun "
        "(only field scenes on 2 or 3 axes spread over ranks)");
  if (!control.checkpoint.empty() || !control.resume.empty() ||
      control.stop_after >= 0)
    throw UsageError(
        "--checkpoint, --resume and --stop-after apply to field scenes (a "
        "march in windows); this scene is point mechanics");
  const scene::Scene& s = std::get<scene::Scene>(any);
  const fs::path staging = MakeStagingDirectory(out);
  const StagingCleanup cleanup{staging};

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

  std::ostringstream human;
  WriteSummary(staging, s, r, sink, files, warnings, total, human);
  MoveInto(staging, out);
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
  const scene::AnyScene any = scene::ReadAnyScene(file);
  if (const auto* field = std::get_if<scene::FieldScene>(&any))
    return CheckFieldScene(*field);
  const scene::Scene& s = std::get<scene::Scene>(any);
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
      "and outputs) or a field scene ([field] and [[term]] tables, "
      "docs/field_scenes.md); without SCENE the default scene (Rothkopf & "
      "Nordström 2023, Fig. 14). Started by mpirun (mpirun -np N vivp run "
      "SCENE), a field scene on a periodic grid of 2 or 3 axes is spread over "
      "the ranks (docs/distributed.md)");
  cmd->add_option("scene", o->scene, "scene file (TOML)");
  cmd->add_option("--out", o->out,
                  "output directory (default: SCENE-STEM.out, default.out)");
  cmd->add_flag("--force", o->force,
                "write into an existing non-empty output directory, "
                "overwriting the files of the same names");
  cmd->add_flag("--quiet", o->quiet, "no progress line on stderr");
  cmd->add_option("--checkpoint", o->field.checkpoint,
                  "field scene: write the march's state to this HDF5 file at "
                  "window boundaries (refused if it exists, unless --force "
                  "or it is the --resume file)");
  cmd->add_option("--checkpoint-every", o->field.every,
                  "seconds between checkpoints (default 60; 0: every window)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--stop-after", o->field.stop_after,
                  "stop at the first window boundary after this many "
                  "seconds, writing the checkpoint there (exit status 3)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--resume", o->field.resume,
                  "continue a field run from this checkpoint: the fields are "
                  "the uninterrupted run's, bit for bit; the output holds "
                  "the slices from the checkpoint on");
  cmd->footer(scene::SchemaHelp() + "\n" + scene::FieldSchemaHelp());
  return [o] { return RunScene(*o); };
}

Runner AddSceneCommand(CLI::App& app) {
  auto file = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("scene", "Scene files");
  cmd->require_subcommand(1);
  CLI::App* check =
      cmd->add_subcommand("check", "Validate a scene file without solving it");
  check->add_option("file", *file, "scene file (TOML)")->required();
  check->footer(scene::SchemaHelp() + "\n" + scene::FieldSchemaHelp());
  auto table = std::make_shared<bool>(false);
  CLI::App* effects = cmd->add_subcommand(
      "effects", "Print the effect catalogue as the README's Markdown table");
  effects->callback([table] { *table = true; });
  return [file, table] {
    if (*table) {
      std::cout << scene::EffectTableMarkdown();
      return 0;
    }
    return CheckScene(*file);
  };
}

}  // namespace vivp::apps
