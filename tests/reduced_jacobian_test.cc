// The assembled Jacobian of the reduced point-mechanics system
// (core/action/reduced_system.h) against central differences of its
// matrix-free residual, for every kind of density the assembly treats
// apart: a separable one with a constant mass (Kepler: only the node's own
// block besides K ⊗ M), one with velocity–position terms (a charge in a
// magnetic field), a dissipative Λ (the damped oscillator), a mass that
// varies along the path (the assembly gives up K ⊗ M after one Jacobian),
// and a first-order density (M = 0). Each in the band storage the solver
// factors and through the entry-by-entry sink, three assemblies in a row.
// Also the two shortcuts beside the assembly: K ⊗ M added at band offsets
// located once (BandedMatrix::BlockOffset), the Euler–Lagrange
// acceleration from the velocity rows of the Hessian alone, and from
// M⁻¹ ∂L/∂x for a Lagrangian that declares kConstantMass (with the checks
// that catch a wrong declaration).
#define BOOST_TEST_MODULE reduced_jacobian
#include <Eigen/Dense>
#include <algorithm>
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/action/erased_problem.h"
#include "core/action/euler_lagrange.h"
#include "core/action/reduced_system.h"
#include "core/linalg/banded.h"
#include "core/sbp/builder.h"
#include "problems/anharmonic.h"
#include "problems/composed.h"
#include "problems/coupled_oscillators.h"
#include "problems/cyclotron.h"
#include "problems/damped_oscillator.h"
#include "problems/exponential.h"
#include "problems/free_fall.h"
#include "problems/kepler.h"
#include "problems/pendulum.h"

namespace {

using vivp::action::ReducedSystem;

// L = ½(1 + x²)ẋ² − ½x²: the vv block differs from node to node.
struct VaryingMass {
  static constexpr int kDim = 1;
  template <class T>
  T operator()(const T* x, const T* v) const {
    return T(0.5) * (T(1) + x[0] * x[0]) * v[0] * v[0] - T(0.5) * x[0] * x[0];
  }
};

struct DenseSink {
  Eigen::MatrixXd m;
  void Add(int i, int j, double v) { m(i, j) += v; }
};

// J by central differences of the residual, column by column.
template <class System>
Eigen::MatrixXd Differences(const System& s, std::vector<double> y) {
  const int n = s.size();
  Eigen::MatrixXd j(n, n);
  std::vector<double> fp(n), fm(n);
  for (int c = 0; c < n; ++c) {
    const double y0 = y[c], h = 1e-6 * std::max(1.0, std::abs(y0));
    y[c] = y0 + h;
    s.Residual(y.data(), fp.data());
    y[c] = y0 - h;
    s.Residual(y.data(), fm.data());
    y[c] = y0;
    for (int r = 0; r < n; ++r) j(r, c) = (fp[r] - fm[r]) / (2 * h);
  }
  return j;
}

// max |J − J_fd| / max |J| over three assemblies in a row, each in the band
// storage and in a dense sink; and for the residual evaluated with the
// Jacobian (ResidualAndJacobian), max |F − F_alone| / max |F| and whether its
// band equals the Jacobian's alone entry for entry.
// OverwriteJacobian, into a band holding NaN: max |J_over − J| / max |J|
// (NaN if an entry was not written) and whether its residual equals
// ResidualAndJacobian's to the bit.
struct Errors {
  double jacobian = 0, fused_residual = 0, overwritten = 0;
  bool fused_band_equal = true, overwritten_residual_equal = true;
};
template <class P>
Errors WorstErrors(const P& problem, const std::string& op, int order) {
  constexpr int d = P::kDim;
  const int n = 40;
  const double dt = 0.05;
  const vivp::sbp::RegularizedOperator<double> dbar(
      vivp::sbp::MakeOperator<double>(op, n, 0.0, dt * (n - 1)), -1.0);
  std::array<double, d> x0{}, v0{};
  for (int c = 0; c < d; ++c) {
    x0[c] = 0.8 + 0.1 * c;
    v0[c] = 0.3 - 0.2 * c;
  }
  const ReducedSystem<P, double> s(problem, dbar, x0, v0, order);
  // A smooth path, not a solution, and multipliers of size one.
  std::vector<double> y(s.size(), 0.7);
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < d; ++c)
      y[s.X(i, c)] =
          x0[c] + v0[c] * dt * i + 0.2 * std::sin(0.3 * i + c) * (c + 1);
  const Eigen::MatrixXd reference = Differences(s, y);
  const double scale = reference.cwiseAbs().maxCoeff();
  // The band probed on a system of its own: the first assembly of `s` is
  // then the one that still tries K ⊗ M on a varying mass.
  const ReducedSystem<P, double> other(problem, dbar, x0, v0, order);
  const auto probe = vivp::linalg::ProbeBand(other, y.data(), n, 32);
  Errors e;
  std::vector<double> f(s.size()), fused_f(s.size()), over_f(s.size());
  for (int k = 0; k < 3; ++k) {
    DenseSink dense{Eigen::MatrixXd::Zero(s.size(), s.size())};
    s.Jacobian(y.data(), dense);
    vivp::linalg::BandedMatrix<double> band(s.size(), probe.kl, probe.ku);
    band.SetZero();
    s.Jacobian(y.data(), band);
    vivp::linalg::BandedMatrix<double> fused(s.size(), probe.kl, probe.ku);
    fused.SetZero();
    s.ResidualAndJacobian(y.data(), fused_f.data(), fused);
    // A constant mass's K ⊗ M is written over the band first (the node
    // terms added to it); any other density's band is zeroed first.
    vivp::linalg::BandedMatrix<double> over(s.size(), probe.kl, probe.ku);
    std::fill(over.data(),
              over.data() + std::size_t(over.leading_dimension()) * over.size(),
              std::numeric_limits<double>::quiet_NaN());
    s.OverwriteJacobian(y.data(), over, over_f.data());
    e.overwritten_residual_equal &= over_f == fused_f;
    s.Residual(y.data(), f.data());
    double f_scale = 0, f_gap = 0;
    for (int r = 0; r < s.size(); ++r) {
      f_scale = std::max(f_scale, std::abs(f[r]));
      f_gap = std::max(f_gap, std::abs(fused_f[r] - f[r]));
      for (int c = 0; c < s.size(); ++c) {
        e.jacobian =
            std::max(e.jacobian, std::abs(band(r, c) - reference(r, c)));
        e.jacobian =
            std::max(e.jacobian, std::abs(dense.m(r, c) - reference(r, c)));
        e.fused_band_equal &= fused(r, c) == band(r, c);
        // NaN (an entry the overwrite missed) fails the test below.
        const double gap = std::abs(over(r, c) - band(r, c));
        e.overwritten = std::isnan(gap) ? gap : std::max(e.overwritten, gap);
      }
    }
    e.fused_residual = std::max(e.fused_residual, f_gap / f_scale);
  }
  e.jacobian /= scale;
  e.overwritten /= scale;
  return e;
}

