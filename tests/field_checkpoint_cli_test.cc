// `vivp run --checkpoint/--stop-after/--resume` on a field scene end to end:
// a run stopped at a window boundary and resumed writes the slices of the
// uninterrupted run, bit for bit (17 digits in field.csv); every misuse —
// --stop-after alone, a checkpoint file that exists, a missing or foreign
// checkpoint, a scene without window boundaries or with error control, a
// point-mechanics scene — exits 2 with one line and overwrites nothing
// (docs/field_scenes.md §5).
#define BOOST_TEST_MODULE field_checkpoint_cli

#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/cli_run.h"

namespace fs = std::filesystem;

namespace {

using Run = vivp::testing::CliRun;
using vivp::testing::Lines;

struct Scratch : vivp::testing::ScratchDirectory {
  Scratch() : ScratchDirectory("vivp_field_checkpoint_cli_") {}
  fs::path Scene(const std::string& name, const std::string& text) const {
    std::ofstream(dir / (name + ".toml")) << text;
    return dir / (name + ".toml");
  }
  Run Vivp(const std::string& args) const {
    return vivp::testing::RunVivp("run --quiet " + args);
  }
  std::string At(const std::string& file) const {
    return (dir / file).string();
  }
};

std::vector<std::string> Rows(const fs::path& csv) {
  std::ifstream in(csv);
  std::vector<std::string> rows;
  for (std::string line; std::getline(in, line);) rows.push_back(line);
  return rows;
}

// The sine-Gordon breather on [−20, 20) periodic, 128 points, SBP42 in
// windows of 9 to t = 4 (65 points), every third slice written.
std::string Breather(const std::string& method = "window_points = 9\n",
                     const std::string& time = "points = 65\n") {
  return "[field]\ndomain = [-20.0, 20.0]\npoints = 128\n"
         "[[term]]\ntype = \"kinetic\"\n[[term]]\ntype = \"gradient\"\n"
         "[[term]]\ntype = \"sine_gordon\"\n[initial]\nprofile = "
         "\"breather\"\n[time]\nend = 4.0\n" +
         time + "[method]\noperator = \"sbp42\"\n" + method +
         "[output]\nstride = 3\ndiagnostics = [\"energy\"]\n";
}

void Refused(const Run& r, const std::vector<std::string>& pieces) {
  BOOST_TEST(r.status == 2, r.err);
  BOOST_TEST(Lines(r.err) == 1, r.err);
  for (const auto& p : pieces)
    BOOST_TEST(r.err.find(p) != std::string::npos,
               "'" << p << "' in " << r.err);
}

}  // namespace

