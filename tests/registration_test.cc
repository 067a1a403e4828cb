// A Lagrangian added the way a researcher adds one: the struct and one
// registration statement in one file (here, this test's), nothing else
// edited. It is then a problem of `vivp converge` — measured against a
// reference integration of its Euler–Lagrange equations, since it has no
// closed form given — a scene type with its parameter, and a problem of
// `vivp bench` through its Hamiltonian form.
#define BOOST_TEST_MODULE registration
#include <unistd.h>

#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>

#include "figures/solver_figures.h"
#include "lagrangians/register.h"
#include "scene/run.h"
#include "scene/scene.h"
#include "studies/bench_problems.h"
#include "studies/registry.h"

namespace {

// --- the researcher's file ---
// A Duffing oscillator, L = ½ẋ² − ½ax² − ¼bx⁴: no closed form is given.
struct Duffing {
  static constexpr int kDim = 1;
  double a = 1.0, b = 4.0;
  template <class T>
  T operator()(const T* x, const T* v) const {
    return T(0.5) * v[0] * v[0] - T(0.5 * a) * x[0] * x[0] -
           T(0.25 * b) * x[0] * x[0] * x[0] * x[0];
  }
};

const bool registered = vivp::Register<Duffing>({
    .name = "fixture_duffing",
    .description = "Duffing oscillator, L = ½ẋ² − ½ax² − ¼bx⁴",
    .initial = {{1.0}, {0.0}},
    .parameters = {{"a", &Duffing::a}, {"b", &Duffing::b}},
});
// --- end of the researcher's file ---

}  // namespace

BOOST_AUTO_TEST_CASE(RegisteredLagrangian_IsAConvergeProblemWithAReference) {
  BOOST_TEST(registered);
  const vivp::studies::NamedProblem& p =
      vivp::studies::FindProblem("fixture_duffing");
  BOOST_TEST(p.reference.find("Euler–Lagrange") != std::string::npos,
             p.reference);
  BOOST_TEST(vivp::studies::ProblemNameList().find("fixture_duffing") !=
             std::string::npos);
  // The study converges at the operator's order against the reference:
  // SBP42's corrected end position at order 4 (docs/method.md §7).
  const vivp::studies::ConvergenceStudy s = vivp::studies::RunConvergence(
      p, {.op = "sbp42", .t_end = 2.0}, {129, 257, 513, 1025},
      vivp::variational::SolveOptions{});
  for (const auto& r : s.rows) BOOST_TEST(r.converged, r.reason);
  BOOST_TEST_MESSAGE("orders: x " << s.orders.x << ", x+λ4 "
                                  << s.orders.x_corrected);
  BOOST_TEST(std::abs(s.orders.x_corrected - 4.0) < 0.3);
  BOOST_TEST(s.rows.back().err_x_corrected < 1e-9);
}

BOOST_AUTO_TEST_CASE(RegisteredLagrangian_IsASceneTypeWithItsParameters) {
  const vivp::scene::Scene s = vivp::scene::ParseScene(
      "[system]\ndof = 1\n"
      "[[effect]]\ntype = \"fixture_duffing\"\nb = 0.0\n"
      "[initial]\nx = [1.0]\nv = [0.0]\n"
      "[time]\nend = 3.0\npoints = 301\n"
      "[method]\nkind = \"variational\"\noperator = \"sbp42\"\n",
      "fixture.toml");
  // With b = 0 the oscillator is harmonic with ω = 1: x(3) = cos 3.
  class End : public vivp::scene::RunSink {
   public:
    void Begin(const vivp::scene::RunLayout&) override {}
    void Node(double, const double* x, const double*, const double*) override {
      last = x[0];
    }
    double last = NAN;
  } sink;
  const auto outcome = vivp::scene::RunScene(s, sink);
  BOOST_TEST(outcome.converged, outcome.status);
  BOOST_TEST(std::abs(sink.last - std::cos(3.0)) < 1e-6);
}

BOOST_AUTO_TEST_CASE(
    RegisteredLagrangian_IsABenchProblemThroughItsLegendreForm) {
  // L = ½ẋ² − V is separable: the steppers (Störmer–Verlet among them) run
  // on H = ½p² + V, the variational solver on L, against the reference
  // integration at t = 10. Orders from two step counts, measured.
  const auto& b = vivp::studies::FindBenchProblem("fixture_duffing");
  auto has = [&](const std::string& m) {
    return std::find(b.methods.begin(), b.methods.end(), m) != b.methods.end();
  };
  BOOST_TEST(has("verlet"));
  BOOST_TEST(has("gauss2"));
  BOOST_TEST(has("variational_sbp42_uniform"));
  BOOST_TEST(has("variational_lgl8_embedded"));
  BOOST_TEST(has("variational_lgl8_halves"));
  BOOST_TEST(!has("variational_sbp42_embedded"));
  BOOST_TEST(b.reference.find("Euler–Lagrange") != std::string::npos);
  auto order = [&](const std::string& m, long n) {
    const auto coarse = b.measure(m, double(n), 5);
    const auto fine = b.measure(m, double(2 * n), 5);
    BOOST_TEST(coarse.status == "ok", m << ": " << coarse.status);
    BOOST_TEST(fine.status == "ok", m << ": " << fine.status);
    BOOST_TEST_MESSAGE(m << " " << n << ": " << coarse.error << " → "
                         << fine.error << ", max|dH|/H " << fine.energy_error);
    return std::log2(coarse.error / fine.error);
  };
  BOOST_TEST(std::abs(order("verlet", 2000) - 2.0) < 0.1);
  BOOST_TEST(std::abs(order("gauss2", 500) - 4.0) < 0.2);
  // SBP42's corrected hand-off: order 4 (docs/method.md §7).
  BOOST_TEST(std::abs(order("variational_sbp42_uniform", 1000) - 4.0) < 0.3);
}

BOOST_AUTO_TEST_CASE(RegisteredLagrangian_WithoutAHamiltonianForm_IsNamed) {
  // The first-order system has a dissipative term and a singular M: the
  // bench says so instead of listing it.
  try {
    vivp::studies::FindBenchProblem("exponential");
    BOOST_FAIL("exponential was accepted");
  } catch (const std::invalid_argument& e) {
    BOOST_TEST(
        std::string(e.what()).find("no Hamiltonian form") != std::string::npos,
        e.what());
  }
  // A vector potential makes H non-separable: no Störmer–Verlet.
  const auto& c = vivp::studies::FindBenchProblem("cyclotron");
  const bool verlet = std::find(c.methods.begin(), c.methods.end(), "verlet") !=
                      c.methods.end();
  BOOST_TEST(!verlet);
  const auto w = c.measure("gauss3", 400, 5);
  BOOST_TEST(w.status == "ok", w.status);
  BOOST_TEST(w.error < 1e-9, w.error);
}

BOOST_AUTO_TEST_CASE(RegisteredLagrangian_HasTheFigureProgramsFigures) {
  // fig_problem (target problem_figures) draws these for every registered
  // Lagrangian; here for the fixture, into a fresh directory.
  const auto dir = std::filesystem::temp_directory_path() /
                   ("vivp_registration_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto png = vivp::figures::OperatorPairConvergenceFigure(
      dir, "fixture_duffing_convergence", "fixture_duffing", "Duffing");
  BOOST_TEST(std::filesystem::file_size(png) > 1000u);
  std::filesystem::remove_all(dir);
}