const std::vector<std::string> kOperators = {"sbp21", "sbp42", "sbp63",
                                             "sbp84"};

}  // namespace

BOOST_DATA_TEST_CASE(assembled_jacobian_is_the_residuals_derivative,
                     boost::unit_test::data::make(kOperators), op) {
  const Errors kepler =
      WorstErrors(vivp::problems::Kepler{.e = 0.9}, op, /*order=*/2);
  const Errors cyclotron = WorstErrors(vivp::problems::Cyclotron{}, op, 2);
  const Errors damped = WorstErrors(vivp::problems::DampedOscillator{}, op, 2);
  const Errors varying = WorstErrors(VaryingMass{}, op, 2);
  const Errors first = WorstErrors(vivp::problems::Exponential{}, op, 1);
  for (const auto& [name, e] : {std::pair{"Kepler", kepler},
                                {"cyclotron", cyclotron},
                                {"damped", damped},
                                {"varying mass", varying},
                                {"first order", first}}) {
    BOOST_TEST_MESSAGE(op << ", " << name << ": Jacobian " << e.jacobian
                          << ", residual with the Jacobian "
                          << e.fused_residual);
    // Central differences at h = 1e-6: truncation h² ~ 1e-12 and
    // cancellation ε/h ~ 1e-10 relative; an entry missing or counted twice
    // is O(1).
    BOOST_TEST(e.jacobian < 1e-7, name);
    // The residual's pointwise gradient from the second-order derivatives'
    // pass: the same numbers up to rounding in the automatic
    // differentiation (Clang 14: the same bits for all five problems).
    BOOST_TEST(e.fused_residual < 1e-13, name);
    BOOST_TEST(e.fused_band_equal, name);
    // Written over NaN: every entry set. The node terms are added to the
    // K ⊗ M fill instead of the fill to them, which could move a last bit
    // where an entry sums several node terms; for these five problems the
    // bands are equal entry for entry.
    BOOST_TEST(e.overwritten == 0.0, name);
    BOOST_TEST(e.overwritten_residual_equal, name);
  }
}

