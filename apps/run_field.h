// `vivp run` and `vivp scene check` on a field scene (scene/field_scene.h;
// docs/field_scenes.md): the solve in memory first, then the space-time
// field, the diagnostics, the plots and summary.json written into a staging
// directory and moved into the output directory. An under-resolved grid is
// refused (exit status 2) and a failed solve reported (exit status 1), both
// before anything is written. Private to apps/.
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/field_run.h"
#include "scene/field_scene.h"

namespace vivp::apps {

// Checkpoint and restart of a uniform march from the command line
// (docs/field_scenes.md §5): checkpoints written to `checkpoint` (HDF5,
// scene/field_hdf5.h) at window boundaries at most every `every` seconds
// (0: at every boundary), the run stopped at the first boundary after
// `stop_after` seconds (negative: never), and a run resumed from `resume`:
// its fields are then those of the uninterrupted run, bit for bit, and its
// output holds the slices from the checkpoint on.
struct FieldRunControl {
  std::string checkpoint;
  double every = 60;
  double stop_after = -1;
  std::string resume;
  bool force = false;      // overwrite an existing checkpoint file
  std::string scene_file;  // for the message of a stopped run
};

// The checks of `control` against the scene (a UsageError each), the
// checkpoint to resume from, the hooks that write checkpoints and stop, and
// the message of a stopped run (run_field_checkpoint.cc).
struct FieldRunStopped {
  double t;
  int windows;
};
void CheckFieldRunControl(const scene::FieldScene& s,
                          const FieldRunControl& control);
spacetime::FieldCheckpoint ReadResume(const FieldRunControl& control);
scene::FieldRunHooks MakeFieldRunHooks(
    const FieldRunControl& control, const spacetime::FieldCheckpoint* resume,
    std::chrono::steady_clock::time_point start);
int ReportStopped(const FieldRunStopped& stop, const scene::FieldScene& s,
                  const FieldRunControl& control);

// Exit status 3: stopped at a checkpoint as asked (--stop-after).
int RunFieldScene(const scene::FieldScene& s, const std::filesystem::path& out,
                  bool quiet, const FieldRunControl& control = {});
int CheckFieldScene(const scene::FieldScene& s);

// The slices of a run that are written: every stride-th and the last.
std::vector<std::size_t> WrittenSlices(const scene::FieldScene& s,
                                       const scene::FieldRun& run);

// The heat map, snapshots and one curve per diagnostic against time
// (report/field_plots.h); a plot that cannot be drawn is a warning. Returns
// the PNGs drawn.
std::vector<std::string> WriteFieldPlots(const std::filesystem::path& dir,
                                         const scene::FieldScene& s,
                                         const scene::FieldRun& run,
                                         std::vector<std::string>& warnings);

// field.csv (t, x, φ[, φ_t] per row) or field.bin (float64, slice-major) of
// a field on one axis, returning the file's layout for summary.json; and
// diagnostics.csv (run_field_csv.cc).
nlohmann::json WriteField(const std::filesystem::path& dir,
                          const scene::FieldScene& s,
                          const scene::FieldRun& run,
                          const std::vector<std::size_t>& slices);
void WriteDiagnostics(const std::filesystem::path& dir,
                      const scene::FieldRun& run,
                      const std::vector<std::size_t>& slices);

// The index of the kept time nearest to `time` (heat maps, spectra).
std::size_t Nearest(const std::vector<double>& t, double time);

// field.h5: the written slices (scene/field_hdf5.h); returns the file's
// layout for summary.json.
nlohmann::json WriteFieldHdf5(const std::filesystem::path& dir,
                              const scene::FieldScene& s,
                              const scene::FieldRun& run,
                              const std::vector<std::size_t>& slices);

// A field on 2 or 3 axes: heat maps of the slices nearest the scene's
// heat_maps times and field.gif of the written slices; a picture that cannot
// be drawn is a warning. Returns the files drawn and describes them in
// `pictures` (for summary.json).
std::vector<std::string> WriteSlicePictures(
    const std::filesystem::path& dir, const scene::FieldScene& s,
    const scene::FieldRun& run, const std::vector<std::size_t>& slices,
    std::vector<std::string>& warnings, nlohmann::json& pictures);

// spectrum.csv and spectrum.png: P(k) of φ (component 0) at the slices
// nearest the scene's spectra times, each checked against Parseval's
// identity; described in `spectra` (for summary.json).
std::vector<std::string> WriteSpectra(const std::filesystem::path& dir,
                                      const scene::FieldScene& s,
                                      const scene::FieldRun& run,
                                      std::vector<std::string>& warnings,
                                      nlohmann::json& spectra);

}  // namespace vivp::apps
