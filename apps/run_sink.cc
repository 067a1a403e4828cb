#include "apps/run_sink.h"

#include <iomanip>
#include <stdexcept>

namespace vivp::apps {

void FileSink::Begin(const scene::RunLayout& layout) {
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

void FileSink::Node(double t, const double* x, const double* v,
                    const double* columns) {
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

void FileSink::Finish() {
  trajectory_.close();
  if (!trajectory_) throw std::runtime_error("cannot write trajectory.csv");
  if (!layout_.columns.empty()) {
    diagnostics_.close();
    if (!diagnostics_) throw std::runtime_error("cannot write diagnostics.csv");
  }
}

}  // namespace vivp::apps
