#include "apps/run_progress.h"

#include <unistd.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace vivp::apps {

ProgressLine::ProgressLine(const FileSink& sink, double t_start, double t_end,
                           bool show)
    : ProgressLine(
          [&sink, t_start, t_end]() -> std::string {
            const double f = sink.fraction();
            if (!(f > 0)) return "";
            std::ostringstream line;
            line << std::fixed << std::setprecision(0) << 100 * f
                 << " % (t = " << std::setprecision(3)
                 << t_start + f * (t_end - t_start) << " of " << t_end << "), ";
            return line.str();
          },
          show, [&sink] { return sink.fraction(); }) {}

ProgressLine::ProgressLine(std::function<std::string()> status, bool show,
                           std::function<double()> fraction)
    : status_(std::move(status)), fraction_(std::move(fraction)) {
  if (show && isatty(STDERR_FILENO)) thread_ = std::thread([this] { Loop(); });
}

void ProgressLine::Stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
  if (printed_) std::cerr << "\r\033[K" << std::flush;
}

void ProgressLine::Loop() {
  const auto start = std::chrono::steady_clock::now();
  std::unique_lock<std::mutex> lock(mutex_);
  if (wake_.wait_for(lock, std::chrono::seconds(1), [this] { return done_; }))
    return;
  do {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
            .count();
    const std::string status = status_();
    std::ostringstream line;
    line << "\r\033[Kvivp: " << (status.empty() ? "solving, " : status);
    line << std::fixed << std::setprecision(1) << seconds << " s";
    const double f = fraction_ ? fraction_() : 0.0;
    if (f >= 0.02 && f < 1)
      line << ", about " << std::setprecision(0) << seconds * (1 - f) / f
           << " s left";
    std::cerr << line.str() << std::flush;
    printed_ = true;
  } while (!wake_.wait_for(lock, std::chrono::milliseconds(500),
                           [this] { return done_; }));
}

}  // namespace vivp::apps
