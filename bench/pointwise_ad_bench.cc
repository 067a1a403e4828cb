// Which automatic differentiation for the pointwise density
// (docs/method.md §4): Ceres Jets or Eigen's AutoDiffScalar, first order (the
// residual ∇S) and nested second order (the Newton Jacobian), on the
// damped-oscillator density f(x1, v1, x2, v2) = L1 − L2 + Λ. Nested Jets
// cannot take a user's `T(0.5)` (Ceres 2.1), so the density here lifts its
// constants explicitly for both.
#include <chrono>
#include <cstdio>

#include "bench/timing.h"
#include "core/autodiff/pointwise.h"
#include "core/autodiff/scalar.h"

namespace {

constexpr double kMu = 0.5, kKappa = 1.0, kXi = 0.00071;

template <class T, class C>
T DampedDensity(const T* z, C lift) {
  const T& x1 = z[0];
  const T& v1 = z[1];
  const T& x2 = z[2];
  const T& v2 = z[3];
  return lift(0.5 * kMu) * (v1 * v1 - v2 * v2) -
         lift(0.5 * kKappa) * (x1 * x1 - x2 * x2) -
         lift(0.5 * kXi) * (v1 + v2) * (x1 - x2);
}

constexpr int kNodes = 1 << 20;

template <class F>
double NsPerNode(F&& f) {
  return 1e9 * vivp::bench::MedianSeconds(f, 5) / kNodes;
}

}  // namespace

int main() {
  double sink = 0;
  auto z_at = [](int i, double* z) {
    z[0] = 1e-6 * i;
    z[1] = 0.3;
    z[2] = z[0];
    z[3] = 0.3;
  };
  // First order: gradient in 4 variables.
  const double adiff1 = NsPerNode([&] {
    for (int i = 0; i < kNodes; ++i) {
      double z[4];
      z_at(i, z);
      const auto g = vivp::autodiff::Gradient<double, 4>(
          [](const auto* s) {
            using T = std::decay_t<decltype(*s)>;
            return DampedDensity(s, [](double c) { return T(c); });
          },
          z);
      sink += g.second[1];
    }
  });
  using Jet4 = ceres::Jet<double, 4>;
  const double jet1 = NsPerNode([&] {
    for (int i = 0; i < kNodes; ++i) {
      double z[4];
      z_at(i, z);
      Jet4 s[4];
      for (int k = 0; k < 4; ++k) s[k] = Jet4(z[k], k);
      const Jet4 f = DampedDensity(s, [](double c) { return Jet4(c); });
      sink += f.v[1];
    }
  });
  // Second order: Hessian in 4 variables.
  const double adiff2 = NsPerNode([&] {
    for (int i = 0; i < kNodes; ++i) {
      double z[4];
      z_at(i, z);
      const auto h = vivp::autodiff::Hessian<double, 4>(
          [](const auto* s) {
            using T = std::decay_t<decltype(*s)>;
            return DampedDensity(s, [](double c) { return T(c); });
          },
          z);
      sink += h.hessian(1, 1);
    }
  });
  using Nested = ceres::Jet<Jet4, 4>;
  const double jet2 = NsPerNode([&] {
    for (int i = 0; i < kNodes; ++i) {
      double z[4];
      z_at(i, z);
      Nested s[4];
      for (int k = 0; k < 4; ++k) {
        s[k] = Nested(Jet4(z[k], k));
        s[k].v[k] = Jet4(1.0);
      }
      const Nested f = DampedDensity(
          s, [](double c) { return vivp::autodiff::Lift<Nested>(c); });
      sink += f.v[1].v[1];
    }
  });
  std::printf(
      "# pointwise AD of the damped density (4 variables), ns per node, "
      "median of 5 runs over 2^20 nodes\n");
  std::printf("%-28s %12s %12s %8s\n", "derivative", "AutoDiffScalar",
              "ceres::Jet", "ratio");
  std::printf("%-28s %12.1f %12.1f %8.2f\n", "gradient (residual)", adiff1,
              jet1, adiff1 / jet1);
  std::printf("%-28s %12.1f %12.1f %8.2f\n", "Hessian (Newton Jacobian)",
              adiff2, jet2, adiff2 / jet2);
  std::printf("# (checksum %g)\n", sink);
}
