// `vivp run` on a field scene and `vivp converge --field` end to end, on
// tiny grids: the files and summary of a run; bad input exits 2 with one
// line naming the value's place and the fix, and leaves nothing behind;
// an existing directory is not overwritten without --force; the measured
// orders in Δt and Δx are the operators' (docs/field_scenes.md).
#define BOOST_TEST_MODULE field_cli
#include <unistd.h>

#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "tests/scene_cli.h"

namespace fs = std::filesystem;

namespace {

using Run = vivp::testing::CliRun;
using vivp::testing::Lines;
using vivp::testing::Refused;
using vivp::testing::Slurp;

struct Scratch : vivp::testing::SceneScratch {
  Scratch() : SceneScratch("vivp_field_cli_") {}
};

// Klein–Gordon (m = 1) on [0, L) periodic, 32 points, SBP42 to t = 1.
std::string KleinGordon(
    const std::string& length = "6.283185307179586",
    const std::string& initial = "profile = \"plane_wave\"\n",
    const std::string& space = "points = 32\n",
    const std::string& time = "points = 33\n", const std::string& output = "") {
  return "title = \"Klein-Gordon plane wave\"\n[field]\ndomain = [0.0, " +
         length + "]\n" + space +
         "[[term]]\ntype = \"kinetic\"\n[[term]]\ntype = \"gradient\"\n"
         "[[term]]\ntype = \"mass\"\n[initial]\n" +
         initial + "[time]\nend = 1.0\n" + time +
         "[method]\noperator = \"sbp42\"\nwindow_points = 9\n"
         "[output]\ndiagnostics = [\"energy\", \"error\"]\n" +
         output;
}

nlohmann::json Converge(const std::string& args) {
  const Run r = vivp::testing::RunVivp("converge --json - " + args);
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  return nlohmann::json::parse(r.out);
}

}  // namespace

