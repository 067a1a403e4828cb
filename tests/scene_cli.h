// What the scene CLI tests share: scene files written into a scratch
// directory and run with `vivp run`, and the check of a refusal (exit 2,
// one line naming the problem, nothing written).
#pragma once

#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/cli_run.h"

namespace vivp::testing {

struct SceneScratch : ScratchDirectory {
  explicit SceneScratch(const std::string& prefix) : ScratchDirectory(prefix) {}
  // Writes `text` to NAME.toml and runs it into NAME.out.
  CliRun RunScene(const std::string& name, const std::string& text,
                  const std::string& flags = "") const {
    std::ofstream(dir / (name + ".toml")) << text;
    return RunVivp("run --quiet " + (dir / (name + ".toml")).string() +
                   " --out " + (dir / (name + ".out")).string() + flags);
  }
  // Nothing of a refused run: no output directory, no staging directory.
  bool Clean(const std::string& name) const {
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().filename().string().find("partial") != std::string::npos)
        return false;
    return !std::filesystem::exists(dir / (name + ".out"));
  }
};

// A refusal: exit 2, one line on stderr that contains every piece.
inline void Refused(const CliRun& r, const std::vector<std::string>& pieces) {
  BOOST_TEST(r.status == 2, r.err);
  BOOST_TEST(Lines(r.err) == 1, r.err);
  for (const auto& p : pieces)
    BOOST_TEST(r.err.find(p) != std::string::npos,
               "'" << p << "' in " << r.err);
}

}  // namespace vivp::testing
