// `vivp run` and `vivp scene check` end to end: the default scene
// writes its files and a readable summary; an existing directory is not
// overwritten without --force; bad input exits 2 with one line and leaves no
// output behind; a solve that does not converge is reported, exit status 1.
#define BOOST_TEST_MODULE scene_cli
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <boost/test/unit_test.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli_run.h"

namespace fs = std::filesystem;

namespace {

using Run = vivp::testing::CliRun;

using vivp::testing::Slurp;

// A scratch directory of this test process, removed at the end.
struct Scratch {
  fs::path dir = fs::temp_directory_path() /
                 ("vivp_scene_cli_" + std::to_string(getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() { fs::remove_all(dir); }
};

Run Vivp(const std::string& args) { return vivp::testing::RunVivp(args); }

std::string Scene(const std::string& name) {
  return (fs::path(VIVP_SCENES_DIR) / name).string();
}

}  // namespace

BOOST_AUTO_TEST_CASE(DefaultScene_WritesItsFilesAndSummary) {
  Scratch s;
  const fs::path out = s.dir / "default";
  const Run r = Vivp("run --quiet --out " + out.string());
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  for (const char* f :
       {"trajectory.csv", "diagnostics.csv", "summary.json", "trajectory.png",
        "energy.png", "error.png", "trajectory.gp", "energy.gp"})
    BOOST_TEST(fs::file_size(out / f) > 0u, f);
  BOOST_TEST(r.out.find("Damped oscillator at late time") != std::string::npos);
  const auto j = nlohmann::json::parse(Slurp(out / "summary.json"));
  BOOST_TEST(j["status"]["converged"].get<bool>());
  BOOST_TEST(j["points"].get<int>() == 2048);
  BOOST_TEST(j["scene"]["method"]["operator"].get<std::string>() == "sbp42");
  BOOST_TEST(j["solver"]["iterations"].get<int>() == 1);  // linear: one step
  // Rothkopf & Nordström (2023), Figs. 14–15 (docs/method.md §11): bounded,
  // max path error ≈ 4e-3, energy 0.5 → 0.374 following the exact decay.
  BOOST_TEST(j["reference"]["max_error_x"].get<double>() <= 5e-3);
  BOOST_TEST(j["reference"]["max_error_x"].get<double>() > 1e-4);
  const auto& e = j["diagnostics"]["energy"];
  BOOST_TEST(e["initial"].get<double>() == 0.5,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(
      j["diagnostics"]["energy_reference"]["final"].get<double>() == 0.374,
      boost::test_tools::tolerance(0.001));
  // The energy column follows the exact decay: measured max deviation 7.8e-4
  // at every node before the last. The last node carries the boundary
  // closure of D in v = (Dx)_N (docs/method.md §11: the equation of motion
  // holds except at the last two nodes); there it is 4.4e-3.
  {
    std::istringstream in(Slurp(out / "diagnostics.csv"));
    std::string line;
    std::getline(in, line);
    BOOST_TEST_REQUIRE(line.rfind("t,energy,", 0) == 0u, line);
    std::vector<double> dev;
    while (std::getline(in, line)) {
      std::istringstream row(line);
      std::string cell;
      std::vector<double> v;
      while (std::getline(row, cell, ',')) v.push_back(std::stod(cell));
      BOOST_TEST_REQUIRE(v.size() ==
                         7u);  // t, E, x_ref, v_ref, E_ref, err x, err v
      dev.push_back(std::abs(v[1] - v[4]));
    }
    BOOST_TEST_REQUIRE(dev.size() == 2048u);
    BOOST_TEST(*std::max_element(dev.begin(), dev.end() - 1) <= 1e-3);
    BOOST_TEST(dev.back() <= 5e-3);
    BOOST_TEST(
        dev.back() ==
            std::abs(
                e["final"].get<double>() -
                j["diagnostics"]["energy_reference"]["final"].get<double>()),
        boost::test_tools::tolerance(1e-9));
  }
  // 2048 rows plus the header.
  const std::string csv = Slurp(out / "trajectory.csv");
  BOOST_TEST(std::count(csv.begin(), csv.end(), '\n') == 2049);
  BOOST_TEST(csv.rfind("t,x0,v0\n", 0) == 0u);
}

BOOST_AUTO_TEST_CASE(ExistingOutput_IsNotOverwrittenWithoutForce) {
  Scratch s;
  const fs::path out = s.dir / "keep";
  fs::create_directories(out);
  std::ofstream(out / "notes.txt") << "mine\n";
  const std::string args =
      "run --quiet " + Scene("fig05_freefall.toml") + " --out " + out.string();
  Run r = Vivp(args);
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.err == "vivp: error: output directory " + out.string() +
                          " is not empty; choose another directory or pass "
                          "--force to overwrite its files\n");
  BOOST_TEST(!fs::exists(out / "trajectory.csv"));
  r = Vivp(args + " --force");
  BOOST_TEST(r.status == 0, r.err);
  BOOST_TEST(fs::exists(out / "trajectory.csv"));
  BOOST_TEST(Slurp(out / "notes.txt") == "mine\n");  // other files untouched
}

BOOST_AUTO_TEST_CASE(BadScene_ExitsTwoWithOneLineAndLeavesNothingBehind) {
  Scratch s;
  const fs::path scene = s.dir / "bad.toml";
  std::ofstream(scene) << "[system]\ndof = 1\n[[effect]]\ntype = \"kinetc\"\n";
  const fs::path out = s.dir / "never";
  const Run r =
      Vivp("run --quiet " + scene.string() + " --out " + out.string());
  BOOST_TEST(r.status == 2);
  // The built-in effects, then the Lagrangians registered in lagrangians/
  // (none of the project's own are effects; one a user adds as the README
  // shows is listed after them, and must not fail this test).
  const std::string expected = scene.string() +
                               ":4:8: unknown effect type 'kinetc' (did you "
                               "mean 'kinetic'?); expected one of kinetic, "
                               "gravity, spring, quartic, pendulum, central, "
                               "gaussian_well, chain, damping, growth, "
                               "cyclotron";
  BOOST_TEST(r.err.substr(0, expected.size()) == expected);
  BOOST_TEST(
      std::regex_match(r.err.substr(std::min(expected.size(), r.err.size())),
                       std::regex("(, [a-z][a-z0-9_]*)*\n")),
      r.err);
  BOOST_TEST(!fs::exists(out));
  for (const auto& e : fs::directory_iterator(s.dir))
    BOOST_TEST(e.path().filename().string().find("partial") ==
               std::string::npos);
  const Run c = Vivp("scene check " + scene.string());
  BOOST_TEST(c.status == 2);
  BOOST_TEST(c.err == r.err);
}

BOOST_AUTO_TEST_CASE(SceneCheck_AcceptsEveryShippedScene) {
  Scratch s;
  int n = 0;
  for (const auto& e : fs::directory_iterator(VIVP_SCENES_DIR)) {
    const Run r = Vivp("scene check " + e.path().string());
    // A build with fewer VIVP_DIMS (the sanitizer build of .ci/run)
    // refuses the FPU chain's dof = 8 by name; nothing else may fail.
    if (r.status == 2 &&
        r.err.find("is not among the compiled sizes") != std::string::npos &&
        e.path().stem() == "fpu_chain")
      continue;
    BOOST_TEST(r.status == 0, e.path() << ": " << r.err);
    BOOST_TEST(r.out.find(": ok") != std::string::npos);
    ++n;
  }
  BOOST_TEST(n >= 9);
}

BOOST_AUTO_TEST_CASE(UnderResolvedSolve_IsReportedNotHidden) {
  // A stiff spring (ω = 100) on a grid with Δt·ω = 10: beyond SBP42's
  // stability limit, the global solve is reported as not converged (exit 1)
  // with the points it needs; the summary says so too.
  Scratch s;
  const fs::path scene = s.dir / "stiff.toml";
  std::ofstream(scene) << "[system]\ndof = 1\n"
                          "[[effect]]\ntype = \"kinetic\"\n"
                          "[[effect]]\ntype = \"spring\"\nk = 1e4\n"
                          "[initial]\nx = [1.0]\nv = [0.0]\n"
                          "[time]\nend = 10.0\npoints = 11\n";
  const fs::path out = s.dir / "stiff";
  const Run r =
      Vivp("run --quiet " + scene.string() + " --out " + out.string());
  BOOST_TEST(r.status == 1);
  BOOST_TEST(r.err.find("did not converge") != std::string::npos, r.err);
  const auto j = nlohmann::json::parse(Slurp(out / "summary.json"));
  BOOST_TEST(!j["status"]["converged"].get<bool>());
  BOOST_TEST(j["status"]["message"].get<std::string>().find("points") !=
             std::string::npos);
}
