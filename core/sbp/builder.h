// The one place an SBP operator is made: by name, with checked arguments.
//
//   auto D = vivp::sbp::MakeOperator<double>("sbp21", 32, 0.0, 1.0);
//
// Every failure throws std::invalid_argument whose message names the bad value
// and the valid range, e.g.
//   "sbp42 needs at least 8 points, got 5"
#pragma once

#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "core/sbp/mattsson_nordstrom2004.h"
#include "core/sbp/operator.h"
#include "core/sbp/strand1994.h"

namespace vivp::sbp {

inline constexpr std::array<std::string_view, 4> kOperatorNames = {
    "sbp21", "sbp42", "sbp63", "sbp84"};

inline std::string OperatorNameList() {
  std::string out;
  for (auto n : kOperatorNames)
    out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

// The coefficient table of an operator by name ("sbp21", ..., "sbp84").
inline const Coefficients& Table(std::string_view name) {
  if (name == "sbp21") return Sbp21();
  if (name == "sbp42") return Sbp42();
  if (name == "sbp63") return Sbp63();
  if (name == "sbp84") return Sbp84();
  throw std::invalid_argument("unknown SBP operator '" + std::string(name) +
                              "'; valid operators: " + OperatorNameList());
}

template <class Real>
Operator<Real> MakeOperator(std::string_view name, long long points,
                            Real t_start = Real(0), Real t_end = Real(1)) {
  const Coefficients& table = Table(name);
  if (points < table.min_points) {
    throw std::invalid_argument(std::string(name) + " needs at least " +
                                std::to_string(table.min_points) +
                                " points, got " + std::to_string(points));
  }
  if (points > (1LL << 30)) {
    throw std::invalid_argument("too many points (" + std::to_string(points) +
                                "); at most 2^30 are supported");
  }
  if (!std::isfinite(static_cast<long double>(t_start)) ||
      !std::isfinite(static_cast<long double>(t_end)) || !(t_end > t_start)) {
    std::ostringstream msg;
    msg << "time interval [" << t_start << ", " << t_end
        << "] is invalid; need finite values with t_end > t_start";
    throw std::invalid_argument(msg.str());
  }
  return Operator<Real>(table, static_cast<int>(points), t_start, t_end);
}

}  // namespace vivp::sbp
