// The one place an SBP operator is made: by name, with checked arguments.
//
//   auto D = vivp::sbp::MakeOperator<double>("sbp21", 32, 0.0, 1.0);
//
// Every failure throws std::invalid_argument whose message names the bad value
// and the valid range, e.g.
//   "sbp42 needs at least 8 points, got 5"
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/sbp/lobatto.h"
#include "core/sbp/mattsson_nordstrom2004.h"
#include "core/sbp/operator.h"
#include "core/sbp/strand1994.h"

namespace vivp::sbp {

// The registered operators, in the order of their accuracy. An operator is
// its coefficient file (the table with its measured row, coefficients.h)
// and its row here; everything else looks it up by name through Table().
inline const std::vector<const Coefficients*>& Operators() {
  static const std::vector<const Coefficients*> all = {
      &Sbp21(),
      &Sbp42(),
      &Sbp63(),
      &Sbp84(),
  };
  return all;
}

// "sbp21", "sbp42", ...: the names of Operators(), in their order.
inline const std::vector<std::string>& OperatorNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const Coefficients* c : Operators()) out.emplace_back(c->name);
    return out;
  }();
  return names;
}

// "sbp21, sbp42, sbp63, sbp84".
inline std::string OperatorNameList() {
  std::string out;
  for (const auto& n : OperatorNames()) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// The coefficient table of an operator by name ("sbp21", ..., "sbp84", or
// a spectral element of lobatto.h, "lgl8", ...); an unknown name is
// std::invalid_argument naming the valid ones. The elements are not in
// Operators(): they are windows of a fixed size, for time marches only.
inline const Coefficients& Table(std::string_view name) {
  for (const Coefficients* c : Operators())
    if (c->name == name) return *c;
  for (const Coefficients* c : ElementOperators())
    if (c->name == name) return *c;
  throw std::invalid_argument("unknown SBP operator '" + std::string(name) +
                              "'; valid operators: " + OperatorNameList() +
                              ", and the spectral elements " +
                              ElementOperatorNameList());
}

// Whether an operator is a spectral element (a window of a fixed size).
inline bool IsElement(std::string_view name) {
  return Table(name).max_points > 0;
}

// What MakeOperator checks, without building the operator: its table, or
// std::invalid_argument naming the bad value and the valid range. (A march
// validates its grid so once per run; building the operator for that was a
// ninth of a one-window solve of 33 points, callgrind.)
template <class Real>
const Coefficients& CheckOperatorArguments(std::string_view name,
                                           long long points, Real t_start,
                                           Real t_end) {
  const Coefficients& table = Table(name);
  if (points < table.min_points) {
    throw std::invalid_argument(std::string(name) + " needs at least " +
                                std::to_string(table.min_points) +
                                " points, got " + std::to_string(points));
  }
  if (table.max_points > 0 && points != table.max_points) {
    throw std::invalid_argument(
        std::string(name) + " is one spectral element of exactly " +
        std::to_string(table.max_points) + " points, got " +
        std::to_string(points) + "; march in windows of " +
        std::to_string(table.max_points) + " points");
  }
  if (points > (1LL << 30)) {
    throw std::invalid_argument("too many points (" + std::to_string(points) +
                                "); at most 2^30 are supported");
  }
  CheckInterval(t_start, t_end);
  return table;
}

template <class Real>
Operator<Real> MakeOperator(std::string_view name, long long points,
                            Real t_start = Real(0), Real t_end = Real(1)) {
  const Coefficients& table =
      CheckOperatorArguments(name, points, t_start, t_end);
  return Operator<Real>(table, static_cast<int>(points), t_start, t_end);
}

}  // namespace vivp::sbp
