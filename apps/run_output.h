// What `vivp run` writes once the solve is done, besides the CSV files of
// run_sink.h: the plots and summary.json (docs/scenes.md §4). Private to
// apps/.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "apps/run_sink.h"
#include "scene/run.h"
#include "scene/scene.h"

namespace vivp::apps {

// gnuplot scripts next to the PNGs; they read the CSV files directly. A
// plot that cannot be drawn is a warning (in `warnings`), not a failure of
// the run: the data and the scripts are written either way. Returns the
// PNGs drawn.
std::vector<std::string> WritePlots(const std::filesystem::path& dir,
                                    const scene::Scene& s,
                                    const scene::RunLayout& layout,
                                    const std::vector<ColumnStats>& stats,
                                    std::vector<std::string>& warnings);

// Writes summary.json into `dir` and the same account for a reader to
// `human`: status, end state, errors against the reference, diagnostics.
// `r` is not const: its solver figures are read with json::operator[].
void WriteSummary(const std::filesystem::path& dir, const scene::Scene& s,
                  scene::RunOutcome& r, const FileSink& sink,
                  const std::vector<std::string>& files,
                  const std::vector<std::string>& warnings, double total,
                  std::ostream& human);

}  // namespace vivp::apps