// A block added at an offset located once is the block AddBlockInBand adds,
// to the bit, and a block reaching outside the band has no offset.
BOOST_AUTO_TEST_CASE(block_offsets_add_what_add_block_in_band_adds) {
  vivp::linalg::BandedMatrix<double> a(9, 3, 2), b(9, 3, 2);
  Eigen::Matrix2d block;
  block << 0.3, -1.7, 2.9, 0.11;
  const double scale = 1.0 / 3.0;
  int inside = 0;
  for (int i = 0; i + 2 <= 9; ++i)
    for (int j = 0; j + 2 <= 9; ++j) {
      const std::ptrdiff_t at = a.BlockOffset<2>(i, j);
      const bool fits =
          b.AddBlockInBand<2>(i, j, Eigen::Matrix2d(scale * block));
      BOOST_TEST((at >= 0) == fits);
      if (at < 0) continue;
      ++inside;
      a.AddBlockAt<2>(at, scale, block);
    }
  BOOST_TEST(inside > 0);
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) BOOST_TEST(a(i, j) == b(i, j));
}

// ẍ from ∂L/∂x and the velocity rows [G_vx G_vv] (GradientAndLastRows)
// against ẍ from the whole doubled-density derivatives: the same bits, for
// a separable density (Kepler, the anharmonic oscillator) and one whose
// velocity rows couple to the position (the cyclotron).
template <class P>
void CheckAcceleration(const P& problem, const double* x, const double* v) {
  constexpr int d = P::kDim;
  double p[2 * d];
  for (int c = 0; c < d; ++c) {
    p[c] = x[c];
    p[d + c] = v[c];
  }
  const auto rows = vivp::action::Acceleration(problem, x, v);
  const auto whole = vivp::action::AccelerationFrom<d>(
      vivp::action::DiagonalDerivatives<double>(problem, p), v);
  for (int c = 0; c < d; ++c) {
    BOOST_TEST(std::isfinite(rows[c]));
    BOOST_TEST(rows[c] == whole[c]);
  }
}

BOOST_AUTO_TEST_CASE(acceleration_from_velocity_rows_equals_whole_hessian) {
  const double x2[] = {0.37, -1.21}, v2[] = {0.8, 2.3};
  CheckAcceleration(vivp::problems::Kepler{.e = 0.9}, x2, v2);
  CheckAcceleration(vivp::problems::Cyclotron{}, x2, v2);
  const double x1[] = {0.83}, v1[] = {-0.4};
  CheckAcceleration(vivp::problems::Anharmonic{}, x1, v1);
}

// L = ½ẋᵀMẋ − V(x) with a full, not unit, mass matrix.
struct FullMass {
  static constexpr int kDim = 2;
  static constexpr bool kConstantMass = true;
  template <class T>
  T operator()(const T* x, const T* v) const {
    return T(0.5) *
               (T(2.0) * v[0] * v[0] + v[0] * v[1] + T(1.5) * v[1] * v[1]) -
           T(0.25) * x[0] * x[0] * x[0] * x[0] - x[0] * x[1] * x[1];
  }
};

// Declared wrongly: ∂²L/∂x∂ẋ = x ≠ 0, and (below) a mass that varies.
struct CoupledDeclared {
  static constexpr int kDim = 1;
  static constexpr bool kConstantMass = true;
  template <class T>
  T operator()(const T* x, const T* v) const {
    return T(0.5) * v[0] * v[0] + T(0.5) * x[0] * x[0] * v[0];
  }
};
struct VaryingDeclared : VaryingMass {
  static constexpr bool kConstantMass = true;
};

// M⁻¹ ∂L/∂x (Accelerator) against G_vv⁻¹(g_x − G_vx ẋ) (Acceleration): the
// same up to the rounding of M⁻¹ against a solve with M, and the same
// through the compiled model (action::Erase) as from the type itself.
template <class P>
void CheckConstantMass(const P& problem, const double* x, const double* v) {
  constexpr int d = P::kDim;
  BOOST_TEST(vivp::action::ConstantMass(problem));
  vivp::action::Accelerator<P> fast(problem);
  const auto erased = vivp::action::Erase(problem);
  vivp::action::Accelerator<vivp::action::ErasedProblem<d>> fast_erased(erased);
  BOOST_TEST(vivp::action::ConstantMass(erased));
  for (int k = 0; k < 3; ++k) {
    double xk[d], vk[d];
    for (int c = 0; c < d; ++c) {
      xk[c] = x[c] * (1.0 + 0.3 * k);
      vk[c] = v[c] - 0.2 * k;
    }
    const auto a = fast(xk, vk);
    const auto general = vivp::action::Acceleration(problem, xk, vk);
    const auto b = fast_erased(xk, vk);
    for (int c = 0; c < d; ++c) {
      BOOST_TEST(std::abs(a[c] - general[c]) <=
                 4e-16 * general.cwiseAbs().maxCoeff());
      BOOST_TEST(a[c] == b[c]);
    }
  }
}

