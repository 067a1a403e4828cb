// Cost of the space-time field solve (solvers/spacetime), four tables:
//
// 0. Where a march's time goes: the sine-Gordon breather ω = 0.3 on
//    [−40, 40) with 400 points, SBP42 in windows of 16, 1201 time points over
//    one period, with each window linear solver (window_solver.h): Newton's
//    residuals, assembly (the sparse Jacobian, or the modes' Hessian
//    blocks), factorizations and solves, and around them each window's setup
//    (operators, system, data: the allocations), predictor (the method of
//    lines' Dormand–Prince start of every window), resolution and
//    a-posteriori checks, and hand-off (corrected end state, kept slices).
// 1. One Newton iteration over all Nt × Nx points of the sine-Gordon breather
//    (order-8 periodic differences on [−20, 20), Δt = 0.01): residual,
//    assembly, factorization and one solve, for the whole grid at once or
//    window by window (each window factored afresh — the worst case; a march
//    reuses factorizations), by the sparse LU and by the spatial modes. Peak
//    memory per row from a child process. The growth in Nt and Nx is read
//    off the rows.
// 2. The breather to T = 100, marched and by the method of lines on the
//    same spatial operator: max error against the exact solution, energy
//    drift, windows, factorizations, time.
// 3. Marching memory against Nt (only the end state kept).
//
// Usage: fields_bench [--quick | --long-run | --profile]   (--quick: table 0
// and the 2^18-point rows of table 1; --long-run: tables 2 and 3;
// --profile: table 0)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include "bench/timing.h"
#include "core/action/field_charges.h"
#include "core/action/field_system.h"
#include "problems/fields/densities.h"
#include "problems/fields/exact.h"
#include "solvers/spacetime/method_of_lines.h"
#include "solvers/spacetime/solve.h"

using namespace vivp;

namespace {

double Since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
      .count();
}

struct Row {
  double residual = 0, assembly = 0, factor = 0, solve = 0;
  long long jacobian_nnz = 0, factor_nnz = 0;
  int windows = 0;
};

// One Newton iteration over nt × nx points in windows of w time points
// (w = nt: the whole grid), the linearization at φ(t, x) = φ₀(x) + tπ₀(x).
Row NewtonIteration(const char* op, int nt, int nx, int w,
                    spacetime::SparseSolver solver, bool modes) {
  const fields::SineGordon sg;
  const fields::SineGordonBreather breather{0.5};
  const auto dx = sbp::SpaceDerivative<double>::Periodic(8, nx, -20.0, 40.0);
  const double dt = 0.01;
  const auto [phi0, pi0] = fields::InitialData(breather, dx);
  Row row;
  spacetime::PatternedMatrix jac;
  spacetime::SparseLu lu(solver);
  spacetime::ModesSolver<fields::SineGordon> spectral(sg);
  int analyzed = 0;
  for (int start = 0; start < nt - 1; start += w - 1) {
    const int pts = std::min(w, nt - start);
    if (pts < w && start > 0) break;  // equal windows only
    const sbp::RegularizedOperator<double> op_t(
        sbp::MakeOperator<double>(op, pts, start * dt, (start + pts - 1) * dt));
    const action::FieldSystem<fields::SineGordon> sys(sg, op_t, dx, phi0, pi0);
    Eigen::VectorXd y(sys.size()), f(sys.size()), delta(sys.size());
    for (int j = 0; j < nx; ++j)
      for (int i = 0; i < pts; ++i)
        y[sys.Phi(i, j, 0)] = phi0[j] + dt * i * pi0[j];
    auto t0 = std::chrono::steady_clock::now();
    sys.Residual(y.data(), f.data());
    row.residual += Since(t0);
    if (modes) {
      // Afresh: the modes of this window and the blocks at its y.
      spectral.Invalidate();
      t0 = std::chrono::steady_clock::now();
      spectral.Prepare(sys, y.data());
      spectral.Assemble(sys, y.data());
      row.assembly += Since(t0);
      t0 = std::chrono::steady_clock::now();
      if (!spectral.Factorize()) std::printf("singular!\n");
      row.factor += Since(t0);
      t0 = std::chrono::steady_clock::now();
      spectral.Solve(f.data());
      row.solve += Since(t0);
      ++row.windows;
      row.jacobian_nnz = 0;
      row.factor_nnz = static_cast<long long>(spectral.factor_bytes() / 8);
      continue;
    }
    t0 = std::chrono::steady_clock::now();
    jac.Assemble(sys.size(), [&](auto& sink) { sys.Jacobian(y.data(), sink); });
    row.assembly += Since(t0);
    t0 = std::chrono::steady_clock::now();
    if (analyzed != jac.patterns()) {
      lu.Analyze(jac.matrix());
      analyzed = jac.patterns();
    }
    if (!lu.Factorize(jac.matrix())) std::printf("singular!\n");
    row.factor += Since(t0);
    t0 = std::chrono::steady_clock::now();
    lu.Solve(f, delta);
    row.solve += Since(t0);
    ++row.windows;
    row.jacobian_nnz = jac.matrix().nonZeros();
    if (row.windows == 1) row.factor_nnz = lu.FactorNonzeros();
  }
  return row;
}

