// The field scene reader (scene/field_scene.h): a density composed of terms
// is the hand-written density of problems/fields/densities.h; the shipped
// field scenes read with their exact solutions and periodic profiles; the
// two kinds of scene are told apart; a profile is exact only for the terms
// it solves; the moving Gaussian's exact solution satisfies the natural
// boundary condition and the wave equation; boundary data at the ends.
#define BOOST_TEST_MODULE field_scene
#include "scene/field_scene.h"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#include "problems/fields/densities.h"
#include "problems/fields/profiles.h"
#include "problems/fields/terms.h"
#include "scene/field_run.h"

namespace fs = std::filesystem;
using namespace vivp;

namespace {

// The density at random (φ, φ_t, φ_x), composed and hand-written.
template <int M, class Hand>
double WorstDifference(const fields::ComposedDensity<M>& composed,
                       const Hand& hand) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2, 2);
  double worst = 0;
  for (int k = 0; k < 50; ++k) {
    double z[3 * M];
    for (double& v : z) v = u(rng);
    worst = std::max(worst, std::abs(composed(z, z + M, z + 2 * M) -
                                     hand(z, z + M, z + 2 * M)));
  }
  return worst;
}

scene::FieldScene Field(const std::string& text) {
  scene::AnyScene any = scene::ParseAnyScene(text, "f.toml");
  BOOST_TEST_REQUIRE(std::holds_alternative<scene::FieldScene>(any));
  return std::get<scene::FieldScene>(std::move(any));
}

std::string Error(const std::string& text) {
  try {
    (void)scene::ParseAnyScene(text, "f.toml");
  } catch (const scene::SceneError& e) {
    return e.what();
  }
  return "";
}

// A scene on [0, 2π) with the given terms, profile lines and output.
std::string Scene(const std::string& terms, const std::string& initial,
                  const std::string& output = "") {
  return "[field]\ndomain = [0.0, 6.283185307179586]\npoints = 32\n" + terms +
         "[initial]\n" + initial + "[time]\nend = 1.0\npoints = 33\n" +
         "[output]\n" + output;
}

const std::string kKleinGordon =
    "[[term]]\ntype = \"kinetic\"\n[[term]]\ntype = \"gradient\"\n"
    "[[term]]\ntype = \"mass\"\n";

}  // namespace

BOOST_AUTO_TEST_CASE(ComposedTerms_AreTheHandWrittenDensities) {
  namespace t = fields::terms;
  BOOST_TEST(WorstDifference(
                 fields::ComposedDensity<1>{
                     {t::Kinetic{}, t::Gradient{1.5}, t::Mass{0.7}}},
                 fields::KleinGordon{0.7, 1.5}) < 1e-14);
  BOOST_TEST(
      WorstDifference(fields::ComposedDensity<1>{{t::Kinetic{}, t::Gradient{},
                                                  t::SineGordon{}}},
                      fields::SineGordon{}) < 1e-14);
  BOOST_TEST(
      WorstDifference(fields::ComposedDensity<1>{{t::Kinetic{}, t::Gradient{},
                                                  t::Phi4{3.0, 0.5}}},
                      fields::Phi4{3.0, 0.5}) < 1e-14);
  BOOST_TEST(WorstDifference(
                 fields::ComposedDensity<2>{{t::Kinetic{}, t::Gradient{},
                                             t::Mass{0.8}, t::Quartic{2.0}}},
                 fields::ComplexPhi4{0.8, 2.0}) < 1e-13);
}

BOOST_AUTO_TEST_CASE(ShippedFieldScenes_ReadWithExactSolutions) {
  for (const char* name :
       {"field_sine_gordon_breather.toml", "field_kink_antikink.toml"}) {
    BOOST_TEST_CONTEXT(name) {
      const scene::AnyScene any =
          scene::ReadAnyScene(fs::path(VIVP_SCENES_DIR) / name);
      const auto& s = std::get<scene::FieldScene>(any);
      BOOST_TEST(s.space_points == 200);
      BOOST_TEST(s.boundary == "periodic");
      BOOST_TEST(s.method.window_points == 16);
      BOOST_TEST(bool(s.exact));
      BOOST_TEST(s.phi0.size() == 200u);
      BOOST_TEST(s.initial.jump < 1e-10);  // periodic to round-off
      // The initial data are the exact solution at t = 0.
      double phi = 0, phi_t = 0;
      const double x37 = s.Space().x(37);
      s.exact(0.0, &x37, &phi, &phi_t);
      BOOST_TEST(s.phi0[37] == phi);
      BOOST_TEST(s.phi_t0[37] == phi_t);
    }
  }
}