BOOST_AUTO_TEST_CASE(constant_mass_acceleration_equals_the_general_one) {
  const double x2[] = {0.37, -1.21}, v2[] = {0.8, 2.3};
  CheckConstantMass(vivp::problems::Kepler{.e = 0.9}, x2, v2);
  CheckConstantMass(vivp::problems::CoupledOscillators{}, x2, v2);
  CheckConstantMass(FullMass{}, x2, v2);
  const double x1[] = {0.83}, v1[] = {-0.4};
  CheckConstantMass(vivp::problems::Anharmonic{}, x1, v1);
  CheckConstantMass(vivp::problems::Pendulum{}, x1, v1);
  CheckConstantMass(vivp::problems::FreeFall{.m = 2.5, .g = 9.81}, x1, v1);
  // Composed at run time: kinetic effects and potentials say so (a full
  // mass matrix in two coordinates); with a Λ effect they do not.
  namespace fx = vivp::problems::effects;
  CheckConstantMass(
      vivp::problems::Composed<1>{{fx::Kinetic{2.5, {}}, fx::Quartic{3.0}}}, x1,
      v1);
  CheckConstantMass(
      vivp::problems::Composed<2>{
          {fx::Kinetic{1.0, {2.0, 0.5, 0.5, 1.5}}, fx::Central{1.0}}},
      x2, v2);
  BOOST_TEST(!vivp::action::ConstantMass(vivp::problems::Composed<1>{
      {fx::Kinetic{}, fx::Spring{}, fx::Damping{}}}));
  // Potentials alone (M = 0): a part of a sum with a kinetic energy, as a
  // scene adds its effects to a registered Lagrangian.
  const auto sum =
      vivp::action::Erase(vivp::problems::Anharmonic{}) +
      vivp::action::Erase(vivp::problems::Composed<1>{{fx::Spring{2.0, {}}}});
  BOOST_TEST(vivp::action::ConstantMass(sum));
  vivp::action::Accelerator<vivp::action::ErasedProblem<1>> summed(sum);
  const double a_sum = summed(x1, v1)[0];
  const double a_general = vivp::action::Acceleration(sum, x1, v1)[0];
  BOOST_TEST(std::abs(a_sum - a_general) <= 4e-16 * std::abs(a_general));
  BOOST_TEST(
      vivp::action::ConstantMass(vivp::problems::Composed<1>{{fx::Spring{}}}));
  // Not declared: the cyclotron (x–ẋ coupling), damped (Λ), first order.
  BOOST_TEST(!vivp::action::ConstantMass(vivp::problems::Cyclotron{}));
  BOOST_TEST(!vivp::action::ConstantMass(vivp::problems::DampedOscillator{}));
  BOOST_TEST(!vivp::action::ConstantMass(vivp::problems::Exponential{}));
}

bool NamesTheDeclaration(const std::invalid_argument& e) {
  return std::string(e.what()).find("kConstantMass") != std::string::npos;
}

// A wrong declaration fails by name: where the acceleration first sees
// ∂²L/∂x∂ẋ ≠ 0, and where an assembly sees ∂²L/∂ẋ² vary from node to node
// (at ẋ = 0 the varying mass has no x–ẋ term for the first check to see).
BOOST_AUTO_TEST_CASE(a_wrong_constant_mass_declaration_is_an_error) {
  const double x[] = {0.8}, v[] = {0.3}, rest[] = {0.0};
  vivp::action::Accelerator<CoupledDeclared> coupled(CoupledDeclared{});
  BOOST_CHECK_EXCEPTION(coupled(x, v), std::invalid_argument,
                        NamesTheDeclaration);
  vivp::action::Accelerator<VaryingDeclared> varying(VaryingDeclared{});
  BOOST_TEST(std::isfinite(varying(x, rest)[0]));
  const int n = 24;
  const vivp::sbp::RegularizedOperator<double> dbar(
      vivp::sbp::MakeOperator<double>("sbp42", n, 0.0, 1.0), -1.0);
  const ReducedSystem<VaryingDeclared, double> s(VaryingDeclared{}, dbar, {0.8},
                                                 {0.0}, 2);
  std::vector<double> y(s.size(), 0.0);
  for (int i = 0; i < n; ++i) y[s.X(i, 0)] = 0.8 - 0.3 * i / double(n);
  vivp::linalg::BandwidthProbe probe;
  BOOST_CHECK_EXCEPTION(s.Jacobian(y.data(), probe), std::invalid_argument,
                        NamesTheDeclaration);
}
