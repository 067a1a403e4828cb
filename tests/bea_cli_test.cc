// `vivp bea` end to end: bad input exits with status 2 and one line naming
// the problem and the fix; derive prints the formulas; verify writes the
// promised JSON keys.
#define BOOST_TEST_MODULE bea_cli
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <boost/test/unit_test.hpp>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli_run.h"

namespace {

using Run = vivp::testing::CliRun;

Run Vivp(const std::string& args) { return vivp::testing::RunVivp(args); }

bool Contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

}  // namespace

BOOST_AUTO_TEST_CASE(BadInput_ExitsTwoWithOneLineNamingTheFix) {
  struct Case {
    std::string args, expected;
  };
  const Case cases[] = {
      {"bea derive --method lmm4 --matrix 1,2 --order 2", "a11,a12,a22"},
      {"bea derive --method sv --order 12 --dim 2", "reasonable time"},
      {"bea derive --method sv --order 3", "even"},
      {"bea derive --method rk4 --order 2", "use sv, lmm4 or midpoint"},
      {"bea verify --method lmm4 --dim 2 --steps 0.1", "numeric coefficients"},
      {"bea verify --method sv --steps 0.1,x", "comma-separated numbers"},
      {"bea verify --method sv --potential pendulum --steps -0.1 --t-end 10",
       "[1e-06, 0.5] for --t-end 10, got h = -0.1"},
      {"bea verify --method sv --potential pendulum --steps 0.1 --t-end -5",
       "the end time must be positive"},
  };
  for (const auto& c : cases) {
    const auto r = Vivp(c.args);
    BOOST_TEST(r.status == 2, c.args);
    BOOST_TEST(Contains(r.err, c.expected), c.args << " -> " << r.err);
    BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1, c.args);
  }
}

BOOST_AUTO_TEST_CASE(UnstableAlpha_WarnsWhy) {
  const auto r = Vivp("bea derive --method lmm4 --alpha 0.2 --order 2");
  BOOST_TEST(r.status == 0);
  BOOST_TEST(Contains(r.err, "warning: unstable"));
  BOOST_TEST(Contains(r.err, "alpha <= 0"));
  // verify would only measure the blow-up: refused, with the reason.
  const auto v = Vivp(
      "bea verify --method lmm4 --alpha 0.2 --dim 2 --steps 0.1,0.05 "
      "--t-end 150 --json -");
  BOOST_TEST(v.status == 2);
  BOOST_TEST(Contains(v.err,
                      "verify cannot measure conservation with an "
                      "unstable method: unstable"));
  BOOST_TEST(Contains(v.err, "alpha <= 0"));
  BOOST_TEST(std::count(v.err.begin(), v.err.end(), '\n') == 1);
  BOOST_TEST(v.out.empty());
}

BOOST_AUTO_TEST_CASE(DeriveStormerVerlet_PrintsHamiltonianAndPassedChecks) {
  const auto r = Vivp("bea derive --method sv --order 4 --w");
  BOOST_TEST(r.status == 0);
  // GiNaC orders terms by hash: check pieces, not the full line.
  BOOST_TEST(Contains(r.out, "H_mod = "));
  BOOST_TEST(Contains(r.out, "-1/24*W_1^2"));
  BOOST_TEST(!Contains(r.out, "FAILED"));
  BOOST_TEST(Contains(r.out, "check: the modified Lagrangian generates"));
}

BOOST_AUTO_TEST_CASE(VerifyLmm4_JsonHasRowsAndSlopes) {
  const auto r = Vivp(
      "bea verify --method lmm4 --alpha -0.2 --dim 2 --steps 0.2,0.1 "
      "--t-end 20 --json -");
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  BOOST_TEST(j["method"] == "lmm4");
  BOOST_TEST(j["rows"].size() == 2u);
  for (const char* key : {"h", "H0", "H2", "H4", "I0", "I2", "I4"})
    BOOST_TEST(j["rows"][0].contains(key), key);
  for (const char* key : {"H0", "H2", "H4", "I0", "I2", "I4"})
    BOOST_TEST(j["slopes"].contains(key), key);
}
