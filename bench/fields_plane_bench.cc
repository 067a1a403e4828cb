// Cost of the space-time field solve in 2 + 1 dimensions (solvers/spacetime
// on an sbp::SpaceGrid of two periodic axes), on the sine-Gordon ring
// soliton of Christiansen & Lomdahl ("Numerical solutions of 2+1 dimensional
// sine-Gordon solitons", Physica D 2 (1981) 482): φ(0) = 4 atan(exp(3 − r)),
// φ_t(0) = 0 on [−14, 14)², order-8 periodic differences.
//
// 1. One Newton iteration over one window of 16 time points on N² points
//    (Δt = 0.02) with the space-diagonalized solve: residual, Hessian
//    blocks, factorization of every distinct mode's time system, one solve;
//    peak memory of the run.
// 2. (--ring N T [W [F]]) The ring marched to T on N² points, SBP42 in
//    windows of W (16) at F (0.9) of the resolution limit: time, Newton
//    iterations, fallbacks, microseconds per site and time step, peak memory,
//    energy at 0 and T. Started by mpirun (`mpirun -np 2
//    fields_plane_bench --ring N T W F`), the same march with space spread
//    over the ranks (solvers/distributed/solve.h); rank 0 prints, and the
//    peak memory is per rank.
// 3. (--compare) Work at equal error on 64² points to t = 2 against the
//    method of lines on the same spatial operator (leapfrog, Gauss4): the
//    error of φ at t = 2 against a Gauss6 run of 4096 steps (time error
//    only), seconds and nanoseconds per site and step.
//
// Usage: fields_plane_bench [--ring N T [W [F]]] [--compare]   (default: table
// 1)
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench/timing.h"
#include "core/action/field_charges.h"
#include "core/action/field_system.h"
#include "problems/fields/densities.h"
#include "solvers/distributed/solve.h"
#include "solvers/spacetime/method_of_lines.h"
#include "solvers/spacetime/resolution.h"
#include "solvers/spacetime/solve.h"

using namespace vivp;

namespace {

using Density = fields::SineGordonIn<2>;
using Grid = sbp::SpaceGrid<double>;

double Since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
      .count();
}

Grid RingGrid(int n) {
  const auto axis = sbp::SpaceDerivative<double>::Periodic(8, n, -14.0, 28.0);
  return Grid({axis, axis});
}

// The ring's initial data on the grid.
void RingData(const Grid& g, std::vector<double>& phi0,
              std::vector<double>& pi0) {
  phi0.resize(g.points());
  pi0.assign(g.points(), 0.0);
  for (int j = 0; j < g.points(); ++j)
    phi0[j] = 4 * std::atan(std::exp(3 - std::hypot(g.x(j, 0), g.x(j, 1))));
}

void Table1() {
  std::printf(
      "One Newton iteration, sine-Gordon ring on N² points, one window of 16\n"
      "time points (SBP42, Δt = 0.02), space-diagonalized solve (seconds;\n"
      "peak RSS of the run)\n\n"
      "| N² | unknowns | residual | blocks | factor | solve | total | "
      "distinct systems | factors MB | peak MB |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n");
  for (int n : {128, 256, 512}) {
    const double mb = bench::PeakMegabytesInChild([&] {
      const Density density;
      const Grid g = RingGrid(n);
      std::vector<double> phi0, pi0;
      RingData(g, phi0, pi0);
      const int w = 16;
      const sbp::RegularizedOperator<double> op(
          sbp::MakeOperator<double>("sbp42", w, 0.0, 0.02 * (w - 1)));
      const action::FieldSystem<Density> sys(density, op, g, phi0, pi0);
      std::vector<double> y(sys.size(), 0.0), f(sys.size());
      for (int j = 0; j < g.points(); ++j)
        for (int i = 0; i < w; ++i) y[sys.Phi(i, j, 0)] = phi0[j];
      spacetime::ModesSolver<Density> modes(density);
      auto t0 = std::chrono::steady_clock::now();
      sys.Residual(y.data(), f.data());
      const double residual = Since(t0);
      t0 = std::chrono::steady_clock::now();
      modes.Prepare(sys, y.data());
      modes.Assemble(sys, y.data());
      const double blocks = Since(t0);
      t0 = std::chrono::steady_clock::now();
      if (!modes.Factorize()) std::printf("singular!\n");
      const double factor = Since(t0);
      t0 = std::chrono::steady_clock::now();
      modes.Solve(f.data());
      const double solve = Since(t0);
      std::printf(
          "| %d² | %d | %.3f | %.3f | %.3f | %.3f | **%.3f** | %d | %.0f |", n,
          sys.size(), residual, blocks, factor, solve,
          residual + blocks + factor + solve, modes.distinct_systems(),
          modes.factor_bytes() / 1048576.0);
    });
    std::printf(" %.0f |\n", mb);
  }
  std::printf("\n");
}

