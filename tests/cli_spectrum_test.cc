// `vivp spectrum` end to end: bad input exits with status 2 and one line that
// names the problem and the valid values; good input writes what it promises.
#define BOOST_TEST_MODULE cli_spectrum
#include <sys/wait.h>

#include <array>
#include <boost/test/unit_test.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli_run.h"

namespace fs = std::filesystem;

namespace {

struct Run {
  int status;
  std::string output;  // stdout and stderr together
};

Run Vivp(const std::string& args) {
  const auto r = vivp::testing::RunVivp(args);
  return {r.status, r.out + r.err};
}

using vivp::testing::Lines;

fs::path TempDir(const std::string& name) {
  fs::path p = fs::temp_directory_path() /
               ("vivp_cli_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(p);
  return p;
}

}  // namespace

BOOST_AUTO_TEST_CASE(BadInput_ExitsTwoWithOneLineNamingValidValues) {
  struct Case {
    std::string args;
    std::string expected;
  };
  const Case cases[] = {
      {"spectrum --operator sbp99 --points 32",
       "vivp: error: --operator: sbp99 not in {sbp21,sbp42,sbp63,sbp84} (see "
       "'vivp --help')"},
      {"spectrum --operator sbp42 --points 5",
       "vivp: error: sbp42 needs at least 8 points, got 5"},
      {"spectrum --operator sbp21 --points=-4",
       "vivp: error: --points: must be >= 1 (time points; the operator's "
       "minimum: sbp21 2, sbp42 8, sbp63 12, sbp84 16), got -4 (see 'vivp "
       "--help')"},
      {"spectrum --operator sbp21 --points abc",
       "vivp: error: --points: expected a whole number >= 1 (time points; the "
       "operator's minimum: sbp21 2, sbp42 8, sbp63 12, sbp84 16), got 'abc' "
       "(see 'vivp --help')"},
      {"spectrum --operator sbp21 --points 32 --sigma0 nan",
       "vivp: error: --sigma0: must be finite, got 'nan' (see 'vivp --help')"},
      {"spectrum --operator sbp21 --points 32 --sigma0 inf",
       "vivp: error: --sigma0: must be finite, got 'inf' (see 'vivp --help')"},
      {"spectrum --operator sbp21 --points 32 --sigma0 x",
       "vivp: error: --sigma0: expected a finite number, got 'x' (see 'vivp "
       "--help')"},
  };
  for (const Case& c : cases) {
    const Run r = Vivp(c.args);
    BOOST_TEST_CONTEXT(c.args) {
      BOOST_TEST(r.status == 2);
      BOOST_TEST(Lines(r.output) == 1);
      BOOST_TEST(r.output == c.expected + "\n");
    }
  }
}

BOOST_AUTO_TEST_CASE(Json_HasTheDocumentedKeys) {
  const fs::path dir = TempDir("json");
  fs::create_directories(dir);
  const fs::path file = dir / "s.json";
  const Run r =
      Vivp("spectrum --operator sbp21 --points 32 --json " + file.string());
  BOOST_TEST(r.status == 0, r.output);
  std::ifstream in(file);
  const auto j = nlohmann::json::parse(in);
  BOOST_TEST(j.at("operator") == "sbp21");
  BOOST_TEST(j.at("points") == 32);
  BOOST_TEST(j.at("D").at("eigenvalues").size() == 32u);
  BOOST_TEST(j.at("D").at("zero_modes") == 2);
  BOOST_TEST(j.at("D").at("geometric_multiplicity") == 1);
  BOOST_TEST(j.at("D").at("right_null_vector").size() == 32u);
  BOOST_TEST(j.at("D").at("left_null_vector").size() == 32u);
  BOOST_TEST(j.at("Dbar").at("eigenvalues").size() == 33u);
  BOOST_TEST(j.at("Dbar").at("zero_modes") == 0);
  BOOST_TEST(j.at("Dbar").at("min_abs_eigenvalue").get<double>() > 0.99);
  BOOST_TEST(j.at("Dbar").at("min_real_part").get<double>() > 0.0);
  BOOST_TEST(j.at("Dbar").at("real_eigenvalues").size() == 1u);

  // An existing file is not overwritten without --force.
  const Run again = Vivp("spectrum --points 32 --json " + file.string());
  BOOST_TEST(again.status == 2);
  BOOST_TEST(again.output.find("exists; choose another name or pass --force") !=
             std::string::npos);
  BOOST_TEST(
      Vivp("spectrum --points 32 --force --json " + file.string()).status == 0);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(Plot_WritesPngDataAndScript_AndRefusesNonEmptyDir) {
  const fs::path dir = TempDir("plot");
  const Run r =
      Vivp("spectrum --operator sbp42 --points 16 --plot " + dir.string());
  BOOST_TEST(r.status == 0, r.output);
  for (const char* f : {"fig03_null_vectors.png", "fig03_null_vectors.gp",
                        "fig03_null_vectors_left.dat", "fig04_spectrum.png",
                        "fig04_spectrum.gp", "fig04_spectrum_D.dat",
                        "fig04_spectrum_Dbar.dat"}) {
    BOOST_TEST(fs::exists(dir / f), f);
    if (fs::exists(dir / f)) BOOST_TEST(fs::file_size(dir / f) > 0u, f);
  }
  const Run again =
      Vivp("spectrum --operator sbp42 --points 16 --plot " + dir.string());
  BOOST_TEST(again.status == 2);
  BOOST_TEST(again.output.find("is not empty") != std::string::npos);
  fs::remove_all(dir);
}
