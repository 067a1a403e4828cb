// Modified energies and momenta along computed trajectories (docs/bea.md §5),
// measured as fitted log-log slopes of the maximum deviation against h, plus
// the agreement of the compiled evaluation with GiNaC's own.
#define BOOST_TEST_MODULE bea_conservation
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>

#include "solvers/bea/conservation.h"
#include "studies/bea_experiment.h"

using namespace vivp::bea;
namespace utf = boost::unit_test;

namespace {

DeriveOptions Options(int order, PotentialModel model,
                      std::optional<GiNaC::matrix> symmetry = std::nullopt) {
  DeriveOptions o;
  o.order = order;
  o.model = model;
  o.symmetry = symmetry;
  return o;
}

int Column(const Sweep& s, const std::string& name) {
  for (std::size_t c = 0; c < s.names.size(); ++c)
    if (s.names[c] == name) return static_cast<int>(c);
  BOOST_FAIL("no quantity " << name);
  return -1;
}

double Slope(const Sweep& s, const std::string& name) {
  return s.slopes[Column(s, name)];
}

}  // namespace

BOOST_AUTO_TEST_CASE(CompiledEvaluation_AgreesWithGiNaCSubstitution) {
  auto r = Derive(MakeLmm4(ScalarMatrix(GiNaC::numeric(-1, 5), 2)),
                  Options(4, PotentialModel::kGeneric));
  Gaussian potential(2);
  ModifiedQuantities q(r, potential);
  const double x[] = {0.7, -1.3}, v[] = {0.4, 0.25}, h = 0.15;
  GiNaC::exmap values;
  for (int i = 0; i < 2; ++i) {
    values[r.x(i)] = x[i];
    values[r.v(i)] = v[i];
  }
  std::vector<int> a(2);
  for (a[0] = 0; a[0] <= 8; ++a[0])
    for (a[1] = 0; a[0] + a[1] <= 8; ++a[1])
      values[r.jet->U(a)] = potential.Derivative(a, x);
  GiNaC::symbol hs("h");
  values[hs] = h;
  const GiNaC::ex exact = GiNaC::evalf(r.hamiltonian.ToEx(hs).subs(values));
  const double reference = GiNaC::ex_to<GiNaC::numeric>(exact).to_double();
  const double compiled = q.Hamiltonian(4, h, x, v);
  // Round-off bound: a few eps per term of H times its magnitude.
  BOOST_TEST(std::abs(compiled - reference) <=
             64 * std::numeric_limits<double>::epsilon() *
                 (1 + std::abs(reference)));
}

BOOST_AUTO_TEST_CASE(CompiledOmegaAndModifiedLagrangian_AgreeWithGiNaC) {
  // Proves: the compiled symplectic form ω (2d × 2d) and modified
  // Lagrangian L_mod, truncated at h^4, equal GiNaC's evaluation of the same
  // series at a point (Störmer–Verlet, d = 1, generic U at the pendulum).
  auto r = Derive(MakeStormerVerlet(1), Options(4, PotentialModel::kGeneric));
  BOOST_TEST_REQUIRE(r.modified_lagrangian.has_value());
  Pendulum potential;
  ModifiedQuantities q(r, potential);
  BOOST_TEST_REQUIRE(q.has_lagrangian());
  const double x[] = {0.7}, v[] = {-0.4}, h = 0.2;
  GiNaC::exmap values;
  values[r.x(0)] = x[0];
  values[r.v(0)] = v[0];
  for (int a = 0; a <= 10; ++a)
    values[r.jet->U(std::vector<int>{a})] =
        potential.Derivative(std::vector<int>{a}, x);
  GiNaC::symbol hs("h");
  values[hs] = h;
  auto reference = [&](const Series& s) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(s.ToEx(hs).subs(values)))
        .to_double();
  };
  const double eps = std::numeric_limits<double>::epsilon();
  const double lag = reference(*r.modified_lagrangian);
  BOOST_TEST(std::abs(q.Lagrangian(4, h, x, v) - lag) <=
             64 * eps * (1 + std::abs(lag)));
  double omega[4];
  q.SymplecticForm(4, h, x, v, omega);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const double w = reference(r.omega[i][j]);
      BOOST_TEST(
          std::abs(omega[2 * i + j] - w) <= 64 * eps * (1 + std::abs(w)),
          "omega(" << i << "," << j << ") " << omega[2 * i + j] << " vs " << w);
    }
  // ω_0 = [[0, −1], [1, 0]]·(mass 1): the h-free part is the canonical form.
  q.SymplecticForm(0, h, x, v, omega);
  BOOST_TEST(omega[1] == -1.0);
  BOOST_TEST(omega[2] == 1.0);
}

