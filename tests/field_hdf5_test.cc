// Field data as HDF5 files (scene/field_hdf5.h): a march killed after a
// window, whose checkpoint file was written at every boundary, resumes from
// the file bit-identically; h5dump reads the checkpoint and the slices; a
// missing or foreign file and an existing slices file are refused.
#define BOOST_TEST_MODULE field_hdf5
#include "scene/field_hdf5.h"

#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "problems/fields/densities.h"
#include "solvers/spacetime/solve.h"

namespace {

using vivp::sbp::SpaceDerivative;
using Grid = vivp::sbp::SpaceGrid<double>;
namespace fs = std::filesystem;

struct Killed {};

fs::path Dir() {
  const fs::path d =
      fs::temp_directory_path() / ("vivp_hdf5_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

// h5dump's output for the file (its exit status in `status`).
std::string Dump(const fs::path& file, int& status) {
  const fs::path out = file.string() + ".dump";
  status = std::system(
      ("h5dump -H '" + file.string() + "' > '" + out.string() + "' 2>&1")
          .c_str());
  std::ifstream in(out);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_march_resumes_from_its_checkpoint_file) {
  const fs::path dir = Dir();
  const Grid g({SpaceDerivative<double>::Periodic(4, 16, -8.0, 16.0),
                SpaceDerivative<double>::Bounded("sbp42", 12, -5.0, 5.0)});
  std::vector<double> phi0(g.points()), pi0(g.points());
  for (int j = 0; j < g.points(); ++j) {
    const double x = g.x(j, 0), y = g.x(j, 1);
    phi0[j] = 3.0 * std::exp(-0.3 * (x * x + y * y));
    pi0[j] = 0.2 * std::cos(0.5 * x - 0.3 * y);
  }
  const vivp::fields::SineGordonIn<2> sg;
  const vivp::spacetime::FieldGrid fg{
      .op = "sbp42", .points = 65, .t_end = 2.0, .window_points = 9};
  const auto whole = vivp::spacetime::SolveField(sg, g, fg, phi0, pi0);
  BOOST_REQUIRE(whole.status.converged);
  const fs::path file = dir / "march.h5";
  vivp::spacetime::FieldSolveOptions o;
  o.on_checkpoint = [&](const vivp::spacetime::FieldCheckpoint& c) {
    vivp::scene::WriteCheckpoint(file.string(), c);
    if (c.node == 40) throw Killed{};
  };
  BOOST_CHECK_THROW(vivp::spacetime::SolveField(sg, g, fg, phi0, pi0, o),
                    Killed);
  BOOST_TEST(!fs::exists(file.string() + ".tmp"));
  const auto c = vivp::scene::ReadCheckpoint(file.string());
  BOOST_TEST(c.node == 40);
  vivp::spacetime::FieldSolveOptions r;
  r.resume = &c;
  const auto resumed = vivp::spacetime::SolveField(sg, g, fg, phi0, pi0, r);
  BOOST_REQUIRE(resumed.status.converged);
  long long differ = 0;
  const std::size_t n = g.points();
  for (std::size_t k = 0; k < resumed.phi.size(); ++k)
    differ += resumed.phi[k] != whole.phi[40 * n + k];
  for (std::size_t k = 0; k < n; ++k)
    differ += resumed.end.phi[k] != whole.end.phi[k];
  BOOST_TEST_MESSAGE("resumed from " << file << ": values that differ "
                                     << differ);
  BOOST_TEST(differ == 0);
  int status = 0;
  const std::string dump = Dump(file, status);
  BOOST_TEST(status == 0);
  for (const char* name : {"\"phi\"", "\"phi_t\"", "\"carry\"", "\"node\""})
    BOOST_TEST(dump.find(name) != std::string::npos, name);
  // The slices of the whole run, readable by h5dump; not overwritten.
  const fs::path slices = dir / "slices.h5";
  vivp::scene::WriteFieldSlices(slices.string(), g, 1, whole.t, whole.phi,
                                whole.phi_t);
  const std::string sd = Dump(slices, status);
  BOOST_TEST(status == 0);
  BOOST_TEST(sd.find("DATASPACE  SIMPLE { ( 65, 12, 16, 1 )") !=
             std::string::npos);
  BOOST_CHECK_THROW(vivp::scene::WriteFieldSlices(
                        slices.string(), g, 1, whole.t, whole.phi, whole.phi_t),
                    std::runtime_error);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_file_that_is_no_checkpoint_is_refused) {
  const fs::path dir = Dir();
  auto refused = [](const std::string& path) {
    try {
      vivp::scene::ReadCheckpoint(path);
    } catch (const std::runtime_error& e) {
      BOOST_TEST_MESSAGE(e.what());
      return std::string(e.what()).find(path) != std::string::npos;
    }
    return false;
  };
  BOOST_TEST(refused((dir / "missing.h5").string()));
  std::ofstream((dir / "text.h5").string()) << "not HDF5\n";
  BOOST_TEST(refused((dir / "text.h5").string()));
  // An HDF5 file of slices is not a checkpoint.
  const Grid g(SpaceDerivative<double>::Periodic(2, 4, 0.0, 1.0));
  vivp::scene::WriteFieldSlices((dir / "slices.h5").string(), g, 1, {0.0},
                                std::vector<double>(4, 0.0),
                                std::vector<double>(4, 0.0));
  BOOST_TEST(refused((dir / "slices.h5").string()));
  fs::remove_all(dir);
}