BOOST_AUTO_TEST_CASE(Run_WritesTheFieldDiagnosticsPlotsAndSummary) {
  Scratch s;
  const Run r = s.RunScene("kg", KleinGordon());
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const fs::path out = s.dir / "kg.out";
  for (const char* f :
       {"field.csv", "diagnostics.csv", "summary.json", "field.png",
        "snapshots.png", "energy.png", "error.png"})
    BOOST_TEST(fs::exists(out / f), f);
  const auto j = nlohmann::json::parse(Slurp(out / "summary.json"));
  BOOST_TEST(j["status"]["converged"].get<bool>());
  BOOST_TEST(j["grid"]["time"]["windows"].get<int>() == 4);
  BOOST_TEST(j["resolution"]["omega_dt"].get<double>() <
             j["resolution"]["limit"].get<double>());
  BOOST_TEST(j["scene"]["field"]["space_order"].get<int>() == 8);
  // Measured: max error 3e-5, corrected end state 2e-7; energy 6.283.
  BOOST_TEST(j["diagnostics"]["error"]["max"].get<double>() < 1e-4);
  BOOST_TEST(j["diagnostics"]["error"]["end_state"].get<double>() < 1e-6);
  BOOST_TEST(j["diagnostics"]["energy"]["initial"].get<double>() ==
                 2 * std::numbers::pi,  // ½A²(ω² + k² + m²)·π, ω² = 2
             boost::test_tools::tolerance(1e-6));
  const std::string csv = Slurp(out / "field.csv");
  BOOST_TEST(csv.rfind("t,x,phi,phi_t\n", 0) == 0u);
  BOOST_TEST(std::count(csv.begin(), csv.end(), '\n') == 33 * 32 + 1);
  BOOST_TEST(r.out.find("Klein-Gordon plane wave") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(BinaryField_HasTheLayoutItsSummaryStates) {
  Scratch s;
  const Run r = s.RunScene(
      "bin", KleinGordon("6.283185307179586", "profile = \"plane_wave\"\n",
                         "points = 32\n", "points = 33\n",
                         "stride = 4\nformat = \"binary\"\n"));
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto j =
      nlohmann::json::parse(Slurp(s.dir / "bin.out" / "summary.json"));
  const auto& layout = j["layout"];
  BOOST_TEST(layout["file"].get<std::string>() == "field.bin");
  BOOST_TEST(layout["shape"] == nlohmann::json({9, 32, 2}));  // t = 0, …, 1
  BOOST_TEST(layout["t"].size() == 9u);
  BOOST_TEST(fs::file_size(s.dir / "bin.out" / "field.bin") ==
             std::uintmax_t(9 * 32 * 2 * 8));
}

BOOST_AUTO_TEST_CASE(NonPeriodicProfile_IsRefusedUnlessAllowed) {
  // cos x on [0, 6): the continuation jumps by |cos 6 − 1| = 0.0398.
  Scratch s;
  Refused(
      s.RunScene("jump", KleinGordon("6.0")),
      {"jump.toml:12:11: the profile 'plane_wave' is not periodic on [0, "
       "6)",
       "jumps by |φ(x_last + Δx) − φ(x0)| = 0.0398297", "allow_jump = true"});
  BOOST_TEST(s.Clean("jump"));
  const Run r = s.RunScene(
      "allowed",
      KleinGordon("6.0", "profile = \"plane_wave\"\nallow_jump = true\n"));
  BOOST_TEST(r.status == 0, r.err);
  BOOST_TEST(r.err.rfind("vivp: warning: ", 0) == 0u, r.err);
  BOOST_TEST(r.err.find("jumps by |φ(x_last + Δx) − φ(x0)| = 0.0398297") !=
             std::string::npos);
  BOOST_TEST(fs::exists(s.dir / "allowed.out" / "field.csv"));
}

BOOST_AUTO_TEST_CASE(BadGridsAndProfiles_AreRefusedWithNothingWritten) {
  Scratch s;
  Refused(s.RunScene("few",
                     KleinGordon("6.283185307179586",
                                 "profile = \"plane_wave\"\n", "points = 8\n")),
          {"few.toml:4:10: points = 8 is too few for the spatial operator; "
           "expected at least 9 for periodic differences of order 8"});
  // 64 points: ω_max = 17.6, Δt = 1/8.
  Refused(s.RunScene("coarse", KleinGordon("6.283185307179586",
                                           "profile = \"plane_wave\"\n",
                                           "points = 64\n", "points = 9\n")),
          {"coarse.toml:15:10: under-resolved: Δt·ω_max = 2.2",
           "use at least 19 time points"});
  Refused(s.RunScene("name", KleinGordon("6.283185307179586",
                                         "profile = \"plain_wave\"\n")),
          {"name.toml:12:11: 'plain_wave' is not a valid profile (did you mean "
           "'plane_wave'?); expected one of gaussian, kink, kink_antikink, "
           "breather, plane_wave, csv"});
  Refused(s.RunScene("nan", KleinGordon("6.283185307179586",
                                        "profile = \"plane_wave\"\n"
                                        "amplitude = nan\n")),
          {"nan.toml:13:13: 'amplitude' must be finite, got nan"});
  Refused(s.RunScene("mixed", KleinGordon() + "[system]\ndof = 1\n"),
          {"mixed.toml:21:1: the scene mixes [field] (a field) with [system]"});
  for (const char* name : {"few", "coarse", "name", "nan", "mixed"})
    BOOST_TEST(s.Clean(name), name);
}

BOOST_AUTO_TEST_CASE(CsvProfile_IsCheckedRowByRow) {
  Scratch s;
  const std::string scene = KleinGordon(
      "6.283185307179586", "profile = \"csv\"\nfile = \"samples.csv\"\n");
  auto samples = [&](int rows, int bad_row) {
    std::ofstream f(s.dir / "samples.csv");
    f << "phi,phi_t\n";
    for (int j = 0; j < rows; ++j)
      f << (j == bad_row
                ? "inf"
                : std::to_string(std::cos(2 * std::numbers::pi * j / 32)))
        << "," << std::sin(2 * std::numbers::pi * j / 32) * std::sqrt(2.0)
        << "\n";
  };
  samples(31, -1);
  const std::string path = (s.dir / "samples.csv").string();
  Refused(s.RunScene("short", scene),
          {"short.toml:13:8: the profile file '" + path +
           "' has 31 rows of samples; expected 32 rows φ, φ_t"});
  samples(32, 4);
  Refused(s.RunScene("inf", scene),
          {"'" + path + "' line 6: non-finite value 'inf' in column 1"});
  BOOST_TEST(s.Clean("short"));
  BOOST_TEST(s.Clean("inf"));
  // The plane wave's own samples: no exact solution to measure against,
  // and the run starts from them (E(0) = 2π).
  samples(32, -1);
  Refused(s.RunScene("exact", scene),
          {"diagnostic 'error' needs an exact solution: a CSV profile has no "
           "exact solution"});
  std::string energy_only = scene;
  energy_only.replace(energy_only.find("\"energy\", \"error\""), 17,
                      "\"energy\"");
  const Run r = s.RunScene("ok", energy_only);
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto j =
      nlohmann::json::parse(Slurp(s.dir / "ok.out" / "summary.json"));
  BOOST_TEST(j["diagnostics"]["energy"]["initial"].get<double>() ==
                 2 * std::numbers::pi,
             boost::test_tools::tolerance(1e-5));
}

BOOST_AUTO_TEST_CASE(ExistingOutput_IsNotOverwrittenWithoutForce) {
  Scratch s;
  fs::create_directories(s.dir / "kg.out");
  std::ofstream(s.dir / "kg.out" / "notes.txt") << "mine\n";
  Refused(s.RunScene("kg", KleinGordon()), {"is not empty", "--force"});
  BOOST_TEST(!fs::exists(s.dir / "kg.out" / "field.csv"));
  const Run r = s.RunScene("kg", KleinGordon(), " --force");
  BOOST_TEST(r.status == 0, r.err);
  BOOST_TEST(fs::exists(s.dir / "kg.out" / "field.csv"));
  BOOST_TEST(Slurp(s.dir / "kg.out" / "notes.txt") == "mine\n");
}

BOOST_AUTO_TEST_CASE(ConvergeField_MeasuresTheOrdersInTimeAndSpace) {
  // Klein–Gordon, order-8 differences on 16 and 32 points (the spatial
  // error below the temporal one). Measured: SBP21 2.00 both, SBP42 3.08
  // at the last node and 4.24 corrected (Δt = 1/(Nt − 1)).
  const auto a = Converge(
      "--field klein_gordon --operator sbp21 --points 17,33,65 "
      "--space-points 16");
  BOOST_TEST(a["rows"].size() == 3u);
  BOOST_TEST(a["rows"][0]["dt"].get<double>() == 1.0 / 17);
  BOOST_TEST(a["rows"][0]["dt_true"].get<double>() == 1.0 / 16);
  for (const char* k : {"x", "x_corrected"}) {
    BOOST_TEST(a["orders_true_dt"][k].get<double>() > 1.9, k);
    BOOST_TEST(a["orders_true_dt"][k].get<double>() < 2.1, k);
  }
  const auto b = Converge(
      "--field klein_gordon --operator sbp42 --points 17,33,65 "
      "--space-points 32 --slab-points 9");
  BOOST_TEST(b["orders_true_dt"]["x"].get<double>() > 2.8);
  BOOST_TEST(b["orders_true_dt"]["x"].get<double>() < 3.3);
  BOOST_TEST(b["orders_true_dt"]["x_corrected"].get<double>() > 3.8);
  BOOST_TEST(b["orders_true_dt"]["x_corrected"].get<double>() < 4.6);
  // Order-2 differences in Δx (measured 1.87 on 8, 12, 16 points).
  const auto c = Converge(
      "--field klein_gordon --operator sbp42 --points 65 --space-points "
      "8,12,16 --space-order 2");
  BOOST_TEST(c["study"].get<std::string>() == "space");
  BOOST_TEST(c["orders"]["x"].get<double>() > 1.7);
  BOOST_TEST(c["orders"]["x"].get<double>() < 2.2);
}

BOOST_AUTO_TEST_CASE(ConvergeField_RefusesBadOptionsByName) {
  Scratch s;
  const std::string json = (s.dir / "study.json").string();
  auto vivp = [&](const std::string& args) {
    return vivp::testing::RunVivp("converge --json " + json + " " + args);
  };
  Refused(vivp("--field nope"),
          {"unknown field problem 'nope'; valid field problems: "
           "klein_gordon, sine_gordon_breather, sine_gordon_kink"});
  Refused(vivp("--field klein_gordon --space-points 4"),
          {"--space-points: periodic differences of order 8 need at least 9 "
           "points; got 4"});
  Refused(vivp("--field klein_gordon --points 17,33 --space-points 8,16"),
          {"give one --points value"});
  Refused(vivp("--field klein_gordon --solver newton"),
          {"--solver applies to --problem (point mechanics)"});
  Refused(vivp("--field klein_gordon --space-order 5"),
          {"--space-order: expected 2, 4, 6 or 8, got 5"});
  BOOST_TEST(!fs::exists(json));
}

// A field scene under error control: `[method] tolerance` chooses the
// steps (no `[time] points`), and `linear_solver` picks the window's linear
// solve; both solves give the same field (the sparse LU is the reference).
BOOST_AUTO_TEST_CASE(Tolerance_ChoosesTheStepsWithEitherLinearSolver) {
  Scratch s;
  auto scene = [](const std::string& linear) {
    return KleinGordon("6.283185307179586", "profile = \"plane_wave\"\n",
                       "points = 32\n", "") +
           "[method]\ntolerance = 1e-6\nlinear_solver = \"" + linear + "\"\n";
  };
  // KleinGordon() already has a [method] table: merge the keys into it.
  auto merged = [&](const std::string& linear) {
    std::string t = scene(linear);
    const auto second = t.rfind("[method]\n");
    t.erase(second, std::string("[method]\n").size());
    const auto first = t.find("[method]\n") + std::string("[method]\n").size();
    const auto keys = t.substr(t.find("tolerance = "));
    t.erase(t.find("tolerance = "));
    return t.insert(first, keys);
  };
  nlohmann::json j[2];
  std::string csv[2];
  const char* solvers[2] = {"modes", "sparse-lu"};
  for (int i = 0; i < 2; ++i) {
    const Run r = s.RunScene(solvers[i], merged(solvers[i]));
    BOOST_TEST_REQUIRE(r.status == 0, r.err);
    BOOST_TEST(r.out.find("under error control") != std::string::npos);
    const fs::path out = s.dir / (std::string(solvers[i]) + ".out");
    j[i] = nlohmann::json::parse(Slurp(out / "summary.json"));
    csv[i] = Slurp(out / "field.csv");
    BOOST_TEST(j[i]["solver"]["linear_solver"].get<std::string>() ==
               solvers[i]);
    BOOST_TEST(j[i]["solver"]["unchecked"].get<std::string>().empty());
    // Measured: largest error of φ over the slices 1e-9 (the spatial error
    // of 32 points is 4e-7 in φ_t).
    BOOST_TEST(j[i]["diagnostics"]["error"]["max"].get<double>() < 1e-6);
  }
  BOOST_TEST(j[0]["solver"]["mode_factorizations"].get<long long>() > 0);
  BOOST_TEST(j[0]["grid"]["time"]["points"] == j[1]["grid"]["time"]["points"]);
  BOOST_TEST(j[0]["diagnostics"]["error"]["max"].get<double>() ==
                 j[1]["diagnostics"]["error"]["max"].get<double>(),
             boost::test_tools::tolerance(1e-6));
  BOOST_TEST(std::count(csv[0].begin(), csv[0].end(), '\n') ==
             std::count(csv[1].begin(), csv[1].end(), '\n'));
  // A tolerance with a step count, a global solve, or an unknown linear
  // solver: refused by name, nothing written.
  const std::string with_points = KleinGordon() + "";
  std::string bad = with_points;
  bad.insert(bad.find("window_points"), "tolerance = 1e-6\n");
  Refused(s.RunScene("both", bad), {"tolerance", "points"});
  BOOST_TEST(s.Clean("both"));
  std::string global = merged("modes");
  global.replace(global.find("window_points = 9"), 17, "window_points = 0");
  Refused(s.RunScene("global", global), {"window_points = 0", "tolerance"});
  BOOST_TEST(s.Clean("global"));
  std::string solver = merged("gmres");
  Refused(s.RunScene("gmres", solver), {"linear_solver", "modes", "sparse-lu"});
  BOOST_TEST(s.Clean("gmres"));
  std::string negative = merged("modes");
  negative.replace(negative.find("tolerance = 1e-6"), 16, "tolerance = -1e-6");
  Refused(s.RunScene("negative", negative), {"tolerance"});
  BOOST_TEST(s.Clean("negative"));
}

// `vivp converge --field … --tolerance`: one march per tolerance, each row
// converged, the errors tracking the tolerance.
BOOST_AUTO_TEST_CASE(ConvergeField_TracksTheTolerance) {
  const auto j = Converge(
      "--field klein_gordon --operator sbp63 --tolerance 1e-4,1e-6,1e-8");
  BOOST_TEST(j["study"].get<std::string>() == "tolerance");
  BOOST_TEST_REQUIRE(j["rows"].size() == 3u);
  for (const auto& r : j["rows"]) {
    BOOST_TEST(r["converged"].get<bool>());
    // Measured: 0.09, 0.02, 0.06 of the tolerance.
    BOOST_TEST(r["max_error_v"].get<double>() <= r["tolerance"].get<double>());
  }
  BOOST_TEST(j["rows"][2]["points"].get<long long>() >
             j["rows"][0]["points"].get<long long>());
  // Measured slope 1.04.
  BOOST_TEST(j["tracking_max_v"]["slope"].get<double>() > 0.7);
  BOOST_TEST(j["tracking_max_v"]["slope"].get<double>() < 1.5);
}
