// Effects composed at run time (problems/composed.h) against the hand-written
// problems of Rothkopf & Nordström 2023 and the comparison set: the same L
// and Λ values at scattered points, and the same trajectory from the solver.
#define BOOST_TEST_MODULE composed_effects
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>

#include "problems/anharmonic.h"
#include "problems/composed.h"
#include "problems/damped_oscillator.h"
#include "problems/exponential.h"
#include "problems/free_fall.h"
#include "problems/kepler.h"
#include "problems/pendulum.h"
#include "solvers/variational/solve_ivp.h"

using namespace vivp;
using namespace vivp::variational;
using namespace vivp::problems;

namespace {

// max |L_a − L_b| and |Λ_a − Λ_b| over 200 random doubled states.
template <int D, class A, class B>
double MaxDifference(const A& a, const B& b) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.2, 1.5);
  double worst = 0;
  for (int k = 0; k < 200; ++k) {
    double x1[D], v1[D], x2[D], v2[D];
    for (int c = 0; c < D; ++c) {
      x1[c] = u(rng);
      v1[c] = u(rng) - 0.7;
      x2[c] = u(rng);
      v2[c] = u(rng) - 0.7;
    }
    worst = std::max(worst, std::abs(a(x1, v1) - b(x1, v1)));
    if constexpr (action::HasLambda<A> || action::HasLambda<B>) {
      double la = 0, lb = 0;
      if constexpr (action::HasLambda<A>) la = a.Lambda(x1, v1, x2, v2);
      if constexpr (action::HasLambda<B>) lb = b.Lambda(x1, v1, x2, v2);
      worst = std::max(worst, std::abs(la - lb));
    }
  }
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_CASE(EffectSums_EqualTheHandWrittenLagrangians) {
  using namespace effects;
  BOOST_TEST(MaxDifference<1>(DampedOscillator{},
                              Composed<1>{{Kinetic{0.5, {}}, Spring{1.0, {}},
                                           Damping{0.00071}}}) <= 1e-15);
  BOOST_TEST(
      MaxDifference<1>(Anharmonic{}, Composed<1>{{Kinetic{}, Quartic{20.0}}}) <=
      1e-13);
  BOOST_TEST(MaxDifference<1>(FreeFall{},
                              Composed<1>{{Kinetic{}, Gravity{}}}) <= 1e-15);
  BOOST_TEST(MaxDifference<1>(Exponential{}, Composed<1>{{Growth{2.5}}}) <=
             1e-15);
  BOOST_TEST(MaxDifference<1>(problems::Pendulum{},
                              Composed<1>{{Kinetic{}, effects::Pendulum{}}}) <=
             1e-15);
  BOOST_TEST(MaxDifference<2>(Kepler{}, Composed<2>{{Kinetic{}, Central{}}}) <=
             1e-15);
}

BOOST_AUTO_TEST_CASE(ChainWithFixedEnds_IsTheSumOfItsBonds) {
  // Three masses between walls: bonds x0, x1 − x0, x2 − x1, x2.
  const auto c = Composed<3>{{effects::Chain{2.0, 0.5, true}}};
  const double x[3] = {0.1, -0.3, 0.2}, v[3] = {0, 0, 0};
  double expected = 0;
  for (double d : {0.1, -0.4, 0.5, 0.2})
    expected -= 0.5 * 2.0 * d * d + 0.25 * 0.5 * d * d * d * d;
  BOOST_TEST(std::abs(c(x, v) - expected) <= 1e-15);
}

BOOST_AUTO_TEST_CASE(ComposedDampedOscillator_SolvesLikeTheHandWrittenOne) {
  const auto composed =
      Composed<1>{{effects::Kinetic{0.5, {}}, effects::Spring{1.0, {}},
                   effects::Damping{0.00071}}};
  const Grid g{.op = "sbp42", .points = 2048, .t_start = 0.0, .t_end = 204.8};
  const auto a = SolveIvp(DampedOscillator{}, {{1.0}, {0.0}}, g);
  const auto b = SolveIvp(composed, {{1.0}, {0.0}}, g);
  BOOST_TEST(a.status.converged);
  BOOST_TEST(b.status.converged);
  BOOST_TEST((a.x1 - b.x1).cwiseAbs().maxCoeff() <= 1e-12);
}

