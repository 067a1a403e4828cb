#include "scene/text.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace vivp::scene::detail {

namespace {

std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1,
                         diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string Join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string Suggest(const std::string& given,
                    const std::vector<std::string>& valid) {
  std::string best;
  std::size_t best_distance = 3;  // at most two edits away
  for (const auto& v : valid) {
    const std::size_t d = EditDistance(given, v);
    if (d < best_distance) {
      best_distance = d;
      best = v;
    }
  }
  return best.empty() ? "" : " (did you mean '" + best + "'?)";
}

std::string OneLine(std::string_view s) {
  std::string out;
  for (const char c : s) {
    if (c == '\n')
      out += "\\n";
    else if (c == '\t')
      out += "\\t";
    else if (c == '\r')
      out += "\\r";
    else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned char>(c));
      out += buf;
    } else {
      out += c;
    }
  }
  return out;
}

// Appended piece by piece: "'" + OneLine(s) draws a false -Wrestrict from
// GCC 12 once Quote is compiled on its own (GCC bug 105329).
std::string Quote(const std::string& s) {
  std::string out = "'";
  out += OneLine(s);
  out += "'";
  return out;
}

std::string FiniteNumbers(int n) {
  return std::to_string(n) + (n == 1 ? " finite number" : " finite numbers");
}

std::string FormatNumber(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace vivp::scene::detail
