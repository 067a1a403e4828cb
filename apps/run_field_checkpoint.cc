// `vivp run SCENE --checkpoint FILE [--checkpoint-every S] [--stop-after S]`
// and `--resume FILE` on a field scene: a uniform march writes its state at
// window boundaries (solvers/spacetime/checkpoint.h) as HDF5
// (scene/field_hdf5.h, written to FILE.tmp and renamed, so a run killed
// while writing keeps the last complete checkpoint), stops where asked, and
// resumes bit for bit.
#include <filesystem>
#include <iostream>

#include "apps/command.h"
#include "apps/run_field.h"
#include "scene/field_hdf5.h"

namespace vivp::apps {

namespace fs = std::filesystem;

void CheckFieldRunControl(const scene::FieldScene& s,
                          const FieldRunControl& c) {
  const bool any = !c.checkpoint.empty() || !c.resume.empty();
  if (!any && c.stop_after >= 0)
    throw UsageError(
        "--stop-after stops at a checkpoint; give --checkpoint FILE too");
  if (!any) return;
  if (s.Charged())
    throw UsageError(
        "--checkpoint and --resume are not built for a charged field's "
        "march; run it without them");
  if (s.method.tolerance.enabled())
    throw UsageError(
        "--checkpoint and --resume take uniform marches; this scene's "
        "[method] tolerance chooses the steps, and the step controller's "
        "history is not checkpointed (remove the tolerance and give [time] "
        "points)");
  if (s.method.window_points == 0 || s.method.window_points >= s.time_points)
    throw UsageError(
        "--checkpoint and --resume act at window boundaries; this scene "
        "solves in one window (give [method] window_points, e.g. 16)");
  if (!(c.every >= 0))
    throw UsageError("--checkpoint-every: expected seconds >= 0");
  if (!c.checkpoint.empty() && c.checkpoint != c.resume &&
      fs::exists(c.checkpoint) && !c.force)
    throw UsageError("--checkpoint " + c.checkpoint +
                     " exists and is not overwritten; resume from it with "
                     "--resume " +
                     c.checkpoint + ", or give --force");
}

spacetime::FieldCheckpoint ReadResume(const FieldRunControl& c) {
  try {
    return scene::ReadCheckpoint(c.resume);
  } catch (const std::exception& e) {
    throw UsageError("--resume: " + std::string(e.what()));
  }
}

scene::FieldRunHooks MakeFieldRunHooks(
    const FieldRunControl& c, const spacetime::FieldCheckpoint* resume,
    std::chrono::steady_clock::time_point start) {
  scene::FieldRunHooks hooks;
  hooks.resume = resume;
  if (c.checkpoint.empty()) return hooks;
  auto last = std::make_shared<std::chrono::steady_clock::time_point>(start);
  hooks.on_checkpoint = [c, start, last](const spacetime::FieldCheckpoint& p) {
    using Seconds = std::chrono::duration<double>;
    const auto now = std::chrono::steady_clock::now();
    const bool stop =
        c.stop_after >= 0 && Seconds(now - start).count() >= c.stop_after;
    if (!stop && Seconds(now - *last).count() < c.every) return;
    scene::WriteCheckpoint(c.checkpoint, p);
    *last = now;
    if (stop) throw FieldRunStopped{p.t, p.windows};
  };
  return hooks;
}

int ReportStopped(const FieldRunStopped& stop, const scene::FieldScene& s,
                  const FieldRunControl& c) {
  std::cerr << "vivp: stopped at t = " << stop.t << " of " << s.t_end
            << " after " << stop.windows
            << " windows (--stop-after); the checkpoint is " << c.checkpoint
            << "; continue with: vivp run " << c.scene_file << " --resume "
            << c.checkpoint << " --checkpoint " << c.checkpoint << "\n";
  return 3;
}

}  // namespace vivp::apps
