// Honest failure from the command line: every way a run can fail to produce
// a trustworthy result ends with exit status 1 and one line on stderr that
// names what went wrong, where (the time) and the residual left; a scene
// still writes its summary with the failure; a plot that cannot be drawn is
// a warning, not an exit. A request that cannot run at all is refused before
// any work, with exit status 2 and one sentence.
#define BOOST_TEST_MODULE failure_cli
#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli_run.h"

namespace fs = std::filesystem;

namespace {

using Run = vivp::testing::CliRun;
using vivp::testing::Lines;

struct Scratch {
  fs::path dir = fs::temp_directory_path() /
                 ("vivp_failure_cli_" + std::to_string(getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() { fs::remove_all(dir); }
};

Run Vivp(const std::string& args) { return vivp::testing::RunVivp(args); }

nlohmann::json Summary(const fs::path& out) {
  std::ifstream in(out / "summary.json");
  return nlohmann::json::parse(in);
}

// Kepler e = 0.9 from pericentre for ten orbits, with the given method lines.
std::string Kepler09(const std::string& time, const std::string& method) {
  return "[system]\ndof = 2\n"
         "[[effect]]\ntype = \"kinetic\"\n"
         "[[effect]]\ntype = \"central\"\n"
         "[initial]\nx = [0.1, 0.0]\nv = [0.0, 4.358898943540674]\n"
         "[time]\nend = 62.83185307179586\n" +
         time + "[method]\nkind = \"variational\"\n" + method +
         "[output]\ndiagnostics = [\"energy\"]\n";
}

// The stderr line that carries the failure.
std::string FailureLine(const Run& r) {
  const std::string key = "vivp: the solve did not converge: ";
  const auto at = r.err.find(key);
  if (at == std::string::npos) return "";
  return r.err.substr(at, r.err.find('\n', at) - at);
}

}  // namespace

BOOST_AUTO_TEST_CASE(UniformGridTooCoarse_FailsTheCheckAndKeepsItsSummary) {
  // Kepler e = 0.9 on a uniform grid of 4001 points, SBP42: each window
  // converges, but the first deviates by 19 % from an independent
  // integration of the Euler–Lagrange equations (the old march returned it
  // as converged, with an end error of 5.7).
  Scratch s;
  const fs::path scene = s.dir / "k.toml";
  std::ofstream(scene) << Kepler09("points = 4001\n",
                                   "operator = \"sbp42\"\nslab_points = 48\n");
  const fs::path out = s.dir / "k";
  const Run r =
      Vivp("run --quiet " + scene.string() + " --out " + out.string());
  BOOST_TEST(r.status == 1, r.err);
  const std::string line = FailureLine(r);
  BOOST_TEST(line.find("window [0, 0.738274] was solved but rejected: "
                       "under-resolved") != std::string::npos,
             r.err);
  BOOST_TEST(line.find("18.9 % of the solution's size") != std::string::npos);
  BOOST_TEST(line.find("use more points, or a tolerance") != std::string::npos);
  BOOST_TEST(line.find("last residual") != std::string::npos);
  const auto j = Summary(out);
  BOOST_TEST(!j["status"]["converged"].get<bool>());
  BOOST_TEST(j["solver"]["failed_at"].get<double>() == 0.0);
  BOOST_TEST(
      j["status"]["message"].get<std::string>() ==
      line.substr(std::string("vivp: the solve did not converge: ").size()));
  // No nodes: no plots, said once as a warning, not as gnuplot's errors.
  BOOST_TEST(r.err.find("warning: no plots") != std::string::npos);
  BOOST_TEST(r.err.find("pclose") == std::string::npos);
  BOOST_TEST(Lines(r.err) == 2, r.err);
}

BOOST_AUTO_TEST_CASE(ToleranceBelowRoundOff_IsReportedWithItsTime) {
  // SBP84 cannot bring the velocity of a window's last node below ≈1e-10
  // near pericentre in double precision: 1e-12 is refused at the first
  // windows, with the step, the estimate and its round-off level.
  Scratch s;
  const fs::path scene = s.dir / "tight.toml";
  std::ofstream(scene) << Kepler09("",
                                   "operator = \"sbp84\"\ntolerance = 1e-12\n");
  const fs::path out = s.dir / "tight";
  const Run r =
      Vivp("run --quiet " + scene.string() + " --out " + out.string());
  BOOST_TEST(r.status == 1, r.err);
  const std::string line = FailureLine(r);
  BOOST_TEST(
      line.find("the tolerance cannot be met at t = ") != std::string::npos,
      r.err);
  BOOST_TEST(line.find("below the round-off of the window's velocity "
                       "estimate") != std::string::npos);
  BOOST_TEST(line.find("use a larger tolerance") != std::string::npos);
  const auto j = Summary(out);
  BOOST_TEST(!j["status"]["converged"].get<bool>());
  BOOST_TEST(j["solver"]["failed_at"].get<double>() >= 0.0);
  BOOST_TEST(j["solver"]["tolerance"]["relative"].get<double>() == 1e-12);
}

BOOST_AUTO_TEST_CASE(CollisionOrbit_NaNNeverLeavesAWindow) {
  // Radial infall onto the Kepler centre: x(0) = (1, 0) at rest reaches
  // r = 0 at t = π/(2√2) ≈ 1.11, where the equations of motion blow up. The
  // window that meets the singularity fails with the predictor's non-finite
  // state, nothing non-finite is handed on or written, and the run says
  // where.
  Scratch s;
  const fs::path scene = s.dir / "fall.toml";
  std::ofstream(scene) << "[system]\ndof = 2\n"
                          "[[effect]]\ntype = \"kinetic\"\n"
                          "[[effect]]\ntype = \"central\"\n"
                          "[initial]\nx = [1.0, 0.0]\nv = [0.0, 0.0]\n"
                          "[time]\nend = 3.0\npoints = 3001\n"
                          "[method]\nkind = \"variational\"\n"
                          "slab_points = 48\n";
  const fs::path out = s.dir / "fall";
  const Run r =
      Vivp("run --quiet " + scene.string() + " --out " + out.string());
  BOOST_TEST(r.status == 1, r.err);
  const std::string line = FailureLine(r);
  BOOST_TEST(line.find("window [") != std::string::npos, r.err);
  BOOST_TEST((line.find("non-finite") != std::string::npos ||
              line.find("under-resolved") != std::string::npos),
             line);
  const auto j = Summary(out);
  const double at = j["solver"]["failed_at"].get<double>();
  BOOST_TEST(at > 0.5);
  BOOST_TEST(at < 1.12);
  std::ifstream csv(out / "trajectory.csv");
  std::string row;
  std::getline(csv, row);  // header
  while (std::getline(csv, row)) {
    BOOST_TEST(row.find("nan") == std::string::npos, row);
    BOOST_TEST(row.find("inf") == std::string::npos, row);
  }
}

BOOST_AUTO_TEST_CASE(GlobalNewtonThatDiverges_IsARowNotAnAbort) {
  // One global solve of the anharmonic oscillator over [0, 10] does not
  // converge from the linear initial guess: its row says why, the other row
  // is measured, the study ends with exit status 1 and one line.
  const Run r = Vivp(
      "converge --problem anharmonic --t-end 10 --points 512,4096 "
      "--slab-points 0");
  BOOST_TEST(r.status == 1, r.err);
  BOOST_TEST(r.out.find("NOT CONVERGED:") != std::string::npos, r.out);
  BOOST_TEST(r.err == "vivp: some solves did not converge (see the table)\n");
}

BOOST_AUTO_TEST_CASE(ToleranceStudy_UnreachableRowIsReported) {
  // A study over tolerances keeps the rows it could compute.
  const Run r = Vivp(
      "converge --problem kepler_e09 --operator sbp84 --t-end "
      "6.283185307179586 "
      "--tolerance 1e-6,1e-13");
  BOOST_TEST(r.status == 1, r.err);
  BOOST_TEST(r.out.find("NOT CONVERGED: the tolerance cannot be met at t = ") !=
                 std::string::npos,
             r.out);
  BOOST_TEST(r.err == "vivp: some runs did not converge (see the table)\n");
}

BOOST_AUTO_TEST_CASE(PlotThatCannotBeDrawn_IsAWarning) {
  // gnuplot replaced by a program that fails: the run still succeeds, its
  // data and scripts are written, and each missing PNG is one warning line
  // quoting gnuplot.
  Scratch s;
  const fs::path bin = s.dir / "bin";
  fs::create_directories(bin);
  {
    std::ofstream g(bin / "gnuplot");
    g << "#!/bin/sh\ncat > /dev/null\necho 'broken gnuplot' >&2\nexit 1\n";
  }
  fs::permissions(bin / "gnuplot", fs::perms::owner_all);
  const fs::path out = s.dir / "default";
  const Run r =
      vivp::testing::RunCommand("PATH=" + bin.string() + ":$PATH " + VIVP_EXE,
                                "run --quiet --out " + out.string());
  BOOST_TEST(r.status == 0, r.err);
  BOOST_TEST(r.err.find("vivp: warning: gnuplot did not draw trajectory.png "
                        "(gnuplot: broken gnuplot)") != std::string::npos,
             r.err);
  BOOST_TEST(Lines(r.err) == 3, r.err);  // trajectory, energy, error
  BOOST_TEST(fs::exists(out / "trajectory.csv"));
  BOOST_TEST(fs::exists(out / "trajectory.gp"));
  BOOST_TEST(!fs::exists(out / "trajectory.png"));
  const auto j = Summary(out);
  BOOST_TEST(j["status"]["converged"].get<bool>());
  BOOST_TEST(j["warnings"].size() == 3u);
}

BOOST_AUTO_TEST_CASE(ImpossibleCombinations_OneSentenceInTheCommandLineWords) {
  // Not a failure of a run but of the request: refused before any work with
  // exit status 2 and one sentence, the solver layer's refusal
  // (solver_choice.h) in the command line's words.
  auto refusal = [](const std::string& args) {
    const Run r = Vivp("converge --problem anharmonic " + args);
    BOOST_TEST(r.status == 2, args);
    BOOST_TEST(r.out.empty(), r.out);
    return r.err;
  };
  BOOST_TEST(refusal("--slab-points 4") ==
             "vivp: error: --slab-points 4 is below the minimum of sbp42 (8); "
             "expected --slab-points >= 8, or 0 for one global solve\n");
  BOOST_TEST(refusal("--tolerance 1e-6 --slab-points 0") ==
             "vivp: error: --tolerance marches in windows, but --slab-points "
             "0 asks for one global solve; expected --slab-points >= 8 or no "
             "--slab-points (24)\n");
  BOOST_TEST(refusal("--solver ceres-lm --extended-residual") ==
             "vivp: error: --extended-residual evaluates reduced Newton's "
             "residual in long double, which --solver ceres-lm does not use; "
             "expected --solver newton, or no --extended-residual\n");
  BOOST_TEST(refusal("--solver ceres-lm --operator sbp84 --tolerance 1e-6") ==
             "vivp: error: --solver ceres-lm has no default window for "
             "--operator sbp84: Levenberg-Marquardt loses Newton's accuracy "
             "in every window measured (its normal equations square a "
             "condition number near 1e9); expected --slab-points to march "
             "anyway (0: one global solve), or --solver newton\n");
}
