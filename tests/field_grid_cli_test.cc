// `vivp run` on field scenes of 2 and 3 axes end to end, on small grids:
// per-axis lists are read, the slices go to field.h5 (readable by h5dump),
// heat maps and field.gif are drawn, the error against an exact plane wave
// is that of the 1+1-dimensional scenes, and every bad value of a grid
// scene — axes of different counts, an empty or inconsistent domain, a
// non-finite value, a face or format the grid does not offer, an output
// directory that exists — exits 2 with one line, nothing written
// (docs/field_scenes.md).
#define BOOST_TEST_MODULE field_grid_cli

#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "tests/scene_cli.h"

namespace fs = std::filesystem;

namespace {

using Run = vivp::testing::CliRun;
using vivp::testing::Lines;
using vivp::testing::Refused;
using vivp::testing::Slurp;

struct Scratch : vivp::testing::SceneScratch {
  Scratch() : SceneScratch("vivp_field_grid_cli_") {}
};

// Klein–Gordon (m = 1) on the periodic square [0, 2π)², a plane wave along
// k, SBP42 to t = 1 in windows of 9; `field` replaces the [field] table's
// lines after domain, `initial` the profile's keys, `output` is appended.
std::string Plane(const std::string& field = "points = [16, 16]\n",
                  const std::string& initial = "k = [1.0, 2.0]\n",
                  const std::string& output = "",
                  const std::string& domain =
                      "[[0.0, 6.283185307179586], [0.0, 6.283185307179586]]") {
  return "[field]\ndomain = " + domain + "\n" + field +
         "[[term]]\ntype = \"kinetic\"\n[[term]]\ntype = \"gradient\"\n"
         "[[term]]\ntype = \"mass\"\n[initial]\nprofile = \"plane_wave\"\n" +
         initial +
         "[time]\nend = 1.0\npoints = 33\n[method]\noperator = \"sbp42\"\n"
         "window_points = 9\n[output]\n"
         "diagnostics = [\"energy\", \"momentum\", \"error\"]\n" +
         output;
}

}  // namespace

BOOST_AUTO_TEST_CASE(PlaneWave_WritesHdf5HeatMapsAndGif) {
  Scratch s;
  const Run r =
      s.RunScene("pw", Plane("points = [16, 16]\n", "k = [1.0, 2.0]\n",
                             "spectra = [0.0, 1.0]\n"));
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const fs::path out = s.dir / "pw.out";
  for (const char* f :
       {"field.h5", "diagnostics.csv", "summary.json", "heat_map_0.png",
        "heat_map_1.png", "heat_map_2.png", "field.gif", "energy.png",
        "momentum_x.png", "momentum_y.png", "error.png", "spectrum.csv",
        "spectrum.png"})
    BOOST_TEST(fs::exists(out / f), f);
  BOOST_TEST(!fs::exists(out / "field.csv"));
  const auto j = nlohmann::json::parse(Slurp(out / "summary.json"));
  BOOST_TEST(j["layout"]["shape"] == nlohmann::json({33, 16, 16, 1}));
  BOOST_TEST(j["scene"]["field"]["axes"].size() == 2u);
  BOOST_TEST(j["grid"]["space"]["points"].get<int>() == 256);
  BOOST_TEST(j["pictures"]["heat_maps"].size() == 3u);
  BOOST_TEST(j["pictures"]["heat_maps"][1]["t"].get<double>() == 0.5);
  // Measured: max error 1.3e-3 (16 points per axis, order-8 differences,
  // |k| = √5), corrected end state below it; the energy, 118.42, changes by
  // 0.020 (1.7e-4 of itself, the time discretization's at Δt = 1/32)
  // before the last slice, whose φ_t is the closure row.
  BOOST_TEST(j["diagnostics"]["error"]["max"].get<double>() < 3e-3);
  BOOST_TEST(j["diagnostics"]["error"]["end_state"].get<double>() <
             j["diagnostics"]["error"]["max"].get<double>());
  // The wave's power A²/2 sits in the bin of |k| = √5 (bins of width 1 about
  // 0, 1, 2, …), and the spectra add up to the mean square (Parseval).
  BOOST_TEST(j["spectra"].size() == 2u);
  BOOST_TEST(j["spectra"][0]["parseval_error"].get<double>() < 1e-12);
  BOOST_TEST(j["spectra"][0]["mean_square"].get<double>() == 0.5,
             boost::test_tools::tolerance(1e-14));
  BOOST_TEST(Slurp(out / "spectrum.csv").find("\n0,2,0.499999999999999") !=
             std::string::npos);
  const double e0 = j["diagnostics"]["energy"]["initial"].get<double>();
  BOOST_TEST(j["diagnostics"]["energy"]["max_change_interior"].get<double>() <
             3e-4 * e0);
  // P_y = 2 P_x for a wave along (1, 2), up to the differences' error: at 16
  // points D_y resolves k_y = 2 less well than D_x resolves k_x = 1
  // (measured: 2e-4 apart).
  BOOST_TEST(j["diagnostics"]["momentum_y"]["initial"].get<double>() ==
                 2 * j["diagnostics"]["momentum_x"]["initial"].get<double>(),
             boost::test_tools::tolerance(1e-3));
  const Run dump =
      vivp::testing::RunCommand("h5dump", "-H " + (out / "field.h5").string());
  BOOST_TEST_REQUIRE(dump.status == 0, dump.err);
  BOOST_TEST(dump.out.find("DATASET \"phi\"") != std::string::npos);
  BOOST_TEST(dump.out.find("( 33, 16, 16, 1 )") != std::string::npos, dump.out);
}

