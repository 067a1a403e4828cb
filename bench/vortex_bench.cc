// The Abelian Higgs model at critical coupling (e = v = λ = 1) in 2 + 1 D
// (docs/gauge.md §9, studies/vortex.h): a Nielsen–Olesen vortex and
// antivortex at (±L/4, 0) of the periodic [−L/2, L/2)², relaxed to a static
// critical point by L-BFGS, their energy per unit winding against the
// Bogomolny bound 2π v² for several h, the fitted order; then the relaxed
// pair marched with the space-time action: how far |φ| and the energy
// density move, the action's Gauss law, Newton's iterations and the
// seconds per window.
//
// Usage: vortex_bench [--static N...] [--march N] [--length L] [--op OP]
//                     [--window W] [--dt DT] [--windows K] [--simplicial]
//   --static 48 96 192   the grids of the bound's sweep (default)
//   --march N            march the pair relaxed on N × N points
//   --simplicial         factor Newton's normal equations by Eigen's
//                        simplicial LDLᵀ instead of CHOLMOD's supernodal LLᵀ
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "studies/vortex.h"

namespace {

struct Args {
  std::vector<int> grids;
  int march = 0, window = 16, windows = 2;
  double length = 24, dt = 0.1;
  std::string op = "sbp42";
  bool cholmod = true;
};

Args Parse(int argc, char** argv) {
  Args a;
  for (int k = 1; k < argc; ++k) {
    auto next = [&] {
      if (k + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", argv[k]);
        std::exit(2);
      }
      return argv[++k];
    };
    if (!std::strcmp(argv[k], "--static"))
      while (k + 1 < argc && argv[k + 1][0] != '-')
        a.grids.push_back(std::atoi(argv[++k]));
    else if (!std::strcmp(argv[k], "--march"))
      a.march = std::atoi(next());
    else if (!std::strcmp(argv[k], "--length"))
      a.length = std::atof(next());
    else if (!std::strcmp(argv[k], "--op"))
      a.op = next();
    else if (!std::strcmp(argv[k], "--window"))
      a.window = std::atoi(next());
    else if (!std::strcmp(argv[k], "--dt"))
      a.dt = std::atof(next());
    else if (!std::strcmp(argv[k], "--simplicial"))
      a.cholmod = false;
    else if (!std::strcmp(argv[k], "--windows"))
      a.windows = std::atoi(next());
    else {
      std::fprintf(stderr,
                   "usage: vortex_bench [--static N...] [--march N] "
                   "[--length L] [--op OP] [--window W] [--dt DT] "
                   "[--windows K] [--simplicial]\n");
      std::exit(2);
    }
  }
  if (a.grids.empty() && a.march == 0) a.grids = {48, 96, 192};
  return a;
}

void Static(const Args& a) {
  std::printf(
      "Vortex + antivortex on [-L/2, L/2)^2, L = %g, separation L/2 = %g; the "
      "static residual max|dU/dx|/h^2 at the ansatz, after L-BFGS, after "
      "Newton:\n"
      "%5s %7s %15s %12s %9s %9s %6s %7s %9s %6s %7s\n",
      a.length, a.length / 2, "N", "h", "U", "U/4π − 1", "start", "L-BFGS",
      "iters", "s", "Newton", "steps", "s");
  std::vector<double> hs, ds;
  for (int n : a.grids) {
    const auto r = vivp::studies::RelaxVortexPair(n, a.length);
    std::printf(
        "%5d %7.4f %15.11f %12.4e %9.1e %9.1e %6d %7.2f %9.1e %6d %7.2f\n", n,
        r.h, r.energy, r.deficit, r.start_residual, r.lbfgs_residual,
        r.iterations, r.lbfgs_seconds, r.residual, r.newton, r.seconds);
    hs.push_back(r.h);
    ds.push_back(r.deficit);
  }
  for (std::size_t k = 1; k < hs.size(); ++k)
    std::printf("order between h = %g and %g: %.3f\n", hs[k - 1], hs[k],
                std::log(ds[k - 1] / ds[k]) / std::log(hs[k - 1] / hs[k]));
  if (hs.size() > 1) {
    const auto fit = vivp::studies::FitPower(hs, ds);
    std::printf("least-squares fit: U/4π − 1 ≈ %.4f h^%.3f\n", fit.prefactor,
                fit.order);
  }
}

void March(const Args& a) {
  const auto pair = vivp::studies::RelaxVortexPair(a.march, a.length);
  std::printf(
      "Relaxed on %d^2 points, L = %g (h = %g): U/4π − 1 = %.4e, residual "
      "%.1e (%d L-BFGS iterations, %d Newton steps, %.1f s)\n",
      a.march, a.length, pair.h, pair.deficit, pair.residual, pair.iterations,
      pair.newton, pair.seconds);
  const auto r = vivp::studies::MarchVortexPair(pair, a.op, a.window, a.dt,
                                                a.windows, a.cholmod);
  std::printf(
      "%s, window %d, dt %g, %s: %s, %d windows to t = %g, %lld Newton "
      "iterations\n  max | |φ|(t) − |φ|(0) | = %.3e\n  max |Δ energy "
      "density| = %.3e (of max %.3f)\n  Gauss (action) = %.3e\n",
      a.op.c_str(), a.window, a.dt,
      a.cholmod ? "CHOLMOD supernodal" : "Eigen simplicial LDLT",
      r.ok ? "ok" : r.reason.c_str(), r.windows, r.t_end, r.newton, r.modulus,
      r.energy_density, r.energy_scale, r.gauss);
  for (std::size_t k = 0; k < r.window_seconds.size(); ++k)
    std::printf("  window %zu: %.2f s\n", k, r.window_seconds[k]);
}

}  // namespace

int main(int argc, char** argv) {
  const Args a = Parse(argc, argv);
  if (!a.grids.empty()) Static(a);
  if (a.march > 0) March(a);
  return 0;
}