namespace {

// The same composition, differentiated whole: no AddDiagonalDerivatives, so
// core/action/density.h takes ∂/∂(x, v) of L and Λ in all 2d variables.
template <int D>
struct Whole {
  static constexpr int kDim = D;
  const Composed<D>& c;
  template <class T>
  T operator()(const T* x, const T* v) const {
    return c(x, v);
  }
  template <class T>
  T Lambda(const T* x1, const T* v1, const T* x2, const T* v2) const {
    return c.Lambda(x1, v1, x2, v2);
  }
};

// Largest difference, relative to the largest entry, between the term-by-term
// and the whole derivatives (gradient and mixed Hessian of the ± density)
// over 100 random points p = (x₊, v₊).
template <int D>
double TermByTermDeviation(const Composed<D>& c) {
  static_assert(action::DifferentiatesByTerms<Composed<D>, double>);
  static_assert(!action::DifferentiatesByTerms<Whole<D>, double>);
  const Whole<D> whole{c};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  double worst = 0;
  for (int k = 0; k < 100; ++k) {
    double p[2 * D];
    for (double& e : p) e = u(rng);
    const auto a = action::DiagonalDerivatives<double>(c, p);
    const auto b = action::DiagonalDerivatives<double>(whole, p);
    const auto ga = action::DiagonalGradient<double>(c, p);
    const auto gb = action::DiagonalGradient<double>(whole, p);
    const double scale = std::max(
        {1.0, b.dm.cwiseAbs().maxCoeff(), b.dmp.cwiseAbs().maxCoeff()});
    worst = std::max({worst, (a.dm - b.dm).cwiseAbs().maxCoeff() / scale,
                      (a.dmp - b.dmp).cwiseAbs().maxCoeff() / scale,
                      (ga - gb).cwiseAbs().maxCoeff() / scale,
                      (ga - b.dm).cwiseAbs().maxCoeff() / scale});
  }
  return worst;
}

}  // namespace

// Each effect declares whether it depends on x, on ẋ or on both (kDepends),
// and a composition differentiates each term only in those variables. A
// wrong declaration would silently drop derivatives; this checks every
// effect, alone and all together, against differentiating the whole density.
BOOST_AUTO_TEST_CASE(TermByTermDerivatives_EqualThoseOfTheWholeDensity) {
  using namespace effects;
  const std::vector<double> m2 = {2.0, 0.3, 0.3, 1.0};
  const std::vector<Effect> each2 = {
      Kinetic{0.7, {}},      Kinetic{1.0, m2},
      Gravity{1.5, 9.81, 1}, Spring{2.0, {0.1, -0.2}},
      Quartic{3.0},          effects::Pendulum{2.0, 1},
      Central{1.3},          GaussianWell{0.8},
      Chain{2.0, 0.5, true}, Chain{1.0, 0.0, false},
      Damping{0.3},          Growth{2.5}};
  for (const Effect& e : each2) {
    BOOST_TEST_CONTEXT("effect #" << e.index()) {
      BOOST_TEST(TermByTermDeviation(Composed<2>{{e}}) <= 1e-14);
    }
  }
  std::vector<Effect> all(each2.begin(), each2.end());
  all.erase(all.begin());  // one kinetic term
  BOOST_TEST(TermByTermDeviation(Composed<2>{all}) <= 1e-14);
  BOOST_TEST(TermByTermDeviation(Composed<3>{
                 {Kinetic{}, Chain{1.0, 1.0, true}, Central{}, Damping{0.1},
                  Gravity{}, Spring{1.0, {0.0, 1.0, 2.0}}}}) <= 1e-14);
}
