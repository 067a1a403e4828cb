// A Lagrangian of one's own, solved and measured with an installed vivp.
// A particle runs up an exponential wall:
//   L = ½ẋ² − ½e^(−2x),  so  ẍ = e^(−2x),  and from x(0) = 0, ẋ(0) = 0
//   x(t) = ln cosh t.
// The program solves it with SBP42 on four grids, fits the order of the
// error at t = 2, plots the errors (exponential_wall.png in the directory
// given, default the current one) and exits with 1 if a check fails.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "report/plot.h"
#include "solvers/variational/solve.h"
#include "studies/convergence.h"
#include "studies/registry.h"

struct ExponentialWall {
  static constexpr int kDim = 1;
  template <class T>
  T operator()(const T* x, const T* v) const {
    using std::exp;
    return T(0.5) * v[0] * v[0] - T(0.5) * exp(T(-2.0) * x[0]);
  }
};

int main(int argc, char** argv) {
  const double t_end = 2.0, exact = std::log(std::cosh(t_end));
  vivp::studies::ConvergenceStudy study;
  std::vector<std::vector<double>> errors;  // Δt, |x_N − x|, |x_N + λ4 − x|
  for (const long long n : {32, 64, 128, 256}) {
    const auto sol =
        vivp::variational::Solve(ExponentialWall{}, {.x = {0.0}, .v = {0.0}},
                                 {.op = "sbp42", .points = n, .t_end = t_end});
    study.rows.push_back({
        .points = n,
        .dt = t_end / n,
        .dt_true = t_end / (n - 1),
        .err_x = std::abs(sol.x1(n - 1, 0) - exact),
        .err_x_corrected = std::abs(sol.corrected.position[0] - exact),
        .converged = sol.status.converged,
    });
    const auto& r = study.rows.back();
    errors.push_back({r.dt, r.err_x, r.err_x_corrected});
    std::printf("Nt = %3lld: error of x_N %.2e, of x_N + λ4 %.2e\n", n, r.err_x,
                r.err_x_corrected);
  }
  vivp::studies::FitOrders(study, 1e-13);  // below 1e-13: round-off
  std::printf("fitted orders: x_N %.2f, x_N + λ4 %.2f\n", study.orders.x,
              study.orders.x_corrected);

  vivp::report::Figure fig(argc > 1 ? argv[1] : ".", "exponential_wall");
  const auto data = fig.Data("errors", errors, "dt err_x err_x_corrected");
  fig.script() << "set logscale xy\nset key top left\nset xlabel 'Δt'\n"
               << "set ylabel 'error at t = 2'\n"
               << "plot '" << data << "' using 1:2 with linespoints title "
               << "'x_N', '' using 1:3 with linespoints title 'x_N + λ4'\n";
  std::printf("wrote %s\n", fig.Render().c_str());

  int failed = 0;
  auto check = [&](bool ok, const char* what) {
    std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
    failed += !ok;
  };
  check(std::ranges::all_of(study.rows,
                            &vivp::studies::ConvergenceRow::converged),
        "every solve converged");
  // x_N is of order 3 with SBP42, x_N + λ4 of order 4 (docs/method.md §7).
  check(study.orders.x_corrected >= 3.5, "x_N + λ4 converges at order ≥ 3.5");
  check(study.rows.back().err_x_corrected <= 1e-8,
        "its error at Nt = 256 ≤ 1e-8");
  // vivp::vivp links vivp's own named Lagrangians too (lagrangians/).
  check(vivp::studies::HasProblem("anharmonic"),
        "vivp's named problems linked");
  return failed ? 1 : 0;
}