BOOST_AUTO_TEST_CASE(StormerVerletPendulum_ModifiedHamiltonian_FallsAsH6) {
  auto r = Derive(MakeStormerVerlet(1), Options(4, PotentialModel::kGeneric));
  Pendulum potential;
  ModifiedQuantities q(r, potential);
  ConservationSetup s;
  s.x0 = Eigen::VectorXd::Constant(1, 1.0);
  s.v0 = Eigen::VectorXd::Zero(1);
  s.t_end = 100;
  auto sweep = ConservationSweep(r, q, potential, s, {0.2, 0.1, 0.05, 0.025});
  BOOST_TEST(std::abs(Slope(sweep, "H4") - 6) <= 0.3);
  BOOST_TEST(std::abs(Slope(sweep, "H0") - 2) <= 0.2);
}

BOOST_AUTO_TEST_CASE(
    StormerVerletPendulum_ModifiedHamiltonian_DoesNotDriftOver1e5Steps) {
  auto r = Derive(MakeStormerVerlet(1), Options(4, PotentialModel::kGeneric));
  Pendulum potential;
  ModifiedQuantities q(r, potential);
  ConservationSetup s;
  s.x0 = Eigen::VectorXd::Constant(1, 1.0);
  s.v0 = Eigen::VectorXd::Zero(1);
  s.t_end = 1e4;
  const auto dev = Deviations(r, q, potential, s, 0.1);
  BOOST_REQUIRE(dev.t.size() >= 99990);
  const int c = 2;  // H4
  const int n = static_cast<int>(dev.t.size());
  const double first = dev.deviation.col(c).head(n / 10).cwiseAbs().maxCoeff();
  const double last = dev.deviation.col(c).tail(n / 10).cwiseAbs().maxCoeff();
  // Bounded oscillation: the last tenth stays within the first tenth's band
  // (a drift of even 1e-3 of the band per period would double it).
  BOOST_TEST(last <= 1.5 * first);
  BOOST_TEST(first <= 1e-5);
}

BOOST_AUTO_TEST_CASE(Lmm4Gaussian_H4AndI4_FallAsH6InTheAsymptoticRange) {
  const vivp::studies::GaussianWellExperiment e;
  auto sweep =
      ConservationSweep(e.derivation, e.quantities, e.potential,
                        e.Setup(150, 6), {0.15, 0.1, 0.075, 0.05, 0.04, 0.03});
  BOOST_TEST(std::abs(Slope(sweep, "H4") - 6) <= 0.4);
  BOOST_TEST(std::abs(Slope(sweep, "I4") - 6) <= 0.4);
  BOOST_TEST(std::abs(Slope(sweep, "H2") - 4) <= 0.4);
  BOOST_TEST(std::abs(Slope(sweep, "H0") - 2) <= 0.2);
}

