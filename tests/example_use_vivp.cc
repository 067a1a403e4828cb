// examples/ is shown verbatim: its CMakeLists.txt in the README ("Use vivp
// from your own project"), its program in docs/own_project.md. The program
// itself is built and run against an installed vivp by
// scripts/check-install.sh (.ci/run), outside this build.
#define BOOST_TEST_MODULE example_use_vivp
#include <boost/test/unit_test.hpp>
#include <string>
#include <tuple>

#include "tests/readme_quote.h"

BOOST_AUTO_TEST_CASE(Docs_ShowTheExampleProjectVerbatim) {
  // file, language, the document that shows it
  const std::tuple<const char*, const char*, const char*> files[] = {
      {"/examples/CMakeLists.txt", "cmake", "README.md"},
      {"/examples/exponential_wall.cc", "cpp", "docs/own_project.md"}};
  for (const auto& [file, language, doc] : files)
    BOOST_TEST(
        readme_quote::DocShows(
            doc, readme_quote::Slurp(std::string(VIVP_SOURCE_DIR) + file),
            language),
        doc << " does not show " << file << " verbatim");
}
