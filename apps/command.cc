#include "apps/command.h"

#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

namespace vivp::apps {

nlohmann::json JsonNumber(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

void WriteJson(const std::string& target, const nlohmann::json& j, int indent) {
  if (target == "-") {
    std::cout << j.dump(indent) << "\n";
    return;
  }
  std::ofstream f(target);
  f << j.dump(indent) << "\n";
  if (!f) throw std::runtime_error("cannot write " + target);
}

namespace fs = std::filesystem;

void CheckOutputDirectory(const fs::path& dir, bool force) {
  if (force || !fs::exists(dir)) return;
  if (!fs::is_directory(dir))
    throw UsageError("output path " + dir.string() +
                     " exists and is not a directory; choose another path");
  if (!fs::is_empty(dir))
    throw UsageError("output directory " + dir.string() +
                     " is not empty; choose another directory or pass --force "
                     "to overwrite its files");
}

void CheckOutputFile(const fs::path& file, bool force) {
  if (!force && fs::exists(file))
    throw UsageError("output file " + file.string() +
                     " exists; choose another name or pass --force to "
                     "overwrite it");
}

fs::path MakeStagingDirectory(const fs::path& out) {
  const fs::path parent = out.has_parent_path() ? out.parent_path() : ".";
  fs::create_directories(parent);
  const fs::path staging = parent / ("." + out.filename().string() +
                                     ".partial-" + std::to_string(getpid()));
  fs::remove_all(staging);
  fs::create_directories(staging);
  return staging;
}

void MoveInto(const fs::path& staging, const fs::path& out) {
  fs::create_directories(out);
  for (const auto& entry : fs::directory_iterator(staging))
    fs::rename(entry.path(), out / entry.path().filename());
}

CLI::Validator FiniteNumber() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (s.empty() || end != s.c_str() + s.size())
          return "expected a finite number, got '" + s + "'";
        if (!std::isfinite(v)) return "must be finite, got '" + s + "'";
        return {};
      },
      "FINITE", "FiniteNumber");
}

CLI::Validator WholeNumberAtLeast(long long minimum, const std::string& hint) {
  return CLI::Validator(
      [minimum, hint](std::string& s) -> std::string {
        long long v = 0;
        const auto [ptr, ec] =
            std::from_chars(s.data(), s.data() + s.size(), v);
        if (ec != std::errc() || ptr != s.data() + s.size())
          return "expected a whole number " + hint + ", got '" + s + "'";
        if (v < minimum) return "must be " + hint + ", got " + s;
        return {};
      },
      "INT", "WholeNumberAtLeast");
}

}  // namespace vivp::apps