BOOST_AUTO_TEST_CASE(SceneKinds_AreToldApart) {
  const std::string field = Scene(kKleinGordon, "profile = \"plane_wave\"\n");
  BOOST_TEST(Field(field).components == 1);
  // The point-mechanics reader refuses a field scene by name.
  try {
    (void)scene::ParseScene(field, "f.toml");
    BOOST_ERROR("a field scene read as point mechanics");
  } catch (const scene::SceneError& e) {
    BOOST_TEST(std::string(e.what()).find("this is a field scene") !=
               std::string::npos);
  }
  const std::string mixed = field + "[system]\ndof = 1\n";
  BOOST_TEST(Error(mixed).find("f.toml:16:1: the scene mixes [field] (a field) "
                               "with [system] (point mechanics)") == 0u,
             Error(mixed));
  const auto mechanics = scene::ParseAnyScene(
      "[system]\ndof = 1\n[[effect]]\ntype = \"kinetic\"\n[initial]\n"
      "x = [1.0]\nv = [0.0]\n[time]\nend = 1.0\npoints = 9\n",
      "m.toml");
  BOOST_TEST(std::holds_alternative<scene::Scene>(mechanics));
}

BOOST_AUTO_TEST_CASE(Profiles_AreExactOnlyForTheTermsTheySolve) {
  // A plane wave solves Klein–Gordon; with a quartic term it does not, and
  // the error diagnostic is then refused with the reason.
  BOOST_TEST(bool(Field(Scene(kKleinGordon, "profile = \"plane_wave\"\n",
                              "diagnostics = [\"error\"]\n"))
                      .exact));
  const std::string quartic = kKleinGordon + "[[term]]\ntype = \"quartic\"\n";
  BOOST_TEST(!Field(Scene(quartic, "profile = \"plane_wave\"\n")).exact);
  BOOST_TEST(Error(Scene(quartic, "profile = \"plane_wave\"\n",
                         "diagnostics = [\"error\"]\n"))
                 .find("needs an exact solution: a plane wave of one "
                       "component is exact for the terms kinetic, gradient "
                       "and mass only") != std::string::npos);
  // Two components with the quartic term: exact, with ω² = k² + m² + λA².
  const auto complex = Field(
      "[field]\ncomponents = 2\ndomain = [0.0, 6.283185307179586]\n"
      "points = 16\n" +
      quartic + "[initial]\nprofile = \"plane_wave\"\namplitude = 0.5\n" +
      "[time]\nend = 1.0\npoints = 17\n");
  double phi[2], phi_t[2];
  const double origin = 0.0;
  complex.exact(0.0, &origin, phi, phi_t);
  BOOST_TEST(phi_t[1] == -0.5 * std::sqrt(1 + 1 + 0.25),
             boost::test_tools::tolerance(1e-14));
  // A kink needs its potential.
  BOOST_TEST(Error(Scene(kKleinGordon, "profile = \"kink\"\n"))
                 .find("needs the kink of one potential, and the terms list "
                       "neither") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(MirroredGaussian_MeetsTheNaturalBoundaryCondition) {
  // On [−3, 5] with φ_x = 0 at both ends, a pulse at 4 moving right at
  // v = 0.5, c = 2: the images keep φ_x = 0 at the ends and φ_tt = c²φ_xx
  // (central differences of step h, error O(h²) ≈ 1e-6).
  fields::MovingGaussian g{
      .amplitude = 1.0, .width = 0.6, .center = 4.0, .velocity = 0.5, .c = 2.0};
  g.images = fields::MovingGaussian::Images::kMirrored;
  g.x0 = -3;
  g.length = 8;
  const double h = 1e-3;
  auto phi = [&](double t, double x) { return g(t, x).first; };
  for (double t : {0.0, 0.7, 2.9})
    for (double end : {-3.0, 5.0})
      BOOST_TEST(std::abs(phi(t, end + h) - phi(t, end - h)) / (2 * h) < 1e-9);
  for (double t : {0.3, 1.8})
    for (double x : {-2.5, 0.0, 4.5}) {
      const double tt =
          (phi(t + h, x) - 2 * phi(t, x) + phi(t - h, x)) / (h * h);
      const double xx =
          (phi(t, x + h) - 2 * phi(t, x) + phi(t, x - h)) / (h * h);
      BOOST_TEST(std::abs(tt - 4 * xx) < 1e-4);
    }
  // Odd images: φ = 0 at the ends instead.
  g.images = fields::MovingGaussian::Images::kAntiMirrored;
  for (double t : {0.0, 0.7, 2.9})
    for (double end : {-3.0, 5.0}) BOOST_TEST(std::abs(phi(t, end)) < 1e-15);
  // Without images, at t = 0: the pulse itself, with φ_t = −v φ_x.
  g.images = fields::MovingGaussian::Images::kNone;
  const auto [f, ft] = g(0.0, 4.3);
  BOOST_TEST(f == std::exp(-0.09 / 0.72), boost::test_tools::tolerance(1e-14));
  BOOST_TEST(ft == -0.5 * (-0.3 / 0.36) * f,
             boost::test_tools::tolerance(1e-14));
}

// boundary = "dirichlet" | "neumann" | [left, right] with boundary_values
// (core/action/field_boundary.h), the shipped string scene solved on a
// coarser grid: at t = 10 the pulse is back at the centre upside down, and
// the data hold at the ends.
BOOST_AUTO_TEST_CASE(BoundaryData_AreReadCheckedAndSolved) {
  const scene::AnyScene any = scene::ReadAnyScene(fs::path(VIVP_SCENES_DIR) /
                                                  "field_wave_dirichlet.toml");
  auto s = std::get<scene::FieldScene>(any);
  BOOST_TEST(s.boundary == "dirichlet");
  BOOST_TEST(s.ends[1] == "dirichlet");
  BOOST_TEST(bool(s.exact));
  s.space_points = 101;
  s.time_points = 401;
  s.phi0.assign(101, 0.0);
  s.phi_t0.assign(101, 0.0);
  const auto dx = s.Space();
  for (int j = 0; j < 101; ++j) {
    const double x = dx.x(j);
    s.exact(0.0, &x, &s.phi0[j], &s.phi_t0[j]);
  }
  const auto run = scene::RunFieldScene(s);
  BOOST_TEST_REQUIRE(run.solution.status.converged, run.solution.status.reason);
  double flipped = 0;
  for (int j = 0; j < 101; ++j)
    flipped = std::max(flipped, std::abs(run.solution.end.phi[j] + s.phi0[j]));
  BOOST_TEST_MESSAGE("string at t = 10: max |φ + φ(0)| = " << flipped);
  BOOST_TEST(flipped < 5e-3);
  BOOST_TEST(run.solution.end.phi[0] == 0.0);
  BOOST_TEST(run.solution.end.phi[100] == 0.0);

  const std::string terms =
      "[[term]]\ntype = \"kinetic\"\n[[term]]\ntype = \"gradient\"\n";
  auto interval = [&](const std::string& boundary, const std::string& initial) {
    return "[field]\ndomain = [0.0, 4.0]\npoints = 41\n" + boundary +
           "space_operator = \"sbp42\"\n" + terms + "[initial]\n" + initial +
           "[time]\nend = 1.0\npoints = 33\n";
  };
  const std::string pulse =
      "profile = \"gaussian\"\ncenter = 2.0\nwidth = 0.25\n";
  const auto mixed = Field(interval(
      "boundary = [\"dirichlet\", \"neumann\"]\nboundary_values = [0.0, 0.5]\n",
      pulse));
  BOOST_TEST(mixed.boundary == "dirichlet/neumann");
  BOOST_TEST(!mixed.exact);  // no images for these ends
  BOOST_TEST(mixed.Boundary().right.value(0.3, 0) == 0.5);
  const std::string natural = Error(
      interval("boundary = \"natural\"\nboundary_values = [1, 2]\n", pulse));
  BOOST_TEST(natural.find("f.toml:5:19: 'boundary_values' does not apply to "
                          "boundary = \"natural\"") == 0u,
             natural);
  BOOST_TEST(Error(interval("boundary = [\"dirichlet\"]\n", pulse))
                 .find("boundary has 1 entries; expected [left, right]") !=
             std::string::npos);
  BOOST_TEST(Error(interval("boundary = [\"periodic\", \"natural\"]\n", pulse))
                 .find("'periodic' is not a valid boundary") !=
             std::string::npos);
  // A profile that is not the Dirichlet value at an end: refused with the
  // jump, accepted with allow_jump as a warning.
  const std::string far =
      "boundary = \"dirichlet\"\nboundary_values = [0.0, 1.0]\n";
  const std::string refused = Error(interval(far, pulse));
  BOOST_TEST(refused.find("f.toml:12:11: the profile 'gaussian' is ") == 0u,
             refused);
  BOOST_TEST(refused.find("at the right end, the dirichlet value 1 (a jump "
                          "of 1 at t = 0)") != std::string::npos);
  BOOST_TEST(
      Field(interval(far, pulse + "allow_jump = true\n")).warnings.size() ==
      1u);
}
