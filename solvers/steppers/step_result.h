// What a stepper reports: the outcome of one step and of a whole run.
#pragma once

#include <string>

namespace vivp::steppers {

enum class StepOutcome {
  kOk,
  kUnstable,      // the state left every bound (non-finite or blew up)
  kNewtonFailed,  // the implicit equations did not converge
};

inline std::string ToString(StepOutcome s) {
  switch (s) {
    case StepOutcome::kOk:
      return "ok";
    case StepOutcome::kUnstable:
      return "unstable";
    case StepOutcome::kNewtonFailed:
      return "newton_failed";
  }
  return "unknown";
}

struct StepReport {
  StepOutcome status = StepOutcome::kOk;
  int iterations = 0;  // nonlinear (or linearly implicit) iterations
};

}  // namespace vivp::steppers