void Ring(int n, double t_end, int w, double fraction) {
  const auto& comm = distributed::Comm::World();
  const bool spread = distributed::Launched();
  if (comm.root())
    std::printf(
        "Sine-Gordon ring on %d² points to t = %g (SBP42, windows of %d, Δt "
        "at\n"
        "%g of the resolution limit)\n\n"
        "| time points | Δt | windows | Newton its | fallbacks | seconds | "
        "μs per site·step | E(0) | E(T) | converged |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n",
        n, t_end, w, fraction);
  auto run = [&] {
    const Density density;
    const Grid g = RingGrid(n);
    std::vector<double> phi0, pi0;
    RingData(g, phi0, pi0);
    const double omega = spacetime::FastestFieldFrequency(
        density, g, spacetime::SpectralRadius(g), phi0, pi0);
    const long long nt =
        (static_cast<long long>(std::ceil(t_end * omega / fraction / (w - 1))) *
         (w - 1)) +
        1;
    spacetime::FieldSolveOptions o;
    o.keep_field = false;
    const auto start = std::chrono::steady_clock::now();
    if (comm.root())
      o.on_window = [&](int done, int total, double t) {
        const double s = Since(start);
        std::fprintf(stderr, "\r  window %d/%d, t = %.2f, %.0f s, ETA %.0f s ",
                     done, total, t, s, s * (total - done) / done);
      };
    const spacetime::FieldGrid fg{
        .op = "sbp42", .points = nt, .t_end = t_end, .window_points = w};
    const auto r =
        spread ? distributed::SolveField(comm, density, g, fg, phi0, pi0, o)
               : spacetime::SolveField(density, g, fg, phi0, pi0, o);
    if (!comm.root()) return;
    std::fprintf(stderr, "\n");
    if (spread) std::printf("(space on %d ranks)\n", comm.size());
    const auto e0 = action::ChargesOfSlice(density, g, phi0, pi0);
    const auto e1 = r.status.converged ? action::ChargesOfSlice(
                                             density, g, r.end.phi, r.end.phi_t)
                                       : action::FieldCharges{};
    std::printf("| %lld | %.4g | %d | %lld | %d | %.1f | %.3f |", nt, r.dt,
                r.windows, r.factorizations, r.fallbacks, r.seconds_total,
                1e6 * r.seconds_total / (double(nt - 1) * g.points()));
    std::printf(" %.10g | %.10g | %s |\n", e0.energy, e1.energy,
                r.status.converged ? "yes" : r.status.reason.c_str());
    std::printf(
        "\nseconds in: residual %.1f, blocks %.1f, factor %.1f, solve %.1f, "
        "setup %.1f, predictor %.1f, check %.1f, hand-off %.1f; Newton "
        "corrections %d, predictor steps %ld\n",
        r.seconds_residual, r.seconds_assembly, r.seconds_factor,
        r.seconds_solve, r.seconds_setup, r.seconds_predictor, r.seconds_check,
        r.seconds_handoff, r.corrections, r.predictor_steps);
  };
  if (!spread) {
    std::printf("peak MB of the run: %.0f\n\n",
                bench::PeakMegabytesInChild(run));
    return;
  }
  // No fork under MPI: this process's own peak, per rank, on rank 0.
  run();
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  double mb[1] = {usage.ru_maxrss / 1024.0};
  comm.Max(mb);
  if (comm.root()) std::printf("peak MB of a rank: %.0f\n\n", mb[0]);
}

