// README "Use vivp from your own project": examples/ is shown there
// verbatim. The program itself is built and run against an installed vivp
// by scripts/check-install.sh (.ci/run), outside this build.
#define BOOST_TEST_MODULE example_use_vivp
#include <boost/test/unit_test.hpp>
#include <string>
#include <utility>

#include "tests/readme_quote.h"

BOOST_AUTO_TEST_CASE(Readme_ShowsTheExampleProjectVerbatim) {
  const std::pair<const char*, const char*> files[] = {
      {"/examples/CMakeLists.txt", "cmake"},
      {"/examples/exponential_wall.cc", "cpp"}};
  for (const auto& [file, language] : files)
    BOOST_TEST(
        readme_quote::ReadmeShows(
            readme_quote::Slurp(std::string(VIVP_SOURCE_DIR) + file), language),
        "README does not show " << file << " verbatim");
}