BOOST_AUTO_TEST_CASE(ThreeAxesAndFaces_Run) {
  Scratch s;
  // A plane wave in 3+1 D, drawn in its middle z-plane.
  const Run r3 = s.RunScene(
      "cube",
      Plane("points = 10\nspace_order = 4\n", "k = [1.0, 0.0, 1.0]\n",
            "heat_maps = [1.0]\nanimation = false\n",
            "[[0.0, 6.283185307179586], [0.0, 6.283185307179586], [0.0, "
            "6.283185307179586]]"));
  BOOST_TEST_REQUIRE(r3.status == 0, r3.err);
  const auto j = nlohmann::json::parse(Slurp(s.dir / "cube.out/summary.json"));
  BOOST_TEST(j["layout"]["shape"] == nlohmann::json({33, 10, 10, 10, 1}));
  BOOST_TEST(fs::exists(s.dir / "cube.out/heat_map_0.png"));
  BOOST_TEST(!fs::exists(s.dir / "cube.out/field.gif"));
  // Neumann faces on y with a slope the wave does not have: the faces' flux
  // changes the energy, which the march keeps to its time discretization's
  // error when they are natural (zero flux; a wave along x has ∂_yφ = 0).
  auto energy_change = [&](const std::string& name, const std::string& bc) {
    const Run r = s.RunScene(
        name, Plane("points = [16, 17]\nboundary = [\"periodic\", " + bc +
                        "]\nspace_order = 8\nspace_operator = \"sbp42\"\n",
                    "k = [1.0, 0.0]\n"));
    BOOST_TEST_REQUIRE(r.status == 0, r.err);
    const auto k =
        nlohmann::json::parse(Slurp(s.dir / (name + ".out/summary.json")));
    return k["diagnostics"]["energy"]["max_change_interior"].get<double>();
  };
  const double natural = energy_change("natural", "\"natural\"");
  const double slope = energy_change(
      "neumann", "\"neumann\"]\nboundary_values = [[0, 0], [0.1, 0.1]");
  // Measured: 7.8e-4 (of E ≈ 39.5, the time discretization's) with natural
  // faces, 0.106 with the slopes.
  BOOST_TEST(natural < 2e-3);
  BOOST_TEST(slope > 50 * natural);
}

BOOST_AUTO_TEST_CASE(BadGridInput_IsRefusedWithNothingWritten) {
  Scratch s;
  Refused(s.RunScene("count", Plane("points = [16, 16, 16]\n")),
          {"count.toml:3:10: 'points' has 3 entries but the domain has 2 axes",
           "expected one entry per axis"});
  Refused(s.RunScene("empty", Plane("points = 16\n", "k = [1.0, 2.0]\n", "",
                                    "[[0.0, 6.0], [2.0, 1.0]]")),
          {"empty.toml:2:23: domain = [2, 1] is empty",
           "expected domain = [x0, x1]"});
  Refused(s.RunScene("four", Plane("points = 16\n", "k = [1.0, 2.0]\n", "",
                                   "[[0, 1], [0, 1], [0, 1], [0, 1]]")),
          {"four.toml:2:10: domain has 4 axes", "expected 1, 2 or 3 axes"});
  Refused(s.RunScene("nan", Plane("points = 16\n", "k = [1.0, nan]\n")),
          {"nan.toml:12:11: 'k' must be finite, got nan"});
  Refused(s.RunScene("inf", Plane("points = 16\n", "k = [1.0, 2.0]\n", "",
                                  "[[0.0, 6.0], [0.0, inf]]")),
          {"inf.toml:2:", "'domain' must be finite"});
  Refused(s.RunScene("jump", Plane("points = 16\n", "k = [1.0, 1.5]\n")),
          {"is not periodic on axis y [0, 6.28319)", "allow_jump = true"});
  Refused(
      s.RunScene("dirichlet",
                 Plane("points = 16\nboundary = [\"periodic\", \"dirichlet\"]\n"
                       "space_operator = \"sbp42\"\n")),
      {"dirichlet faces of axis 1 (y) are not offered on grids of 2 or 3 axes",
       "expected \"natural\" or \"neumann\""});
  Refused(s.RunScene("csv", Plane("points = 16\n", "k = [1.0, 2.0]\n",
                                  "format = \"csv\"\n")),
          {"format = 'csv' is for one axis", "expected format = \"hdf5\""});
  Refused(
      s.RunScene("spectra", Plane("points = 16\nboundary = [\"periodic\", "
                                  "\"natural\"]\nspace_operator = \"sbp42\"\n",
                                  "k = [1.0, 0.0]\n", "spectra = [0.5]\n")),
      {"'spectra' needs periodic axes; axis y is natural"});
  Refused(s.RunScene("late", Plane("points = 16\n", "k = [1.0, 2.0]\n",
                                   "heat_maps = [0.5, 2.0]\n")),
          {"heat map time 2 is outside the run; expected heat_maps = [t, …]"});
  std::string breather = Plane();
  breather.replace(breather.find("plane_wave"), 10, "breather");
  Refused(s.RunScene("profile", breather),
          {"'breather' is not a valid profile",
           "expected one of gaussian, ring, oscillon, plane_wave"});
  for (const char* name : {"count", "empty", "four", "nan", "inf", "jump",
                           "dirichlet", "csv", "late", "profile", "spectra"})
    BOOST_TEST(s.Clean(name), name);
  // An output directory that holds a file: refused, the file kept.
  fs::create_directories(s.dir / "kept.out");
  std::ofstream(s.dir / "kept.out" / "field.h5") << "mine\n";
  Refused(s.RunScene("kept", Plane()), {"is not empty", "--force"});
  BOOST_TEST(Slurp(s.dir / "kept.out" / "field.h5") == "mine\n");
}

