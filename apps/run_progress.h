// The progress line of `vivp run` on a terminal. Private to apps/.
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "apps/run_sink.h"

namespace vivp::apps {

// After a second, a line on stderr (when it is a terminal) every half
// second: elapsed time and, for marched and stepped runs, how far in time
// and the time left at the rate so far (once 2 % is done).
class ProgressLine {
 public:
  ProgressLine(const FileSink& sink, double t_start, double t_end, bool show);
  // `status` says how far the run is ("window 3 of 40 (t = …), "), or
  // returns "" when it cannot tell; `fraction` (optional) the part done,
  // for the time left. Both are called from the line's thread.
  ProgressLine(std::function<std::string()> status, bool show,
               std::function<double()> fraction = nullptr);
  ~ProgressLine() { Stop(); }
  void Stop();

 private:
  void Loop();

  std::function<std::string()> status_;
  std::function<double()> fraction_;
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  bool printed_ = false;
};

}  // namespace vivp::apps
