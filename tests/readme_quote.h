// The README and some pages of docs/ show sources verbatim (the examples
// they teach with); these tests read the source, cut out what the document
// quotes and look for it there as a fenced code block. Include after
// <boost/test/unit_test.hpp>.
#pragma once

#include <fstream>
#include <iterator>
#include <string>

namespace readme_quote {

inline std::string Slurp(const std::string& path) {
  std::ifstream in(path);
  BOOST_REQUIRE_MESSAGE(in, "cannot read " << path);
  return std::string((std::istreambuf_iterator<char>(in)),
                     std::istreambuf_iterator<char>());
}

// The text between the example markers of a source file.
inline std::string Example(const std::string& path) {
  const std::string s = Slurp(path);
  const std::string begin = "// --- example ---\n";
  const auto b = s.find(begin);
  const auto e = s.find("// --- end of example ---");
  BOOST_REQUIRE_MESSAGE(
      b != std::string::npos && e != std::string::npos && b < e,
      path << " has no example markers");
  return s.substr(b + begin.size(), e - b - begin.size());
}

// Whether the document `doc` (a path in the source tree, e.g.
// "docs/fields.md") holds `code` as a fenced block in `language`.
inline bool DocShows(const std::string& doc, const std::string& code,
                     const std::string& language = "cpp") {
  const std::string text = Slurp(std::string(VIVP_SOURCE_DIR "/") + doc);
  return text.find("```" + language + "\n" + code + "```") != std::string::npos;
}

// Whether README.md holds `code` as a fenced block in `language`.
inline bool ReadmeShows(const std::string& code,
                        const std::string& language = "cpp") {
  return DocShows("README.md", code, language);
}

}  // namespace readme_quote