// 0. Where a march's time goes, per window linear solver.
void Table0() {
  std::printf(
      "Where a march's time goes: sine-Gordon breather ω = 0.3 on [−40, 40),\n"
      "400 points (order-8 periodic differences), SBP42 in windows of 16,\n"
      "1201 time points over one period (seconds)\n\n"
      "| linear solver | residual | assembly | factor | solve | setup | "
      "predictor | check | hand-off | other | total | μs per point | "
      "Newton its | solves | fallbacks |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  const double omega = 0.3;
  const fields::SineGordon sg;
  const auto dx = sbp::SpaceDerivative<double>::Periodic(8, 400, -40.0, 80.0);
  const auto [phi0, pi0] =
      fields::InitialData(fields::SineGordonBreather{omega}, dx);
  for (const auto linear : {spacetime::WindowLinearSolver::kSparseLu,
                            spacetime::WindowLinearSolver::kModes}) {
    spacetime::FieldSolveOptions o;
    o.linear = linear;
    const spacetime::FieldGrid grid{.op = "sbp42",
                                    .points = 1201,
                                    .t_end = 2 * std::numbers::pi / omega,
                                    .window_points = 16};
    const auto r = spacetime::SolveField(sg, dx, grid, phi0, pi0, o);
    const double known = r.seconds_residual + r.seconds_assembly +
                         r.seconds_factor + r.seconds_solve + r.seconds_setup +
                         r.seconds_predictor + r.seconds_check +
                         r.seconds_handoff;
    std::printf(
        "| %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | "
        "**%.3f** | %.2f | %lld | %d | %d |%s\n",
        r.linear_solver.c_str(), r.seconds_residual, r.seconds_assembly,
        r.seconds_factor, r.seconds_solve, r.seconds_setup, r.seconds_predictor,
        r.seconds_check, r.seconds_handoff, r.seconds_total - known,
        r.seconds_total, 1e6 * r.seconds_total / (1201.0 * 400),
        r.factorizations, r.corrections, r.fallbacks,
        r.status.converged ? "" : (" " + r.status.reason).c_str());
  }
  std::printf("\n");
}

void Table1(bool quick) {
  std::printf(
      "One Newton iteration, sine-Gordon breather, order-8 periodic space,\n"
      "every window factored afresh (seconds; nnz of the Jacobian and of one\n"
      "window's L+U — for the modes, the values their band factors hold;\n"
      "assembly is the Hessian blocks there; peak RSS of the run)\n\n");
  std::printf(
      "| time op | solver | Nt × Nx | window | windows | residual | "
      "assembly | factor | solve | total | J nnz | LU nnz | peak MB |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  struct Config {
    const char* op;
    int nt, nx, w;
    spacetime::SparseSolver solver;
    bool modes = false;
  };
  using S = spacetime::SparseSolver;
  std::vector<Config> configs = {
      {"sbp21", 512, 512, 512, S::kUmfpack},
      {"sbp42", 512, 512, 8, S::kUmfpack},
      {"sbp42", 512, 512, 16, S::kUmfpack},
      {"sbp21", 512, 512, 512, S::kUmfpack, true},
      {"sbp42", 512, 512, 512, S::kUmfpack, true},
      {"sbp42", 512, 512, 16, S::kUmfpack, true},
      {"sbp84", 512, 512, 16, S::kUmfpack, true},
      {"sbp42", 2048, 2048, 2048, S::kUmfpack, true},
      {"sbp42", 2048, 2048, 16, S::kUmfpack, true},
  };
  if (!quick) {
    const std::vector<Config> more = {
        {"sbp42", 512, 512, 8, S::kEigen},
        {"sbp42", 512, 512, 16, S::kEigen},
        {"sbp21", 128, 512, 128, S::kUmfpack},
        {"sbp21", 256, 512, 256, S::kUmfpack},
        {"sbp21", 1024, 512, 1024, S::kUmfpack},
        {"sbp21", 512, 128, 512, S::kUmfpack},
        {"sbp21", 512, 256, 512, S::kUmfpack},
        {"sbp21", 512, 1024, 512, S::kUmfpack},
        {"sbp42", 128, 512, 8, S::kUmfpack},
        {"sbp42", 256, 512, 8, S::kUmfpack},
        {"sbp42", 1024, 512, 8, S::kUmfpack},
        {"sbp42", 512, 128, 8, S::kUmfpack},
        {"sbp42", 512, 256, 8, S::kUmfpack},
        {"sbp42", 512, 1024, 8, S::kUmfpack},
        {"sbp42", 64, 64, 64, S::kUmfpack},
        {"sbp42", 128, 128, 128, S::kUmfpack},
        {"sbp84", 2048, 2048, 2048, S::kUmfpack, true},
        {"sbp42", 4096, 1024, 4096, S::kUmfpack, true},
    };
    configs.insert(configs.end(), more.begin(), more.end());
  }
  for (const Config& c : configs) {
    const double mb = bench::PeakMegabytesInChild([&] {
      const Row r = NewtonIteration(c.op, c.nt, c.nx, c.w, c.solver, c.modes);
      const double total = r.residual + r.assembly + r.factor + r.solve;
      std::printf(
          "| %s | %s | %d × %d | %s | %d | %.3f | %.3f | %.3f | %.3f "
          "| **%.2f** | %lld | %lld |",
          c.op,
          c.modes ? "modes"
                  : std::string(spacetime::SparseSolverName(c.solver)).c_str(),
          c.nt, c.nx, c.w == c.nt ? "global" : std::to_string(c.w).c_str(),
          r.windows, r.residual, r.assembly, r.factor, r.solve, total,
          r.jacobian_nnz, r.factor_nnz);
    });
    std::printf(" %.0f |\n", mb);
  }
}

void Table2() {
  std::printf(
      "\nThe breather (ω = 0.5) to T = 100, order-8 periodic differences: the\n"
      "space-time solve (SBP42 in time, marched in windows of 16)\n"
      "and the method of lines on the same spatial operator (gauss6, fixed\n"
      "step); max error against the exact solution up to t = 50 and up to\n"
      "t = 100, energy drift\n\n"
      "| method | domain | Δt | Nx | error t ≤ 50 | error t ≤ 100 | max |φ| | "
      "energy drift | windows | factorizations | seconds | peak MB |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  struct Config {
    const char* method;
    int steps, nx;
    double half = 20;  // domain [−half, half)
  };
  // The last rows widen the domain at Δx = 0.2 and 0.1: the departure
  // after t ≈ 70 is seeded by the spatial step and by the truncation of the
  // breather's tails at ±20, in the semi-discrete flow itself.
  for (const Config c :
       {Config{"sbp42", 5000, 200}, Config{"sbp42", 10000, 200},
        Config{"sbp42", 5000, 400}, Config{"gauss6", 5000, 200},
        Config{"gauss6", 5000, 400}, Config{"gauss6", 5000, 300, 30},
        Config{"gauss6", 5000, 600, 30}, Config{"sbp42", 5000, 600, 30}}) {
    const double mb = bench::PeakMegabytesInChild([&] {
      const int nx = c.nx;
      const fields::SineGordon sg;
      const fields::SineGordonBreather breather{0.5};
      const auto dx =
          sbp::SpaceDerivative<double>::Periodic(8, nx, -c.half, 2 * c.half);
      const auto [phi0, pi0] = fields::InitialData(breather, dx);
      const double e0 = action::ChargesOfSlice(sg, dx, phi0, pi0).energy;
      std::vector<double> t, phi, phi_t;
      bool converged = false;
      std::string message;
      int windows = 0;
      long long factorizations = 0;
      double seconds = 0;
      if (std::string(c.method) == "sbp42") {
        auto s = spacetime::SolveField(
            sg, dx, {"sbp42", c.steps + 1, 100.0, 16}, phi0, pi0);
        t = std::move(s.t), phi = std::move(s.phi);
        phi_t = std::move(s.phi_t);
        converged = s.status.converged, message = s.status.reason,
        windows = s.windows;
        factorizations = s.factorizations, seconds = s.seconds_total;
      } else {
        auto s = spacetime::SolveFieldMol(
            sg, dx, 100.0, phi0, pi0,
            {.method = c.method, .steps = c.steps, .output_every = 1});
        t = std::move(s.t), phi = std::move(s.phi);
        phi_t = std::move(s.phi_t);
        converged = s.status.converged, message = s.status.reason,
        seconds = s.seconds;
      }
      double err50 = 0, err = 0, drift = 0, peak = 0;
      for (std::size_t k = 0; k < t.size(); ++k) {
        for (int j = 0; j < nx; ++j) {
          const double e = std::abs(phi[k * nx + j] - breather(t[k], dx.x(j)));
          err = std::max(err, e);
          if (t[k] <= 50) err50 = std::max(err50, e);
          peak = std::max(peak, std::abs(phi[k * nx + j]));
        }
        const std::span<const double> p(phi.data() + k * nx, nx);
        const std::span<const double> q(phi_t.data() + k * nx, nx);
        drift = std::max(
            drift, std::abs(action::ChargesOfSlice(sg, dx, p, q).energy - e0));
      }
      std::printf(
          "| %s | [−%g, %g) | %.3g | %d | %.2e | %.2e | %.3f | %.2e | %d | "
          "%lld "
          "| %.1f |",
          c.method, c.half, c.half, 100.0 / c.steps, nx, err50, err, peak,
          drift, windows, factorizations, seconds);
      if (!converged) std::printf(" %s |", message.c_str());
    });
    std::printf(" %.0f |\n", mb);
  }
}

// 3. Marching memory: the breather on 512 points, SBP42 in windows of 16,
//    only the end state kept (keep_field = false), for growing Nt. The peak
//    resident memory of the run should not grow with Nt.
void Table3() {
  std::printf(
      "\nMarching memory: the breather on [−20, 20), 512 points, SBP42 in\n"
      "windows of 16, Δt = 0.02, only the end state kept\n\n"
      "| Nt | windows | seconds | peak MB |\n|---|---|---|---|\n");
  for (const int nt : {501, 2001, 8001}) {
    const double mb = bench::PeakMegabytesInChild([&] {
      const fields::SineGordon sg;
      const auto dx =
          sbp::SpaceDerivative<double>::Periodic(8, 512, -20.0, 40.0);
      const auto [phi0, pi0] =
          fields::InitialData(fields::SineGordonBreather{0.5}, dx);
      spacetime::FieldSolveOptions o;
      o.keep_field = false;
      const auto s = spacetime::SolveField(
          sg, dx, {"sbp42", nt, 0.02 * (nt - 1), 16}, phi0, pi0, o);
      std::printf("| %d | %d | %.1f |", nt, s.windows, s.seconds_total);
      if (!s.status.converged) std::printf(" %s |", s.status.reason.c_str());
    });
    std::printf(" %.0f |\n", mb);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string arg = argc > 1 ? argv[1] : "";
  if (arg != "" && arg != "--quick" && arg != "--long-run" &&
      arg != "--profile") {
    std::fprintf(stderr,
                 "fields_bench: unknown argument '%s' (--quick: table 0 and "
                 "the 2^18-point rows of table 1; --long-run: tables 2 and 3 "
                 "only; --profile: table 0 only)\n",
                 arg.c_str());
    return 2;
  }
  if (arg == "--profile" || arg == "" || arg == "--quick") Table0();
  if (arg == "--profile") return 0;
  if (arg != "--long-run") Table1(arg == "--quick");
  if (arg != "--quick") {
    Table2();
    Table3();
  }
  return 0;
}
