// What `vivp run` keeps of a run as it goes (docs/scenes.md §4): the CSV files
// written node by node, the statistics of each diagnostic column and the
// errors against the reference, for the summary and the plots. Private to
// apps/.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "scene/run.h"

namespace vivp::apps {

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
  explicit FileSink(const std::filesystem::path& dir) : dir_(dir) {}

  void Begin(const scene::RunLayout& layout) override;
  void Node(double t, const double* x, const double* v,
            const double* columns) override;
  void Progress(double fraction) override { fraction_ = fraction; }
  void Finish();

  const scene::RunLayout& layout() const { return layout_; }
  const std::vector<ColumnStats>& stats() const { return stats_; }
  double fraction() const { return fraction_; }
  long long nodes() const { return nodes_; }
  double last_t() const { return last_t_; }
  double max_error_x_ = 0, max_error_v_ = 0, end_error_x_ = 0, end_error_v_ = 0;
  std::vector<double> end_reference_;  // (x, v) of the reference at the end

 private:
  std::filesystem::path dir_;
  scene::RunLayout layout_;
  std::ofstream trajectory_, diagnostics_;
  std::vector<ColumnStats> stats_;
  std::atomic<double> fraction_{0};
  long long nodes_ = 0;
  double last_t_ = 0;
};

}  // namespace vivp::apps
