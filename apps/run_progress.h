// The progress line of `vivp run` on a terminal. Private to apps/.
#pragma once

#include <condition_variable>
#include <mutex>
#include <thread>

#include "apps/run_sink.h"

namespace vivp::apps {

// After a second, a line on stderr (when it is a terminal) every half
// second: elapsed time and, for marched and stepped runs, how far in time.
class ProgressLine {
 public:
  ProgressLine(const FileSink& sink, double t_start, double t_end, bool show);
  ~ProgressLine() { Stop(); }
  void Stop();

 private:
  void Loop();

  const FileSink& sink_;
  double t_start_, t_end_;
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  bool printed_ = false;
};

}  // namespace vivp::apps
