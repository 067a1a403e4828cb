// How `vivp` subcommands plug into the command line.
//
// Each subcommand registers its options on a CLI11 subcommand and returns the
// function that runs it. Bad input is reported by throwing UsageError (exit
// status 2, one line); any other failure is a std::exception (exit status 1).
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace vivp::apps {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

using Runner = std::function<int()>;

Runner AddSpectrumCommand(CLI::App& app);
Runner AddConvergeCommand(CLI::App& app);
Runner AddBeaCommand(CLI::App& app);
Runner AddBenchCommand(CLI::App& app);
Runner AddRunCommand(CLI::App& app);
Runner AddSceneCommand(CLI::App& app);

// Refuses to write into an existing non-empty directory unless force is set,
// so nothing a user keeps there is overwritten without being asked.
void CheckOutputDirectory(const std::filesystem::path& dir, bool force);
// Same for a single output file.
void CheckOutputFile(const std::filesystem::path& file, bool force);
// An empty staging directory beside `out`, unique to this process: a run
// writes there and MoveInto moves its files into `out` once all are
// written, so a failure leaves nothing behind and a user's other files in
// `out` stay untouched.
std::filesystem::path MakeStagingDirectory(const std::filesystem::path& out);
void MoveInto(const std::filesystem::path& staging,
              const std::filesystem::path& out);
// Removes a staging directory when it goes out of scope (after MoveInto,
// an empty one).
struct StagingCleanup {
  std::filesystem::path dir;
  ~StagingCleanup() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

// A JSON number, or null for a non-finite value (a fitted order that does
// not exist, an error that overflowed): JSON has no NaN or infinity.
nlohmann::json JsonNumber(double v);

// Writes `j` (indented by `indent`) to standard output for target "-", else
// to the file `target`; a file that cannot be written is an error.
void WriteJson(const std::string& target, const nlohmann::json& j,
               int indent = 1);

// Splits a comma-separated option value such as "16,32,64" and converts each
// item with `item_of` (nullopt for an item it does not accept). A bad item or
// an empty list is a UsageError naming the flag, what it expects and an
// example, so every list option reads and fails the same way.
template <class T, class ItemOf>
std::vector<T> ParseList(const std::string& list, const std::string& flag,
                         const std::string& expected,
                         const std::string& example, ItemOf item_of) {
  std::vector<T> out;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const std::optional<T> v = item.empty() ? std::nullopt : item_of(item);
    if (!v)
      throw UsageError(flag + ": expected a comma-separated list of " +
                       expected + " such as " + example + ", got '" + list +
                       "'");
    out.push_back(*v);
  }
  if (out.empty())
    throw UsageError(flag + ": expected at least one value, such as " +
                     example);
  return out;
}

// CLI11 validators with messages that name the valid values.
CLI::Validator FiniteNumber();
CLI::Validator WholeNumberAtLeast(long long minimum, const std::string& hint);

}  // namespace vivp::apps