BOOST_AUTO_TEST_CASE(Lmm4Gaussian_ReproducesTheDocumentedSweep) {
  // docs/bea.md §5: H4's maximum deviation over T = 150 is about 4e-4,
  // 2.5e-5, 2e-6, 3e-8 and 1.4e-9 at h = 0.2, 0.15, 0.1, 0.05, 0.03. With
  // 12th-order differences (x' recovered well below H4's deviation even at
  // h = 0.2) the measured values are 4.50e-4, 2.66e-5, 2.08e-6, 3.02e-8 and
  // 1.39e-9: within the one or two digits given, allowed 20% here.
  const vivp::studies::GaussianWellExperiment e;
  const std::vector<double> h = {0.2, 0.15, 0.1, 0.05, 0.03};
  const double published[] = {4e-4, 2.5e-5, 2e-6, 3e-8, 1.4e-9};
  auto sweep = ConservationSweep(e.derivation, e.quantities, e.potential,
                                 e.Setup(150, 12), h);
  for (std::size_t k = 0; k < h.size(); ++k) {
    const double measured = sweep.rows[k].max_deviation[Column(sweep, "H4")];
    BOOST_TEST_INFO("h = " << h[k]);
    BOOST_TEST(measured / published[k] <= 1.2);
    BOOST_TEST(measured / published[k] >= 1 / 1.2);
  }
}

// Known shortfall: over the full range 0.3 ... 0.03 the fitted slopes are
// 6.8 (H4) and 7.4 (I4), against 6.1 over 0.15 ... 0.03 (above): at
// h >= 0.2 the truncated series is not yet asymptotic (H4's deviation at
// h = 0.3 equals H2's). The numbers of docs/bea.md §5 (4e-4 at h = 0.2 ...
// 1.4e-9 at 0.03), which this implementation reproduces (above), give 6.44
// fitted over 0.2 ... 0.03 (6.6 between the end points): outside 6 ± 0.4
// too, and steeper the larger the first step. The local slopes of I4
// between successive steps from 0.15 down are 6.27, 6.13, 6.07, 6.02.
BOOST_AUTO_TEST_CASE(Lmm4Gaussian_H4AndI4_FallAsH6OverTheFullRange,
                     *utf::expected_failures(2)) {
  const vivp::studies::GaussianWellExperiment e;
  auto sweep = ConservationSweep(e.derivation, e.quantities, e.potential,
                                 e.Setup(150, 6),
                                 {0.3, 0.2, 0.15, 0.1, 0.075, 0.05, 0.03});
  BOOST_TEST(std::abs(Slope(sweep, "H4") - 6) <= 0.4);
  BOOST_TEST(std::abs(Slope(sweep, "I4") - 6) <= 0.4);
}

BOOST_AUTO_TEST_CASE(Lmm4Gaussian_FourthOrderDifferences_StallNearH4) {
  // With 4th-order differences the recovered x' carries an O(h^4) error, so
  // H4 cannot fall faster than h^4: the "floor" is the measurement.
  const vivp::studies::GaussianWellExperiment e;
  auto sweep =
      ConservationSweep(e.derivation, e.quantities, e.potential,
                        e.Setup(150, 4), {0.1, 0.075, 0.05, 0.04, 0.03});
  BOOST_TEST(std::abs(Slope(sweep, "H4") - 4) <= 0.4);
}

BOOST_AUTO_TEST_CASE(Lmm4Gaussian_PaperStep_DeviationsOrderedH0H2H4) {
  // McLachlan & Offen 2023, Fig. 1 at h = 0.15: each correction reduces the
  // deviation.
  const vivp::studies::GaussianWellExperiment e;
  auto sweep = ConservationSweep(e.derivation, e.quantities, e.potential,
                                 e.Setup(150, 6), {0.15});
  const auto& d = sweep.rows[0].max_deviation;
  BOOST_TEST(d[Column(sweep, "H2")] < d[Column(sweep, "H0")] / 10);
  BOOST_TEST(d[Column(sweep, "H4")] < d[Column(sweep, "H2")] / 10);
  BOOST_TEST(d[Column(sweep, "I4")] < d[Column(sweep, "I2")] / 10);
}
