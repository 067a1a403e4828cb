// Conservation laws and time symmetry of the stepper family, measured.
// Round-off bounds are c·n·eps·scale with the step count n and the size of
// the conserved quantity; each property is shown to discriminate by a method
// that must violate it (RK4, or implicit midpoint for the NLDNLS energy).
#define BOOST_TEST_MODULE steppers_conservation
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "problems/kepler.h"
#include "problems/nldnls.h"
#include "problems/phase_space.h"
#include "solvers/steppers/integrate.h"
#include "solvers/steppers/methods.h"

namespace bdata = boost::unit_test::data;
using namespace vivp;
using steppers::StepOutcome;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
using Chain = problems::NldnlsChain<16>;

template <class Problem>
using VectorOf = typename steppers::HamiltonianSystem<Problem>::Vector;

template <class Problem>
VectorOf<Problem> Initial(const Problem& p) {
  const auto init = vivp::problems::InitialState(p);
  return VectorOf<Problem>::Map(init.data());
}

// Largest |I(y_n) − I(y_0)| over a run, for the energy and for each of the
// problem's invariants.
struct Drift {
  double energy = 0;
  std::vector<double> invariants;
  steppers::RunReport report;
};

template <class Problem>
Drift MeasureDrift(const Problem& p, const std::string& method, double h,
                   long steps) {
  const steppers::HamiltonianSystem<Problem> system(p);
  auto stepper = steppers::MakeStepper<Problem>(method, system);
  auto y = Initial(p);
  const double e0 = system.Energy(y);
  const auto i0 =
      vivp::problems::InvariantValues(p, y.data(), y.data() + Problem::kDim);
  Drift d;
  d.invariants.assign(i0.size(), 0.0);
  d.report = steppers::Integrate(
      stepper, y, h, steps, [&](double, const VectorOf<Problem>& x) {
        d.energy = std::max(d.energy, std::fabs(system.Energy(x) - e0));
        const auto i = vivp::problems::InvariantValues(
            p, x.data(), x.data() + Problem::kDim);
        for (std::size_t k = 0; k < i.size(); ++k)
          d.invariants[k] = std::max(d.invariants[k], std::fabs(i[k] - i0[k]));
      });
  return d;
}

}  // namespace

// ℓ = q × p is a quadratic invariant: symplectic Runge–Kutta methods (midpoint,
// Gauss) keep it exactly and Störmer–Verlet keeps it because the force is
// central. What remains is round-off, growing at most like n·eps·|ℓ|.
BOOST_DATA_TEST_CASE(Kepler_AngularMomentumKeptToRoundOff,
                     bdata::make({"midpoint", "gauss2", "gauss3", "verlet",
                                  "discrete_gradient"}),
                     method) {
  const problems::Kepler kepler;
  const long n = 10000;  // 50 orbits at 200 steps per orbit
  const Drift d = MeasureDrift(kepler, method, 2 * M_PI / 200, n);
  BOOST_TEST_REQUIRE((d.report.status == StepOutcome::kOk));
  const double l0 = std::fabs(
      kepler.Invariants(Initial(kepler).data(), Initial(kepler).data() + 2)[0]);
  BOOST_TEST_MESSAGE(method << ": max |Δℓ| = " << d.invariants[0] << " = "
                            << d.invariants[0] / (kEps * l0) << " eps·|ℓ|");
  BOOST_TEST(d.invariants[0] <= 1.0 * n * kEps * l0);
}

// The contrast: RK4 at the same step loses ℓ by truncation, far above the
// round-off bound above.
BOOST_AUTO_TEST_CASE(Kepler_Rk4LosesAngularMomentumBeyondRoundOff) {
  const long n = 10000;
  const Drift d = MeasureDrift(problems::Kepler{}, "rk4", 2 * M_PI / 200, n);
  BOOST_TEST_MESSAGE("rk4: max |Δℓ| = " << d.invariants[0]);
  BOOST_TEST(d.invariants[0] > 1e3 * n * kEps);
}