void Compare() {
  std::printf(
      "Work at equal error: sine-Gordon ring on 64² points to t = 2, error of\n"
      "φ(2) against Gauss6 with 4096 steps on the same spatial operator\n\n"
      "| method | steps | max error | seconds | ns per site·step |\n"
      "|---|---|---|---|---|\n");
  const Density density;
  const Grid g = RingGrid(64);
  std::vector<double> phi0, pi0;
  RingData(g, phi0, pi0);
  const double t_end = 2;
  spacetime::MolOptions ro{.method = "gauss6", .steps = 4096};
  const auto ref = spacetime::SolveFieldMol(density, g, t_end, phi0, pi0, ro);
  const std::size_t n = g.points();
  const std::vector<double> exact(ref.phi.end() - long(n), ref.phi.end());
  auto error = [&](const std::vector<double>& phi) {
    double e = 0;
    for (std::size_t j = 0; j < n; ++j)
      e = std::max(e, std::abs(phi[phi.size() - n + j] - exact[j]));
    return e;
  };
  auto row = [&](const std::string& name, long long steps, double err,
                 double seconds) {
    std::printf("| %s | %lld | %.2e | %.4f | %.0f |\n", name.c_str(), steps,
                err, seconds, 1e9 * seconds / (double(steps) * double(n)));
  };
  for (const char* method : {"leapfrog", "gauss4"})
    for (long long steps : {128, 256, 512, 1024, 2048}) {
      spacetime::MolSolution s;
      const double sec = bench::MedianSeconds(
          [&] {
            s = spacetime::SolveFieldMol(
                density, g, t_end, phi0, pi0,
                spacetime::MolOptions{.method = method, .steps = steps});
          },
          3);
      if (s.status.converged) row(method, steps, error(s.phi), sec);
    }
  for (const char* op : {"sbp42", "sbp84"})
    for (long long steps : {128, 256, 512, 1024}) {
      spacetime::FieldSolveOptions o;
      o.keep_field = false;
      spacetime::FieldSolution s;
      const spacetime::FieldGrid fg{
          .op = op, .points = steps + 1, .t_end = t_end, .window_points = 17};
      const double sec = bench::MedianSeconds(
          [&] { s = spacetime::SolveField(density, g, fg, phi0, pi0, o); }, 3);
      if (s.status.converged)
        row(std::string(op) + " W = 17", steps, error(s.end.phi), sec);
      else
        std::printf("| %s | %lld | %s |\n", op, steps, s.status.reason.c_str());
    }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  const distributed::Session mpi(&argc, &argv);
  if (argc >= 2 && std::strcmp(argv[1], "--ring") == 0) {
    const int n = argc >= 3 ? std::atoi(argv[2]) : 512;
    const double t = argc >= 4 ? std::atof(argv[3]) : 50.0;
    const int w = argc >= 5 ? std::atoi(argv[4]) : 16;
    const double f = argc >= 6 ? std::atof(argv[5]) : 0.9;
    if (n < 8 || !(t > 0) || w < 8 || !(f > 0 && f <= 1)) {
      std::fprintf(stderr,
                   "fields_plane_bench: --ring N T [W [F]] needs N ≥ 8, T > 0, "
                   "W ≥ 8 and 0 < F ≤ 1\n");
      return 2;
    }
    Ring(n, t, w, f);
    return 0;
  }
  if (argc >= 2 && std::strcmp(argv[1], "--compare") == 0) {
    Compare();
    return 0;
  }
  if (argc >= 2) {
    std::fprintf(
        stderr, "usage: fields_plane_bench [--ring N T [W [F]]] [--compare]\n");
    return 2;
  }
  Table1();
  return 0;
}
