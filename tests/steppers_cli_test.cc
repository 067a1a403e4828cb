// `vivp bench` end to end: bad input exits with status 2 and one line naming
// the valid values; a good run writes JSON rows with every measured field,
// the error falls with the step at the method's order, and an unstable
// configuration is a status in the rows, not a crash.
#define BOOST_TEST_MODULE steppers_cli
#include <sys/wait.h>

#include <array>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli_run.h"

namespace {

struct Run {
  int status;
  std::string output;
};

Run Vivp(const std::string& args, bool with_stderr = true) {
  const auto r = vivp::testing::RunVivp(args);
  return {r.status, with_stderr ? r.out + r.err : r.out};
}

using vivp::testing::Lines;

// A bench run that must succeed, its JSON rows parsed (--json - in args).
nlohmann::json BenchJson(const std::string& args) {
  const Run r = Vivp(args, false);
  BOOST_REQUIRE_MESSAGE(r.status == 0, args + ": " + r.output);
  return nlohmann::json::parse(r.output);
}

}  // namespace

BOOST_AUTO_TEST_CASE(BenchBadInput_ExitsTwoWithOneLineNamingValidValues) {
  struct Case {
    const char* args;
    const char* expect;
  };
  const Case cases[] = {
      {"bench --problem nope", "valid: harmonic, pendulum"},
      {"bench --problem kepler --methods rk4,foo", "valid: rk4, midpoint"},
      {"bench --problem nldnls --methods verlet", "valid: rk4, midpoint"},
      {"bench --problem kepler --steps -3", "positive"},
      {"bench --problem kepler --steps nan", "positive"},
      {"bench --problem kepler --steps 10.5 --methods rk4", "whole numbers"},
      {"bench --problem kepler --repeats 2", "at least 5"},
      {"bench --problem kepler --budget inf", "finite"},
      {"bench --problem kepler --rounds 0 --steps 64", "at least 1"},
      {"bench --problem kepler --rounds 3", "add --steps or drop --rounds"},
      {"bench --problem anharmonic --methods rk4 --slab-points 96",
       "none is selected"},
      {"bench --problem anharmonic --methods variational_sbp84_uniform "
       "--slab-points 10",
       "minimum window of sbp84 (16 points)"},
      {"bench --problem anharmonic --methods variational_sbp84_uniform "
       "--slab-points 1",
       "at least 2"},
  };
  for (const auto& c : cases) {
    const Run r = Vivp(c.args);
    BOOST_TEST_CONTEXT(c.args) {
      BOOST_TEST(r.status == 2);
      BOOST_TEST(Lines(r.output) == 1);
      BOOST_TEST(r.output.find(c.expect) != std::string::npos, r.output);
    }
  }
}

BOOST_AUTO_TEST_CASE(BenchJson_RowsCarryEveryMeasureAndFitTheOrder) {
  const auto j = BenchJson(
      "bench --problem pendulum --methods gauss2,odeint_dopri5 "
      "--steps 64,128,256 --json -");
  BOOST_TEST(j.at("problem") == "pendulum");
  BOOST_REQUIRE(j.at("rows").size() == 6u);
  for (const auto& row : j.at("rows")) {
    for (const char* key : {"method", "steps", "error", "energy_error",
                            "seconds", "evaluations", "iterations", "status"})
      BOOST_TEST(row.contains(key), key);
    BOOST_TEST(row.at("status") == "ok");
    // "seconds" (a measured wall time) is only required to be present
    // (above): timings belong to benchmark tables, not to pass/fail tests.
    BOOST_TEST(row.at("evaluations").get<long>() > 0);
  }
  // gauss2 at 64, 128, 256 steps over 10 periods: order 4 within ±0.15.
  const double e64 = j["rows"][0]["error"], e256 = j["rows"][2]["error"];
  BOOST_TEST(std::fabs(std::log2(e64 / e256) / 2 - 4) <= 0.15);
  BOOST_TEST(j["rows"][0]["iterations"].get<long>() > 0);
}

BOOST_AUTO_TEST_CASE(BenchUnstableConfiguration_IsAStatusNotACrash) {
  // RK4 on the harmonic oscillator at 3 steps for 10 periods: hω ≈ 21.
  const auto j = BenchJson(
      "bench --problem harmonic --methods rk4,midpoint --steps 3 --json -");
  BOOST_TEST(j["rows"][0]["status"] == "unstable");
  BOOST_TEST(j["rows"][0]["error"].is_null());
  BOOST_TEST(j["rows"][1]["status"] == "ok");
}

// --slab-points reaches the variational methods' marches: windows of 96
// instead of the default 48 change the discrete solution (another end
// error) and the evaluation count, and the JSON records the length.
BOOST_AUTO_TEST_CASE(BenchSlabPoints_SetsTheVariationalWindow) {
  const std::string run =
      "bench --problem anharmonic --methods variational_sbp84_uniform "
      "--steps 384 --json -";
  const auto a = BenchJson(run);
  const auto b = BenchJson(run + " --slab-points 96");
  BOOST_TEST(a.at("slab_points") == 0);
  BOOST_TEST(b.at("slab_points") == 96);
  const auto& ra = a.at("rows").at(0);
  const auto& rb = b.at("rows").at(0);
  BOOST_TEST(ra.at("status") == "ok");
  BOOST_TEST(rb.at("status") == "ok");
  // Both converge (SBP84 at 384 steps over 10 time units ends within 1e-3
  // of the exact solution; measured 3.8e-4 and 2.0e-4) to different
  // discrete solutions.
  BOOST_TEST(ra.at("error").get<double>() < 1e-3);
  BOOST_TEST(rb.at("error").get<double>() < 1e-3);
  BOOST_TEST(ra.at("error").get<double>() != rb.at("error").get<double>());
  BOOST_TEST(ra.at("evaluations").get<long>() !=
             rb.at("evaluations").get<long>());
}

// --rounds measures the same points in interleaved rounds: the rows are
// those of a plain run (order, errors, counts), only the times are medians
// of rounds, and the JSON records the rounds.
BOOST_AUTO_TEST_CASE(BenchRounds_KeepsTheRowsOfAPlainRun) {
  const std::string run =
      "bench --problem pendulum --methods gauss2,odeint_dopri5 "
      "--steps 64,128 --json -";
  const auto a = BenchJson(run);
  const auto b = BenchJson(run + " --rounds 3");
  BOOST_TEST(a.at("rounds") == 1);
  BOOST_TEST(b.at("rounds") == 3);
  BOOST_REQUIRE(a.at("rows").size() == 4u);
  BOOST_REQUIRE(b.at("rows").size() == 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    auto ra = a["rows"][i], rb = b["rows"][i];
    // The times are medians of different runs and are not compared:
    // timings belong to benchmark tables, not to pass/fail tests.
    ra.erase("seconds");
    rb.erase("seconds");
    BOOST_TEST(ra == rb, ra.dump() + " against " + rb.dump());
  }
}
