// README "Use vivp from your own project": examples/ is shown there
// verbatim. The program itself is built and run against an installed vivp
// by scripts/check-install.sh (.ci/run), outside this build.
#define BOOST_TEST_MODULE example_use_vivp
#include <boost/test/unit_test.hpp>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

namespace {

std::string Slurp(const std::string& path) {
  std::ifstream in(path);
  BOOST_REQUIRE_MESSAGE(in, "cannot read " << path);
  return std::string((std::istreambuf_iterator<char>(in)),
                     std::istreambuf_iterator<char>());
}

}  // namespace

BOOST_AUTO_TEST_CASE(Readme_ShowsTheExampleProjectVerbatim) {
  const std::string readme = Slurp(VIVP_SOURCE_DIR "/README.md");
  const std::pair<const char*, const char*> files[] = {
      {"/examples/CMakeLists.txt", "cmake"},
      {"/examples/exponential_wall.cc", "cpp"}};
  for (const auto& [file, language] : files) {
    const std::string code = Slurp(std::string(VIVP_SOURCE_DIR) + file);
    BOOST_TEST(readme.find("```" + std::string(language) + "\n" + code +
                           "```") != std::string::npos,
               "README does not show " << file << " verbatim");
  }
}
