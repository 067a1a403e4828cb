// What a stepper reports: the outcome of one step and of a whole run.
#pragma once

#include <string>

namespace vivp::steppers {

enum class Status {
  kOk,
  kUnstable,      // the state left every bound (non-finite or blew up)
  kNewtonFailed,  // the implicit equations did not converge
};

inline std::string ToString(Status s) {
  switch (s) {
    case Status::kOk:
      return "ok";
    case Status::kUnstable:
      return "unstable";
    case Status::kNewtonFailed:
      return "newton_failed";
  }
  return "unknown";
}

struct StepReport {
  Status status = Status::kOk;
  int iterations = 0;  // nonlinear (or linearly implicit) iterations
};

}  // namespace vivp::steppers