BOOST_AUTO_TEST_CASE(StoppedAndResumed_WritesTheUninterruptedSlices) {
  Scratch s;
  const fs::path scene = s.Scene("breather", Breather());
  const Run full = s.Vivp(scene.string() + " --out " + s.At("full"));
  BOOST_TEST_REQUIRE(full.status == 0, full.err);
  // --stop-after 0: stop at the first window boundary.
  const Run stopped =
      s.Vivp(scene.string() + " --out " + s.At("first") + " --checkpoint " +
             s.At("c.h5") + " --checkpoint-every 0 --stop-after 0");
  BOOST_TEST_REQUIRE(stopped.status == 3, stopped.err);
  BOOST_TEST(stopped.err.find("vivp: stopped at t = 0.5 of 4 after 1 "
                              "windows") != std::string::npos,
             stopped.err);
  BOOST_TEST(!fs::exists(s.dir / "first"));
  BOOST_TEST(fs::exists(s.dir / "c.h5"));
  BOOST_TEST(!fs::exists(s.dir / "c.h5.tmp"));
  // Resumed, checkpointing into the same file, stopped again, resumed.
  const Run again =
      s.Vivp(scene.string() + " --out " + s.At("second") + " --resume " +
             s.At("c.h5") + " --checkpoint " + s.At("c.h5") +
             " --checkpoint-every 0 --stop-after 0");
  BOOST_TEST_REQUIRE(again.status == 3, again.err);
  BOOST_TEST(again.err.find("t = 1 of 4 after 2 windows") != std::string::npos,
             again.err);
  const Run last = s.Vivp(scene.string() + " --out " + s.At("last") +
                          " --resume " + s.At("c.h5"));
  BOOST_TEST_REQUIRE(last.status == 0, last.err);
  const auto rows = Rows(s.dir / "full" / "field.csv");
  const auto resumed = Rows(s.dir / "last" / "field.csv");
  // Nodes 18, 21, …, 63 (every third of the whole run, from the checkpoint
  // at node 16, t = 1, on) and the last, 64: 17 slices of 128 points.
  BOOST_TEST_REQUIRE(resumed.size() == 1 + 17 * 128u);
  BOOST_TEST(resumed.front() == rows.front());
  const std::vector<std::string> tail(rows.end() - (resumed.size() - 1),
                                      rows.end());
  BOOST_TEST(
      (tail == std::vector<std::string>(resumed.begin() + 1, resumed.end())));
  const auto j =
      nlohmann::json::parse(std::ifstream(s.dir / "last" / "summary.json"));
  BOOST_TEST(j["resumed_from"]["t"].get<double>() == 1.0);
  BOOST_TEST(j["resumed_from"]["windows"].get<int>() == 2);
}

BOOST_AUTO_TEST_CASE(Misuse_IsRefusedWithNothingOverwritten) {
  Scratch s;
  const std::string scene = s.Scene("breather", Breather()).string();
  Refused(s.Vivp(scene + " --out " + s.At("a") + " --stop-after 5"),
          {"--stop-after stops at a checkpoint; give --checkpoint FILE too"});
  std::ofstream(s.dir / "mine.h5") << "mine\n";
  Refused(s.Vivp(scene + " --out " + s.At("b") + " --checkpoint " +
                 s.At("mine.h5")),
          {"mine.h5 exists and is not overwritten", "--force"});
  std::ifstream kept(s.dir / "mine.h5");
  std::string line;
  std::getline(kept, line);
  BOOST_TEST(line == "mine");
  Refused(
      s.Vivp(scene + " --out " + s.At("c") + " --resume " + s.At("none.h5")),
      {"--resume: ", "none.h5: no such checkpoint file"});
  // A checkpoint of this scene does not resume one with other time points.
  BOOST_TEST_REQUIRE(s.Vivp(scene + " --out " + s.At("d") + " --checkpoint " +
                            s.At("c.h5") +
                            " --checkpoint-every 0 "
                            "--stop-after 0")
                         .status == 3);
  const std::string other =
      s.Scene("other", Breather("window_points = 9\n", "points = 129\n"))
          .string();
  Refused(s.Vivp(other + " --out " + s.At("e") + " --resume " + s.At("c.h5")),
          {"the checkpoint is of a run with time points 65, this one has 129",
           "resume with the run's own settings"});
  const std::string global =
      s.Scene("global", Breather("window_points = 0\n")).string();
  Refused(
      s.Vivp(global + " --out " + s.At("f") + " --checkpoint " + s.At("g.h5")),
      {"act at window boundaries", "window_points"});
  const std::string adaptive =
      s.Scene("adaptive", Breather("tolerance = 1e-6\n", "")).string();
  Refused(s.Vivp(adaptive + " --out " + s.At("h") + " --checkpoint " +
                 s.At("h.h5")),
          {"take uniform marches", "tolerance"});
  Refused(vivp::testing::RunVivp("run --quiet " VIVP_SCENES_DIR
                                 "/fig08_anharmonic.toml --out " +
                                 s.At("i") + " --checkpoint " + s.At("i.h5")),
          {"apply to field scenes"});
  for (const char* out : {"a", "b", "c", "e", "f", "h", "i"})
    BOOST_TEST(!fs::exists(s.dir / out), out);
}
