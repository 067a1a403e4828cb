// What the linear algebra of one marched window costs: the matrix-free
// residual, the Jacobian's assembly, its banded factorization and one
// substitution, for a window of 48 points (the march's default) on Kepler
// e = 0.9 near pericentre, SBP42/63/84. The Newton of a window takes one
// residual and one substitution per correction and an assembly and a
// factorization per fresh Jacobian (solvers/variational/newton.h), so the
// table says what a chord step costs against a fresh Jacobian. Median of 7
// runs of 2,000 repetitions each, µs per call.
#include <cmath>
#include <cstdio>
#include <vector>

#include "bench/timing.h"
#include "core/action/reduced_system.h"
#include "core/sbp/builder.h"
#include "problems/kepler.h"
#include "solvers/variational/newton.h"

using namespace vivp;

int main() {
  const problems::Kepler kepler{.e = 0.9};
  const int n = 48, kRepeats = 2000;
  // Pericentre (r = 0.1, speed √19): the window spans about a radian.
  const double dt = 2e-3, r = 0.1, speed = std::sqrt(19.0);
  std::printf(
      "# one window of %d points, Kepler e = 0.9 at pericentre, "
      "dt = %g; median of 7 runs of %d calls, us per call\n",
      n, dt, kRepeats);
  std::printf("%-6s %4s %4s %9s %9s %9s %9s\n", "op", "kl", "ku", "residual",
              "assembly", "factor", "solve");
  for (const char* op : {"sbp42", "sbp63", "sbp84"}) {
    const sbp::RegularizedOperator<double> dbar(
        sbp::MakeOperator<double>(op, n, 0.0, dt * (n - 1)), -1.0);
    const action::ReducedSystem<problems::Kepler, double> system(
        kepler, dbar, {r, 0.0}, {0.0, speed}, 2);
    // The pericentre arc, and the multipliers near the converged ones.
    std::vector<double> y(system.size(), 0.0);
    for (int i = 0; i < n; ++i) {
      const double phase = speed / r * dt * i;
      y[system.X(i, 0)] = r * std::cos(phase);
      y[system.X(i, 1)] = r * std::sin(phase);
    }
    y[system.Lambda3(1)] = -speed;
    variational::BandedSolver<double> lu;
    lu.Prepare(system, y.data());
    std::vector<double> f(system.size());
    const auto per_call = [&](auto&& body) {
      return 1e6 / kRepeats * bench::MedianSeconds([&] {
               for (int k = 0; k < kRepeats; ++k) body();
             });
    };
    const double residual = per_call([&] {
      system.Residual(y.data(), f.data());
      bench::DoNotOptimize(f[0]);
    });
    const double assembly = per_call([&] {
      lu.Assemble(system, y.data());
      bench::DoNotOptimize(lu.jac.data()[0]);
    });
    lu.Assemble(system, y.data());
    const linalg::BandedMatrix<double> assembled = lu.jac;
    const double factor = per_call([&] {
      lu.jac = assembled;  // FactorBand overwrites it
      bench::DoNotOptimize(lu.Factorize());
    });
    const double copy = per_call([&] {
      lu.jac = assembled;
      bench::DoNotOptimize(lu.jac.data()[0]);
    });
    const double solve = per_call([&] {
      std::fill(f.begin(), f.end(), 1.0);
      lu.Solve(f.data());
      bench::DoNotOptimize(f[0]);
    });
    std::printf("%-6s %4d %4d %9.2f %9.2f %9.2f %9.2f\n", op, lu.kl, lu.ku,
                residual, assembly, factor - copy, solve);
  }
}
