// What every solve reports — one Newton, one global solve, a march of
// point mechanics or of a field — as Ceres has one Solver::Summary: whether
// it converged (never true for a result that is not an answer), why it
// stopped, its Newton iterations (Jacobian factorizations), the last
// residual and the wall time.
#pragma once

#include <limits>
#include <string>

namespace vivp::variational {

struct Summary {
  bool converged = false;
  std::string reason;
  long long iterations = 0;
  // ‖F‖∞ of the equations solved, at the returned point (or, for a solve
  // that failed, the last one); NaN where it was not evaluated.
  double last_residual = std::numeric_limits<double>::quiet_NaN();
  double seconds = 0;
};

}  // namespace vivp::variational
