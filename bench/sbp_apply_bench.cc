// Cost of the stencil apply u -> D u per point, N = 10^3 ... 10^7, for each
// operator, in double and for a Jet<double, 4> (the pointwise derivative type
// of a 2-DOF doubled system). Constant time per point means O(N).
#include <cmath>
#include <cstdio>
#include <vector>

#include "bench/timing.h"
#include "core/sbp/builder.h"

int main() {
  using Jet = ceres::Jet<double, 4>;
  std::printf(
      "# D u: median of 15 runs (7 from N = 10^6), nanoseconds per point;"
      " Jet<double,4> up to N = 10^6 (two arrays of 10^7 Jets take 800 MB)\n");
  std::printf("%-7s %10s %12s %12s %14s\n", "op", "N", "double", "D^T u",
              "Jet<double,4>");
  for (const std::string& name : vivp::sbp::OperatorNames()) {
    for (long n = 1000; n <= 10000000; n *= 10) {
      const auto d = vivp::sbp::MakeOperator<double>(name, n);
      std::vector<double> u(n), du(n);
      for (long i = 0; i < n; ++i) u[i] = std::sin(1e-3 * i);
      const int repeats = n <= 100000 ? 15 : 7;
      const double t_apply = vivp::bench::MedianSeconds(
          [&] {
            d.Apply(std::span<const double>(u), std::span<double>(du));
            vivp::bench::DoNotOptimize(du[n / 2]);
          },
          repeats);
      const double t_transpose = vivp::bench::MedianSeconds(
          [&] {
            d.ApplyTranspose(std::span<const double>(u), std::span<double>(du));
            vivp::bench::DoNotOptimize(du[n / 2]);
          },
          repeats);
      double t_jet = NAN;
      if (n <= 1000000) {
        std::vector<Jet> uj(n), duj(n);
        for (long i = 0; i < n; ++i) uj[i] = Jet(u[i], static_cast<int>(i % 4));
        t_jet = vivp::bench::MedianSeconds(
            [&] {
              d.Apply(std::span<const Jet>(uj), std::span<Jet>(duj));
              vivp::bench::DoNotOptimize(duj[n / 2].a);
            },
            repeats);
      }
      std::printf("%-7s %10ld %12.2f %12.2f", std::string(name).c_str(), n,
                  1e9 * t_apply / n, 1e9 * t_transpose / n);
      if (std::isnan(t_jet))
        std::printf(" %14s\n", "-");
      else
        std::printf(" %14.2f\n", 1e9 * t_jet / n);
    }
  }
}