// NLDNLS (16 sites — the soliton of A = 0.5 is about four sites wide —
// κ = 1, δt = 0.05, 10⁴ steps to t = 500): the
// charge Σ|z|² is quadratic, kept by midpoint, Gauss and the discrete
// gradient; the discrete gradient also keeps H (required: ≤ 1e-12
// relative). Midpoint does not keep H: its drift is measured and must
// exceed the discrete gradient's by orders of magnitude.
BOOST_DATA_TEST_CASE(Nldnls_ChargeKeptWithinOneEMinusTwelveOverTenThousandSteps,
                     bdata::make({"midpoint", "gauss2", "gauss3",
                                  "discrete_gradient"}),
                     method) {
  const Chain chain;
  const Drift d = MeasureDrift(chain, method, 0.05, 10000);
  BOOST_TEST_REQUIRE((d.report.status == StepOutcome::kOk));
  const auto y0 = Initial(chain);
  const double charge = chain.Invariants(y0.data(), y0.data() + Chain::kDim)[0];
  BOOST_TEST_MESSAGE(method << ": charge drift " << d.invariants[0] / charge
                            << ", energy drift " << d.energy
                            << ", iterations/step "
                            << d.report.iterations_per_step());
  BOOST_TEST(d.invariants[0] / charge <= 1e-12);
}

BOOST_AUTO_TEST_CASE(Nldnls_DiscreteGradientKeepsEnergyMidpointDoesNot) {
  const Chain chain;
  const steppers::HamiltonianSystem<Chain> system(chain);
  const double e0 = std::fabs(system.Energy(Initial(chain)));
  const Drift dg = MeasureDrift(chain, "discrete_gradient", 0.05, 10000);
  const Drift mid = MeasureDrift(chain, "midpoint", 0.05, 10000);
  BOOST_TEST_MESSAGE("relative energy drift: discrete gradient "
                     << dg.energy / e0 << ", midpoint " << mid.energy / e0);
  BOOST_TEST(dg.energy / e0 <= 1e-12);
  BOOST_TEST(mid.energy / e0 > 1e3 * dg.energy / e0);
}

// RK4's energy error drifts (grows with t); Störmer–Verlet's stays bounded.
// Measured on one run each: max error over 100 orbits against max over the
// first 10.
BOOST_AUTO_TEST_CASE(Kepler_Rk4EnergyDriftGrowsVerletStaysBounded) {
  const problems::Kepler kepler;
  const double h = 2 * M_PI / 100;
  for (const std::string method : {"rk4", "verlet"}) {
    const Drift early = MeasureDrift(kepler, method, h, 1000);
    const Drift late = MeasureDrift(kepler, method, h, 10000);
    const double growth = late.energy / early.energy;
    BOOST_TEST_MESSAGE(method << ": max |ΔH| 10 orbits " << early.energy
                              << ", 100 orbits " << late.energy << ", growth "
                              << growth);
    if (method == "rk4")
      BOOST_TEST(growth > 5.0);  // linear drift gives ≈ 10
    else
      BOOST_TEST(growth < 1.5);
  }
}

// Symmetric methods: n steps with h then n with −h return to y₀ up to
// round-off, c·n·eps·max|y|. The Kepler flow shears, so round-off committed
// early is amplified on the way back: measured 0.04–5.4 n·eps·scale over
// the family, hence c = 16. RK4 is not symmetric and misses by truncation
// (≈ 2e10 n·eps·scale).
BOOST_DATA_TEST_CASE(Kepler_SymmetricMethodsAreTimeReversibleToRoundOff,
                     bdata::make({"midpoint", "verlet", "gauss2", "gauss3",
                                  "triple_jump", "suzuki", "triple_jump6",
                                  "discrete_gradient", "rk4"}),
                     method) {
  const problems::Kepler kepler;
  const steppers::HamiltonianSystem<problems::Kepler> system(kepler);
  auto stepper = steppers::MakeStepper<problems::Kepler>(method, system);
  const auto y0 = Initial(kepler);
  auto y = y0;
  const int n = 1000;
  const double h = 2 * M_PI / 200;
  double scale = 0;
  for (int k = 0; k < n; ++k) {
    BOOST_TEST_REQUIRE((stepper.Step(y, h).status == StepOutcome::kOk));
    scale = std::max(scale, y.lpNorm<Eigen::Infinity>());
  }
  for (int k = 0; k < n; ++k)
    BOOST_TEST_REQUIRE((stepper.Step(y, -h).status == StepOutcome::kOk));
  const double miss = (y - y0).lpNorm<Eigen::Infinity>();
  BOOST_TEST_MESSAGE(method << ": return error " << miss << " = "
                            << miss / (n * kEps * scale) << " n·eps·scale");
  if (std::string(method) == "rk4")
    BOOST_TEST(miss > 1e3 * n * kEps * scale);
  else
    BOOST_TEST(miss <= 16.0 * n * kEps * scale);
}