BOOST_AUTO_TEST_CASE(ShippedPlaneWaveScene_DrawsItsSlices) {
  Scratch s;
  const Run r = vivp::testing::RunVivp("run --quiet " VIVP_SCENES_DIR
                                       "/field2d_plane_wave.toml --out " +
                                       (s.dir / "shipped").string());
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  for (const char* f : {"field.h5", "heat_map_0.png", "field.gif"})
    BOOST_TEST(fs::exists(s.dir / "shipped" / f), f);
  const auto j =
      nlohmann::json::parse(Slurp(s.dir / "shipped" / "summary.json"));
  // Measured: 3.0e-5 over one period, 3.0e-6 at the corrected end state.
  BOOST_TEST(j["diagnostics"]["error"]["max"].get<double>() < 1e-4);
  const Run check = vivp::testing::RunVivp("scene check " VIVP_SCENES_DIR
                                           "/field2d_ring_soliton.toml");
  BOOST_TEST(check.status == 0, check.err);
  BOOST_TEST(check.out.find("97 × 97 points") != std::string::npos, check.out);
}

// `vivp converge --field` on a grid: refining one axis with the other
// fine, the fitted order in its Δx is the differences' 2q (measured 3.82
// for order 4 and 8.04 for order 8 along y); a grid of the wrong number of
// axes is refused by name. Under AddressSanitizer the command line runs
// unoptimized and the two studies took 84 s; the order-8 differences are
// the same code with a longer stencil, so the sanitizer build runs the
// order-4 study only (VIVP_SANITIZED, tests/CMakeLists.txt).
BOOST_AUTO_TEST_CASE(ConvergeField_MeasuresTheOrderPerAxis) {
  std::vector<std::tuple<const char*, const char*, double>> studies = {
      {"4", "64x8,64x16,64x32", 3.5}};
#if !defined(VIVP_SANITIZED)
  studies.emplace_back("8", "64x12,64x16,64x24,64x32", 7.5);
#endif
  for (const auto& [order, grids, lowest] : studies) {
    const Run r = vivp::testing::RunVivp(
        std::string("converge --json - --field klein_gordon_2d --points 257 "
                    "--slab-points 16 --space-order ") +
        order + " --space-points " + grids);
    BOOST_TEST_REQUIRE(r.status == 0, r.err);
    const auto j = nlohmann::json::parse(r.out);
    BOOST_TEST(j["study"].get<std::string>() == "space");
    BOOST_TEST(j["refined_axis"].get<int>() == 1);
    // x stays at 64 points while y is refined.
    BOOST_TEST(j["rows"][0]["axis_points"][0].get<int>() == 64);
    BOOST_TEST(j["rows"].back()["axis_points"] == nlohmann::json({64, 32}));
    BOOST_TEST(j["orders"]["x"].get<double>() > lowest, order);
  }
  const Run bad = vivp::testing::RunVivp(
      "converge --field klein_gordon_2d --points 257 --space-points 16x16x16");
  Refused(bad, {"--space-points: expected a comma-separated list of grids N "
                "or NXxNY (one number per axis)"});
}

// format = "hdf5" on one axis: field.h5 of shape slices × N × components
// instead of field.csv, the 1+1-dimensional plots as before.
BOOST_AUTO_TEST_CASE(OneAxis_WritesHdf5WhenAsked) {
  Scratch s;
  const Run r = s.RunScene(
      "line", Plane("points = 32\n", "k = 1.0\n", "format = \"hdf5\"\n",
                    "[[0.0, 6.283185307179586]]"));
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const fs::path out = s.dir / "line.out";
  BOOST_TEST(fs::exists(out / "field.h5"));
  BOOST_TEST(fs::exists(out / "field.png"));  // the space-time heat map
  BOOST_TEST(!fs::exists(out / "field.csv"));
  const auto j = nlohmann::json::parse(Slurp(out / "summary.json"));
  BOOST_TEST(j["layout"]["shape"] == nlohmann::json({33, 32, 1}));
}
