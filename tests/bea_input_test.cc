// Backward error analysis: bad input gets an error that names the problem
// and the fix; instability gets an explanation.
#define BOOST_TEST_MODULE bea_input
#include <boost/test/unit_test.hpp>
#include <string>

#include "solvers/bea/derivation.h"
#include "solvers/bea/multistep.h"

using namespace vivp::bea;

namespace {

// The call throws std::invalid_argument whose message contains `text`.
template <class F>
bool ThrowsWith(F&& f, const std::string& text) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    BOOST_TEST_MESSAGE(e.what());
    return std::string(e.what()).find(text) != std::string::npos;
  }
  return false;
}

}  // namespace

BOOST_AUTO_TEST_CASE(MakeLmm4_NonSymmetricMatrix_IsRejected) {
  GiNaC::matrix a(2, 2);
  a(0, 0) = a(1, 1) = GiNaC::numeric(-1, 5);
  a(0, 1) = GiNaC::numeric(1, 10);
  BOOST_TEST(ThrowsWith([&] { MakeLmm4(a); }, "not symmetric"));
}

BOOST_AUTO_TEST_CASE(MakeMultistep_InconsistentCoefficients_AreRejected) {
  // sum j^2 A_j = 2 I.
  BOOST_TEST(ThrowsWith([&] { MakeMultistep({ScalarMatrix(2, 2)}); },
                        "consistency (2.3)"));
  BOOST_TEST(ThrowsWith([&] { MakeMultistep({ScalarMatrix(2, 2)}); },
                        "sum_j j^2 A_j = I"));
}

BOOST_AUTO_TEST_CASE(CheckStability_PositiveAlpha_IsUnstableWithReason) {
  auto m = MakeLmm4(ScalarMatrix(GiNaC::numeric(1, 5), 2));
  const auto s = CheckStability(NumericCoefficients(m));
  BOOST_TEST(!s.stable);
  // alpha = 0.2: the extra roots solve zeta^2 + 3 zeta + 1 = 0, |zeta| = 2.618.
  BOOST_TEST(s.max_root_modulus > 1.5);
  BOOST_TEST(s.reason.find("alpha <= 0") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(CheckStability_NonPositiveAlpha_IsStable) {
  for (auto alpha :
       {GiNaC::numeric(-1, 5), GiNaC::numeric(-3), GiNaC::numeric(0)}) {
    const auto s =
        CheckStability(NumericCoefficients(MakeLmm4(ScalarMatrix(alpha, 2))));
    BOOST_TEST(s.stable, "alpha = " << alpha << ": " << s.reason);
  }
  BOOST_TEST(CheckStability(NumericCoefficients(MakeStormerVerlet(3))).stable);
}

BOOST_AUTO_TEST_CASE(Derive_UnreachableOrOddOrder_IsRejected) {
  DeriveOptions o;
  o.order = 12;
  BOOST_TEST(
      ThrowsWith([&] { Derive(MakeStormerVerlet(2), o); }, "reasonable time"));
  o.order = 3;
  BOOST_TEST(ThrowsWith([&] { Derive(MakeStormerVerlet(1), o); }, "even"));
  // A general symbolic A in d = 2 did not finish h^8 in 600 s: refused, with
  // what to do instead; the same order with A = alpha I stays allowed.
  const GiNaC::symbol a11("a11"), a12("a12"), a22("a22"), alpha("alpha");
  const Method general = MakeLmm4(SymmetricMatrix2(a11, a12, a22));
  BOOST_TEST(CoefficientSymbols(general) == 3);
  BOOST_TEST(MaxOrder(general) == 6);
  BOOST_TEST(MaxOrder(MakeLmm4(ScalarMatrix(alpha, 2))) == 8);
  BOOST_TEST(MaxOrder(MakeLmm4(SymmetricMatrix2(-0.2, 0.1, -0.3))) == 8);
  o.order = 8;
  BOOST_TEST(ThrowsWith([&] { Derive(general, o); },
                        "with 3 symbolic coefficients is beyond what the "
                        "engine reaches in reasonable time (maximum 6"));
}

BOOST_AUTO_TEST_CASE(CentralDifferenceWeights_Order6_AreTheClassicalStencil) {
  const auto w = CentralDifferenceWeights(6);
  const double expected[] = {-1.0 / 60, 9.0 / 60,  -45.0 / 60, 0,
                             45.0 / 60, -9.0 / 60, 1.0 / 60};
  for (int j = 0; j < 7; ++j)
    BOOST_TEST(w[j] == expected[j], boost::test_tools::tolerance(1e-14));
}
