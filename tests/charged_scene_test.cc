// `vivp run` on a scene with charged matter ('maxwell' + 'scalar_qed'), end
// to end on a small line: the pair converges, the action's Gauss law holds
// at every slice to round-off and is reported in summary.json beside the
// textbook law, the total charge stays at round-off, |φ| and E are drawn;
// a coupling that changes in time keeps the law; bad input exits 2 with
// one line and writes nothing.
#define BOOST_TEST_MODULE charged_scene
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/scene_cli.h"

namespace fs = std::filesystem;
using vivp::testing::Refused;
using vivp::testing::Slurp;

namespace {

// The pair on [0, 24) with 48 points, SBP42 in windows of 16 to t = 3
// (Δt = 0.1, Δt·ω_max = 0.42); each argument replaces a part.
std::string Pair(const std::string& field = "points = 48\n",
                 const std::string& terms =
                     "[[term]]\ntype = \"maxwell\"\n[[term]]\ntype "
                     "= \"scalar_qed\"\ncharge = 0.7\nmass = 1.0\n",
                 const std::string& initial = "center = 8.5\n",
                 const std::string& time = "end = 3.0\npoints = 31\n",
                 const std::string& method = "window_points = 16\n",
                 const std::string& output =
                     "diagnostics = [\"energy\", \"charge\", "
                     "\"gauss\", \"gauss_textbook\"]\n") {
  return "[field]\ndomain = [0.0, 24.0]\n" + field + terms +
         "[initial]\nprofile = \"charge_pair\"\n" + initial + "[time]\n" +
         time + "[method]\noperator = \"sbp42\"\n" + method + "[output]\n" +
         output;
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_charged_pair_runs_and_reports_gauss_law) {
  const vivp::testing::SceneScratch s("vivp_charged_scene_");
  const auto r = s.RunScene("pair", Pair());
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const fs::path out = s.dir / "pair.out";
  const auto j = nlohmann::json::parse(Slurp(out / "summary.json"));
  const double gauss = j["gauss_residual"].get<double>();
  const double textbook = j["gauss_textbook"].get<double>();
  const auto& d = j["diagnostics"];
  const double charge = d["charge"]["max_change"].get<double>();
  const double energy = d["energy"]["relative_drift"].get<double>();
  BOOST_TEST_MESSAGE("Gauss of the action "
                     << gauss << ", textbook " << textbook << ", charge change "
                     << charge << ", energy drift " << energy);
  BOOST_TEST(j["solver"]["linear_solver"].get<std::string>() ==
             "normal-equations");
  BOOST_TEST(j["solver"]["windows"].get<int>() == 2);
  BOOST_TEST(gauss < 1e-12);
  // The textbook law is apart at O(Δt⁴) with Δt = 0.1: measured 0.004.
  BOOST_TEST(textbook > 1e-6);
  BOOST_TEST(textbook < 0.05);
  BOOST_TEST(d["gauss"]["max"].get<double>() == gauss);
  // The total charge of a neutral torus: round-off (measured 1.5e-15).
  BOOST_TEST(charge < 1e-12);
  // Node-wise energy at the interior rows of SBP42 and the corrected end
  // states: measured 2.2e-3 at Δt = 0.1.
  BOOST_TEST(energy < 0.01);
  for (const char* f : {"field.csv", "field.png", "field_1.png", "gauss.png",
                        "gauss_textbook.png", "diagnostics.csv"})
    BOOST_TEST(fs::exists(out / f), f);
  // The written values are the gauge-invariant ones.
  const std::string csv = Slurp(out / "field.csv");
  BOOST_TEST(csv.rfind("t,x,abs_phi,E_x,rho\n", 0) == 0);
}

// e(t) = 0.7(1 + 0.3 sin 2t) inside the action: the law still holds.
BOOST_AUTO_TEST_CASE(a_coupling_that_changes_in_time_keeps_gauss_law) {
  const vivp::testing::SceneScratch s("vivp_charged_scene_");
  const auto r = s.RunScene(
      "running", Pair("points = 48\n",
                      "[[term]]\ntype = \"maxwell\"\n[[term]]\ntype = "
                      "\"scalar_qed\"\ncharge = 0.7\nmass = 1.0\n"
                      "modulation = 0.3\nfrequency = 2.0\n"));
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto j =
      nlohmann::json::parse(Slurp(s.dir / "running.out" / "summary.json"));
  const double gauss = j["gauss_residual"].get<double>();
  BOOST_TEST_MESSAGE("e(t): Gauss of the action " << gauss);
  BOOST_TEST(gauss < 1e-12);
}

BOOST_AUTO_TEST_CASE(bad_input_is_refused) {
  const vivp::testing::SceneScratch s("vivp_charged_scene_");
  const std::string maxwell = "[[term]]\ntype = \"maxwell\"\n";
  const std::string qed = "[[term]]\ntype = \"scalar_qed\"\ncharge = 0.7\n";
  const std::string higgs = "[[term]]\ntype = \"abelian_higgs\"\n";
  // A gauge term without the charged field it needs, and the reverse.
  Refused(s.RunScene("higgs_alone", Pair("points = 48\n", maxwell + higgs)),
          {"abelian_higgs", "scalar_qed"});
  Refused(s.RunScene("no_maxwell", Pair("points = 48\n", qed)),
          {"scalar_qed", "maxwell"});
  Refused(s.RunScene("kinetic",
                     Pair("points = 48\n",
                          maxwell + qed + "[[term]]\ntype = \"kinetic\"\n")),
          {"kinetic", "scalar_qed"});
  // Boundary data would break gauge invariance.
  Refused(s.RunScene("interval", Pair("points = 48\nboundary = \"natural\"\n",
                                      maxwell + qed)),
          {"periodic", "gauge invariance"});
  // Couplings that are not finite or vanish.
  Refused(s.RunScene("nan", Pair("points = 48\n",
                                 maxwell + "[[term]]\ntype = "
                                           "\"scalar_qed\"\ncharge = nan\n")),
          {"charge"});
  Refused(s.RunScene("inf", Pair("points = 48\n",
                                 maxwell + "[[term]]\ntype = "
                                           "\"scalar_qed\"\ncharge = inf\n")),
          {"charge"});
  Refused(s.RunScene("vanishing", Pair("points = 48\n",
                                       maxwell + qed + "modulation = 1.0\n")),
          {"modulation", "not finite"});
  // A net charge on the torus: the second packet's mirror point is off
  // the grid when the first sits at half a step from x0.
  Refused(s.RunScene("charged", Pair("points = 48\n", maxwell + qed,
                                     "center = 0.25\nallow_jump = true\n")),
          {"total charge", "neutral"});
  Refused(
      s.RunScene("windows", Pair("points = 48\n", maxwell + qed,
                                 "center = 8.5\n", "end = 3.0\npoints = 30\n")),
      {"whole windows", "31"});
  Refused(s.RunScene("global",
                     Pair("points = 48\n", maxwell + qed, "center = 8.5\n",
                          "end = 3.0\npoints = "
                          "31\n",
                          "window_points = 0\n")),
          {"window_points = 0", "marches"});
  Refused(s.RunScene("tolerance",
                     Pair("points = 48\n", maxwell + qed, "center = 8.5\n",
                          "end = 3.0\npoints = 31\n", "tolerance = 1e-6\n")),
          {"error control", "charged"});
  Refused(s.RunScene("coarse",
                     Pair("points = 48\n", maxwell + qed, "center = 8.5\n",
                          "end = 6.0\npoints = "
                          "16\n")),
          {"under-resolved", "time points"});
  Refused(s.RunScene("order",
                     Pair("points = 48\nspace_order = 4\n", maxwell + qed)),
          {"space_order", "links"});
  Refused(s.RunScene("unstable", Pair("points = 48\n",
                                      maxwell + qed + higgs + "v = 2.0\n")),
          {"V'(0)", "vacuum"});
  for (const char* name :
       {"higgs_alone", "no_maxwell", "kinetic", "interval", "nan", "inf",
        "vanishing", "charged", "windows", "global", "tolerance", "coarse",
        "order", "unstable"})
    BOOST_TEST(s.Clean(name), name);
}

namespace {

// A vortex and an antivortex on 24² points of [−6, 6)², SBP21 in one
// window of 8 at Δt = 0.1; each argument replaces a part.
std::string Vortices(
    const std::string& field = "points = 24\n",
    const std::string& terms =
        "[[term]]\ntype = \"maxwell\"\n[[term]]\ntype = \"scalar_qed\"\n"
        "[[term]]\ntype = \"abelian_higgs\"\n",
    const std::string& initial = "profile = \"vortex_pair\"\n") {
  return "[field]\ndomain = [[-6.0, 6.0], [-6.0, 6.0]]\n" + field + terms +
         "[initial]\n" + initial +
         "[time]\nend = 0.7\npoints = 8\n[method]\noperator = \"sbp21\"\n"
         "window_points = 8\n[output]\ndiagnostics = [\"energy\", "
         "\"gauss\"]\nanimation = false\nheat_maps = [0.7]\n";
}

}  // namespace

// At critical coupling a vortex and an antivortex far apart stay where
// they are, and the action's Gauss law holds.
BOOST_AUTO_TEST_CASE(a_vortex_pair_stays_and_is_tracked) {
  const vivp::testing::SceneScratch s("vivp_charged_scene_");
  const auto r = s.RunScene("pair2", Vortices());
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const fs::path out = s.dir / "pair2.out";
  const auto j = nlohmann::json::parse(Slurp(out / "summary.json"));
  const double gauss = j["gauss_residual"].get<double>();
  const double energy =
      j["diagnostics"]["energy"]["relative_drift"].get<double>();
  BOOST_TEST_MESSAGE("vortex pair: Gauss of the action "
                     << gauss << ", energy drift " << energy);
  BOOST_TEST(gauss < 1e-12);
  // A static solution: the energy moves by round-off (measured 1e-14).
  BOOST_TEST(energy < 1e-10);
  for (const char* f : {"field.h5", "vortices.csv", "tracks.png",
                        "heat_map_0.png", "heat_map_0_E.png"})
    BOOST_TEST(fs::exists(out / f), f);
  // Two zeros of φ at every one of the 8 slices, windings +1 and −1.
  const std::string csv = Slurp(out / "vortices.csv");
  BOOST_TEST(std::count(csv.begin(), csv.end(), '\n') == 1 + 2 * 8);
  BOOST_TEST(csv.find(",-1\n") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(bad_vortex_input_is_refused) {
  const vivp::testing::SceneScratch s("vivp_charged_scene_");
  Refused(s.RunScene("oblong", Vortices("points = [24, 20]\n")),
          {"square torus", "24 × 20"});
  Refused(s.RunScene("no_higgs",
                     Vortices("points = 24\n",
                              "[[term]]\ntype = \"maxwell\"\n[[term]]\ntype "
                              "= \"scalar_qed\"\n")),
          {"abelian_higgs", "vacuum"});
  // Two spacings apart, the pair annihilates while it relaxes.
  Refused(s.RunScene("close", Vortices("points = 24\n",
                                       "[[term]]\ntype = \"maxwell\"\n[[term]]"
                                       "\ntype = \"scalar_qed\"\n[[term]]\n"
                                       "type = \"abelian_higgs\"\n",
                                       "profile = \"vortex_pair\"\n"
                                       "separation = 1.0\n")),
          {"moved a vortex", "farther apart"});
  Refused(s.RunScene("three",
                     "[field]\ndomain = [[0.0, 8.0], [0.0, 8.0], [0.0, "
                     "8.0]]\npoints = 10\n[[term]]\ntype = \"maxwell\"\n"
                     "[[term]]\ntype = \"scalar_qed\"\n[initial]\nprofile = "
                     "\"plane_wave\"\n[time]\nend = 1.0\npoints = 8\n"),
          {"1 or 2 axes"});
  for (const char* name : {"oblong", "no_higgs", "close", "three"})
    BOOST_TEST(s.Clean(name), name);
}
